#pragma once

#include <archdam/base/types.h>

#include <deal.II/grid/tria.h>

#include <string>

namespace archdam::geometry
{
  /**
   * Read a Gmsh mesh (`Mesh/Source = gmsh`): an ASCII .msh file of format 2.x
   * or 4.1 holding hexahedra. Physical volume ids become material ids and
   * physical surface ids boundary ids (doc/theory/conventions.md §4-§5; doc/user-guide.md
   * lists them); a face outside any physical surface gets id 0, a cell outside
   * any physical volume material id 0 (rejected later by check_model_ids()).
   *
   * The file is parsed by deal.II's GridIn::read_msh(std::istream &), never by
   * the overload taking a file name: in deal.II 9.4.1 that one goes through
   * the gmsh library and has been seen to scramble vertex coordinates, with no
   * error, when the file holds elements outside any physical group (test
   * gmsh_reader). GridIn turns cells given with inverted vertex order right
   * side out; the cell shapes are checked afterwards (check_cell_shapes()).
   *
   * A file that is missing, not a .msh, binary, of another version, truncated,
   * malformed (check_gmsh_structure(), before GridIn sees it), of other cells
   * than hexahedra or otherwise unreadable is an InputError naming the file
   * and the problem.
   */
  void
  read_gmsh(const std::string &filename, dealii::Triangulation<dim> &tria);
} // namespace archdam::geometry
