#include <archdam/joints/joint_parameters.h>

namespace archdam::joints
{
  using namespace dealii;

  void
  JointParameters::add_parameters(ParameterHandler &prm)
  {
    prm.add_parameter("Model", model,
                      "How the contraction joints between dam blocks behave: glued = "
                      "the two faces of every joint are tied together (the monolithic "
                      "dam).",
                      Patterns::Selection("glued"));
  }
} // namespace archdam::joints
