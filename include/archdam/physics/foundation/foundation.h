#pragma once

#include <archdam/base/types.h>

#include <deal.II/base/parameter_handler.h>

#include <set>
#include <string>

namespace archdam::physics::foundation
{
  /**
   * The `Foundation` subsection (numerics.md §5). The massless foundation has
   * stiffness only, a fixed outer boundary (bottom and sides) and the ground
   * acceleration applied uniformly (relative formulation).
   */
  struct FoundationParameters
  {
    std::string model = "massless";

    void
    add_parameters(dealii::ParameterHandler &prm);

    bool
    rock_has_mass() const
    {
      return false;
    }

    /// Boundary ids whose displacement is fixed.
    std::set<dealii::types::boundary_id>
    fixed_boundaries() const;
  };
} // namespace archdam::physics::foundation
