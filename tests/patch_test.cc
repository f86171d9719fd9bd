// Patch test of the solid (doc/theory/solid.md §1, doc/verification.md "Solid"): a field of
// constant strain is reproduced exactly on a distorted mesh.
//
// The box model without rock (a concrete block [0, L] x [0, W] x [0, H] in
// several cantilever blocks, so that the cells carry different material ids)
// is distorted by moving its interior vertices with a smooth, deterministic,
// non-affine displacement that vanishes on the box faces: the cells become
// general trilinear hexahedra (not parallelepipeds) while the faces stay flat.
//
// The exact solution of linear elasticity without body force
//   u(x) = u0 + G x,   G constant and non-symmetric,
// has the constant strain eps0 = sym(G) and the constant stress
//   sigma0 = lambda tr(eps0) I + 2 mu eps0.
// It is prescribed on the whole boundary and the interior is solved with the
// library's stiffness matrix and factorization:
//   - FESpace "fixed" with every boundary id fixed gives the condensed K_c
//     (K_II on the interior rows, decoupled constrained rows);
//   - FESpace "free" with nothing fixed gives the unconstrained K on the same
//     DoF numbering (checked below through the support points);
//   - with g the boundary values (exact field on constrained DoFs, zero
//     elsewhere): K_c x = -(K g) with the constrained rows of the right-hand
//     side zeroed, i.e. K_II x_I = -K_IB g_B, and u_h = x + g.
// Every nodal value of u_h is compared with u(x) at the DoF's support point,
// and the stress recovered by the library (ElasticMaterial::stress of the
// symmetric gradient, as StressPostprocessor and the monitors do) at every
// quadrature point with sigma0 computed here from lambda and mu written out.
// The principal stresses (library) are compared with the closed-form
// eigenvalues of sigma0 (trigonometric formula for symmetric 3x3 matrices).
//
// Why exact: the affine field lies in the FE space for Q1 and Q2 on a Q1
// (trilinear) mapping (x(xi) is trilinear, so u0 + G x(xi) is in Q1, which is
// in Q2); and the Gauss rule of degree+1 points integrates the constant-stress
// residual sum_cells int sigma0 : grad N_i exactly: grad N_i det J =
// cof(J)^T grad_xi N_i, whose entries are polynomials of degree at most 2
// (Q1) and 3 (Q2) in each reference coordinate, below the 2n-1 = 3 and 5 of
// the Gauss rules. So the discrete solution equals the exact one, and what is
// left is round-off (see the tolerances below).

#include <archdam/fe/fe_space.h>
#include <archdam/geometry/ids.h>
#include <archdam/geometry/splitter.h>
#include <archdam/joints/joint_faces.h>
#include <archdam/geometry/mesh.h>
#include <archdam/parameters/parameters.h>
#include <archdam/physics/solid/materials.h>
#include <archdam/physics/solid/solid_operators.h>
#include <archdam/physics/solid/stress.h>
#include <archdam/time/factorized_operator.h>

#include <deal.II/base/numbers.h>
#include <deal.II/base/quadrature.h>
#include <deal.II/fe/fe_values.h>
#include <deal.II/fe/mapping_q.h>
#include <deal.II/grid/grid_tools.h>
#include <deal.II/hp/fe_values.h>

#include "archdam_tests.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <set>
#include <string>
#include <vector>

using namespace dealii;
using namespace archdam;
using archdam::testing::check_below;
using archdam::testing::log;

namespace
{
  // Box dimensions and material, chosen here (not defaults).
  constexpr double L = 3.0, W = 4.0, H = 5.0; // x, y, z [m]
  constexpr double E = 30e9, nu = 0.2;         // Pa, -

  // The exact field u = u0 + G x (G general, non-symmetric).
  const Tensor<1, dim> u0({1.0e-3, -2.0e-3, 0.5e-3});
  const Tensor<2, dim> G({{1.0e-3, 2.0e-3, -0.5e-3},
                          {-1.5e-3, 0.7e-3, 0.3e-3},
                          {0.4e-3, -0.8e-3, -1.2e-3}});

  double
  box_size(const unsigned int d)
  {
    return d == 0 ? L : d == 1 ? W : H;
  }

  double
  exact_u(const Point<dim> &x, const unsigned int c)
  {
    return u0[c] + (G * x)[c];
  }

