#include <archdam/base/input_error.h>
#include <archdam/base/point_text.h>
#include <archdam/geometry/ids.h>
#include <archdam/geometry/splitter.h>

#include <deal.II/grid/grid_tools.h>

#include <map>
#include <sstream>

namespace archdam::geometry
{
  using namespace dealii;

  namespace
  {
    // Which copy of a vertex a cell uses. All solid cells at a vertex that
    // touches rock share it; otherwise each dam block has its own copy; water
    // always has its own.
    constexpr int water_copy = -2, shared_solid_copy = -1;


    /// The id the face of @p cell towards @p neighbor gets when the splitter
    /// separates them (numbers::internal_face_boundary_id: stays connected).
    types::boundary_id
    interface_id(const Triangulation<dim>::cell_iterator &cell,
                 const Triangulation<dim>::cell_iterator &neighbor,
                 const Point<dim>                        &face_center)
    {
      const auto m = cell->material_id(), n = neighbor->material_id();
      if ((m == ids::water) != (n == ids::water))
        return m == ids::water ? ids::fluid_interface : ids::solid_interface;
      if (ids::is_dam(m) && ids::is_dam(n) && m != n)
        {
          const unsigned int k = m - ids::first_dam_block, j = n - ids::first_dam_block;
          if (j == k + 1)
            return joint_side_1(k);
          if (k == j + 1)
            return joint_side_2(j);
          throw InputError("Mesh: dam blocks " + std::to_string(k) + " and " +
                           std::to_string(j) + " (material ids " + std::to_string(m) +
                           " and " + std::to_string(n) +
                           ") touch at " + point_text(face_center) +
                           " but are not neighbours; blocks must be numbered in order "
                           "along the dam.");
        }
      return numbers::internal_face_boundary_id;
    }
  } // namespace

  void
  split_interfaces(const Triangulation<dim> &conforming, Triangulation<dim> &split)
  {
    AssertThrow(conforming.n_levels() == 1,
                ExcMessage("The splitter works on coarse (unrefined) meshes."));

    // Copies of each vertex: the key of the cells that use it.
    const auto copy_key = [](const Triangulation<dim>::cell_iterator &cell,
                             const bool                               touches_rock) {
      if (cell->material_id() == ids::water)
        return water_copy;
      if (touches_rock || !ids::is_dam(cell->material_id()))
        return shared_solid_copy;
      return static_cast<int>(cell->material_id());
    };
    std::vector<bool> touches_rock(conforming.n_vertices(), false);
    for (const auto &cell : conforming.active_cell_iterators())
      if (cell->material_id() == ids::rock)
        for (const unsigned int v : cell->vertex_indices())
          touches_rock[cell->vertex_index(v)] = true;

    std::map<std::pair<unsigned int, int>, unsigned int> new_index;
    std::vector<Point<dim>>                              vertices;
    std::vector<CellData<dim>>                           cells;
    const auto &old_vertices = conforming.get_vertices();
    for (const auto &cell : conforming.active_cell_iterators())
      {
        CellData<dim> c(GeometryInfo<dim>::vertices_per_cell);
        for (const unsigned int v : cell->vertex_indices())
          {
            const unsigned int old = cell->vertex_index(v);
            const auto key = std::make_pair(old, copy_key(cell, touches_rock[old]));
            const auto it  = new_index.find(key);
            if (it == new_index.end())
              {
                new_index[key] = vertices.size();
                vertices.push_back(old_vertices[old]);
              }
            c.vertices[v] = new_index[key];
          }
        c.material_id = cell->material_id();
        cells.push_back(c);
      }
    split.clear();
    split.create_triangulation(vertices, cells, SubCellData());

    // Boundary ids, face by face: cells are in the same order in both meshes.
    auto old_cell = conforming.begin_active();
    for (const auto &cell : split.active_cell_iterators())
      {
        for (const unsigned int f : cell->face_indices())
          if (cell->face(f)->at_boundary())
            {
              if (old_cell->face(f)->at_boundary())
                cell->face(f)->set_boundary_id(old_cell->face(f)->boundary_id());
              else
                {
                  const auto id = interface_id(old_cell, old_cell->neighbor(f),
                                               old_cell->face(f)->center());
                  // The face came apart, so its cells use different copies of
                  // some vertex: they differ in water/solid or in block. If
                  // they do not, the cells around this face are not connected
                  // as their shared vertices say (a cell with its nodes in a
                  // tangled order, which overlaps its neighbours).
                  if (id == numbers::internal_face_boundary_id)
                    throw InputError("Mesh: the cells around " +
                                     point_text(old_cell->face(f)->center()) +
                                     " share vertices but not their faces: a cell there "
                                     "has its nodes in a tangled order (it is twisted and "
                                     "overlaps its neighbours). Check the node order of "
                                     "the hexahedra there.");
                  cell->face(f)->set_boundary_id(id);
                }
            }
        ++old_cell;
      }
  }
} // namespace archdam::geometry
