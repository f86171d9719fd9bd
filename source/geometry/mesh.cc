#include <archdam/base/input_error.h>
#include <archdam/geometry/ids.h>
#include <archdam/geometry/mesh.h>
#include <archdam/geometry/splitter.h>

#include <deal.II/grid/grid_generator.h>

#include <set>

namespace archdam::geometry
{
  using namespace dealii;

  void
  MeshParameters::add_parameters(ParameterHandler &prm)
  {
    prm.add_parameter("Source", source,
                      "Where the mesh comes from: box = a concrete block on a "
                      "rock block (tests and examples); arch dam = the parametric "
                      "double-curvature arch dam in its canyon with rock and "
                      "reservoir (doc/arch-dam-geometry.md).",
                      Patterns::Selection("box|arch dam"));
    box.add_parameters(prm);
    prm.enter_subsection("Arch dam");
    arch_dam.add_parameters(prm);
    prm.leave_subsection();
  }

  namespace
  {
    /// The solid part of a mesh: water cells removed; the faces they covered
    /// become traction-free (id 0), all others keep their ids.
    void
    remove_water(Triangulation<dim> &mesh)
    {
      std::set<Triangulation<dim>::active_cell_iterator> water;
      for (const auto &cell : mesh.active_cell_iterators())
        if (cell->material_id() == ids::water)
          water.insert(cell);
      if (water.empty())
        return;
      Triangulation<dim> solid;
      GridGenerator::create_triangulation_with_removed_cells(mesh, water, solid);
      // The remaining cells keep their order: copy the boundary ids across.
      auto old_cell = mesh.begin_active();
      for (const auto &cell : solid.active_cell_iterators())
        {
          while (old_cell->material_id() == ids::water)
            ++old_cell;
          for (const unsigned int f : cell->face_indices())
            if (cell->at_boundary(f))
              cell->face(f)->set_boundary_id(old_cell->at_boundary(f) ?
                                               old_cell->face(f)->boundary_id() :
                                               ids::free_surface_solid);
          ++old_cell;
        }
      mesh.clear();
      mesh.copy_triangulation(solid);
    }
  } // namespace

  void
  create_mesh(const MeshParameters &p, parallel::shared::Triangulation<dim> &tria,
              const bool keep_water)
  {
    Triangulation<dim> serial;
    if (p.source == "arch dam")
      generate_arch_dam(p.arch_dam, serial);
    else
      generate_box(p.box, serial);
    if (!keep_water)
      remove_water(serial);

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
