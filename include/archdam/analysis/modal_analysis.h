#pragma once

#include <archdam/base/types.h>

#include <deal.II/base/parameter_handler.h>
#include <deal.II/lac/affine_constraints.h>

#include <array>
#include <vector>

namespace archdam::analysis
{
  /// The `Modal analysis` subsection (numerics.md §6, step 2).
  struct ModalParameters
  {
    unsigned int n_modes          = 10;
    double       tolerance        = 1e-10;
    bool         write_mode_shapes = true;

    void
    add_parameters(dealii::ParameterHandler &prm);
  };

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
   * (numerics.md §6, step 2), by SLEPc's Krylov-Schur method with the
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

  /// Participation of mode phi in direction d: Gamma_d = phi^T M iota_d, and
  /// effective modal mass Gamma_d^2 (phi mass-normalized).
  std::array<double, dim>
  participation_factors(const Vector &shape, const std::array<Vector, dim> &mass_times_iota);
} // namespace archdam::analysis