  /// Hooke's law written out here: sigma0 from eps0 = sym(G).
  SymmetricTensor<2, dim>
  exact_stress()
  {
    const double lambda = E * nu / ((1 + nu) * (1 - 2 * nu));
    const double mu     = E / (2 * (1 + nu));
    SymmetricTensor<2, dim> sigma;
    double                  tr = 0;
    for (unsigned int i = 0; i < dim; ++i)
      tr += G[i][i];
    for (unsigned int i = 0; i < dim; ++i)
      for (unsigned int j = i; j < dim; ++j)
        sigma[i][j] = (i == j ? lambda * tr : 0.) + mu * (G[i][j] + G[j][i]);
    return sigma;
  }

  /// Largest and smallest eigenvalue of a symmetric 3x3 matrix by the
  /// trigonometric closed form (O. K. Smith, CACM 4(4), 1961).
  std::pair<double, double>
  closed_form_principal(const SymmetricTensor<2, dim> &a)
  {
    const double q  = (a[0][0] + a[1][1] + a[2][2]) / 3;
    const double p1 = a[0][1] * a[0][1] + a[0][2] * a[0][2] + a[1][2] * a[1][2];
    const double p2 = (a[0][0] - q) * (a[0][0] - q) + (a[1][1] - q) * (a[1][1] - q) +
                      (a[2][2] - q) * (a[2][2] - q) + 2 * p1;
    const double p = std::sqrt(p2 / 6);
    double       b[3][3];
    for (unsigned int i = 0; i < 3; ++i)
      for (unsigned int j = 0; j < 3; ++j)
        b[i][j] = (a[i][j] - (i == j ? q : 0.)) / p;
    const double det = b[0][0] * (b[1][1] * b[2][2] - b[1][2] * b[2][1]) -
                       b[0][1] * (b[1][0] * b[2][2] - b[1][2] * b[2][0]) +
                       b[0][2] * (b[1][0] * b[2][1] - b[1][1] * b[2][0]);
    const double r   = std::clamp(det / 2, -1., 1.);
    const double phi = std::acos(r) / 3;
    return {q + 2 * p * std::cos(phi), q + 2 * p * std::cos(phi + 2 * numbers::PI / 3)};
  }

  /// Smooth non-affine displacement of the interior vertices, exactly zero on
  /// the faces of the box (so they stay flat); deterministic, the same on all
  /// ranks. Amplitude: a quarter of the smallest cell edge (the cells stay
  /// valid; checked through the Jacobians below).
  Point<dim>
  distort(const Point<dim> &x, const double amplitude)
  {
    const double tol = 1e-10;
    for (unsigned int d = 0; d < dim; ++d)
      if (std::abs(x[d]) < tol || std::abs(x[d] - box_size(d)) < tol)
        return x;
    const double s = x[0] / L, t = x[1] / W, r = x[2] / H;
    const double bubble =
      std::sin(numbers::PI * s) * std::sin(numbers::PI * t) * std::sin(numbers::PI * r);
    Point<dim> y = x;
    y[0] += amplitude * bubble * std::sin(2.3 * s + 1.1 * t * t + 0.4);
    y[1] += amplitude * bubble * std::cos(1.7 * t - 0.9 * r * s);
    y[2] += amplitude * bubble * std::sin(1.3 * r * r + 2.1 * s - 0.5 * t);
    return y;
  }

  /// Support point and component of each locally owned DoF (Q1 mapping, as in
  /// the library's assembly), as (x, y, z, component).
  std::map<types::global_dof_index, std::pair<Point<dim>, unsigned int>>
  support_points(const fe::FESpace &space)
  {
    std::map<types::global_dof_index, std::pair<Point<dim>, unsigned int>> result;
    const MappingQ<dim>                                                    mapping(1);
    std::vector<types::global_dof_index>                                   dofs;
    for (const auto &cell : space.dof_handler.active_cell_iterators())
      if (cell->is_locally_owned())
        {
          const auto     &fe = cell->get_fe();
          AssertThrow(fe.get_unit_support_points().size() == fe.dofs_per_cell,
                      ExcMessage("element without support points"));
          Quadrature<dim> q(fe.get_unit_support_points());
          FEValues<dim>   fv(mapping, fe, q, update_quadrature_points);
          fv.reinit(cell);
          dofs.resize(fe.dofs_per_cell);
          cell->get_dof_indices(dofs);
          for (unsigned int i = 0; i < fe.dofs_per_cell; ++i)
            if (space.locally_owned.is_element(dofs[i]))
              result[dofs[i]] = {fv.quadrature_point(i), fe.system_to_component_index(i).first};
        }
    return result;
  }

