#pragma once

#include <archdam/base/types.h>

#include <deal.II/base/point.h>
#include <deal.II/base/tensor.h>
#include <deal.II/base/types.h>
#include <deal.II/grid/tria.h>

#include <array>
#include <string>
#include <vector>

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

  /// A straight edge of the mesh, between two vertices.
  using Segment = std::array<dealii::Point<dim>, 2>;

  /// The distance from @p x to the segment @p s.
  double
  distance(const dealii::Point<dim> &x, const Segment &s);

  /**
   * The lines where the dam's surface meets its base and its contraction
   * joints (doc/theory/results.md §3): the edges a surface face shares with
   * another face of its cell that is
   *  - on the base: an interface with a rock cell, or a truncated base
   *    (ids 1, 2);
   *  - on joint k: a joint face of the split mesh (ids 100 + 2k,
   *    101 + 2k), or, in a mesh whose joints are glued (not split), a face
   *    between dam blocks k and k + 1.
   * From every cell of @p tria (a shared triangulation holds all of them on
   * every process), so each process gets all the lines.
   */
  struct SurfaceEdges
  {
    std::vector<Segment>                               base;
    std::vector<std::pair<unsigned int, Segment>>      joints;

    explicit SurfaceEdges(const dealii::Triangulation<dim> &tria);

    /// The distance from @p x to the base's lines (infinity without a base).
    double
    to_base(const dealii::Point<dim> &x) const;

    /// The nearest joint line to @p x: its joint and distance (infinity
    /// without joints).
    std::pair<unsigned int, double>
    nearest_joint(const dealii::Point<dim> &x) const;
  };
} // namespace archdam::geometry
