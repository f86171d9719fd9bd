#include <archdam/geometry/ids.h>
#include <archdam/physics/solid/solid_operators.h>

#include <deal.II/fe/fe_values.h>
#include <deal.II/hp/fe_values.h>
#include <deal.II/lac/dynamic_sparsity_pattern.h>
#include <deal.II/lac/full_matrix.h>
#include <deal.II/lac/sparsity_tools.h>

namespace archdam::physics::solid
{
  using namespace dealii;

  namespace
  {
    bool
    has_inertia(const types::material_id id, const InertiaOf inertia)
    {
      return ids::is_dam(id) || (inertia == InertiaOf::dam_and_rock && id == ids::rock);
    }
  } // namespace

  namespace
  {
    /// Add the cell matrices of M and K of the solid cells for which
    /// @p take(cell, dofs) holds, condensed with @p constraints, to the matrices,
    /// and with @p damping those of D = alpha_c M_c + beta_c K_c, each cell
    /// with its material's coefficients, to @p damping_matrix.
    template <typename CellFilter>
    void
    add_cell_matrices(const fe::FESpace               &space,
                      const MaterialParameters        &materials,
                      const InertiaOf                  inertia,
                      const AffineConstraints<double> &constraints,
                      const CellFilter                &take,
                      SparseMatrix                    &mass,
                      SparseMatrix                    &stiffness,
                      const DampingParameters         *damping        = nullptr,
                      SparseMatrix                    *damping_matrix = nullptr)
    {
      hp::FEValues<dim> hp_fe_values(space.fe_collection, space.q_collection,
                                     update_values | update_gradients | update_JxW_values);
      FullMatrix<double>                   cell_m, cell_k, cell_d;
      std::vector<types::global_dof_index> dofs;
      std::vector<SymmetricTensor<2, dim>> eps;
      std::vector<double>                  div;
      std::vector<Tensor<1, dim>>          phi;

      for (const auto &cell : space.dof_handler.active_cell_iterators())
        if (cell->is_locally_owned() && cell->active_fe_index() == fe::FESpace::solid_index)
          {
            dofs.resize(cell->get_fe().n_dofs_per_cell());
            cell->get_dof_indices(dofs);
            if (!take(cell, dofs))
              continue;
            hp_fe_values.reinit(cell);
            const FEValues<dim>   &fv  = hp_fe_values.get_present_fe_values();
            const unsigned int     n   = fv.dofs_per_cell;
            const ElasticMaterial &mat = materials.of(cell->material_id());
            const double rho = has_inertia(cell->material_id(), inertia) ? mat.density : 0.;
            const double lambda = mat.lambda(), mu = mat.mu();

            cell_m.reinit(n, n);
            cell_k.reinit(n, n);
            eps.resize(n);
            div.resize(n);
            phi.resize(n);
            for (const unsigned int q : fv.quadrature_point_indices())
              {
                for (unsigned int i = 0; i < n; ++i)
                  {
                    eps[i] = fv[space.displacement].symmetric_gradient(i, q);
                    div[i] = fv[space.displacement].divergence(i, q);
                    phi[i] = fv[space.displacement].value(i, q);
                  }
                const double dx = fv.JxW(q);
                for (unsigned int i = 0; i < n; ++i)
                  for (unsigned int j = 0; j <= i; ++j)
                    {
                      cell_m(i, j) += rho * phi[i] * phi[j] * dx;
                      cell_k(i, j) += (lambda * div[i] * div[j] + 2 * mu * eps[i] * eps[j]) * dx;
                    }
              }
            for (unsigned int i = 0; i < n; ++i)
              for (unsigned int j = i + 1; j < n; ++j)
                {
                  cell_m(i, j) = cell_m(j, i);
                  cell_k(i, j) = cell_k(j, i);
                }
            constraints.distribute_local_to_global(cell_m, dofs, mass);
            constraints.distribute_local_to_global(cell_k, dofs, stiffness);
            if (damping)
              {
                const auto [alpha, beta] = damping->of(cell->material_id());
                cell_d                   = cell_m;
                cell_d *= alpha;
                cell_d.add(beta, cell_k);
                constraints.distribute_local_to_global(cell_d, dofs, *damping_matrix);
              }
          }
      mass.compress(VectorOperation::add);
      stiffness.compress(VectorOperation::add);
      if (damping)
        damping_matrix->compress(VectorOperation::add);
    }

