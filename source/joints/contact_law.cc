#include <archdam/joints/contact_law.h>

namespace archdam::joints
{
  PairStrength
  MohrCoulomb::strength(const LawParameters &values, const double area,
                        const PairHistory &history) const
  {
    const bool residual = history.damaged;
    return {values.friction_coefficient,
            area * (residual ? values.residual_cohesion : values.cohesion),
            area * (residual ? values.residual_tensile_strength : values.tensile_strength)};
  }

  PairStrength
  SofteningShearKey::strength(const LawParameters &values, const double area,
                              const PairHistory &history) const
  {
    // the intact part left: 1 when closed so far, 0 from Softening opening on
    const double kappa  = history.largest_opening;
    const double intact = kappa >= values.softening_opening ?
                            0. :
                            1. - kappa / values.softening_opening;
    const auto between = [&](const double residual, const double full) {
      return residual + intact * (full - residual);
    };
    return {values.friction_coefficient,
            area * between(values.residual_cohesion, values.cohesion),
            area * between(values.residual_tensile_strength, values.tensile_strength)};
  }

  std::unique_ptr<JointLaw>
  make_joint_law(const Law law)
  {
    if (law == Law::softening_shear_key)
      return std::make_unique<SofteningShearKey>();
    return std::make_unique<MohrCoulomb>();
  }
} // namespace archdam::joints
