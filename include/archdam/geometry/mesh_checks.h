#pragma once

#include <archdam/base/types.h>

#include <deal.II/grid/tria.h>

namespace archdam::geometry
{
  /**
   * Scaled Jacobian of a hexahedral cell (Knupp 2000, the Verdict library's
   * definition): the smallest, over the 8 corners, of det(e1, e2, e3) for the
   * unit edge vectors leaving the corner, and of the same determinant for the
   * unit principal axes (the mean edge vector in each direction). 1 for a
   * rectangular box, cos(theta) for a parallelepiped sheared by theta, 0 for
   * a degenerate cell, negative for an inverted corner.
   */
  double
  scaled_jacobian(const dealii::Triangulation<dim>::cell_iterator &cell);

  /// Below this scaled Jacobian a cell is inverted or degenerate (an input
  /// error): its Jacobian vanishes or changes sign inside the cell.
  constexpr double min_valid_scaled_jacobian = 1e-6;

  /**
   * Cell shapes (any mesh source): a cell with a scaled Jacobian below
   * min_valid_scaled_jacobian is an InputError naming its centre, material
   * id and value.
   */
  void
  check_cell_shapes(const dealii::Triangulation<dim> &conforming);

  /**
   * The ids of a conforming mesh before splitting (doc/theory/conventions.md §4-§5,
   * doc/user-guide.md "Ids"), for every mesh source. Each rule broken is an
   * InputError naming the place:
   *  - material ids are 1 (rock), 2 (water) or 10 + k (dam block k, k < 90);
   *    any other (0: a cell outside every physical volume) has no material;
   *  - the dam blocks are numbered 10, 11, ... without gaps and each block
   *    shares faces (a joint) with the next;
   *  - a boundary face of a solid cell has id 0 (traction-free, also what a
   *    face outside every physical surface gets), 1 or 2; a boundary face of
   *    a water cell has id 3, 4 or 5: water has no default condition, so a
   *    water face without an id is an error; ids 6, 7 and 100 + ... are the
   *    splitter's;
   *  - the mesh is conforming: two boundary faces at the same place (cells
   *    that touch without sharing their nodes, e.g. Gmsh volumes meshed
   *    without BooleanFragments/Coherence) would leave a joint face without
   *    its partner, or water not coupled to the dam.
   */
  void
  check_model_ids(const dealii::Triangulation<dim> &conforming);
} // namespace archdam::geometry
