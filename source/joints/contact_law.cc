#include <archdam/joints/contact_law.h>

namespace archdam::joints
{
  using namespace dealii;

  PairStrength
  strength_of(const JointLaw &law, const double area, const bool damaged)
  {
    // doc/theory/joints.md §2: sigma_t and c drop to their residual values once a pair
    // has opened or slipped.
    return {law.friction_coefficient,
            area * (damaged ? law.residual_cohesion : law.cohesion),
            area * (damaged ? law.residual_tensile_strength : law.tensile_strength)};
  }
} // namespace archdam::joints