    /// @p A on the pattern of the solid cells for which @p take(cell, dofs)
    /// holds, condensed with @p constraints.
    template <typename CellFilter>
    void
    reinit_on_cells(const fe::FESpace               &space,
                    const AffineConstraints<double> &constraints,
                    const CellFilter                &take,
                    SparseMatrix                    &A)
    {
      IndexSet rows = space.locally_relevant;
      for (const auto &line : constraints.get_lines())
        for (const auto &entry : line.entries)
          rows.add_index(entry.first);
      rows.compress();
      DynamicSparsityPattern               dsp(rows);
      std::vector<types::global_dof_index> dofs;
      for (const auto &cell : space.dof_handler.active_cell_iterators())
        if (cell->is_locally_owned() && cell->active_fe_index() == fe::FESpace::solid_index)
          {
            dofs.resize(cell->get_fe().n_dofs_per_cell());
            cell->get_dof_indices(dofs);
            if (take(cell, dofs))
              constraints.add_entries_local_to_global(dofs, dsp, false);
          }
      SparsityTools::distribute_sparsity_pattern(dsp, space.locally_owned, space.comm, rows);
      A.reinit(space.locally_owned, space.locally_owned, dsp, space.comm);
    }
  } // namespace

  void
  assemble_dam_damping(const fe::FESpace        &space,
                       const MaterialParameters &materials,
                       const DampingParameters  &damping,
                       SparseMatrix             &dam_damping)
  {
    const auto dam = [](const auto &cell, const auto &) { return ids::is_dam(cell->material_id()); };
    reinit_on_cells(space, space.constraints, dam, dam_damping);
    // M and K of the dam alone are needed only for the cells' D.
    SparseMatrix mass, stiffness;
    mass.reinit(dam_damping);
    stiffness.reinit(dam_damping);
    add_cell_matrices(space, materials, InertiaOf::dam, space.constraints, dam, mass, stiffness,
                      &damping, &dam_damping);
  }

  void
  assemble_mass_and_stiffness(const fe::FESpace        &space,
                              const MaterialParameters &materials,
                              const InertiaOf           inertia,
                              SparseMatrix             &mass,
                              SparseMatrix             &stiffness,
                              const DampingParameters  *damping,
                              SparseMatrix             *damping_matrix)
  {
    space.reinit(stiffness);
    mass.reinit(stiffness); // the same pattern: Kbar = c1 M + c2 K relies on it
    if (damping)
      damping_matrix->reinit(stiffness);
    add_cell_matrices(space, materials, inertia, space.constraints,
                      [](const auto &, const auto &) { return true; },
                      mass, stiffness, damping, damping_matrix);
  }

  void
  assemble_mass_and_stiffness_columns(const fe::FESpace                          &space,
                                      const MaterialParameters                   &materials,
                                      const InertiaOf                             inertia,
                                      const std::vector<types::global_dof_index> &columns,
                                      SparseMatrix                               &mass,
                                      SparseMatrix                               &stiffness,
                                      const DampingParameters                    *damping,
                                      SparseMatrix                               *damping_columns)
  {
    std::vector<bool> is_column(space.dof_handler.n_dofs(), false);
    for (const auto i : columns)
      is_column[i] = true;
    const auto touches = [&](const auto &, const std::vector<types::global_dof_index> &dofs) {
      for (const auto i : dofs)
        if (is_column[i])
          return true;
      return false;
    };

    // The model's constraints without the lines of the columns themselves.
    const AffineConstraints<double> others = fe::constraints_without(space, is_column);
    reinit_on_cells(space, others, touches, stiffness);
    mass.reinit(stiffness);
    if (damping)
      damping_columns->reinit(stiffness);
    add_cell_matrices(space, materials, inertia, others, touches, mass, stiffness, damping,
                      damping_columns);
  }

  void
  assemble_inertia_load(const fe::FESpace        &space,
                        const MaterialParameters &materials,
                        const InertiaOf           inertia,
                        const Tensor<1, dim>     &b,
                        Vector                   &load)
  {
    space.reinit(load);
    hp::FEValues<dim> hp_fe_values(space.fe_collection, space.q_collection,
                                   update_values | update_JxW_values);
    dealii::Vector<double>               cell_f;
    std::vector<types::global_dof_index> dofs;

    for (const auto &cell : space.dof_handler.active_cell_iterators())
      if (cell->is_locally_owned() && cell->active_fe_index() == fe::FESpace::solid_index &&
          has_inertia(cell->material_id(), inertia))
        {
          hp_fe_values.reinit(cell);
          const FEValues<dim> &fv  = hp_fe_values.get_present_fe_values();
          const double         rho = materials.of(cell->material_id()).density;
          cell_f.reinit(fv.dofs_per_cell);
          for (const unsigned int q : fv.quadrature_point_indices())
            for (unsigned int i = 0; i < fv.dofs_per_cell; ++i)
              cell_f(i) += rho * (b * fv[space.displacement].value(i, q)) * fv.JxW(q);
          dofs.resize(fv.dofs_per_cell);
          cell->get_dof_indices(dofs);
          space.constraints.distribute_local_to_global(cell_f, dofs, load);
        }
    load.compress(VectorOperation::add);
  }
} // namespace archdam::physics::solid
