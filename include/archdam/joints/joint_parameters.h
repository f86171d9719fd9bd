#pragma once

#include <deal.II/base/parameter_handler.h>

#include <string>

namespace archdam::joints
{
  /// The Mohr-Coulomb law with tension cut-off of one joint (doc/theory/joints.md §2,
  /// the paper's Table 1). Stresses in Pa, the gap in m.
  struct JointLaw
  {
    double friction_coefficient      = 1.0;
    double cohesion                  = 0.;
    double tensile_strength          = 0.;
    double residual_cohesion         = 0.;
    double residual_tensile_strength = 0.;
    double initial_gap               = 0.;
  };

  /// The `Contraction joints` subsection (doc/theory/joints.md).
  struct JointParameters
  {
    /// glued | frictional contact
    std::string model = "glued";
    /// mixed | monolithic
    std::string solver = "mixed";
    /// all joints | neighbouring joints
    std::string coupling = "all joints";
    std::string mixed_solves = "condensed on the pairs";
    JointLaw    law;
    /// "k: name = value, ...; ..." overrides of the law for single joints
    std::string per_joint;
    double       force_tolerance = 1e-8;
    double       gap_tolerance   = 1e-9;
    unsigned int max_iterations  = 50000;
    double       penalty_factor  = 1e8;
    /// stop | continue
    std::string on_non_convergence = "stop";
    /// "name: x, y, z; ..." points whose nearest node pair is recorded
    std::string monitor_points;

    void
    add_parameters(dealii::ParameterHandler &prm);

    bool
    frictional() const
    {
      return model == "frictional contact";
    }

    /// The law of joint @p k: the global one with its per-joint overrides.
    /// Throws InputError for a malformed override or a value out of range.
    JointLaw
    law_of(unsigned int k) const;

    /// Throws InputError if `Per joint` is malformed or names a joint the
    /// model does not have (k >= @p n_joints).
    void
    check_per_joint(unsigned int n_joints) const;
  };
} // namespace archdam::joints
