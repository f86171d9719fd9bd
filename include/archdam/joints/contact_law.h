#pragma once

#include <archdam/base/types.h>
#include <archdam/joints/joint_parameters.h>

#include <deal.II/base/tensor.h>

namespace archdam::joints
{
  /// The states of a node pair (doc/theory/joints.md §2, the paper's Table 1).
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
} // namespace archdam::joints
