#include <archdam/joints/node_pairs.h>

#include <algorithm>

#include <deal.II/base/quadrature_lib.h>
#include <deal.II/fe/fe_values.h>
#include <deal.II/fe/mapping_q1.h>
#include <deal.II/grid/grid_tools.h>

#include <cmath>
#include <map>

namespace archdam::joints
{
  using namespace dealii;

  namespace
  {
    /// Local frame from the normal: eta horizontal (e_z x xi), or e_x x xi
    /// for a horizontal joint; zeta = xi x eta.
    std::array<Tensor<1, dim>, dim>
    frame_of(const Tensor<1, dim> &xi)
    {
      const Tensor<1, dim> helper =
        std::abs(xi[2]) < 0.9 ? Point<dim>::unit_vector(2) : Point<dim>::unit_vector(0);
      Tensor<1, dim> eta = cross_product_3d(helper, xi);
      eta /= eta.norm();
      return {{xi, eta, cross_product_3d(xi, eta)}};
    }
  } // namespace

  NodePairs::NodePairs(const fe::FESpace &space, const std::vector<JointFacePair> &faces)
    : comm(space.comm)
    , owned(space.locally_owned)
  {
    const auto  &dof_handler = space.dof_handler;
    const auto  &fe          = space.fe_collection[fe::FESpace::solid_index];
    const double tol = 1e-8 * GridTools::diameter(dof_handler.get_triangulation());
    MappingQ1<dim>     mapping;
    FEFaceValues<dim>  face_values(mapping, fe, QGauss<dim - 1>(space.degree + 1),
                                  update_values | update_normal_vectors | update_JxW_values);

    using Key = std::array<long long, dim>;
    std::map<Key, std::vector<unsigned int>> buckets;
    const auto key = [&](const Point<dim> &p) {
      Key k;
      for (unsigned int d = 0; d < dim; ++d)
        k[d] = std::llround(p[d] / (1e3 * tol));
      return k;
    };
    const auto find = [&](const Point<dim> &p) -> int {
      const Key k = key(p);
      for (int dx = -1; dx <= 1; ++dx)
        for (int dy = -1; dy <= 1; ++dy)
          for (int dz = -1; dz <= 1; ++dz)
            {
              const auto it = buckets.find({{k[0] + dx, k[1] + dy, k[2] + dz}});
              if (it != buckets.end())
                for (const unsigned int i : it->second)
                  if (pairs[i].position.distance(p) < tol)
                    return i;
            }
      return -1;
    };

    std::vector<Tensor<1, dim>>          normal_sums;
    std::vector<types::global_dof_index> dofs(fe.n_dofs_per_cell());
    for (const unsigned int side : {1u, 2u})
      for (const auto &fp : faces)
        {
          const auto &tria_cell = side == 1 ? fp.cell_1 : fp.cell_2;
          const unsigned int f  = side == 1 ? fp.face_1 : fp.face_2;
          const typename DoFHandler<dim>::active_cell_iterator cell(
            &dof_handler.get_triangulation(), tria_cell->level(), tria_cell->index(),
            &dof_handler);
          cell->get_dof_indices(dofs);
          face_values.reinit(cell, f);
          for (unsigned int i = 0; i < fe.n_dofs_per_cell(); ++i)
            {
              const unsigned int c = fe.system_to_component_index(i).first;
              if (c >= dim || !fe.has_support_on_face(i, f))
                continue;
              const Point<dim> x =
                mapping.transform_unit_to_real_cell(cell, fe.get_unit_support_points()[i]);
              int p = find(x);
              if (p < 0)
                {
                  AssertThrow(side == 1, ExcMessage("Joint " + std::to_string(fp.joint) +
                                                    ": a support point of side 2 has no "
                                                    "partner on side 1."));
                  p = pairs.size();
                  NodePair pair;
                  pair.joint    = fp.joint;
                  pair.position = x;
                  pair.area     = 0.;
                  pair.dofs_1.fill(numbers::invalid_dof_index);
                  pair.dofs_2.fill(numbers::invalid_dof_index);
                  pairs.push_back(pair);
                  normal_sums.emplace_back();
                  buckets[key(x)].push_back(p);
                }
              if (side == 2)
                {
                  pairs[p].dofs_2[c] = dofs[i];
                  continue;
                }
              pairs[p].dofs_1[c] = dofs[i];
              if (c != 0)
                continue;
              // Tributary area and mean normal: int N_i dA, int N_i n dA.
              for (unsigned int q = 0; q < face_values.n_quadrature_points; ++q)
                {
                  const double w = face_values.shape_value_component(i, q, 0) *
                                   face_values.JxW(q);
                  pairs[p].area += w;
                  normal_sums[p] += w * face_values.normal_vector(q);
                }
            }
        }

    // Which DOFs are free: the owner knows, everybody learns.
    std::vector<int> free(pairs.size() * 2 * dim, 0);
    for (unsigned int p = 0; p < pairs.size(); ++p)
      for (unsigned int c = 0; c < dim; ++c)
        for (const unsigned int s : {0u, 1u})
          {
            const auto d = s == 0 ? pairs[p].dofs_1[c] : pairs[p].dofs_2[c];
            if (owned.is_element(d))
              free[(2 * p + s) * dim + c] = space.constraints.is_constrained(d) ? 0 : 1;
          }
    Utilities::MPI::sum(free, comm, free);

    std::vector<NodePair> kept;
    for (unsigned int p = 0; p < pairs.size(); ++p)
      {
        NodePair pair = pairs[p];
        AssertThrow(pair.dofs_2[0] != numbers::invalid_dof_index,
                    ExcMessage("Joint " + std::to_string(pair.joint) +
                               ": a support point of side 1 has no partner on side 2."));
        bool any_free = false, shared = pair.dofs_1 == pair.dofs_2;
        for (unsigned int c = 0; c < dim; ++c)
          {
            pair.free_1[c] = free[(2 * p) * dim + c] == 1;
            pair.free_2[c] = free[(2 * p + 1) * dim + c] == 1;
            any_free       = any_free || pair.free_1[c] || pair.free_2[c];
          }
        if (shared || !any_free)
          continue;
        pair.frame = frame_of(normal_sums[p] / normal_sums[p].norm());
        joints     = std::max(joints, pair.joint + 1);
        kept.push_back(pair);
      }
    pairs.swap(kept);
  }

