#include <archdam/base/data_files.h>
#include <archdam/base/input_error.h>
#include <archdam/base/number_text.h>
#include <archdam/geometry/box_mesh.h>
#include <archdam/geometry/arch_dam_mesh.h>
#include <archdam/geometry/gmsh_mesh.h>
#include <archdam/geometry/ids.h>
#include <archdam/geometry/mesh.h>
#include <archdam/geometry/mesh_checks.h>
#include <archdam/geometry/splitter.h>

#include <deal.II/grid/grid_tools.h>

#include <unistd.h>

#include <array>
#include <cmath>
#include <iomanip>
#include <set>
#include <sstream>

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
  check_model_size(const MeshParameters &p, const unsigned int degree, const bool solves)
  {
    // Solid cells carry 3 degree^3 DOFs each and water cells degree^3 (the
    // nodes a cell adds in a large structured mesh). The peak memory of a
    // run is its factorization's: 9.5 GB at the reference case's 291,114
    // DOFs, growing as DOFs^(4/3) for a 3-D mesh in nested dissection order
    // (doc/performance.md §5: 2.3 GB at 96 k, 0.5 GB at 27 k); building the
    // mesh alone takes about 2 kB a cell.
    std::array<double, 2> cells{0., 0.};
    std::string           set_by;
    switch (p.source)
      {
        case MeshSource::box:
          cells[0] = box_cell_count(p.box);
          set_by   = "Mesh/Box (Cells in x, y, z = " + std::to_string(p.box.cells_x) + ", " +
                   std::to_string(p.box.cells_y) + ", " + std::to_string(p.box.cells_z) +
                   "; Rock cell size = " + number_text(p.box.rock_cell_size) + " m)";
          break;
        case MeshSource::arch_dam:
          cells  = arch_dam_cell_count(p.arch_dam);
          set_by = "Mesh/Arch dam (Cells over height = " +
                   std::to_string(p.arch_dam.cells_over_height) + ", Cells across each block = " +
                   std::to_string(p.arch_dam.cells_across_block) + ", Cells through thickness = " +
                   std::to_string(p.arch_dam.cells_through) + "; Rock cell size = " +
                   number_text(p.arch_dam.rock_cell_size) + " m, Water cell size = " +
                   number_text(p.arch_dam.water_cell_size) + " m)";
          break;
        case MeshSource::gmsh: // its size is the file's
          return;
      }
    const double n_cells = cells[0] + cells[1];
    const double dofs    = (3 * cells[0] + cells[1]) * std::pow(double(degree), 3);
    const double needed  = solves ? 9.5e9 * std::pow(dofs / 291114., 4. / 3.) : 2e3 * n_cells;
    const double memory  = double(sysconf(_SC_PHYS_PAGES)) * double(sysconf(_SC_PAGE_SIZE));
    if (std::isfinite(needed) && needed <= 0.8 * memory)
      return;
    std::ostringstream text;
    text << std::setprecision(3) << set_by << " gives about " << n_cells
         << " cells and " << dofs << " DOFs, ";
    if (solves)
      text << "whose factorization would need about " << needed / 1e9
           << " GB (9.5 GB at 291,114 DOFs, growing as DOFs^(4/3); doc/performance.md §5)";
    else
      text << "a mesh of about " << needed / 1e9 << " GB";
    text << ", and this machine has " << memory / 1e9
         << " GB: make the cells larger or fewer (doc/user-guide.md, \"Look at the model first\").";
    throw InputError(text.str());
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
