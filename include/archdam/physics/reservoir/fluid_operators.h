#pragma once

#include <archdam/fe/fe_space.h>
#include <archdam/physics/reservoir/reservoir_parameters.h>

#include <array>
#include <vector>

namespace archdam::physics::reservoir
{
  using CellIterator = dealii::DoFHandler<dim>::active_cell_iterator;

  /**
   * A fluid face (id 6) and a solid face (id 7) of the same fluid-solid
   * interface where one face contains the other (doc/theory/conventions.md §6: the water
   * mesh may be coarser than the solid's, or finer). The coupling is
   * integrated on the smaller face.
   */
  struct InterfacePair
  {
    CellIterator fluid_cell;
    unsigned int fluid_face;
    CellIterator solid_cell;
    unsigned int solid_face;
    bool         integrate_on_fluid; ///< the fluid face is the smaller one
  };

  /// Every interface pair of the mesh (the same list on every rank). Throws
  /// InputError if a wetted face (id 6 or 7) has no partner.
  std::vector<InterfacePair>
  match_interface_faces(const fe::FESpace &space);

  /// The matrix couplings of the pairs' fluid and solid DOFs (both ways), for
  /// fe::FESpace::add_couplings.
  void
  add_interface_couplings(const fe::FESpace                  &space,
                          const std::vector<InterfacePair>   &pairs,
                          dealii::DynamicSparsityPattern     &dsp);

  /// p = 0 on the free surface (id 3) unless it carries gravity waves.
  void
  constrain_free_surface(const fe::FESpace                 &space,
                         const ReservoirParameters         &p,
                         dealii::AffineConstraints<double> &constraints);

  /**
   * The discrete reservoir of doc/theory/reservoir.md §3 (paper eq. 3.1):
   *   G p_tt + H p_t + Q p + S u_tt + S iota a_g = 0,
   *   G = (1/g) int_free N^T N + (1/c^2) int_water N^T N,
   *   H = (1/c) int_truncation N^T N + q int_bottom N^T N,
   *   Q = int_water grad N^T grad N,
   *   S = rho_w int_interface N_f^T n^T N_s  (n: the water's outward normal),
   * with the solid carrying -(1/rho_w) S^T p. S lives in the fluid rows and
   * solid columns, S_transpose = S^T in the solid rows; `influence[d]` is
   * S iota_d, the interface integral rho_w int N_f n_d, so that the ground
   * motion enters the water as -sum_d a_g,d influence[d] even where the
   * solid DOFs are fixed. Every matrix has the couplings of the water cells
   * and of the interface (a subset of the model's pattern), assembled with the
   * model's constraints.
   * Incompressible water drops the 1/c^2 term and the radiation terms.
   */
  struct FluidOperators
  {
    SparseMatrix           G, H, Q, S, S_transpose;
    std::array<Vector, dim> influence;
  };

  void
  assemble_fluid_operators(const fe::FESpace                &space,
                           const ReservoirParameters        &p,
                           double                            g,
                           const std::vector<InterfacePair> &pairs,
                           FluidOperators                   &ops);

  /**
   * The columns of S at the solid DOFs @p columns (e.g. the prescribed outer
   * boundary of a massed foundation, doc/theory/foundation.md §7), which the constrained
   * S of FluidOperators drops: the coupling of every interface pair that
   * touches them, with the model's constraints on the fluid rows and on the
   * other columns, but not on @p columns. The pairs of other columns may add
   * entries there too; a product with a vector that vanishes off @p columns
   * gives S(:, columns) times its entries there.
   */
  void
  assemble_coupling_columns(const fe::FESpace                                  &space,
                            double                                              density,
                            const std::vector<InterfacePair>                   &pairs,
                            const std::vector<dealii::types::global_dof_index> &columns,
                            SparseMatrix                                       &S_columns);

  /// The DOFs of the pressure that are free (not constrained), locally owned.
  dealii::IndexSet
  free_pressure_dofs(const fe::FESpace &space);
} // namespace archdam::physics::reservoir
