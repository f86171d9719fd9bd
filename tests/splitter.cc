// The splitter on the arch dam with its reservoir (doc/theory/conventions.md §6, issue
// "mesh"): from the conforming mesh of dam, rock and water,
//  - the 13 joints come apart as pairs of coincident faces (ids 100 + 2k on
//    block k, 101 + 2k on block k + 1) that pair 1:1, and the joint edge
//    against the rock stays shared (no vertex of a node pair touches rock);
//  - water and solid share no vertex, and every fluid-side face (id 6) has a
//    coincident solid-side face (id 7) and vice versa;
//  - every boundary face carries a documented id;
//  - two blocks that touch but are not neighbours are an input error.
// The references are the conforming mesh's own adjacency, counted here
// independently of the splitter.

#include <archdam/base/input_error.h>
#include <archdam/geometry/arch_dam_mesh.h>
#include <archdam/geometry/ids.h>
#include <archdam/geometry/mesh.h>
#include <archdam/geometry/splitter.h>
#include <archdam/joints/joint_faces.h>
#include <archdam/parameters/parameters.h>

#include <deal.II/grid/grid_generator.h>

#include <map>
#include <set>

#include "archdam_tests.h"

using namespace dealii;
using namespace archdam;

int
main(int argc, char **argv)
{
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  auto                            &log = testing::log();

  const Parameters p = parameters_from_string(R"(
subsection Mesh
  set Source = arch dam
  subsection Arch dam
    set Cells over height = 5
    set Cells across each block = 1
    set Cells through thickness = 1
    set Rock cell size = 90
    set Water cell size = 70
  end
end
)");
  Triangulation<dim> conforming;
  geometry::generate_arch_dam(p.mesh.arch_dam, conforming);

  // Reference counts from the conforming mesh: interior faces between blocks
  // k and k + 1, and between water and solid.
  unsigned int joint_faces_expected = 0, wet_faces_expected = 0;
  for (const auto &cell : conforming.active_cell_iterators())
    for (const unsigned int f : cell->face_indices())
      if (!cell->at_boundary(f))
        {
          const auto m = cell->material_id(), n = cell->neighbor(f)->material_id();
          if (ids::is_dam(m) && n == m + 1)
            ++joint_faces_expected;
          if (m == ids::water && n != ids::water)
            ++wet_faces_expected;
        }

  parallel::shared::Triangulation<dim> tria(MPI_COMM_WORLD);
  geometry::create_mesh(p.mesh, tria, true);

  // Joints.
  const auto pairs = joints::pair_joint_faces(tria);
  std::set<unsigned int> joints;
  for (const auto &pr : pairs)
    joints.insert(pr.joint);
  log << "joints: " << joints.size() << " (expected 13)" << std::endl;
  log << "joint face pairs equal the block-to-block faces of the conforming mesh: "
      << (pairs.size() == joint_faces_expected ? "yes" : "NO") << std::endl;

  // Vertices that touch rock, and the water/solid vertex sets.
  std::set<unsigned int> rock_vertices, water_vertices, solid_vertices;
  for (const auto &cell : tria.active_cell_iterators())
    for (const unsigned int v : cell->vertex_indices())
      {
        if (cell->material_id() == ids::rock)
          rock_vertices.insert(cell->vertex_index(v));
        (cell->material_id() == ids::water ? water_vertices : solid_vertices)
          .insert(cell->vertex_index(v));
      }
  bool pairs_off_rock = true;
  for (const auto &pr : pairs)
    {
      const auto f1 = pr.cell_1->face(pr.face_1), f2 = pr.cell_2->face(pr.face_2);
      for (const unsigned int v : f1->vertex_indices())
        for (const unsigned int w : f2->vertex_indices())
          if (f1->vertex_index(v) != f2->vertex_index(w) &&
              f1->vertex(v).distance(f2->vertex(w)) < 1e-9)
            pairs_off_rock = pairs_off_rock && !rock_vertices.count(f1->vertex_index(v)) &&
                             !rock_vertices.count(f2->vertex_index(w));
    }
  log << "no duplicated joint vertex touches rock (joint edge grouted): "
      << (pairs_off_rock ? "yes" : "NO") << std::endl;
  unsigned int shared = 0;
  for (const auto v : water_vertices)
    shared += solid_vertices.count(v);
  log << "vertices shared by water and solid: " << shared << std::endl;

  // Fluid-solid faces match 1:1 by their centres.
  std::map<std::array<long long, 3>, int> balance;
  unsigned int                            n6 = 0, n7 = 0;
  std::set<types::boundary_id>            ids_found;
  bool                                    documented = true;
  for (const auto &face : tria.active_face_iterators())
    if (face->at_boundary())
      {
        const auto id = face->boundary_id();
        ids_found.insert(id);
        documented = documented && (id <= 7 || (id >= 100 && id < 100 + 2 * 13));
        if (id == ids::fluid_interface || id == ids::solid_interface)
          {
            std::array<long long, 3> key;
            for (unsigned int d = 0; d < dim; ++d)
              key[d] = std::llround(face->center()[d] * 1e6);
            balance[key] += id == ids::fluid_interface ? 1 : -1;
            (id == ids::fluid_interface ? n6 : n7) += 1;
          }
      }
  bool matched = true;
  for (const auto &[key, b] : balance)
    matched = matched && b == 0;
  log << "fluid-side faces (6) = solid-side faces (7) = wet faces of the conforming mesh: "
      << (n6 == wet_faces_expected && n7 == wet_faces_expected ? "yes" : "NO") << std::endl;
  log << "every fluid-side face has a coincident solid-side face: " << (matched ? "yes" : "NO")
      << std::endl;
  log << "boundary ids:";
  for (const auto id : ids_found)
    if (id < 100)
      log << " " << id;
  log << " and joints 100..125; all documented: " << (documented ? "yes" : "NO") << std::endl;

  // Blocks 0 and 2 touching: an input error.
  Triangulation<dim> bad, split;
  GridGenerator::subdivided_hyper_rectangle(bad, {2, 1, 1}, Point<dim>(), Point<dim>(2, 1, 1));
  unsigned int k = 0;
  for (const auto &cell : bad.active_cell_iterators())
    cell->set_material_id(ids::first_dam_block + 2 * k++);
  try
    {
      geometry::split_interfaces(bad, split);
      log << "blocks 0 and 2 touching: NO ERROR" << std::endl;
    }
  catch (const InputError &e)
    {
      log << "blocks 0 and 2 touching: " << e.what() << std::endl;
    }
}
