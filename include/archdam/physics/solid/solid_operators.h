#pragma once

#include <archdam/fe/fe_space.h>
#include <archdam/physics/solid/damping.h>
#include <archdam/physics/solid/materials.h>

#include <deal.II/base/tensor.h>

namespace archdam::physics::solid
{
  /// Which solid cells carry inertia (the massless foundation has none).
  enum class InertiaOf
  {
    dam,
    dam_and_rock
  };

  /**
   * Consistent mass M = int rho N^T N and stiffness
   * K = int (lambda div N div N + 2 mu eps(N) : eps(N)) of the solid cells
   * (doc/theory/solid.md §3), assembled with the model's constraints (constrained rows
   * and columns condensed, so the step unknowns there stay zero). With
   * @p damping, also the damping matrix D = sum over the cells of
   * alpha_c M_c + beta_c K_c with the coefficients of each cell's material
   * (doc/theory/solid.md §4), on the same pattern, into @p damping_matrix.
   */
  void
  assemble_mass_and_stiffness(const fe::FESpace          &space,
                              const MaterialParameters   &materials,
                              InertiaOf                   inertia,
                              SparseMatrix               &mass,
                              SparseMatrix               &stiffness,
                              const DampingParameters    *damping        = nullptr,
                              SparseMatrix               *damping_matrix = nullptr);

  /**
   * The dam's own damping matrix D_dam = sum over the dam's cells of
   * alpha_d M_e + beta_d K_e (no Westergaard mass), condensed with the
   * model's constraints, on the pattern of the dam's cells only: the
   * energy balance's damping in the dam, and with D_dam iota_d = alpha_d
   * M_dam iota_d the load of the dam's mass term relative to the ground
   * (doc/theory/solid.md §4).
   */
  void
  assemble_dam_damping(const fe::FESpace        &space,
                       const MaterialParameters &materials,
                       const DampingParameters  &damping,
                       SparseMatrix             &dam_damping);

  /**
   * The full (unconstrained) columns of M and K at the constrained DOFs
   * @p columns: the entries of the cells touching them, condensed with the
   * model's constraints other than the lines of @p columns. They carry the
   * coupling of prescribed DOFs to the free ones (time::PrescribedDofs);
   * their other entries are partial and never used. With @p damping, also
   * the columns of the damping matrix D (assemble_mass_and_stiffness) into
   * @p damping_columns.
   */
  void
  assemble_mass_and_stiffness_columns(const fe::FESpace                                  &space,
                                      const MaterialParameters                           &materials,
                                      InertiaOf                                           inertia,
                                      const std::vector<dealii::types::global_dof_index> &columns,
                                      SparseMatrix                                       &mass,
                                      SparseMatrix                                       &stiffness,
                                      const DampingParameters *damping         = nullptr,
                                      SparseMatrix            *damping_columns = nullptr);

  /**
   * The load of a uniform acceleration field b acting on the mass of the chosen
   * cells, F_i = int rho b . N_i. With b = -g e_z it is gravity; with b = e_d it
   * is the influence load M iota_d of the relative formulation (doc/theory/foundation.md §2),
   * whose effective earthquake load is -a_g,d(t) M iota_d.
   */
  void
  assemble_inertia_load(const fe::FESpace               &space,
                        const MaterialParameters        &materials,
                        InertiaOf                        inertia,
                        const dealii::Tensor<1, dim>    &b,
                        Vector                          &load);
} // namespace archdam::physics::solid
