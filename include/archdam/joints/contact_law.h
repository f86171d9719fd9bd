#pragma once

#include <archdam/base/types.h>
#include <archdam/joints/joint_parameters.h>

#include <deal.II/base/tensor.h>

namespace archdam::joints
{
  /// The states of a node pair (numerics.md §3, the paper's Table 1).
  enum class PairState : unsigned char
  {
    separation = 0,
    stick      = 1,
    slip       = 2
  };

  /// Strength of one pair as forces: friction coefficient, cohesion c A and
  /// tensile strength sigma_t A (intact or residual).
  struct PairStrength
  {
    double friction, cohesion_force, tensile_force;

    /// Shear capacity -mu f_xi + c A at the normal force f_xi (compression < 0).
    double
    shear_capacity(const double f_xi) const
    {
      return cohesion_force - friction * f_xi;
    }
  };

  PairStrength
  strength_of(const JointLaw &law, double area, bool damaged);

  /**
   * One pair of the contact problem with all other pairs frozen: the relative
   * displacement responds to the pair's own force f (on side 1, local frame,
   * f_xi < 0 = compression) as w = s - A f, A = h C_ii (3x3, symmetric
   * positive definite). Finds f and the state so that the law holds:
   *  - stick: gap delta = delta_0 + w_xi = 0 and tangential w = @p w_previous
   *    (no slip in the step), f_xi <= sigma_t A, |f_t| <= -mu f_xi + c A;
   *  - slip: delta = 0, |f_t| = -mu f_xi + c A, f_t along the slip increment
   *    (the force on side 2, -f_t, opposes the slip of side 2), f_xi <= sigma_t A;
   *  - separation: f = 0 (and delta > 0).
   * Stick is tried first (an intact joint holds tension), then slip, else the
   * pair separates.
   */
  PairState
  solve_pair(const dealii::Tensor<2, dim> &A, const dealii::Tensor<1, dim> &s,
             const dealii::Tensor<1, dim> &w_previous, double initial_gap,
             const PairStrength &strength, dealii::Tensor<1, dim> &f);
} // namespace archdam::joints
