#pragma once

#include <archdam/base/types.h>

#include <deal.II/base/index_set.h>
#include <deal.II/base/parameter_handler.h>
#include <deal.II/distributed/shared_tria.h>
#include <deal.II/dofs/dof_handler.h>
#include <deal.II/fe/fe_values_extractors.h>
#include <deal.II/hp/fe_collection.h>
#include <deal.II/hp/q_collection.h>
#include <deal.II/lac/affine_constraints.h>
#include <deal.II/lac/dynamic_sparsity_pattern.h>

#include <functional>
#include <set>

namespace archdam::fe
{
  /// The `Finite element` subsection.
  struct FiniteElementParameters
  {
    unsigned int degree = 2;

    void
    add_parameters(dealii::ParameterHandler &prm);
  };

  /**
   * The discrete space of the whole model (doc/style.md §1, step-46): one DoFHandler
   * over an hp::FECollection whose element 0 carries the displacement u
   * (dim components, FE_Q) in solid cells and element 1 the hydrodynamic
   * pressure p (one component) in water cells; the other field is FE_Nothing.
   * Component layout is always (u_x, u_y, u_z, p). Element 2 has no DOFs at
   * all: water cells use it when the reservoir model carries no pressure
   * (Westergaard added mass), so that the wetted faces keep their ids.
   */
  class FESpace
  {
  public:
    static constexpr unsigned int solid_index    = 0;
    static constexpr unsigned int fluid_index    = 1;
    static constexpr unsigned int inert_index    = 2;
    static constexpr unsigned int pressure_comp  = dim;
    static constexpr unsigned int n_components   = dim + 1;

    FESpace(const dealii::parallel::shared::Triangulation<dim> &tria,
            const FiniteElementParameters                    &p);

    /// Distribute DOFs, fix the displacement on the given boundary ids
    /// (homogeneous constraints: the unknowns of a step are increments) and
    /// let @p add_constraints add further homogeneous ones (e.g. glued joints).
    void
    setup(const std::set<dealii::types::boundary_id>                   &fixed_boundaries,
          const std::function<void(dealii::AffineConstraints<double> &)> &add_constraints = {});

    /// Matrices get the couplings of the cells (with the constraints) and
    /// those @p add_couplings adds, e.g. fluid-solid interface couplings
    /// (physics/reservoir): the model's pattern, which the solid's matrices
    /// and every sum of operators share.
    void
    reinit(SparseMatrix &matrix) const;
    /// A matrix with the same rows and columns and the couplings that
    /// @p add_entries puts into the pattern (rows: the relevant DOFs and
    /// their constraints' masters); an operator living on part of the model
    /// (the water's) takes a subset of the model's pattern this way.
    void
    reinit(SparseMatrix                                                 &matrix,
           const std::function<void(dealii::DynamicSparsityPattern &)> &add_entries) const;
    void
    reinit(Vector &vector) const;
    /// A vector with ghost entries, for output and evaluation.
    void
    reinit_ghosted(Vector &vector) const;

    MPI_Comm                                    comm;
    unsigned int                                degree;
    dealii::hp::FECollection<dim>               fe_collection;
    dealii::hp::QCollection<dim>                q_collection;
    dealii::hp::QCollection<dim - 1>            face_q_collection;
    dealii::DoFHandler<dim>                     dof_handler;
    dealii::IndexSet                            locally_owned;
    dealii::IndexSet                            locally_relevant;
    dealii::AffineConstraints<double>           constraints;
    const dealii::FEValuesExtractors::Vector    displacement{0};
    const dealii::FEValuesExtractors::Scalar    pressure{pressure_comp};
    /// Whether water cells carry the pressure (fluid_index) or nothing
    /// (inert_index); set before setup().
    bool                                        pressure_in_water = true;
    /// Extra matrix couplings beyond the cells' own (set before reinit()).
    std::function<void(dealii::DynamicSparsityPattern &)> add_couplings;

  };

  /// The constraints of @p space without the lines of the DOFs i with
  /// @p excluded[i] (the prescribed columns of an operator keep their own
  /// values; the other rows keep the model's constraints).
  dealii::AffineConstraints<double>
  constraints_without(const FESpace &space, const std::vector<bool> &excluded);

  /// Call @p visit(cell, i, dof) for each DOF i (global index dof) of each
  /// locally owned cell of @p space, until it returns true.
  void
  visit_owned_cell_dofs(
    const FESpace &space,
    const std::function<bool(const dealii::DoFHandler<dim>::active_cell_iterator &, unsigned int,
                             dealii::types::global_dof_index)> &visit);
} // namespace archdam::fe
