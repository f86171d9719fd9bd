#include <archdam/base/input_error.h>
#include <archdam/output/monitors.h>

#include <cmath>
#include <cstdlib>
#include <deal.II/base/mpi.h>
#include <deal.II/base/quadrature.h>
#include <deal.II/base/utilities.h>
#include <deal.II/fe/fe_values.h>
#include <deal.II/fe/mapping_q.h>
#include <deal.II/grid/grid_tools.h>

namespace archdam::output
{
  using namespace dealii;

  void
  MonitorParameters::add_parameters(ParameterHandler &prm)
  {
    prm.add_parameter("Points", points,
                      "Named points whose histories are recorded, as "
                      "'name: x, y, z; name: x, y, z' [m]. Stresses are taken "
                      "from the cell that contains the point (on a face shared "
                      "by two cells, from one of them).",
                      Patterns::Anything());
    prm.add_parameter("Quantities", quantities,
                      "What is recorded at each point (comma-separated): "
                      "displacement, velocity, acceleration, principal stress.",
                      Patterns::MultipleSelection(
                        "displacement|velocity|acceleration|principal stress"));
  }

  std::vector<MonitorPoint>
  parse_monitor_points(const std::string &text)
  {
    std::vector<MonitorPoint> result;
    for (const std::string &item : Utilities::split_string_list(text, ';'))
      {
        const auto colon = item.find(':');
        const auto bad   = [&](const std::string &why) {
          return InputError("Monitors/Points: '" + item + "': " + why +
                            " (expected 'name: x, y, z').");
        };
        if (colon == std::string::npos)
          throw bad("no ':' after the name");
        MonitorPoint p;
        p.name = Utilities::trim(item.substr(0, colon));
        if (p.name.empty() || p.name.find_first_of(" ,.[]") != std::string::npos)
          throw bad("the name must be a non-empty word without blanks, commas, dots or brackets");
        const auto coords = Utilities::split_string_list(item.substr(colon + 1), ',');
        if (coords.size() != dim)
          throw bad("need three coordinates");
        for (unsigned int d = 0; d < dim; ++d)
          {
            char *end = nullptr;
            p.location[d] = std::strtod(coords[d].c_str(), &end);
            if (end == coords[d].c_str() || *end != '\0' || !std::isfinite(p.location[d]))
              throw bad("'" + coords[d] + "' is not a finite number");
          }
        for (const auto &q : result)
          if (q.name == p.name)
            throw bad("the name is used twice");
        result.push_back(p);
      }
    return result;
  }

