#include <archdam/analysis/static_resultants.h>
#include <archdam/geometry/ids.h>

#include <deal.II/base/mpi.h>
#include <deal.II/fe/fe_values.h>

#include <algorithm>
#include <cmath>
#include <iomanip>
#include <ostream>

namespace archdam::analysis
{
  using namespace dealii;

  namespace
  {
    double
    relative(const Tensor<1, dim> &sum, const Tensor<1, dim> &a, const Tensor<1, dim> &b)
    {
      const double scale = a.norm() + b.norm();
      return scale > 0 ? sum.norm() / scale : 0.;
    }
  } // namespace

  double
  StaticResultants::out_of_balance() const
  {
    return relative(weight + water + reaction, weight, water);
  }

  double
  StaticResultants::stress_out_of_balance() const
  {
    return relative(weight + water + support_stress, weight, water);
  }

  void
  StaticResultants::print(std::ostream &out) const
  {
    // Components below round-off of the largest are printed as 0: they
    // differ with the order of the sums (the number of MPI processes).
    const auto line = [&](const char *name, const Tensor<1, dim> &f, const double scale,
                          const double unit) {
      out << "  " << std::left << std::setw(22) << name << std::right << std::setprecision(6);
      for (unsigned int d = 0; d < dim; ++d)
        out << std::setw(14) << (std::abs(f[d]) < 1e-10 * scale ? 0. : f[d] / unit);
      out << '\n';
    };
    const auto balance = [&](const double x) {
      out << "  out of balance ";
      if (x < 1e-9)
        out << "below 1e-9";
      else
        out << std::setprecision(2) << x;
      out << " of the applied loads\n";
    };
    const double forces = std::max({weight.norm(), water.norm(), reaction.norm()});
    out << "Static resultants on the dam [MN]:                x             y             z\n";
    line("weight", weight, forces, 1e6);
    line("water", water, forces, 1e6);
    line("support (reactions)", reaction, forces, 1e6);
    balance(out_of_balance());
    // (a moment's round-off: the forces' times the model's metres)
    const double moments =
      std::max({weight_moment.norm(), water_moment.norm(), reaction_moment.norm(), forces});
    out << "  moments [MN m] about the support's centroid (" << std::setprecision(6)
        << centroid[0] << ", " << centroid[1] << ", " << centroid[2] << ") m:\n";
    line("weight", weight_moment, moments, 1e6);
    line("water", water_moment, moments, 1e6);
    line("support (reactions)", reaction_moment, moments, 1e6);
    out << "  the support's force from the stress on its faces (falls with the mesh):\n";
    line("support (stress)", support_stress, forces, 1e6);
    balance(stress_out_of_balance());
    out << std::flush;
  }

