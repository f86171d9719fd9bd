#pragma once

#include <archdam/geometry/box_mesh.h>

#include <deal.II/distributed/shared_tria.h>

#include <string>

namespace archdam::geometry
{
  /// The `Mesh` subsection: where the model's mesh comes from.
  struct MeshParameters
  {
    std::string   source = "box";
    BoxParameters box;

    void
    add_parameters(dealii::ParameterHandler &prm);
  };

  /**
   * Build the model mesh on every rank (a parallel::shared::Triangulation holds
   * the whole mesh everywhere and partitions the cells): generate or read the
   * conforming mesh, check that it carries the ids the physics needs, and
   * split joints and fluid-solid interfaces (splitter.h).
   */
  void
  create_mesh(const MeshParameters                          &p,
              dealii::parallel::shared::Triangulation<dim> &tria);
} // namespace archdam::geometry
