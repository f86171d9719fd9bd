#include <archdam/base/input_error.h>
#include <archdam/base/point_text.h>
#include <archdam/geometry/ids.h>
#include <archdam/geometry/splitter.h>
#include <archdam/joints/joint_faces.h>

#include <deal.II/fe/fe.h>
#include <deal.II/grid/grid_tools.h>

#include <array>
#include <cmath>
#include <map>
#include <set>
#include <sstream>

namespace archdam::joints
{
  using namespace dealii;

  namespace
  {
    /// Points closer than this fraction of the mesh extent coincide.
    constexpr double relative_tolerance = 1e-8;

    using Key = std::array<long long, dim>;

    Key
    key_of(const Point<dim> &p, const double h)
    {
      Key k;
      for (unsigned int d = 0; d < dim; ++d)
        k[d] = std::llround(p[d] / h);
      return k;
    }

  } // namespace

  std::vector<JointFacePair>
  pair_joint_faces(const Triangulation<dim> &tria)
  {
    const double extent = GridTools::diameter(tria);
    const double tol    = relative_tolerance * extent;
    const double h      = 1e3 * tol; // bucket size for the face centres

    using CellFace = std::pair<Triangulation<dim>::cell_iterator, unsigned int>;
    std::map<Key, std::vector<CellFace>> side_1;
    std::vector<CellFace>                side_2;
    for (const auto &cell : tria.active_cell_iterators())
      for (const unsigned int f : cell->face_indices())
        if (cell->face(f)->at_boundary() &&
            geometry::is_joint_face(cell->face(f)->boundary_id()))
          {
            if ((cell->face(f)->boundary_id() - 100) % 2 == 0)
              side_1[key_of(cell->face(f)->center(), h)].emplace_back(cell, f);
            else
              side_2.emplace_back(cell, f);
          }

    const auto coincide = [&](const CellFace &a, const CellFace &b) {
      for (const unsigned int v : a.first->face(a.second)->vertex_indices())
        {
          bool found = false;
          for (const unsigned int w : b.first->face(b.second)->vertex_indices())
            found = found || a.first->face(a.second)->vertex(v).distance(
                               b.first->face(b.second)->vertex(w)) < tol;
          if (!found)
            return false;
        }
      return true;
    };

    std::vector<JointFacePair> pairs;
    std::set<std::pair<unsigned int, unsigned int>> used; // side-1 cells and faces
    for (const auto &two : side_2)
      {
        const auto   face2 = two.first->face(two.second);
        const auto   joint = geometry::joint_of(face2->boundary_id());
        const Key    k     = key_of(face2->center(), h);
        bool         found = false;
        for (int dx = -1; dx <= 1 && !found; ++dx)
          for (int dy = -1; dy <= 1 && !found; ++dy)
            for (int dz = -1; dz <= 1 && !found; ++dz)
              {
                const auto it = side_1.find({{k[0] + dx, k[1] + dy, k[2] + dz}});
                if (it == side_1.end())
                  continue;
                for (const auto &one : it->second)
                  if (coincide(one, two))
                    {
                      const auto joint_1 =
                        geometry::joint_of(one.first->face(one.second)->boundary_id());
                      if (joint_1 != joint)
                        throw InputError("Mesh: a face of joint " + std::to_string(joint) +
                                         " at " + point_text(face2->center()) +
                                         " lies on a face of joint " +
                                         std::to_string(joint_1) + ".");
                      pairs.push_back({joint, one.first, two.first, one.second, two.second});
                      used.emplace(one.first->active_cell_index(), one.second);
                      found = true;
                      break;
                    }
              }
        if (!found)
          throw InputError("Mesh: the face of joint " + std::to_string(joint) +
                           " (block " + std::to_string(joint + 1) + "'s side) at " +
                           point_text(face2->center()) + " has no partner on block " +
                           std::to_string(joint) + ".");
      }
    for (const auto &[key, faces] : side_1)
      for (const auto &one : faces)
        if (used.count({one.first->active_cell_index(), one.second}) == 0)
          {
            const auto joint = geometry::joint_of(one.first->face(one.second)->boundary_id());
            throw InputError("Mesh: the face of joint " + std::to_string(joint) + " (block " +
                             std::to_string(joint) + "'s side) at " +
                             point_text(one.first->face(one.second)->center()) +
                             " has no partner on block " + std::to_string(joint + 1) + ".");
          }
    return pairs;
  }

