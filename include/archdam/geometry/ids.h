#pragma once

#include <deal.II/base/types.h>

/**
 * Material and boundary ids shared by every mesh source (doc/theory/conventions.md §4-§6).
 */
namespace archdam::ids
{
  // material ids
  constexpr dealii::types::material_id rock            = 1;
  constexpr dealii::types::material_id water           = 2;
  constexpr dealii::types::material_id first_dam_block = 10; // block k: 10 + k

  inline bool
  is_dam(const dealii::types::material_id m)
  {
    return m >= first_dam_block && m < 100;
  }

  // boundary ids
  constexpr dealii::types::boundary_id free_surface_solid    = 0;
  constexpr dealii::types::boundary_id foundation_bottom     = 1;
  constexpr dealii::types::boundary_id foundation_sides      = 2;
  constexpr dealii::types::boundary_id reservoir_surface     = 3;
  constexpr dealii::types::boundary_id reservoir_truncation  = 4;
  constexpr dealii::types::boundary_id reservoir_bottom      = 5;
  constexpr dealii::types::boundary_id fluid_interface       = 6;
  constexpr dealii::types::boundary_id solid_interface       = 7;
} // namespace archdam::ids
