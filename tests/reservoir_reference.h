// Shared by the reservoir tests: the model of a straight channel of water in
// front of a vertical dam face (the rigid-dam problem of doc/verification.md,
// "Reservoir"), its exact series solutions, and point evaluation of the FE
// pressure. Nothing here calls the reservoir module: the references are
// independent of the code under test.
//
// Channel: water x in [-L, 0], y in [0, W] (one cell: the side walls y = 0, W
// are rigid, so the problem is two-dimensional), z in [0, H]; the dam is the
// slab x in [0, d] (material 10) behind the face x = 0. Ids: free surface 3,
// upstream truncation 4, bottom 5, side walls 0 (rigid for the water); the
// dam's base is 1 (fixed when the dam is flexible), its other faces 0.
#pragma once

#include <archdam/base/types.h>
#include <archdam/fe/fe_space.h>
#include <archdam/geometry/ids.h>
#include <archdam/geometry/splitter.h>

#include <deal.II/base/mpi.h>
#include <deal.II/base/quadrature.h>
#include <deal.II/fe/fe_values.h>
#include <deal.II/fe/mapping_q1.h>
#include <deal.II/grid/grid_generator.h>

#include <cmath>
#include <complex>
#include <limits>
#include <vector>

namespace archdam::testing
{
  using complex = std::complex<double>;

  struct Channel
  {
    double H = 50., L = 150., W = 10., dam = 5.;
    double c = 1440., rho = 1000.;
    double q = 0.; ///< bottom absorption (1 - alpha_r) / (c (1 + alpha_r))
  };

  /// The channel and dam slab, split at the face x = 0 (ids 6/7); @p nx x nz
  /// water cells; the dam is @p dam_refinement times refined (the water
  /// mesh is then coarser than the solid's at the face).
  inline void
  make_channel(const Channel &ch, const unsigned int nx, const unsigned int nz,
               const unsigned int dam_refinement,
               dealii::parallel::shared::Triangulation<dim> &tria)
  {
    using namespace dealii;
    std::vector<std::vector<double>> steps(3);
    steps[0].assign(nx, ch.L / nx);
    steps[0].push_back(ch.dam);
    steps[1] = {ch.W};
    steps[2].assign(nz, ch.H / nz);
    Triangulation<dim> full, split;
    GridGenerator::subdivided_hyper_rectangle(full, steps, Point<dim>(-ch.L, 0, 0),
                                              Point<dim>(ch.dam, ch.W, ch.H));
    const double tol = 1e-8 * ch.H;
    for (const auto &cell : full.active_cell_iterators())
      {
        const bool water = cell->center()[0] < 0;
        cell->set_material_id(water ? ids::water : ids::first_dam_block);
        for (const auto &face : cell->face_iterators())
          if (face->at_boundary())
            {
              const Point<dim> f = face->center();
              types::boundary_id id = ids::free_surface_solid;
              if (water && std::abs(f[2] - ch.H) < tol)
                id = ids::reservoir_surface;
              else if (water && std::abs(f[0] + ch.L) < tol)
                id = ids::reservoir_truncation;
              else if (std::abs(f[2]) < tol)
                id = water ? ids::reservoir_bottom : ids::foundation_bottom;
              face->set_boundary_id(id);
            }
      }
    geometry::split_interfaces(full, split);
    tria.copy_triangulation(split);
    for (unsigned int r = 0; r < dam_refinement; ++r)
      {
        for (const auto &cell : tria.active_cell_iterators())
          if (cell->material_id() != ids::water)
            cell->set_refine_flag();
        tria.execute_coarsening_and_refinement();
      }
  }

  /// Every DOF of the dam constrained: a rigid dam that does not move
  /// relative to the ground.
  inline void
  fix_solid(const fe::FESpace &space, dealii::AffineConstraints<double> &c)
  {
    std::vector<dealii::types::global_dof_index> dofs;
    for (const auto &cell : space.dof_handler.active_cell_iterators())
      if (cell->active_fe_index() == fe::FESpace::solid_index)
        {
          dofs.resize(cell->get_fe().n_dofs_per_cell());
          cell->get_dof_indices(dofs);
          for (const auto i : dofs)
            if (!c.is_constrained(i))
              c.add_line(i);
        }
  }

