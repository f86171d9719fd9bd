#pragma once

#include <archdam/base/types.h>

#include <deal.II/grid/tria.h>

#include <vector>

namespace archdam::geometry
{
  /**
   * The dam blocks that nothing but their joints holds: on the split model
   * mesh (joint faces and the faces between water and solid are boundary
   * faces there), the solid parts connected through shared faces, and of
   * those the ones without a face on the foundation's outer boundary (ids 1
   * and 2, fixed or on springs in the static stage). Returns the numbers k of
   * the dam blocks in such parts (a block resting on another across a joint,
   * or a whole model without support), sorted.
   */
  std::vector<unsigned int>
  blocks_held_by_joints_alone(const dealii::Triangulation<dim> &split);
} // namespace archdam::geometry
