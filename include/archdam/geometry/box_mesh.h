#pragma once

#include <archdam/base/types.h>

#include <deal.II/base/parameter_handler.h>
#include <deal.II/grid/tria.h>

namespace archdam::geometry
{
  /**
   * A box-shaped "dam on rock": a concrete block [0, L] x [0, W] x [0, H]
   * (x stream, y cross-stream, z up) split into cantilever blocks along y
   * (block 0 at the largest y: left looking downstream),
   * standing on a rock block that extends beyond it upstream, downstream, to the
   * sides and below. With no rock (depth 0) the dam base is the foundation
   * bottom (boundary id 1) and is fixed.
   */
  struct BoxParameters
  {
    double       length         = 10.;  // x
    double       width          = 40.;  // y
    double       height         = 30.;  // z
    unsigned int n_blocks       = 1;
    unsigned int cells_x        = 2;
    unsigned int cells_y        = 4;
    unsigned int cells_z        = 3;
    double       rock_depth     = 20.;
    double       rock_extent    = 20.;
    double       rock_cell_size = 10.;

    void
    add_parameters(dealii::ParameterHandler &prm);
  };

  /// Fill @p tria with the box model; ids as in doc/theory/conventions.md §4-§5.
  void
  generate_box(const BoxParameters &p, dealii::Triangulation<dim> &tria);

  /// The number of cells generate_box() makes for @p p, counted without
  /// making them (infinite for a Rock cell size of 0).
  double
  box_cell_count(const BoxParameters &p);
} // namespace archdam::geometry
