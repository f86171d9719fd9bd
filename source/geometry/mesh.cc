#include <archdam/base/data_files.h>
#include <archdam/base/input_error.h>
#include <archdam/geometry/arch_dam_mesh.h>
#include <archdam/geometry/gmsh_mesh.h>
#include <archdam/geometry/ids.h>
#include <archdam/geometry/mesh.h>
#include <archdam/geometry/mesh_checks.h>
#include <archdam/geometry/splitter.h>

#include <deal.II/grid/grid_tools.h>

#include <set>

namespace archdam::geometry
{
  using namespace dealii;

  void
  MeshParameters::add_parameters(ParameterHandler &prm)
  {
    add_selection(prm, "Source", source, mesh_source_names(),
                  "Where the mesh comes from: box = a concrete block on a "
                  "rock block (tests and examples); arch dam = the parametric "
                  "double-curvature arch dam in its canyon with rock and "
                  "reservoir (doc/arch-dam-geometry.md); gmsh = a hexahedral "
                  "mesh read from Mesh/Gmsh/File (doc/user-guide.md).");
    box.add_parameters(prm);
    prm.enter_subsection("Arch dam");
    arch_dam.add_parameters(prm);
    prm.leave_subsection();
    prm.enter_subsection("Gmsh");
    prm.add_parameter("File", gmsh_file,
                      "The ASCII .msh file (format 2.x or 4.1, hexahedra) of Source = "
                      "gmsh. A relative path is looked for in the case file's folder, "
                      "then in the data folder (doc/user-guide.md). Physical volumes "
                      "are material ids (1 rock, 2 water, 10 + k dam block k), physical "
                      "surfaces boundary ids (0-5); a solid face outside every physical "
                      "surface is traction-free (0).");
    prm.leave_subsection();
  }


  void
  remove_water(Triangulation<dim> &mesh)
  {
    // The solid cells on the mesh's own vertices: the joints' duplicated
    // vertices stay apart (GridGenerator::create_triangulation_with_removed_cells
    // would merge them and glue the joints shut).
    std::vector<Point<dim>>    vertices = mesh.get_vertices();
    std::vector<CellData<dim>> cells;
    for (const auto &cell : mesh.active_cell_iterators())
      if (cell->material_id() != ids::water)
        {
          CellData<dim> data;
          for (const unsigned int v : cell->vertex_indices())
            data.vertices[v] = cell->vertex_index(v);
          data.material_id = cell->material_id();
          cells.push_back(data);
        }
    if (cells.size() == mesh.n_active_cells())
      return;
    SubCellData no_boundary_data;
    GridTools::delete_unused_vertices(vertices, cells, no_boundary_data);
    Triangulation<dim> solid;
    solid.create_triangulation(vertices, cells, no_boundary_data);
    // The remaining cells keep their order: copy the boundary ids across.
    auto old_cell = mesh.begin_active();
    for (const auto &cell : solid.active_cell_iterators())
      {
        while (old_cell->material_id() == ids::water)
          ++old_cell;
        for (const unsigned int f : cell->face_indices())
          if (cell->at_boundary(f))
            {
              const bool kept = old_cell->at_boundary(f) &&
                                old_cell->face(f)->boundary_id() != ids::solid_interface;
              cell->face(f)->set_boundary_id(kept ? old_cell->face(f)->boundary_id() :
                                                    ids::free_surface_solid);
            }
        ++old_cell;
      }
    mesh.clear();
    mesh.copy_triangulation(solid);
  }

  void
  build_model_mesh(const MeshParameters &p, const std::string &base_directory,
                   Triangulation<dim> &model)
  {
    Triangulation<dim> conforming;
    switch (p.source)
      {
        case MeshSource::box:
          generate_box(p.box, conforming);
          break;
        case MeshSource::arch_dam:
          generate_arch_dam(p.arch_dam, conforming);
          break;
        case MeshSource::gmsh:
          if (p.gmsh_file.empty())
            throw InputError("Mesh/Gmsh/File: no file given for Mesh/Source = gmsh.");
          read_gmsh(find_input_file(p.gmsh_file, base_directory, "Mesh/Gmsh/File"),
                    conforming);
          break;
      }

    check_cell_shapes(conforming);
    check_model_ids(conforming);
    unsigned int n_dam_cells = 0;
    for (const auto &cell : conforming.active_cell_iterators())
      n_dam_cells += ids::is_dam(cell->material_id());
    if (n_dam_cells == 0)
      throw InputError("Mesh: the mesh has no dam cells (material id 10 + k).");

    split_interfaces(conforming, model);
  }

  void
  create_mesh(const MeshParameters &p, parallel::shared::Triangulation<dim> &tria,
              const bool keep_water, const std::string &base_directory)
  {
    Triangulation<dim> model;
    build_model_mesh(p, base_directory, model);
    if (!keep_water)
      remove_water(model);
    tria.copy_triangulation(model);
  }
} // namespace archdam::geometry
