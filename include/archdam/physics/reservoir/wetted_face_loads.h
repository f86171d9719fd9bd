#pragma once

#include <archdam/fe/fe_space.h>

namespace archdam::physics::reservoir
{
  /**
   * Hydrostatic pressure p = rho_w g (level - z) on the wetted solid faces
   * (id 7: dam face and submerged rock) below the water level, added to
   * @p load as the traction -p n (n: the solid's outward normal), doc/theory/reservoir.md §8
   * and doc/theory/loading-sequence.md §1.
   */
  void
  add_hydrostatic_load(const fe::FESpace &space, double density, double g, double level,
                       Vector &load);

  /**
   * The generalized Westergaard added mass (doc/theory/reservoir.md §7): at every node i
   * of the wetted solid faces (id 7) at depth h_i below the water surface,
   *   M_a^(i) = (7/8) rho_w sqrt(H h_i) A_i n_i n_i^T,
   * added to @p mass. H is the water depth (level minus the lowest wetted
   * node) and A_i n_i = sum over the node's faces of int N_i n dA, the
   * tributary area with its area-weighted normal, so that
   * A_i n_i n_i^T = b b^T / |b| with b = int N_i n dA.
   */
  void
  add_westergaard_mass(const fe::FESpace &space, double density, double level,
                       SparseMatrix &mass);
} // namespace archdam::physics::reservoir