  /// Extreme eigenvalues of the SPD matrix K: power iteration for the largest,
  /// inverse iteration (with the factorization) for the smallest. Rayleigh
  /// quotients, so the ratio is a (close) lower bound of cond_2(K).
  double
  condition_number_estimate(const fe::FESpace &space, const archdam::SparseMatrix &K,
                            const time::FactorizedOperator &K_inverse)
  {
    archdam::Vector v, w;
    space.reinit(v);
    space.reinit(w);
    const auto start = [&]() {
      for (const auto i : space.locally_owned)
        v(i) = 1.0 + 0.5 * std::sin(0.37 * i);
      v.compress(VectorOperation::insert);
      v /= v.l2_norm();
    };
    double lambda_max = 0, lambda_min = 0;
    start();
    for (unsigned int it = 0; it < 200; ++it)
      {
        K.vmult(w, v);
        lambda_max = w * v;
        v          = w;
        v /= v.l2_norm();
      }
    start();
    for (unsigned int it = 0; it < 50; ++it)
      {
        K_inverse.solve(w, v);
        lambda_min = 1. / (w * v);
        v          = w;
        v /= v.l2_norm();
      }
    return lambda_max / lambda_min;
  }

  void
  run(const unsigned int degree)
  {
    log() << "--- Degree " << degree << " ---" << std::endl;
    const std::string prm = "subsection Mesh\n"
                            "  set Source = box\n"
                            "  subsection Box\n"
                            "    set Length = " + std::to_string(L) + "\n"
                            "    set Width = " + std::to_string(W) + "\n"
                            "    set Height = " + std::to_string(H) + "\n"
                            "    set Number of blocks = 2\n"
                            "    set Cells in x = 4\n"
                            "    set Cells in y = 6\n"
                            "    set Cells in z = 4\n"
                            "    set Rock depth = 0\n"
                            "  end\n"
                            "end\n"
                            "subsection Finite element\n"
                            "  set Degree = " + std::to_string(degree) + "\n"
                            "end\n"
                            "subsection Materials\n"
                            "  subsection Concrete\n"
                            "    set Young's modulus = 30e9\n"
                            "    set Poisson's ratio = 0.2\n"
                            "    set Density = 2400\n"
                            "  end\n"
                            "end\n";
    const Parameters p = parameters_from_string(prm);

    parallel::shared::Triangulation<dim> tria(MPI_COMM_WORLD);
    geometry::create_mesh(p.mesh, tria);
    const double h_min = std::min({L / 4, W / 6, H / 4});
    GridTools::transform([&](const Point<dim> &x) { return distort(x, 0.25 * h_min); }, tria);

    // The mesh is what the test claims: several material ids, boundary ids
    // {0, 1} and the two sides of the joint between the blocks {100, 101},
    // every cell a non-parallelepiped (the trilinear map has a non-zero
    // bilinear part), faces of the box flat.
    {
      std::set<types::material_id> materials;
      std::set<types::boundary_id> boundaries;
      unsigned int                 distorted = 0;
      double                       off_face  = 0;
      for (const auto &cell : tria.active_cell_iterators())
        {
          materials.insert(cell->material_id());
          // Distance of the vertices from the affine map through v0, v1, v2,
          // v4 (zero for a parallelepiped); vertex k = i + 2 j + 4 l.
          double twist = 0;
          for (unsigned int k = 0; k < 8; ++k)
            {
              const Point<dim> affine = cell->vertex(0) +
                                        (k & 1) * (cell->vertex(1) - cell->vertex(0)) +
                                        ((k >> 1) & 1) * (cell->vertex(2) - cell->vertex(0)) +
                                        ((k >> 2) & 1) * (cell->vertex(4) - cell->vertex(0));
              twist = std::max(twist, cell->vertex(k).distance(affine));
            }
          distorted += twist > 1e-2 * h_min;
          for (const auto &face : cell->face_iterators())
            if (face->at_boundary() && !geometry::is_joint_face(face->boundary_id()))
              for (unsigned int k = 0; k < face->n_vertices(); ++k)
                {
                  const Point<dim> x = face->vertex(k);
                  double           d = std::numeric_limits<double>::max();
                  for (unsigned int c = 0; c < dim; ++c)
                    d = std::min({d, std::abs(x[c]),
                                  std::abs(x[c] - box_size(c))});
                  off_face = std::max(off_face, d);
                }
        }
      for (const auto &face : tria.active_face_iterators())
        if (face->at_boundary())
          boundaries.insert(face->boundary_id());
      log() << "cells: " << tria.n_active_cells() << ", non-parallelepiped: " << distorted
            << ", material ids: " << materials.size()
            << ", boundary ids: " << boundaries.size() << std::endl;
      check_below("largest distance of a boundary vertex from the box faces [m]", off_face,
                  1e-14);
    }

    // The joint between the blocks is glued (the program's model for a
    // monolithic dam): constant strain must pass through it exactly too.
    const auto  joint_faces = joints::pair_joint_faces(tria);
    fe::FESpace fixed(tria, p.finite_element), free(tria, p.finite_element);
    const auto  glue = [&](fe::FESpace &space) {
      return [&](AffineConstraints<double> &c) {
        joints::tie_joint_dofs(space.dof_handler, joint_faces, space.locally_relevant, c);
      };
    };
    fixed.setup({ids::free_surface_solid, ids::foundation_bottom}, glue(fixed));
    free.setup({}, glue(free));
    archdam::SparseMatrix M_c, K_c, M, K;
    physics::solid::assemble_mass_and_stiffness(fixed, p.materials,
                                                physics::solid::InertiaOf::dam, M_c, K_c);
    physics::solid::assemble_mass_and_stiffness(free, p.materials,
                                                physics::solid::InertiaOf::dam, M, K);

    // Both spaces number the DoFs alike (same mesh, same elements): checked
    // through the support points, so that K g is the right product.
    const auto points      = support_points(fixed);
    const auto points_free = support_points(free);
    bool       same        = points.size() == points_free.size();
    for (const auto &[i, pc] : points)
      same = same && points_free.count(i) && points_free.at(i).second == pc.second &&
             points_free.at(i).first.distance(pc.first) == 0.;
    same = Utilities::MPI::min(same ? 1 : 0, MPI_COMM_WORLD) == 1;
    unsigned int n_constrained = 0;
    for (const auto i : fixed.locally_owned)
      n_constrained += fixed.constraints.is_constrained(i);
    log() << "DOFs: " << fixed.dof_handler.n_dofs()
          << ", constrained: " << Utilities::MPI::sum(n_constrained, MPI_COMM_WORLD)
          << ", same numbering in both spaces: " << (same ? "yes" : "NO") << std::endl;

    // Boundary values g and the exact nodal field.
    archdam::Vector g, u_exact;
    fixed.reinit(g);
    fixed.reinit(u_exact);
    for (const auto &[i, pc] : points)
      {
        const double value = exact_u(pc.first, pc.second);
        u_exact(i)         = value;
        // g: the boundary values, on the DOFs fixed by Dirichlet lines (those
        // without entries; the glued joint's lines point to a master DOF).
        const auto *entries = fixed.constraints.get_constraint_entries(i);
        g(i)                = entries != nullptr && entries->empty() ? value : 0.;
      }
    g.compress(VectorOperation::insert);
    u_exact.compress(VectorOperation::insert);

    archdam::Vector rhs, x;
    fixed.reinit(rhs);
    fixed.reinit(x);
    K.vmult(rhs, g);
    rhs *= -1.;
    fixed.constraints.set_zero(rhs);

    time::FactorizedOperator K_c_inverse;
    K_c_inverse.factorize(K_c, true);
    K_c_inverse.solve(x, rhs);
    fixed.constraints.distribute(x); // joint side 2 follows side 1
    archdam::Vector u = x;
    u += g;

    // Nodal values. Tolerance: the discrete solution is exact, the computed
    // one carries the round-off of a backward-stable Cholesky solve, relative
    // error <~ c(n) cond(K) eps_mach. cond(K_c) is estimated here (about 30
    // for Q1 and 100 for Q2 on this mesh: few interior nodes per direction,
    // cond ~ (L / h)^2 times the element-level spread from the distortion and
    // nu) and checked to stay below 1e4, so the error is <~ 1e-12 even with a
    // generous c(n); 1e-10 leaves margin above round-off (observed ~1e-15)
    // while a field the discretization does not reproduce shows errors of
    // order 1e-3 here (checked by adding 1e-4 y^2 to u_x: 6e-3 relative).
    const double cond = condition_number_estimate(fixed, K_c, K_c_inverse);
    check_below("cond(K) estimate (power / inverse iteration)", cond, 1e4);
    archdam::Vector error = u;
    error -= u_exact;
    const double u_max = u_exact.linfty_norm();
    check_below("max nodal |u_h - (u0 + G x)| / max |u|", error.linfty_norm() / u_max, 1e-10);

    // Stress at every quadrature point. The gradient error is the nodal error
    // divided by a cell size (the shape-function gradients scale as 1/h), so
    // relative to |G| it is amplified by max|u| / (h |G|) ~ 10 here (max|u| ~
    // 1e-2 m, h ~ 1 m, |G| ~ 1e-3): 1e-9 keeps the same margin as above.
    const SymmetricTensor<2, dim> sigma0  = exact_stress();
    const auto [s1_exact, s3_exact]       = closed_form_principal(sigma0);
    double                        s_max   = 0;
    for (unsigned int i = 0; i < dim; ++i)
      for (unsigned int j = 0; j < dim; ++j)
        s_max = std::max(s_max, std::abs(sigma0[i][j]));
    double G_max = 0;
    for (unsigned int i = 0; i < dim; ++i)
      for (unsigned int j = 0; j < dim; ++j)
        G_max = std::max(G_max, std::abs(G[i][j]));

    archdam::Vector u_ghosted;
    fixed.reinit_ghosted(u_ghosted);
    u_ghosted = u;
    hp::FEValues<dim> hp_fv(fixed.fe_collection, fixed.q_collection,
                            update_gradients | update_JxW_values);
    std::vector<Tensor<2, dim>> grads;
    double grad_error = 0, stress_error = 0, principal_error = 0;
    double min_jxw = std::numeric_limits<double>::max(), volume = 0;
    unsigned int n_points = 0;
    for (const auto &cell : fixed.dof_handler.active_cell_iterators())
      if (cell->is_locally_owned())
        {
          hp_fv.reinit(cell);
          const FEValues<dim> &fv = hp_fv.get_present_fe_values();
          grads.resize(fv.n_quadrature_points);
          fv[fixed.displacement].get_function_gradients(u_ghosted, grads);
          const auto &mat = p.materials.of(cell->material_id());
          for (const unsigned int q : fv.quadrature_point_indices())
            {
              ++n_points;
              min_jxw = std::min(min_jxw, fv.JxW(q));
              volume += fv.JxW(q);
              for (unsigned int i = 0; i < dim; ++i)
                for (unsigned int j = 0; j < dim; ++j)
                  grad_error = std::max(grad_error, std::abs(grads[q][i][j] - G[i][j]));
              const SymmetricTensor<2, dim> sigma = mat.stress(symmetrize(grads[q]));
              for (unsigned int i = 0; i < dim; ++i)
                for (unsigned int j = 0; j < dim; ++j)
                  stress_error = std::max(stress_error, std::abs(sigma[i][j] - sigma0[i][j]));
              const auto [s1, s3] = physics::solid::principal_stresses(sigma);
              principal_error =
                std::max({principal_error, std::abs(s1 - s1_exact), std::abs(s3 - s3_exact)});
            }
        }
    const MPI_Comm comm = MPI_COMM_WORLD;
    log() << "quadrature points: " << Utilities::MPI::sum(n_points, comm) << std::endl;
    check_below("|sum of JxW - L W H| / (L W H) (the distortion keeps the volume)",
                std::abs(Utilities::MPI::sum(volume, comm) - L * W * H) / (L * W * H), 1e-12);
    log() << "all Jacobians positive: "
          << (Utilities::MPI::min(min_jxw, comm) > 0 ? "yes" : "NO") << std::endl;
    check_below("max |grad u_h - G| / max |G_ij| at quadrature points",
                Utilities::MPI::max(grad_error, comm) / G_max, 1e-9);
    check_below("max |sigma_h - sigma0| / max |sigma0_ij| at quadrature points",
                Utilities::MPI::max(stress_error, comm) / s_max, 1e-9);
    check_below("max |s1,s3 (library) - closed-form eigenvalues of sigma0| / max |sigma0_ij|",
                Utilities::MPI::max(principal_error, comm) / s_max, 1e-9);

    // The library's peak of the major principal stress over the dam.
    const auto peak = physics::solid::peak_major_principal_stress(fixed, p.materials,
                                                                  physics::solid::TemperatureField(), u_ghosted);
    check_below("|peak major principal stress (library) - s1 of sigma0| / max |sigma0_ij|",
                std::abs(peak.value - s1_exact) / s_max, 1e-9);
  }
} // namespace

int
main(int argc, char **argv)
{
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  for (const unsigned int degree : {1u, 2u})
    run(degree);
  return 0;
}
