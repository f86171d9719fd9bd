#include <archdam/loads/static_loads.h>

namespace archdam::loads
{
  using namespace dealii;

  void
  StaticLoadParameters::add_parameters(ParameterHandler &prm)
  {
    prm.add_parameter("Gravity", gravity, "Apply the self-weight of the dam (in the static stage, and from there on "
                      "in the dynamic stage; without a static stage the dynamic "
                      "stage starts unloaded at rest).",
                      Patterns::Bool());
    prm.add_parameter("Gravitational acceleration", g, "g [m/s^2].",
                      Patterns::Double(0.));
    prm.add_parameter("Gravity on foundation", gravity_on_rock,
                      "Also apply the self-weight of the rock (usually not: its "
                      "in-situ stress predates the dam).",
                      Patterns::Bool());
    prm.add_parameter("Hydrostatic pressure", hydrostatic,
                      "Apply the hydrostatic water pressure on the wetted dam "
                      "face and rock up to the water level (Reservoir section), "
                      "unless the reservoir model is none.",
                      Patterns::Bool());
  }
} // namespace archdam::loads
