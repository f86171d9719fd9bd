#pragma once

#include <deal.II/base/parameter_handler.h>

#include <string>

namespace archdam::joints
{
  /// The `Contraction joints` subsection (numerics.md §3).
  struct JointParameters
  {
    std::string model = "glued";

    void
    add_parameters(dealii::ParameterHandler &prm);
  };
} // namespace archdam::joints