  Monitors::Monitors(const MonitorParameters                  &p,
                     const fe::FESpace                        &space,
                     const physics::solid::MaterialParameters &materials,
                     const physics::solid::TemperatureField   &temperature)
    : space(space)
    , points(parse_monitor_points(p.points))
  {
    const auto has = [&](const std::string &q) {
      for (const auto &s : Utilities::split_string_list(p.quantities, ','))
        if (s == q)
          return true;
      return false;
    };
    record_u      = has("displacement");
    record_v      = has("velocity");
    record_a      = has("acceleration");
    record_stress = has("principal stress");

    const auto column = [&](const std::string &name, const Peak peak) {
      names.push_back(name);
      peaks.push_back(peak);
    };
    column("time [s]", Peak::magnitude);
    for (const auto &pt : points)
      {
        const auto add3 = [&](const std::string &q, const std::string &unit) {
          for (const char c : {'x', 'y', 'z'})
            column(pt.name + "." + q + c + " [" + unit + "]", Peak::magnitude);
        };
        if (record_u)
          add3("u", "m");
        if (record_v)
          add3("v", "m/s");
        if (record_a)
          add3("a", "m/s^2");
        if (record_stress)
          {
            column(pt.name + ".s1 [Pa]", Peak::largest);
            column(pt.name + ".s3 [Pa]", Peak::smallest);
          }
      }

    // Every rank holds the whole mesh and all cells' DOF indices, so every rank
    // finds the same cell and computes the same weights.
    const MappingQ<dim> mapping(1);
    for (const auto &pt : points)
      {
        const auto found = GridTools::find_active_cell_around_point(
          mapping, space.dof_handler.get_triangulation(), pt.location);
        if (found.first.state() != IteratorState::valid)
          throw InputError("Monitors/Points: point '" + pt.name + "' lies outside the mesh.");
        const typename DoFHandler<dim>::active_cell_iterator cell(
          &space.dof_handler.get_triangulation(), found.first->level(), found.first->index(),
          &space.dof_handler);
        if (cell->active_fe_index() != fe::FESpace::solid_index)
          throw InputError("Monitors/Points: point '" + pt.name + "' lies in the water.");
        const Quadrature<dim> at_point(GeometryInfo<dim>::project_to_unit_cell(found.second));
        FEValues<dim> fv(mapping, space.fe_collection[fe::FESpace::solid_index], at_point,
                         update_values | update_gradients);
        fv.reinit(cell);
        Weights w;
        w.dofs.resize(fv.dofs_per_cell);
        cell->get_dof_indices(w.dofs);
        for (unsigned int i = 0; i < fv.dofs_per_cell; ++i)
          {
            w.value.push_back(fv[space.displacement].value(i, 0));
            w.gradient.push_back(fv[space.displacement].gradient(i, 0));
          }
        w.material           = materials.of(cell->material_id());
        w.temperature_change = temperature.change(cell->material_id(), pt.location);
        weights.push_back(w);
      }
  }

  std::vector<double>
  Monitors::gather(const Vector &vec, const Weights &w) const
  {
    std::vector<double> values(w.dofs.size(), 0.);
    for (unsigned int i = 0; i < w.dofs.size(); ++i)
      if (space.locally_owned.is_element(w.dofs[i]))
        values[i] = vec(w.dofs[i]);
    // Each value comes from exactly one owner; the others contribute zero.
    MPI_Allreduce(MPI_IN_PLACE, values.data(), values.size(), MPI_DOUBLE, MPI_SUM, space.comm);
    return values;
  }

  Tensor<1, dim>
  Monitors::interpolate(const unsigned int k, const std::vector<double> &values) const
  {
    Tensor<1, dim> result;
    for (unsigned int i = 0; i < values.size(); ++i)
      result += values[i] * weights[k].value[i];
    return result;
  }

  Tensor<1, dim>
  Monitors::displacement(const unsigned int k, const Vector &u) const
  {
    return interpolate(k, gather(u, weights[k]));
  }

  std::vector<double>
  Monitors::evaluate(const time::NewmarkState &s, const Vector *acceleration) const
  {
    std::vector<double> row{s.time};
    for (unsigned int k = 0; k < points.size(); ++k)
      {
        const auto push3 = [&](const std::vector<double> &values) {
          const auto t = interpolate(k, values);
          for (unsigned int d = 0; d < dim; ++d)
            row.push_back(t[d]);
        };
        // The nodal displacements serve both u and the stress: gathered once.
        const auto u = record_u || record_stress ? gather(s.u, weights[k]) : std::vector<double>();
        if (record_u)
          push3(u);
        if (record_v)
          push3(gather(s.v, weights[k]));
        if (record_a)
          push3(gather(acceleration ? *acceleration : s.a, weights[k]));
        if (record_stress)
          {
            Tensor<2, dim> grad;
            for (unsigned int i = 0; i < u.size(); ++i)
              grad += u[i] * weights[k].gradient[i];
            const auto [s1, s3] =
              physics::solid::principal_stresses(weights[k].material.stress(symmetrize(grad),
                                                                          weights[k].temperature_change));
            row.push_back(s1);
            row.push_back(s3);
          }
      }
    return row;
  }
} // namespace archdam::output
