#pragma once

#include <archdam/base/types.h>

#include <deal.II/base/tensor.h>
#include <deal.II/base/types.h>

#include <string>

/**
 * The parts of the dam's surface (doc/theory/results.md §3): which faces of
 * the dam's cells are its surface, and which part of it (upstream face,
 * downstream face, crest, side) a face is, from its outward normal. The
 * stress envelope reads the faces' stresses by part; the temperature load
 * measures the through-thickness coordinate between the upstream and the
 * downstream face (physics/solid/thermal.h).
 */
namespace archdam::geometry
{
  enum class SurfacePart
  {
    upstream,
    downstream,
    crest,
    side
  };

  /// "upstream", "downstream", "crest" or "side".
  std::string
  name(SurfacePart part);

  /**
   * The part of a face with the unit outward normal @p n (axes of
   * doc/theory/conventions.md §3):
   *  - crest:      n_z is the largest component (the normal within about 45
   *                degrees of the vertical);
   *  - upstream:   otherwise, n_x <= -0.1;
   *  - downstream: otherwise, n_x >= 0.1;
   *  - side:       the rest, faces that look across the stream or down (the
   *                free ends of a box model; an arch dam has none).
   */
  SurfacePart
  surface_part(const dealii::Tensor<1, dim> &n);

  /// Whether a boundary face of a dam cell with this id is the dam's surface:
  /// free (0) or wetted (7); joint faces, the truncated base and the
  /// interface with the rock (an interior face) are not.
  bool
  on_dam_surface(dealii::types::boundary_id id);
} // namespace archdam::geometry