  std::vector<JointNodeCount>
  count_joint_nodes(const std::vector<JointFacePair> &pairs, const unsigned int n_joints,
                    const unsigned int degree)
  {
    std::vector<JointNodeCount>                                  counts(n_joints);
    std::vector<std::set<std::pair<unsigned int, unsigned int>>> node_pairs(n_joints);
    // An edge of side 1 that is not also an edge of side 2 (one of its ends
    // duplicated) carries degree - 1 node pairs inside it.
    std::vector<std::set<unsigned int>> edges(n_joints);
    // Nodes on the model's truncation (boundary ids 1 and 2: fixed, or
    // prescribed by the transmitting boundary) move with both sides alike
    // and are no pairs of the analysis: a joint standing on a fixed base.
    std::set<unsigned int> truncation_vertices, truncation_lines;
    if (!pairs.empty())
      for (const auto &cell : pairs.front().cell_1->get_triangulation().active_cell_iterators())
        for (const unsigned int f : cell->face_indices())
          if (cell->at_boundary(f) && (cell->face(f)->boundary_id() == ids::foundation_bottom ||
                                       cell->face(f)->boundary_id() == ids::foundation_sides))
            {
              for (const unsigned int v : cell->face(f)->vertex_indices())
                truncation_vertices.insert(cell->face(f)->vertex_index(v));
              for (const unsigned int l : cell->face(f)->line_indices())
                truncation_lines.insert(cell->face(f)->line_index(l));
            }
    for (const auto &p : pairs)
      {
        ++counts[p.joint].faces;
        const auto f1 = p.cell_1->face(p.face_1), f2 = p.cell_2->face(p.face_2);
        for (const unsigned int v : f1->vertex_indices())
          for (const unsigned int w : f2->vertex_indices())
            if (f1->vertex_index(v) != f2->vertex_index(w) &&
                f1->vertex(v).distance(f2->vertex(w)) < 1e-12 * (1 + f1->vertex(v).norm()) &&
                truncation_vertices.count(f1->vertex_index(v)) == 0)
              node_pairs[p.joint].emplace(f1->vertex_index(v), f2->vertex_index(w));
        for (const unsigned int l : f1->line_indices())
          {
            bool shared = truncation_lines.count(f1->line_index(l)) > 0;
            for (const unsigned int m : f2->line_indices())
              shared = shared || f1->line_index(l) == f2->line_index(m);
            if (!shared)
              edges[p.joint].insert(f1->line_index(l));
          }
      }
    const unsigned int inner = degree - 1;
    for (unsigned int j = 0; j < n_joints; ++j)
      counts[j].node_pairs = node_pairs[j].size() + inner * edges[j].size() +
                             inner * inner * counts[j].faces;
    return counts;
  }

  namespace
  {
    /// Face DOFs of a cell with the positions of their support points.
    std::vector<std::pair<types::global_dof_index, Point<dim>>>
    face_dofs(const DoFHandler<dim> &dof_handler, const Triangulation<dim>::cell_iterator &c,
              const unsigned int f, std::vector<unsigned int> &component)
    {
      const typename DoFHandler<dim>::active_cell_iterator cell(&dof_handler.get_triangulation(),
                                                                c->level(), c->index(),
                                                                &dof_handler);
      const auto &fe   = cell->get_fe();
      const auto  face = cell->face(f);
      std::vector<types::global_dof_index> dofs(fe.n_dofs_per_face(f));
      face->get_dof_indices(dofs, cell->active_fe_index());
      // Unit face support points are in the face's own orientation, as are
      // the face's DOFs and vertices: map them bilinearly (the faces are
      // straight-sided, MappingQ1).
      const auto &unit = fe.get_unit_face_support_points(f);
      std::vector<std::pair<types::global_dof_index, Point<dim>>> result;
      component.clear();
      for (unsigned int i = 0; i < dofs.size(); ++i)
        {
          const double x = unit[i][0], y = unit[i][1];
          const Point<dim> p = (1 - x) * (1 - y) * face->vertex(0) + x * (1 - y) * face->vertex(1) +
                               (1 - x) * y * face->vertex(2) + x * y * face->vertex(3);
          result.emplace_back(dofs[i], p);
          component.push_back(fe.face_system_to_component_index(i, f).first);
        }
      return result;
    }
  } // namespace

  void
  tie_joint_dofs(const DoFHandler<dim>            &dof_handler,
                 const std::vector<JointFacePair> &pairs,
                 const IndexSet                   &locally_relevant,
                 AffineConstraints<double>        &constraints)
  {
    const double tol = relative_tolerance * GridTools::diameter(dof_handler.get_triangulation());
    std::vector<unsigned int> comp_1, comp_2;
    for (const auto &p : pairs)
      {
        const auto one = face_dofs(dof_handler, p.cell_1, p.face_1, comp_1);
        const auto two = face_dofs(dof_handler, p.cell_2, p.face_2, comp_2);
        for (unsigned int j = 0; j < two.size(); ++j)
          {
            const auto d2 = two[j].first;
            if (!locally_relevant.is_element(d2) || constraints.is_constrained(d2))
              continue;
            bool tied = false;
            for (unsigned int i = 0; i < one.size() && !tied; ++i)
              if (comp_1[i] == comp_2[j] && one[i].second.distance(two[j].second) < tol)
                {
                  if (one[i].first != d2)
                    {
                      constraints.add_line(d2);
                      constraints.add_entry(d2, one[i].first, 1.);
                    }
                  tied = true;
                }
            AssertThrow(tied, ExcMessage("Joint " + std::to_string(p.joint) +
                                         ": a DOF of side 2 has no coincident DOF on side 1."));
          }
      }
  }
} // namespace archdam::joints
