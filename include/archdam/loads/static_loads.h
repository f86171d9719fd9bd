#pragma once

#include <deal.II/base/parameter_handler.h>

namespace archdam::loads
{
  /// The `Static loads` subsection (doc/theory/loading-sequence.md §1).
  struct StaticLoadParameters
  {
    bool   gravity         = true;
    double g               = 9.81;
    bool   gravity_on_rock = false;
    bool   hydrostatic     = true;

    void
    add_parameters(dealii::ParameterHandler &prm);
  };
} // namespace archdam::loads