  StaticResultants
  static_resultants(const fe::FESpace                        &space,
                    const physics::solid::MaterialParameters &materials,
                    const physics::solid::TemperatureField   &temperature,
                    const Vector                             &u,
                    const Tensor<1, dim>                     &gravity,
                    const std::function<double(double)>      &pressure)
  {
    const auto &fe = space.fe_collection[fe::FESpace::solid_index];
    const auto &q  = space.q_collection[fe::FESpace::solid_index];
    FEValues<dim>     cell_values(fe, q,
                              update_values | update_gradients | update_quadrature_points |
                                update_JxW_values);
    FEFaceValues<dim> face_values(fe, space.face_q_collection[fe::FESpace::solid_index],
                                  update_values | update_gradients | update_quadrature_points |
                                    update_normal_vectors | update_JxW_values);
    // The positions of a cell's DOFs (its nodes).
    FEValues<dim> nodes(fe, Quadrature<dim>(fe.get_unit_support_points()),
                        update_quadrature_points);
    const unsigned int                   n = fe.n_dofs_per_cell();
    std::vector<types::global_dof_index> dofs(n);
    std::vector<double>                  u_cell(n), r(n);
    std::vector<Tensor<2, dim>>          gradients(face_values.n_quadrature_points);

    const auto is_dam = [](const auto &cell) { return ids::is_dam(cell->material_id()); };
    const auto wetted = [](const auto &cell, const unsigned int f) {
      return cell->face(f)->at_boundary() &&
             cell->face(f)->boundary_id() == ids::solid_interface;
    };
    // The support: the rock, or where no rock is meshed under the dam the
    // fixed truncation itself.
    const auto on_rock = [](const auto &cell, const unsigned int f) {
      const auto face = cell->face(f);
      return face->at_boundary() ? (face->boundary_id() == ids::foundation_bottom ||
                                    face->boundary_id() == ids::foundation_sides) :
                                   cell->neighbor(f)->material_id() == ids::rock;
    };

    // The support's nodes and the centroid of its faces, from every dam
    // cell (each rank sees the whole shared mesh).
    std::vector<bool> support(space.dof_handler.n_dofs(), false);
    double            area = 0.;
    Tensor<1, dim>    first_moment;
    for (const auto &cell : space.dof_handler.active_cell_iterators())
      if (is_dam(cell))
        for (const unsigned int f : cell->face_indices())
          if (on_rock(cell, f))
            {
              cell->get_dof_indices(dofs);
              for (unsigned int i = 0; i < n; ++i)
                if (fe.has_support_on_face(i, f))
                  support[dofs[i]] = true;
              area += cell->face(f)->measure();
              first_moment += cell->face(f)->measure() * cell->face(f)->center();
            }

    StaticResultants result;
    if (area > 0)
      result.centroid = Point<dim>(first_moment / area);
    const Point<dim> &c = result.centroid;
    for (const auto &cell : space.dof_handler.active_cell_iterators())
      if (cell->is_locally_owned() && is_dam(cell))
        {
          const auto &material = materials.of(cell->material_id());
          cell->get_dof_indices(dofs);
          cell->get_dof_values(u, u_cell.begin(), u_cell.end());
          std::fill(r.begin(), r.end(), 0.);
          // r = int B^T sigma dV - f over the cell, f its weight and water
          cell_values.reinit(cell);
          for (const unsigned int k : cell_values.quadrature_point_indices())
            {
              SymmetricTensor<2, dim> strain;
              for (unsigned int i = 0; i < n; ++i)
                strain += u_cell[i] * cell_values[space.displacement].symmetric_gradient(i, k);
              const auto           sigma = material.stress(
                strain, temperature.change(cell->material_id(), cell_values.quadrature_point(k)));
              const Tensor<1, dim> b     = material.density * gravity;
              const double         dV    = cell_values.JxW(k);
              result.weight += b * dV;
              result.weight_moment += cross_product_3d(cell_values.quadrature_point(k) - c, b * dV);
              for (unsigned int i = 0; i < n; ++i)
                r[i] += (scalar_product(cell_values[space.displacement].symmetric_gradient(i, k),
                                        sigma) -
                         cell_values[space.displacement].value(i, k) * b) *
                        dV;
            }
          for (const unsigned int f : cell->face_indices())
            {
              const bool water = wetted(cell, f), rock = on_rock(cell, f);
              if (!water && !rock)
                continue;
              face_values.reinit(cell, f);
              if (rock)
                face_values[space.displacement].get_function_gradients(u, gradients);
              for (const unsigned int k : face_values.quadrature_point_indices())
                {
                  const Tensor<1, dim> n_out = face_values.normal_vector(k);
                  const double         dA    = face_values.JxW(k);
                  if (rock)
                    result.support_stress +=
                      material.stress(symmetrize(gradients[k]),
                                      temperature.change(cell->material_id(),
                                                         face_values.quadrature_point(k))) *
                      n_out * dA;
                  else
                    {
                      const Point<dim>     x = face_values.quadrature_point(k);
                      const Tensor<1, dim> t = -pressure(x[dim - 1]) * n_out * dA;
                      result.water += t;
                      result.water_moment += cross_product_3d(x - c, t);
                      for (unsigned int i = 0; i < n; ++i)
                        r[i] -= face_values[space.displacement].value(i, k) * t;
                    }
                }
            }
          // the support's nodes take the residual as the support's force
          nodes.reinit(cell);
          for (unsigned int i = 0; i < n; ++i)
            if (support[dofs[i]])
              {
                Tensor<1, dim> f;
                f[fe.system_to_component_index(i).first] = r[i];
                result.reaction += f;
                result.reaction_moment += cross_product_3d(nodes.quadrature_point(i) - c, f);
              }
        }
    for (Tensor<1, dim> *f : {&result.weight, &result.water, &result.reaction,
                              &result.support_stress, &result.weight_moment,
                              &result.water_moment, &result.reaction_moment})
      *f = Utilities::MPI::sum(*f, space.comm);
    return result;
  }
} // namespace archdam::analysis
