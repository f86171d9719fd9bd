#include <archdam/physics/reservoir/coupled_system.h>

#include <deal.II/lac/exceptions.h>

namespace archdam::physics::reservoir
{
  using namespace dealii;

  void
  linear_combination(SparseMatrix &out, const MatrixTerms &terms)
  {
    // The sum takes the pattern of the term with the most entries, the
    // model's (fe::FESpace::reinit); a term on that pattern is added entry by
    // entry, one on a subset of it (the water's operators) row by row.
    const SparseMatrix *widest = terms.begin()->second;
    for (const auto &term : terms)
      if (term.second->n_nonzero_elements() > widest->n_nonzero_elements())
        widest = term.second;
    out.reinit(*widest);
    out = 0.;
    for (const auto &[c, A] : terms)
      if (c != 0.)
        AssertThrow(MatAXPY(out.petsc_matrix(), c, static_cast<Mat>(*A),
                            A->n_nonzero_elements() == widest->n_nonzero_elements() ?
                              SAME_NONZERO_PATTERN :
                              SUBSET_NONZERO_PATTERN) == 0,
                    ExcMessage("PETSc MatAXPY failed."));
  }

  void
  form_coupled_system(const FluidOperators           &ops,
                      const double                    density,
                      const double                    beta2,
                      const double                    dt,
                      const SparseMatrix             &M,
                      const SparseMatrix             &K,
                      const MatrixTerms              &solid_damping,
                      CoupledSystem                  &system)
  {
    const double phi = -beta2 * dt * dt / density; // paper eq. 3.2
    linear_combination(system.mass, {{1., &M}, {phi, &ops.S}, {phi, &ops.G}});
    MatrixTerms damping = solid_damping;
    damping.emplace_back(phi, &ops.H);
    linear_combination(system.damping, damping);
    linear_combination(system.stiffness,
                       {{1., &K}, {-1. / density, &ops.S_transpose}, {phi, &ops.Q}});
    for (unsigned int d = 0; d < dim; ++d)
      {
        system.fluid_influence[d] = ops.influence[d];
        system.fluid_influence[d] *= phi;
      }
  }

  void
  form_coupled_columns(const fe::FESpace                &space,
                       const std::vector<InterfacePair> &pairs,
                       const double                      density,
                       const double                      beta2,
                       const double                      dt,
                       time::PrescribedDofs             &prescribed)
  {
    const double phi = -beta2 * dt * dt / density; // paper eq. 3.2, as above
    SparseMatrix S_columns;
    assemble_coupling_columns(space, density, pairs, prescribed.dofs, S_columns);
    // The solid's columns and S's have different patterns: PETSc merges them.
    AssertThrow(MatAXPY(prescribed.mass_columns.petsc_matrix(), phi,
                        static_cast<Mat>(S_columns), DIFFERENT_NONZERO_PATTERN) == 0,
                ExcMessage("PETSc MatAXPY failed."));
  }
} // namespace archdam::physics::reservoir
