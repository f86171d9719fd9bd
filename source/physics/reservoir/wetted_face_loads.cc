#include <archdam/geometry/ids.h>
#include <archdam/physics/reservoir/wetted_face_loads.h>

#include <deal.II/fe/fe_values.h>
#include <deal.II/fe/mapping_q1.h>
#include <deal.II/lac/full_matrix.h>

#include <map>

namespace archdam::physics::reservoir
{
  using namespace dealii;

  namespace
  {
    bool
    is_wetted(const DoFHandler<dim>::active_cell_iterator &cell, const unsigned int f)
    {
      return cell->active_fe_index() == fe::FESpace::solid_index &&
             cell->face(f)->at_boundary() &&
             cell->face(f)->boundary_id() == ids::solid_interface;
    }
  } // namespace

  void
  add_hydrostatic_load(const fe::FESpace &space, const double density, const double g,
                       const double level, Vector &load)
  {
    const auto        &fe = space.fe_collection[fe::FESpace::solid_index];
    FEFaceValues<dim>  fv(fe, space.face_q_collection[fe::FESpace::solid_index],
                         update_values | update_quadrature_points | update_normal_vectors |
                           update_JxW_values);
    dealii::Vector<double>               cell_f(fe.n_dofs_per_cell());
    std::vector<types::global_dof_index> dofs(fe.n_dofs_per_cell());
    for (const auto &cell : space.dof_handler.active_cell_iterators())
      if (cell->is_locally_owned())
        for (const unsigned int f : cell->face_indices())
          if (is_wetted(cell, f))
            {
              fv.reinit(cell, f);
              cell_f = 0.;
              for (const unsigned int q : fv.quadrature_point_indices())
                {
                  const double depth = level - fv.quadrature_point(q)[dim - 1];
                  if (depth <= 0)
                    continue;
                  const Tensor<1, dim> traction = -density * g * depth * fv.normal_vector(q);
                  for (unsigned int i = 0; i < cell_f.size(); ++i)
                    cell_f(i) += traction * fv[space.displacement].value(i, q) * fv.JxW(q);
                }
              cell->get_dof_indices(dofs);
              space.constraints.distribute_local_to_global(cell_f, dofs, load);
            }
    load.compress(VectorOperation::add);
  }

  void
  add_westergaard_mass(const fe::FESpace &space, const double density, const double level,
                       SparseMatrix &mass)
  {
    struct Node
    {
      std::array<types::global_dof_index, dim> dofs;
      double                                   z;
      Tensor<1, dim>                           b; // int N_i n dA over its wetted faces
    };
    // Every rank sees the whole mesh: gather the wetted nodes everywhere (a
    // node's faces may belong to several ranks), add each node on the rank
    // owning its x DOF.
    std::map<types::global_dof_index, Node> nodes;

    const auto        &fe = space.fe_collection[fe::FESpace::solid_index];
    const auto        &mapping = StaticMappingQ1<dim>::mapping;
    FEFaceValues<dim>  fv(mapping, fe, space.face_q_collection[fe::FESpace::solid_index],
                          update_values | update_normal_vectors | update_JxW_values);
    const auto        &unit_points = fe.get_unit_support_points();
    const unsigned int n = fe.n_dofs_per_cell();
    std::vector<types::global_dof_index> dofs(n);
    for (const auto &cell : space.dof_handler.active_cell_iterators())
      for (const unsigned int f : cell->face_indices())
        if (is_wetted(cell, f))
          {
            fv.reinit(cell, f);
            cell->get_dof_indices(dofs);
            // the DOFs of each node, by the node's index within the scalar FE
            std::map<unsigned int, std::array<types::global_dof_index, dim>> node_dofs;
            std::map<unsigned int, unsigned int>                            x_dof;
            for (unsigned int i = 0; i < n; ++i)
              if (fe.has_support_on_face(i, f))
                {
                  const auto [component, index] = fe.system_to_component_index(i);
                  node_dofs[index][component]   = dofs[i];
                  if (component == 0)
                    x_dof[index] = i;
                }
            for (const auto &[index, i] : x_dof)
              {
                Node &node = nodes[node_dofs[index][0]];
                node.dofs  = node_dofs[index];
                node.z     = mapping.transform_unit_to_real_cell(cell, unit_points[i])[dim - 1];
                for (const unsigned int q : fv.quadrature_point_indices())
                  node.b += fv.shape_value_component(i, q, 0) * fv.normal_vector(q) * fv.JxW(q);
              }
          }

    double bottom = level;
    for (const auto &[x, node] : nodes)
      bottom = std::min(bottom, node.z);
    const double depth = level - bottom;

    FullMatrix<double>                   block(dim, dim);
    std::vector<types::global_dof_index> block_dofs(dim);
    for (const auto &[x, node] : nodes)
      if (space.locally_owned.is_element(x) && node.z < level)
        {
          const double c = 7. / 8. * density * std::sqrt(depth * (level - node.z)) /
                           node.b.norm();
          for (unsigned int d = 0; d < dim; ++d)
            {
              block_dofs[d] = node.dofs[d];
              for (unsigned int e = 0; e < dim; ++e)
                block(d, e) = c * node.b[d] * node.b[e];
            }
          space.constraints.distribute_local_to_global(block, block_dofs, mass);
        }
    mass.compress(VectorOperation::add);
  }
} // namespace archdam::physics::reservoir
