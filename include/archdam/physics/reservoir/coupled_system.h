#pragma once

#include <archdam/physics/reservoir/fluid_operators.h>
#include <archdam/time/newmark.h>

#include <utility>
#include <vector>

namespace archdam::physics::reservoir
{
  /// A sum of matrices sum_k c_k A_k, as the pairs (c_k, A_k).
  using MatrixTerms = std::vector<std::pair<double, const SparseMatrix *>>;

  /// out = sum_k c_k A_k, on the pattern of the term with the most entries;
  /// every other term's pattern is that one or a subset of it (the model's
  /// pattern and the water's, fe::FESpace::reinit).
  void
  linear_combination(SparseMatrix &out, const MatrixTerms &terms);

  /**
   * The coupled dam-water system in the symmetric form of the paper's eq. 3.2
   * (doc/theory/reservoir.md §5). With Phi = -beta2 dt^2 / rho_w scaling the fluid rows,
   *   M_c = [[M, 0], [Phi S, Phi G]],   D_c = [[D, 0], [0, Phi H]],
   *   K_c = [[K, -(1/rho_w) S^T], [0, Phi Q]]
   * (unknowns (u, p)), so that Kbar = M_c + beta1 dt D_c + beta2 dt^2 K_c is
   * symmetric (the off-diagonal blocks are both -beta2 dt^2/rho_w S) and
   * indefinite (the fluid block is negative definite). It is constant, so it
   * is factorized once (time/newmark.h, as LDL^T). The ground motion enters
   * the fluid rows as -Phi sum_d a_g,d S iota_d (`fluid_influence[d]` holds
   * Phi S iota_d). The solid's damping D is given as @p solid_damping:
   * alpha M + beta K, or the damping matrix assembled per material
   * (doc/theory/solid.md §4).
   */
  struct CoupledSystem
  {
    SparseMatrix            mass, damping, stiffness;
    std::array<Vector, dim> fluid_influence;
  };

  void
  form_coupled_system(const FluidOperators      &ops,
                      double                     density,
                      double                     beta2,
                      double                     dt,
                      const SparseMatrix        &M,
                      const SparseMatrix        &K,
                      const MatrixTerms         &solid_damping,
                      CoupledSystem             &system);

  /**
   * The columns of the coupled system at the prescribed solid DOFs of a
   * massed foundation's outer boundary (doc/theory/foundation.md §7, time::PrescribedDofs).
   * On entry @p prescribed holds the DOFs and the columns of the solid's M,
   * D and K there (solid::assemble_mass_and_stiffness_columns); on exit the
   * columns of M_c, D_c and K_c above:
   *   M_c(:, b) = [M(:, b); Phi S(:, b)],  D_c(:, b) = [D(:, b); 0],  K_c(:, b) = [K(:, b); 0]
   * (the water's own blocks and -(1/rho_w) S^T have no solid columns, so
   * only M's gain rows). The
   * fluid rows Phi S(:, b) carry the boundary's acceleration into the water
   * where the wetted rock meets the outer boundary.
   */
  void
  form_coupled_columns(const fe::FESpace                &space,
                       const std::vector<InterfacePair> &pairs,
                       double                            density,
                       double                            beta2,
                       double                            dt,
                       time::PrescribedDofs             &prescribed);
} // namespace archdam::physics::reservoir
