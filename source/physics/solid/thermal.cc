#include <archdam/base/input_error.h>
#include <archdam/base/number_text.h>
#include <archdam/geometry/dam_surface.h>
#include <archdam/geometry/ids.h>
#include <archdam/physics/solid/thermal.h>

#include <deal.II/fe/fe_values.h>
#include <deal.II/hp/fe_values.h>

#include <algorithm>
#include <cmath>
#include <limits>

namespace archdam::physics::solid
{
  using namespace dealii;

  ThroughThickness::ThroughThickness(const Triangulation<dim> &tria)
  {
    // Every rank holds the whole mesh (parallel::shared::Triangulation), so
    // every rank finds the same faces.
    for (const auto &cell : tria.active_cell_iterators())
      if (ids::is_dam(cell->material_id()))
        for (const unsigned int f : cell->face_indices())
          if (cell->face(f)->at_boundary() &&
              geometry::on_dam_surface(cell->face(f)->boundary_id()))
            {
              const auto     face = cell->face(f);
              Tensor<1, dim> n    = cross_product_3d(face->vertex(3) - face->vertex(0),
                                                 face->vertex(2) - face->vertex(1));
              const Point<dim> centre = face->center();
              if (n * (centre - cell->center()) < 0)
                n = -n;
              n /= n.norm();
              const auto part = geometry::surface_part(n);
              if (part == geometry::SurfacePart::upstream)
                upstream.push_back({centre, n});
              else if (part == geometry::SurfacePart::downstream)
                downstream.push_back({centre, n});
            }
    if (upstream.empty() || downstream.empty())
      throw InputError("Static loads/Temperature change: the dam has no " +
                       std::string(upstream.empty() ? "upstream" : "downstream") +
                       " face (a surface of its cells facing " +
                       (upstream.empty() ? "-x" : "+x") +
                       "), so its through-thickness coordinate is not defined "
                       "(doc/theory/temperature.md §1).");
  }

  double
  ThroughThickness::distance(const std::vector<Plane> &faces, const Point<dim> &x)
  {
    const Plane *nearest = &faces.front();
    double       best    = std::numeric_limits<double>::max();
    for (const Plane &f : faces)
      if (const double d = f.centre.distance_square(x); d < best)
        {
          best    = d;
          nearest = &f;
        }
    return std::abs(nearest->normal * (x - nearest->centre));
  }

  double
  ThroughThickness::operator()(const Point<dim> &x) const
  {
    const double du = distance(upstream, x), dd = distance(downstream, x);
    return du + dd > 0 ? du / (du + dd) : 0.5;
  }

  TemperatureField::TemperatureField(const loads::TemperatureTable &table,
                                     const Triangulation<dim>      &tria)
    : table(table)
  {
    if (table.empty())
      return;
    double z_low = std::numeric_limits<double>::max(), z_high = -z_low;
    for (const auto &cell : tria.active_cell_iterators())
      if (ids::is_dam(cell->material_id()))
        for (const unsigned int v : cell->vertex_indices())
          {
            z_low  = std::min(z_low, cell->vertex(v)[dim - 1]);
            z_high = std::max(z_high, cell->vertex(v)[dim - 1]);
          }
    const double slack = 1e-9 * std::max(1., z_high - z_low);
    if (z_low < table.elevation.front() - slack || z_high > table.elevation.back() + slack)
      throw InputError("Static loads/Temperature change: the table covers the elevations " +
                       number_text(table.elevation.front()) + " to " +
                       number_text(table.elevation.back()) + " m, but the dam reaches from " +
                       number_text(z_low) + " to " + number_text(z_high) +
                       " m: give rows at or beyond both (doc/theory/temperature.md §1).");
    thickness.emplace(tria);
  }

  double
  TemperatureField::change(const types::material_id material, const Point<dim> &x) const
  {
    if (table.empty() || !ids::is_dam(material))
      return 0.;
    const auto [mean, difference] = table.at(x[dim - 1]);
    return mean + difference * (0.5 - (*thickness)(x));
  }

  void
  add_thermal_load(const fe::FESpace        &space,
                   const MaterialParameters &materials,
                   const TemperatureField   &temperature,
                   Vector                   &load)
  {
    if (temperature.empty())
      return;
    hp::FEValues<dim> hp_fe_values(space.fe_collection, space.q_collection,
                                   update_gradients | update_quadrature_points |
                                     update_JxW_values);
    dealii::Vector<double>               cell_f;
    std::vector<types::global_dof_index> dofs;
    for (const auto &cell : space.dof_handler.active_cell_iterators())
      if (cell->is_locally_owned() && cell->active_fe_index() == fe::FESpace::solid_index &&
          ids::is_dam(cell->material_id()))
        {
          hp_fe_values.reinit(cell);
          const FEValues<dim>   &fv  = hp_fe_values.get_present_fe_values();
          const ElasticMaterial &mat = materials.of(cell->material_id());
          cell_f.reinit(fv.dofs_per_cell);
          for (const unsigned int q : fv.quadrature_point_indices())
            {
              const double p =
                mat.thermal_pressure(temperature.change(cell->material_id(), fv.quadrature_point(q)));
              for (unsigned int i = 0; i < fv.dofs_per_cell; ++i)
                cell_f(i) += p * fv[space.displacement].divergence(i, q) * fv.JxW(q);
            }
          dofs.resize(fv.dofs_per_cell);
          cell->get_dof_indices(dofs);
          space.constraints.distribute_local_to_global(cell_f, dofs, load);
        }
    load.compress(VectorOperation::add);
  }
} // namespace archdam::physics::solid
