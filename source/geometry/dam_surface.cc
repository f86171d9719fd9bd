#include <archdam/geometry/dam_surface.h>
#include <archdam/geometry/ids.h>
#include <archdam/geometry/splitter.h>

#include <algorithm>
#include <cmath>
#include <limits>

namespace archdam::geometry
{
  std::string
  name(const SurfacePart part)
  {
    switch (part)
      {
        case SurfacePart::upstream:
          return "upstream";
        case SurfacePart::downstream:
          return "downstream";
        case SurfacePart::crest:
          return "crest";
        default:
          return "side";
      }
  }

  SurfacePart
  surface_part(const dealii::Tensor<1, dim> &n)
  {
    if (n[2] > std::abs(n[0]) && n[2] > std::abs(n[1]))
      return SurfacePart::crest;
    if (n[0] <= -0.1)
      return SurfacePart::upstream;
    if (n[0] >= 0.1)
      return SurfacePart::downstream;
    return SurfacePart::side;
  }

  bool
  on_dam_surface(const dealii::types::boundary_id id)
  {
    return id == ids::free_surface_solid || id == ids::solid_interface;
  }

  double
  distance(const dealii::Point<dim> &x, const Segment &s)
  {
    const dealii::Tensor<1, dim> d = s[1] - s[0];
    const double                 t = std::clamp((x - s[0]) * d / (d * d), 0., 1.);
    return (x - (s[0] + t * d)).norm();
  }

  SurfaceEdges::SurfaceEdges(const dealii::Triangulation<dim> &tria)
  {
    for (const auto &cell : tria.active_cell_iterators())
      if (ids::is_dam(cell->material_id()))
        for (const unsigned int f : cell->face_indices())
          if (cell->face(f)->at_boundary() && on_dam_surface(cell->face(f)->boundary_id()))
            for (const unsigned int g : cell->face_indices())
              {
                if (g == f || g == (f ^ 1u)) // f itself, or the face opposite it
                  continue;
                const auto face     = cell->face(g);
                const auto boundary = face->at_boundary() ? face->boundary_id() :
                                                            dealii::numbers::internal_face_boundary_id;
                const auto neighbour =
                  face->at_boundary() ? dealii::numbers::invalid_material_id :
                                        cell->neighbor(g)->material_id();
                const bool on_base = boundary == ids::foundation_bottom ||
                                     boundary == ids::foundation_sides ||
                                     neighbour == ids::rock;
                const bool on_split_joint = face->at_boundary() && is_joint_face(boundary);
                const bool on_glued_joint = ids::is_dam(neighbour) && neighbour != cell->material_id();
                if (!on_base && !on_split_joint && !on_glued_joint)
                  continue;
                // The edge the two faces share: the two vertices of face f
                // that are vertices of face g too.
                std::vector<dealii::Point<dim>> shared;
                for (const unsigned int i : cell->face(f)->vertex_indices())
                  for (const unsigned int j : face->vertex_indices())
                    if (cell->face(f)->vertex_index(i) == face->vertex_index(j))
                      shared.push_back(cell->face(f)->vertex(i));
                if (shared.size() != 2)
                  continue;
                const Segment edge{{shared[0], shared[1]}};
                if (on_base)
                  base.push_back(edge);
                else
                  joints.emplace_back(on_split_joint ?
                                        joint_of(boundary) :
                                        std::min(neighbour, cell->material_id()) - ids::first_dam_block,
                                      edge);
              }
  }

  double
  SurfaceEdges::to_base(const dealii::Point<dim> &x) const
  {
    double nearest = std::numeric_limits<double>::infinity();
    for (const Segment &s : base)
      nearest = std::min(nearest, distance(x, s));
    return nearest;
  }

  std::pair<unsigned int, double>
  SurfaceEdges::nearest_joint(const dealii::Point<dim> &x) const
  {
    std::pair<unsigned int, double> nearest{0, std::numeric_limits<double>::infinity()};
    for (const auto &[joint, s] : joints)
      if (const double d = distance(x, s); d < nearest.second)
        nearest = {joint, d};
    return nearest;
  }
} // namespace archdam::geometry
