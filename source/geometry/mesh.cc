#include <archdam/base/input_error.h>
#include <archdam/geometry/ids.h>
#include <archdam/geometry/mesh.h>
#include <archdam/geometry/splitter.h>

namespace archdam::geometry
{
  using namespace dealii;

  void
  MeshParameters::add_parameters(ParameterHandler &prm)
  {
    prm.add_parameter("Source", source,
                      "Where the mesh comes from: box = a concrete block on a "
                      "rock block (tests and examples).",
                      Patterns::Selection("box"));
    box.add_parameters(prm);
  }

  void
  create_mesh(const MeshParameters &p, parallel::shared::Triangulation<dim> &tria)
  {
    Triangulation<dim> serial;
    generate_box(p.box, serial);

    unsigned int n_dam_cells = 0;
    for (const auto &cell : serial.active_cell_iterators())
      n_dam_cells += ids::is_dam(cell->material_id());
    if (n_dam_cells == 0)
      throw InputError("Mesh: the mesh has no dam cells (material id 10 + k).");

    Triangulation<dim> split;
    split_interfaces(serial, split);
    tria.copy_triangulation(split);
  }
} // namespace archdam::geometry
