#include <archdam/base/input_error.h>
#include <archdam/geometry/ids.h>
#include <archdam/physics/foundation/reference_motion.h>

#include <deal.II/base/quadrature_lib.h>
#include <deal.II/fe/fe_nothing.h>
#include <deal.II/fe/fe_values.h>
#include <deal.II/fe/mapping_q1.h>

#include <algorithm>
#include <cmath>

namespace archdam::physics::foundation
{
  using namespace dealii;

  ReferenceMotion::ReferenceMotion(const FreeField &free_field, const Triangulation<dim> &mesh)
    : free_field(free_field)
  {
    const FE_Nothing<dim> fe;
    const MappingQ1<dim>  mapping;
    FEFaceValues<dim>     fv(mapping, fe, QGauss<dim - 1>(3),
                             update_quadrature_points | update_JxW_values);
    std::vector<std::pair<double, double>> all;
    for (const auto &cell : mesh.active_cell_iterators())
      if (ids::is_dam(cell->material_id()))
        for (const unsigned int f : cell->face_indices())
          if (!cell->at_boundary(f) && cell->neighbor(f)->material_id() == ids::rock)
            {
              fv.reinit(cell, f);
              for (const unsigned int q : fv.quadrature_point_indices())
                all.emplace_back(fv.quadrature_point(q)[dim - 1], fv.JxW(q));
            }
    if (all.empty())
      throw InputError("Damping: the dam's mass-proportional damping relative to the ground "
                       "needs the dam-rock interface, and no dam cell touches a rock cell; "
                       "set Damping/Mass proportional term = total velocity.");
    // One entry per height (within a millimetre): the free field depends
    // on z alone.
    std::sort(all.begin(), all.end());
    for (const auto &[z, w] : all)
      {
        if (points.empty() || z - points.back().first > 1e-3)
          points.emplace_back(z, 0.);
        points.back().second += w;
        area += w;
      }
    for (auto &p : points)
      p.second /= area;
    z_low  = all.front().first;
    z_high = all.back().first;
  }

  Tensor<1, dim>
  ReferenceMotion::mean(const double t,
                        Tensor<1, dim> (FreeField::*of)(double, double) const) const
  {
    Tensor<1, dim> m;
    for (const auto &[z, w] : points)
      m += w * (free_field.*of)(z, t);
    return m;
  }

  Tensor<1, dim>
  ReferenceMotion::velocity(const double t) const
  {
    return mean(t, &FreeField::velocity);
  }

  Tensor<1, dim>
  ReferenceMotion::displacement(const double t) const
  {
    return mean(t, &FreeField::displacement);
  }
} // namespace archdam::physics::foundation
