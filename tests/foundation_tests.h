// Helpers of the foundation radiation tests (doc/verification.md, "Foundation
// radiation"): rock boxes and columns, lateral ties that make a column
// one-dimensional, the elastic energy (also newmark_energy's), and smooth
// pulses with their exact derivatives.
#pragma once

#include <archdam/fe/fe_space.h>
#include <archdam/geometry/ids.h>
#include <archdam/time/newmark.h>

#include <deal.II/fe/mapping_q1.h>
#include <deal.II/grid/grid_generator.h>
#include <deal.II/numerics/vector_tools.h>

#include <cmath>
#include <map>

#include "archdam_tests.h"

namespace archdam::testing
{
  /// Rock of density 2000 kg/m^3, c_s = 1000 m/s, nu = 0.25 (c_p = sqrt(3) c_s).
  inline physics::solid::ElasticMaterial
  test_rock()
  {
    const double rho = 2000., cs = 1000., nu = 0.25;
    return {2 * rho * cs * cs * (1 + nu), nu, rho};
  }

  /// Boundary ids of the planes of symmetry x = x0 (u_x = 0) and y = y0 (u_y = 0).
  constexpr dealii::types::boundary_id symmetry_x = 8, symmetry_y = 9;

  /// u_x = 0 on the plane symmetry_x, u_y = 0 on symmetry_y (DOFs already
  /// constrained keep their constraint).
  inline void
  constrain_symmetry(const fe::FESpace &space, dealii::AffineConstraints<double> &c)
  {
    const dealii::Functions::ZeroFunction<3> zero(fe::FESpace::n_components);
    for (unsigned int d = 0; d < 2; ++d)
      {
        std::vector<bool> mask(fe::FESpace::n_components, false);
        mask[d] = true;
        dealii::VectorTools::interpolate_boundary_values(space.dof_handler,
                                                         d == 0 ? symmetry_x : symmetry_y, zero,
                                                         c, dealii::ComponentMask(mask));
      }
  }

  /**
   * The rock block [x0, x1] x [y0, y1] x [z0, z1] (material id 1) in nx x ny x nz
   * cells: bottom boundary id 1, top id 0, the sides @p side_id (2 = outer
   * boundary, 0 = free), or 0 on the planes x = x0 / y = y0 when
   * @p symmetric_xy (they are planes of symmetry then).
   */
  inline void
  rock_box(dealii::Triangulation<3> &tria, const dealii::Point<3> &lo, const dealii::Point<3> &hi,
           const std::vector<unsigned int> &cells, const dealii::types::boundary_id side_id,
           const bool symmetric_xy = false)
  {
    dealii::GridGenerator::subdivided_hyper_rectangle(tria, cells, lo, hi);
    const double tol = 1e-6 * lo.distance(hi);
    for (const auto &cell : tria.active_cell_iterators())
      {
        cell->set_material_id(ids::rock);
        for (const auto f : cell->face_indices())
          if (cell->face(f)->at_boundary())
            {
              const auto c = cell->face(f)->center();
              auto       id = side_id;
              if (std::abs(c[2] - lo[2]) < tol)
                id = ids::foundation_bottom;
              else if (std::abs(c[2] - hi[2]) < tol)
                id = ids::free_surface_solid;
              else if (symmetric_xy && std::abs(c[0] - lo[0]) < tol)
                id = symmetry_x;
              else if (symmetric_xy && std::abs(c[1] - lo[1]) < tol)
                id = symmetry_y;
              cell->face(f)->set_boundary_id(id);
            }
      }
  }

  /// Position and component of every DOF of the solid element (all cells).
  inline std::map<dealii::types::global_dof_index, std::pair<dealii::Point<3>, unsigned int>>
  dof_positions(const fe::FESpace &space)
  {
    std::map<dealii::types::global_dof_index, std::pair<dealii::Point<3>, unsigned int>> r;
    const auto &fe      = space.fe_collection[fe::FESpace::solid_index];
    const auto  support = fe.get_unit_support_points();
    const dealii::MappingQ1<3>                   mapping;
    std::vector<dealii::types::global_dof_index> dofs(fe.n_dofs_per_cell());
    for (const auto &cell : space.dof_handler.active_cell_iterators())
      {
        cell->get_dof_indices(dofs);
        for (unsigned int i = 0; i < dofs.size(); ++i)
          r[dofs[i]] = {mapping.transform_unit_to_real_cell(cell, support[i]),
                        fe.system_to_component_index(i).first};
      }
    return r;
  }

  /**
   * Tie every DOF of a column to the DOF of the same component with the
   * smallest index at the same elevation, so that the motion is u(z, t)
   * (a 1-D column in 3-D). Planes whose DOFs are already constrained (the
   * prescribed bottom) are left alone.
   */
  inline void
  tie_column(const fe::FESpace &space, dealii::AffineConstraints<double> &c)
  {
    std::map<std::pair<long, unsigned int>, dealii::types::global_dof_index> master;
    const auto pos = dof_positions(space);
    for (const auto &[i, pc] : pos) // increasing index: the first is the master
      {
        const auto key = std::make_pair(std::lround(pc.first[2] * 1e6), pc.second);
        if (!master.count(key))
          master[key] = i;
        else if (space.locally_relevant.is_element(i) && !c.is_constrained(i) &&
                 !c.is_constrained(master[key]))
          {
            c.add_line(i);
            c.add_entry(i, master[key], 1.);
          }
      }
  }

  /// E = 1/2 v^T M v + 1/2 u^T K u. M and K are condensed (constrained rows
  /// and columns replaced by a diagonal): with the constrained entries of u
  /// and v set to zero the products are those of the full matrices on the
  /// constrained fields (u = C u_free: C^T M C), as the energy needs.
  inline double
  elastic_energy(const SparseMatrix &M, const SparseMatrix &K,
                 const dealii::AffineConstraints<double> &constraints, const time::NewmarkState &s)
  {
    Vector free = s.v, tmp = s.v;
    constraints.set_zero(free);
    M.vmult(tmp, free);
    const double kinetic = 0.5 * (tmp * free);
    free                 = s.u;
    constraints.set_zero(free);
    K.vmult(tmp, free);
    return kinetic + 0.5 * (tmp * free);
  }

  /// The pulse g(t) = A sin^4(pi t / T) on 0 < t < T, zero elsewhere, with its
  /// first and second derivatives (continuous: g, g', g'' vanish at both ends).
  struct Sin4Pulse
  {
    double A, T;
    double
    value(const double t) const
    {
      if (t <= 0 || t >= T)
        return 0.;
      return A * std::pow(std::sin(M_PI * t / T), 4);
    }
    double
    first(const double t) const
    {
      if (t <= 0 || t >= T)
        return 0.;
      const double s = std::sin(M_PI * t / T), c = std::cos(M_PI * t / T);
      return A * 4 * s * s * s * c * M_PI / T;
    }
    double
    second(const double t) const
    {
      if (t <= 0 || t >= T)
        return 0.;
      const double s = std::sin(M_PI * t / T), c = std::cos(M_PI * t / T);
      return A * (M_PI / T) * (M_PI / T) * (12 * s * s * c * c - 4 * s * s * s * s);
    }
  };
} // namespace archdam::testing