  void
  NodePairs::relative_displacement(const Vector &u, std::vector<double> &w) const
  {
    w.assign(dim * pairs.size(), 0.);
    for (unsigned int p = 0; p < pairs.size(); ++p)
      for (unsigned int c = 0; c < dim; ++c)
        {
          double du = 0.;
          if (pairs[p].free_2[c] && owned.is_element(pairs[p].dofs_2[c]))
            du += u(pairs[p].dofs_2[c]);
          if (pairs[p].free_1[c] && owned.is_element(pairs[p].dofs_1[c]))
            du -= u(pairs[p].dofs_1[c]);
          for (unsigned int k = 0; k < dim; ++k)
            w[dim * p + k] += pairs[p].frame[k][c] * du;
        }
    Utilities::MPI::sum(w, comm, w);
  }

  void
  NodePairs::add_transpose(const std::vector<double> &f, const double factor,
                           Vector &rhs) const
  {
    std::vector<types::global_dof_index> indices;
    std::vector<double>                  values;
    for (unsigned int p = 0; p < pairs.size(); ++p)
      for (unsigned int c = 0; c < dim; ++c)
        {
          double g = 0.;
          for (unsigned int k = 0; k < dim; ++k)
            g += pairs[p].frame[k][c] * f[dim * p + k];
          if (pairs[p].free_2[c] && owned.is_element(pairs[p].dofs_2[c]))
            {
              indices.push_back(pairs[p].dofs_2[c]);
              values.push_back(factor * g);
            }
          if (pairs[p].free_1[c] && owned.is_element(pairs[p].dofs_1[c]))
            {
              indices.push_back(pairs[p].dofs_1[c]);
              values.push_back(-factor * g);
            }
        }
    rhs.add(indices, values);
    rhs.compress(VectorOperation::add);
  }

  unsigned int
  NodePairs::nearest(const Point<dim> &x) const
  {
    unsigned int best = 0;
    for (unsigned int p = 1; p < pairs.size(); ++p)
      if (pairs[p].position.distance(x) < pairs[best].position.distance(x))
        best = p;
    return best;
  }
  std::vector<types::global_dof_index>
  NodePairs::interface() const
  {
    std::vector<types::global_dof_index> dofs;
    for (const auto &pair : pairs)
      for (unsigned int k = 0; k < dim; ++k)
        pair.for_each_B_entry(k, [&](const types::global_dof_index d, double) {
          dofs.push_back(d);
        });
    std::sort(dofs.begin(), dofs.end());
    dofs.erase(std::unique(dofs.begin(), dofs.end()), dofs.end());
    return dofs;
  }
} // namespace archdam::joints