  /**
   * Pressure amplitude on the face x = 0 at height z under the harmonic
   * ground acceleration a_g = e^{i omega t} in +x (towards the dam, away from
   * the water), by separation of variables: p = sum_n P_n(s) Y_n(z), s = -x
   * the distance upstream, with the vertical modes Y_n = sin(lambda_n (H - z))
   * (p = 0 at the surface) whose lambda_n solve the bottom condition
   * dp/dz = i omega q p at z = 0,
   *   lambda cos(lambda H) + i omega q sin(lambda H) = 0
   * (rigid bottom: lambda_n = (2n - 1) pi / (2H); absorbing: complex roots,
   * Fenves & Chopra 1984, found by Newton's method with continuation in q).
   * The modes are orthogonal without conjugation, so 1 = sum c_n Y_n with
   * c_n = int Y_n / int Y_n^2. Each P_n solves P'' = kappa_n^2 P,
   * kappa_n^2 = lambda_n^2 - omega^2/c^2 (Re kappa >= 0, the outgoing or
   * decaying branch), with P'(0) = rho c_n (the face condition dp/dn = -rho a_n
   * with n = +x) and
   *  - L <= 0: an infinite channel, P = A e^{-kappa s}: P(0) = -rho c_n / kappa;
   *  - L > 0: the Sommerfeld condition P' = -(i omega / c) P at s = L,
   *    P = A (e^{-kappa s} + r e^{kappa s}), r = e^{-2 kappa L} (kappa - i omega/c)
   *    / (kappa + i omega/c).
   * c = infinity gives the incompressible water (with a rigid end wall at L).
   * The sign: the dam accelerating away from the water gives suction; the
   * textbook formula (doc/theory/reservoir.md §10) is for the opposite direction.
   */
  inline std::vector<complex>
  face_pressure(const Channel &ch, const double omega, const std::vector<double> &z,
                const double L, const unsigned int n_terms = 4000)
  {
    const complex  I(0., 1.);
    const double   H = ch.H;
    const double   k = std::isinf(ch.c) ? 0. : omega / ch.c;
    std::vector<complex> p(z.size(), 0.);
    for (unsigned int n = 1; n <= n_terms; ++n)
      {
        complex lambda = (2. * n - 1.) * M_PI / (2. * H);
        if (ch.q > 0 && omega > 0)
          for (unsigned int step = 1; step <= 20; ++step)
            {
              const double wq = omega * ch.q * step / 20.;
              for (unsigned int it = 0; it < 50; ++it)
                {
                  const complex f  = lambda * std::cos(lambda * H) + I * wq * std::sin(lambda * H);
                  const complex df = std::cos(lambda * H) - lambda * H * std::sin(lambda * H) +
                                     I * wq * H * std::cos(lambda * H);
                  const complex dl = f / df;
                  lambda -= dl;
                  if (std::abs(dl) < 1e-14 * std::abs(lambda))
                    break;
                }
            }
        const complex int_y  = (1. - std::cos(lambda * H)) / lambda;
        const complex int_y2 = H / 2. - std::sin(2. * lambda * H) / (4. * lambda);
        const complex cn     = int_y / int_y2;
        const complex kappa  = std::sqrt(lambda * lambda - complex(k * k, 0.));
        const complex g      = ch.rho * cn;
        complex       P0;
        if (L <= 0)
          P0 = -g / kappa;
        else
          {
            const complex r = std::exp(-2. * kappa * L) * (kappa - I * k) / (kappa + I * k);
            P0              = g * (1. + r) / (kappa * (r - 1.));
          }
        for (unsigned int i = 0; i < z.size(); ++i)
          p[i] += P0 * std::sin(lambda * (H - z[i]));
      }
    return p;
  }

  /// The FE field @p v (a ghosted vector) at point @p x: every rank looks in
  /// its own cells of the given FE index, the results are averaged over the
  /// cells that contain the point.
  inline double
  point_value(const fe::FESpace &space, const Vector &v, const dealii::Point<dim> &x,
              const unsigned int component)
  {
    using namespace dealii;
    double sum = 0., count = 0.;
    std::vector<types::global_dof_index> dofs;
    for (const auto &cell : space.dof_handler.active_cell_iterators())
      if (cell->is_locally_owned() && cell->get_fe().n_dofs_per_cell() > 0)
        {
          auto box = cell->bounding_box();
          box.extend(1e-8 * cell->diameter());
          if (!box.point_inside(x))
            continue;
          const Point<dim> u =
            StaticMappingQ1<dim>::mapping.transform_real_to_unit_cell(cell, x);
          if (!GeometryInfo<dim>::is_inside_unit_cell(u, 1e-8))
            continue;
          const auto &fe = cell->get_fe();
          dofs.resize(fe.n_dofs_per_cell());
          cell->get_dof_indices(dofs);
          double value = 0.;
          for (unsigned int i = 0; i < dofs.size(); ++i)
            if (fe.system_to_component_index(i).first == component)
              value += v(dofs[i]) * fe.shape_value_component(i, u, component);
          bool has = false;
          for (unsigned int i = 0; i < dofs.size(); ++i)
            has |= fe.system_to_component_index(i).first == component;
          if (!has)
            continue;
          sum += value;
          count += 1.;
        }
    sum   = Utilities::MPI::sum(sum, space.comm);
    count = Utilities::MPI::sum(count, space.comm);
    return sum / count;
  }
} // namespace archdam::testing
