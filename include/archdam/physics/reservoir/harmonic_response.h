#pragma once

#include <archdam/physics/reservoir/fluid_operators.h>

#include <deal.II/base/index_set.h>

namespace archdam::physics::reservoir
{
  /**
   * Solve the complex symmetric system (A + iB)(x_re + i x_im) = f_re + i f_im
   * on the DOFs in @p active (locally owned ones; x = 0 elsewhere) through its
   * real symmetric indefinite form
   *   [[A, -B], [-B, -A]] [x_re; x_im] = [f_re; -f_im],
   * factorized by MUMPS LDL^T (time/factorized_operator.h). A and B share one
   * sparsity pattern.
   */
  void
  solve_complex_symmetric(const SparseMatrix      &A,
                          const SparseMatrix      &B,
                          const dealii::IndexSet  &active,
                          const Vector            &f_re,
                          const Vector            &f_im,
                          Vector                  &x_re,
                          Vector                  &x_im);

  /**
   * Steady-state pressure amplitude of the water alone (rigid, fixed solid)
   * under the harmonic ground acceleration a_g(t) = Re(e^{i omega t}) e_d:
   *   (Q - omega^2 G + i omega H) P = -S iota_d   (doc/theory/reservoir.md §9),
   * on the free pressure DOFs.
   */
  void
  harmonic_pressure(const fe::FESpace    &space,
                    const FluidOperators &ops,
                    double                omega,
                    unsigned int          direction,
                    Vector               &p_re,
                    Vector               &p_im);
} // namespace archdam::physics::reservoir

namespace archdam::physics::reservoir
{
  /**
   * Steady-state response (U, P) of the dam (with its water, if @p water is
   * given) to the harmonic ground acceleration a_g(t) = Re(e^{i omega t}) e_d,
   * relative formulation (doc/theory/reservoir.md §9, doc/theory/foundation.md §2):
   *   (K - omega^2 M + i omega D) U - (1/rho_w) S^T P = -M iota_d,
   *   -omega^2 S U + (Q - omega^2 G + i omega H) P = -S iota_d,
   * D = alpha M + beta K. The water rows are scaled by 1/(omega^2 rho_w),
   * which makes the system complex symmetric (the 2x2-block analogue of the
   * paper's eq. 3.2), and solved by solve_complex_symmetric() on all free
   * DOFs. Used to find the resonances of the dam-water system from a sweep.
   */
  void
  harmonic_response(const fe::FESpace          &space,
                    const SparseMatrix         &M,
                    const SparseMatrix         &K,
                    std::pair<double, double>   rayleigh,
                    const Vector               &inertia_load, ///< M iota_d
                    const FluidOperators       *water,
                    double                      density,
                    double                      omega,
                    unsigned int                direction,
                    Vector                     &x_re,
                    Vector                     &x_im);
} // namespace archdam::physics::reservoir
