#include <archdam/geometry/ids.h>
#include <archdam/physics/foundation/outer_boundary.h>

#include <deal.II/fe/fe_values.h>
#include <deal.II/fe/mapping_q1.h>
#include <deal.II/hp/fe_values.h>

#include <map>

namespace archdam::physics::foundation
{
  using namespace dealii;

  std::vector<BoundaryDof>
  outer_boundary_dofs(const fe::FESpace &space)
  {
    hp::FEFaceValues<dim> hp_face(space.fe_collection, space.face_q_collection,
                                  update_values | update_normal_vectors | update_JxW_values |
                                    update_quadrature_points);
    const auto &fe = space.fe_collection[fe::FESpace::solid_index];
    const auto  support = fe.get_unit_support_points();
    const MappingQ1<dim> mapping;

    std::map<types::global_dof_index, BoundaryDof> found;
    std::vector<types::global_dof_index>           dofs(fe.n_dofs_per_cell());
    // Every cell (the triangulation is shared): the list is replicated.
    for (const auto &cell : space.dof_handler.active_cell_iterators())
      if (!cell->is_artificial() && cell->active_fe_index() == fe::FESpace::solid_index)
        for (const unsigned int f : cell->face_indices())
          if (cell->face(f)->at_boundary() &&
              (cell->face(f)->boundary_id() == ids::foundation_bottom ||
               cell->face(f)->boundary_id() == ids::foundation_sides))
            {
              hp_face.reinit(cell, f);
              const auto &fv = hp_face.get_present_fe_values();
              cell->get_dof_indices(dofs);
              for (unsigned int i = 0; i < fe.n_dofs_per_cell(); ++i)
                {
                  const unsigned int c = fe.system_to_component_index(i).first;
                  if (c >= dim || !fe.has_support_on_face(i, f))
                    continue;
                  auto &b = found[dofs[i]];
                  if (b.area == 0. && b.area_normal.norm() == 0.)
                    {
                      b.index     = dofs[i];
                      b.component = c;
                      b.position  = mapping.transform_unit_to_real_cell(cell, support[i]);
                    }
                  for (const unsigned int q : fv.quadrature_point_indices())
                    {
                      b.area += fv.shape_value(i, q) * fv.JxW(q);
                      b.area_normal += fv.shape_value(i, q) * fv.normal_vector(q) * fv.JxW(q);
                    }
                }
            }
    std::vector<BoundaryDof> result;
    result.reserve(found.size());
    for (auto &[index, b] : found)
      {
        b.normal = b.area_normal / b.area_normal.norm();
        result.push_back(b);
      }
    return result;
  }
} // namespace archdam::physics::foundation
