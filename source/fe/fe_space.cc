#include <archdam/fe/fe_space.h>
#include <archdam/geometry/ids.h>

#include <deal.II/base/quadrature_lib.h>
#include <deal.II/dofs/dof_tools.h>
#include <deal.II/fe/fe_nothing.h>
#include <deal.II/fe/fe_q.h>
#include <deal.II/fe/fe_system.h>
#include <deal.II/lac/dynamic_sparsity_pattern.h>
#include <deal.II/lac/sparsity_tools.h>
#include <deal.II/numerics/vector_tools.h>

namespace archdam::fe
{
  using namespace dealii;

  void
  FiniteElementParameters::add_parameters(ParameterHandler &prm)
  {
    prm.add_parameter("Degree", degree,
                      "Polynomial degree of the Lagrange elements (1 or 2) for "
                      "displacement and pressure.",
                      Patterns::Integer(1, 2));
  }

  FESpace::FESpace(const parallel::shared::Triangulation<dim> &tria,
                   const FiniteElementParameters             &p)
    : comm(tria.get_communicator())
    , degree(p.degree)
    , dof_handler(tria)
  {
    fe_collection.push_back(FESystem<dim>(FE_Q<dim>(degree), dim, FE_Nothing<dim>(), 1));
    fe_collection.push_back(FESystem<dim>(FE_Nothing<dim>(), dim, FE_Q<dim>(degree), 1));
    fe_collection.push_back(FESystem<dim>(FE_Nothing<dim>(), dim, FE_Nothing<dim>(), 1));
    for (unsigned int i = 0; i < fe_collection.size(); ++i)
      {
        q_collection.push_back(QGauss<dim>(degree + 1));
        face_q_collection.push_back(QGauss<dim - 1>(degree + 1));
      }
  }

  void
  FESpace::setup(const std::set<types::boundary_id>                   &fixed_boundaries,
                 const std::function<void(AffineConstraints<double> &)> &add_constraints)
  {
    for (const auto &cell : dof_handler.active_cell_iterators())
      if (cell->is_locally_owned())
        cell->set_active_fe_index(cell->material_id() != ids::water ? solid_index :
                                  pressure_in_water                 ? fluid_index :
                                                                      inert_index);
    dof_handler.distribute_dofs(fe_collection);

    locally_owned = dof_handler.locally_owned_dofs();
    DoFTools::extract_locally_relevant_dofs(dof_handler, locally_relevant);

    constraints.clear();
    constraints.reinit(locally_relevant);
    std::map<types::boundary_id, const Function<dim> *> fixed;
    const Functions::ZeroFunction<dim>                  zero(n_components);
    for (const auto id : fixed_boundaries)
      fixed[id] = &zero;
    VectorTools::interpolate_boundary_values(dof_handler, fixed, constraints,
                                             fe_collection.component_mask(displacement));
    if (add_constraints)
      add_constraints(constraints);
    constraints.close();
  }

  void
  FESpace::reinit(SparseMatrix &matrix) const
  {
    reinit(matrix, [this](DynamicSparsityPattern &dsp) {
      DoFTools::make_sparsity_pattern(dof_handler, dsp, constraints, false);
      if (add_couplings)
        add_couplings(dsp);
    });
  }

  void
  FESpace::reinit(SparseMatrix                                         &matrix,
                  const std::function<void(DynamicSparsityPattern &)> &add_entries) const
  {
    // Rows this rank writes: its relevant DOFs and the DOFs they are
    // constrained to (a tied joint DOF may point to a cell this rank does not
    // see as ghost).
    IndexSet rows = locally_relevant;
    for (const auto &line : constraints.get_lines())
      for (const auto &entry : line.entries)
        rows.add_index(entry.first);
    rows.compress();
    DynamicSparsityPattern dsp(rows);
    add_entries(dsp);
    SparsityTools::distribute_sparsity_pattern(dsp, locally_owned, comm, rows);
    matrix.reinit(locally_owned, locally_owned, dsp, comm);
  }

  void
  FESpace::reinit(Vector &vector) const
  {
    vector.reinit(locally_owned, comm);
  }

  void
  FESpace::reinit_ghosted(Vector &vector) const
  {
    vector.reinit(locally_owned, locally_relevant, comm);
  }

  AffineConstraints<double>
  constraints_without(const FESpace &space, const std::vector<bool> &excluded)
  {
    AffineConstraints<double> others(space.locally_relevant);
    for (const auto &line : space.constraints.get_lines())
      if (!excluded[line.index])
        {
          others.add_line(line.index);
          others.add_entries(line.index, line.entries);
          others.set_inhomogeneity(line.index, line.inhomogeneity);
        }
    others.close();
    return others;
  }

  void
  visit_owned_cell_dofs(
    const FESpace &space,
    const std::function<bool(const DoFHandler<dim>::active_cell_iterator &, unsigned int,
                             types::global_dof_index)> &visit)
  {
    std::vector<types::global_dof_index> dofs;
    for (const auto &cell : space.dof_handler.active_cell_iterators())
      if (cell->is_locally_owned())
        {
          dofs.resize(cell->get_fe().n_dofs_per_cell());
          cell->get_dof_indices(dofs);
          for (unsigned int i = 0; i < dofs.size(); ++i)
            if (visit(cell, i, dofs[i]))
              return;
        }
  }
} // namespace archdam::fe
