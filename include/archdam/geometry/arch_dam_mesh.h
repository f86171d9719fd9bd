#pragma once

#include <archdam/geometry/arch_dam_parameters.h>

#include <deal.II/grid/tria.h>

#include <array>

namespace archdam::geometry
{
  /**
   * Fill @p tria with a CONFORMING hexahedral mesh (shared vertices everywhere;
   * the splitter duplicates joint and fluid-solid vertices afterwards) of dam,
   * rock and water. Material ids: 10 + k for dam block k, 1 rock, 2 water.
   * Boundary ids (before splitting): 0 traction-free solid surface (dam
   * downstream face, crest, dam upstream face above the water, ground surface
   * and canyon walls in air), 1 foundation bottom (and, with no rock, the dam's
   * base and abutments, which are then fixed), 2 the four vertical truncation
   * faces of the rock, 3 reservoir free surface, 4 reservoir upstream
   * truncation, 5 reservoir bottom and banks where no rock is meshed. Faces
   * between two cells carry no id.
   *
   * Throws InputError for parameters that give no valid dam or mesh.
   */
  void
  generate_arch_dam(const ArchDamParameters &p, dealii::Triangulation<3> &tria);

  /// The numbers of solid and water cells generate_arch_dam() makes for @p p,
  /// counted without making them (a tenth of the index grid when that has
  /// more than 1e9 cells).
  std::array<double, 2>
  arch_dam_cell_count(const ArchDamParameters &p);
} // namespace archdam::geometry
