#pragma once

#include <archdam/base/types.h>

#include <deal.II/grid/tria.h>

#include <string>

namespace archdam::output
{
  /**
   * The model mesh for ParaView (`archdam CASE.prm --mesh-only`), as two
   * ASCII VTU files:
   *  - @p basename.vtu: the hexahedra with the cell data "material id",
   *    "region" (1 rock, 2 water, 3 dam) and "block" (k for dam block k, -1
   *    elsewhere);
   *  - @p basename_boundary.vtu: every boundary face as a quadrilateral with
   *    the cell data "boundary id" (0-7, 100 + 2k and 101 + 2k on joint k) and
   *    "material id" of the cell it bounds.
   * Call on one rank (the mesh is the same everywhere).
   */
  void
  write_mesh_vtu(const dealii::Triangulation<dim> &mesh, const std::string &basename);
} // namespace archdam::output
