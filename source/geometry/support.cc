#include <archdam/geometry/ids.h>
#include <archdam/geometry/support.h>

#include <set>

namespace archdam::geometry
{
  std::vector<unsigned int>
  blocks_held_by_joints_alone(const dealii::Triangulation<dim> &split)
  {
    const auto solid = [](const auto &cell) { return cell->material_id() != ids::water; };
    // part[c]: the solid part of active cell c (by a search through shared
    // faces), supported[p]: whether part p touches the outer boundary
    std::vector<int>  part(split.n_active_cells(), -1);
    std::vector<bool> supported;
    for (const auto &first : split.active_cell_iterators())
      {
        if (!solid(first) || part[first->active_cell_index()] >= 0)
          continue;
        const int p = supported.size();
        supported.push_back(false);
        std::vector<dealii::Triangulation<dim>::active_cell_iterator> todo{first};
        part[first->active_cell_index()] = p;
        while (!todo.empty())
          {
            const auto cell = todo.back();
            todo.pop_back();
            for (const unsigned int f : cell->face_indices())
              if (cell->at_boundary(f))
                {
                  const auto id = cell->face(f)->boundary_id();
                  if (id == ids::foundation_bottom || id == ids::foundation_sides)
                    supported[p] = true;
                }
              else if (const auto next = cell->neighbor(f);
                       solid(next) && part[next->active_cell_index()] < 0)
                {
                  part[next->active_cell_index()] = p;
                  todo.push_back(next);
                }
          }
      }
    std::set<unsigned int> blocks;
    for (const auto &cell : split.active_cell_iterators())
      if (ids::is_dam(cell->material_id()) && !supported[part[cell->active_cell_index()]])
        blocks.insert(cell->material_id() - ids::first_dam_block);
    return {blocks.begin(), blocks.end()};
  }
} // namespace archdam::geometry
