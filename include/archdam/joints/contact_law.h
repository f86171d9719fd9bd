#pragma once

#include <archdam/base/types.h>
#include <archdam/joints/joint_parameters.h>

#include <algorithm>
#include <memory>

namespace archdam::joints
{
  /// The states of a node pair (doc/theory/joints.md §2, the paper's Table 1).
  enum class PairState : unsigned char
  {
    separation = 0,
    stick      = 1,
    slip       = 2
  };

  /// What a pair's strength may depend on besides its joint's values: its
  /// past, which only ever weakens it.
  struct PairHistory
  {
    bool   damaged         = false; ///< it has opened or slipped
    double largest_opening = 0.;    ///< the largest gap it has reached [m]
  };

  /**
   * The admissible forces of one pair (doc/theory/joints.md §2): the Coulomb
   * cone with a tension cut-off, f_xi <= sigma_t A and |f_t| <= c A - mu f_xi
   * (compression f_xi < 0), as forces. Every contact solver asks the cone
   * only through this: the state update and the residual
   * (JointSolver::update_state()), the linearized slip rows f_t = (c A -
   * mu f_xi) d of the active set, the projections of Gauss-Seidel, the
   * friction loads of the monolithic solver.
   */
  struct PairStrength
  {
    double friction, cohesion_force, tensile_force;

    /// Shear capacity -mu f_xi + c A at the normal force f_xi (compression < 0).
    double
    shear_capacity(const double f_xi) const
    {
      return cohesion_force - friction * f_xi;
    }

    /// The largest normal force inside the cone: sigma_t A, or the apex
    /// c A / mu if that comes first.
    double
    normal_limit() const
    {
      return friction > 0. ? std::min(tensile_force, cohesion_force / friction) : tensile_force;
    }
  };

  /**
   * A joint law (doc/theory/joints.md §2): the strength of a pair of area
   * @p area from its joint's values and its history. The cone's shape is
   * fixed (PairStrength); a law says how its size evolves. The solvers hold
   * one law for all pairs, chosen by `Contraction joints/Law`
   * (make_joint_law()); a new law is one more class here and one more name
   * in Law.
   */
  class JointLaw
  {
  public:
    virtual ~JointLaw() = default;

    virtual PairStrength
    strength(const LawParameters &values, double area, const PairHistory &history) const = 0;
  };

  /// The paper's law: intact cohesion and tensile strength until the pair
  /// first opens or slips, the residual ones from then on.
  class MohrCoulomb : public JointLaw
  {
  public:
    PairStrength
    strength(const LawParameters &values, double area,
             const PairHistory &history) const override;
  };

  /// A shear-key joint: cohesion and tensile strength fall linearly from
  /// the intact to the residual values as the largest opening reached
  /// grows from 0 to Softening opening; friction stays.
  class SofteningShearKey : public JointLaw
  {
  public:
    PairStrength
    strength(const LawParameters &values, double area,
             const PairHistory &history) const override;
  };

  std::unique_ptr<JointLaw>
  make_joint_law(Law law);
} // namespace archdam::joints
