#include <archdam/geometry/ids.h>
#include <archdam/physics/foundation/foundation.h>

namespace archdam::physics::foundation
{
  using namespace dealii;

  void
  FoundationParameters::add_parameters(ParameterHandler &prm)
  {
    prm.add_parameter("Model", model,
                      "Foundation model: massless = rock stiffness without "
                      "inertia, outer boundary fixed, uniform ground motion.",
                      Patterns::Selection("massless"));
  }

  std::set<types::boundary_id>
  FoundationParameters::fixed_boundaries() const
  {
    return {ids::foundation_bottom, ids::foundation_sides};
  }
} // namespace archdam::physics::foundation
