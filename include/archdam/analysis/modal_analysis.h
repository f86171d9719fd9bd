#pragma once

#include <archdam/base/types.h>
#include <archdam/parameters/analysis_parameters.h>
#include <archdam/physics/reservoir/fluid_operators.h>

#include <deal.II/base/parameter_handler.h>
#include <deal.II/lac/affine_constraints.h>

#include <array>
#include <vector>

namespace archdam::analysis
{
  /// Natural modes, lowest first: K phi = omega^2 M phi, phi^T M phi = 1.
  struct NaturalModes
  {
    std::vector<double> omega;  ///< circular frequencies [rad/s]
    std::vector<Vector> shapes; ///< mass-normalized mode shapes
    /// The largest relative residual |K phi - omega^2 M phi| / |K phi|.
    double max_residual = 0.;
  };

  /**
   * The lowest natural modes of the undamped system K phi = omega^2 M phi
   * (doc/theory/loading-sequence.md §2), by SLEPc's Krylov-Schur method with the
   * shift-and-invert transformation about 0: the largest eigenvalues of
   * K^{-1} M, with K factorized once by MUMPS (Cholesky).
   *
   * M may be singular (massless rock, the constrained DOFs): the constrained
   * rows are made massless here, so they belong to the infinite eigenvalues,
   * which shift-and-invert maps to zero, and SLEPc's purification keeps the
   * vectors in the range where M is positive definite. DOFs that no solid
   * element touches (pressure DOFs of water cells when the water is not part
   * of the problem) get a unit stiffness and no mass for the same reason.
   * Throws InputError if fewer than @p p.n_modes modes converge.
   */
  NaturalModes
  compute_natural_modes(const SparseMatrix                      &mass,
                        const SparseMatrix                      &stiffness,
                        const dealii::AffineConstraints<double> &constraints,
                        const ModalParameters                   &p);

  /**
   * The lowest natural modes of the dam coupled with water that carries a
   * pressure (compressible or incompressible model, doc/theory/reservoir.md §9, paper
   * eq. 3.1 without the radiation term H: the truncation boundary and the
   * bottom reflect, so the modes are undamped and omega^2 real). With
   * u, p ~ e^{i omega t} the solid's M u_tt + K u - (1/rho_w) S^T p = 0 and
   * the water's G p_tt + Q p + S u_tt = 0 give the pencil
   *   A x = omega^2 B x,   A = [[K, -(1/rho_w) S^T], [0, Q]],
   *                        B = [[M, 0], [S, G]],   x = (u, p),
   * non-symmetric but with real positive eigenvalues (it is symmetrizable
   * by the water's energy). Solved like compute_natural_modes() but as a
   * non-Hermitian problem (Krylov-Schur, shift-and-invert about 0 with an
   * LU factorization of A by MUMPS). Each shape is normalized by the solid's
   * mass, u^T M u = 1, so participation_factors() give the solid's share;
   * max_residual is |A x - omega^2 B x| / |A x| over the solid's and the
   * water's rows separately. @p pressure_scale [Pa/m] is the order of the
   * modes' pressure per unit displacement, rho_w omega^2 H_w (Westergaard),
   * used to balance the pencil; a factor 10 off does not matter.
   */
  NaturalModes
  compute_coupled_modes(const SparseMatrix                           &mass,
                        const SparseMatrix                           &stiffness,
                        const physics::reservoir::FluidOperators     &water,
                        double                                        water_density,
                        double                                        pressure_scale,
                        const dealii::AffineConstraints<double>      &constraints,
                        const ModalParameters                        &p);

  /// Participation of mode phi in direction d: Gamma_d = phi^T M iota_d, and
  /// effective modal mass Gamma_d^2 (phi mass-normalized).
  std::array<double, dim>
  participation_factors(const Vector &shape, const std::array<Vector, dim> &mass_times_iota);
} // namespace archdam::analysis
