// The mesh report (cells and DOFs per region, dam and water volume, wetted
// area, joints and node pairs, worst cell) against closed forms for the Gmsh
// example (gmsh_example.h: structured boxes, so every number follows from the
// .geo file's dimensions), for elements of degree 1 and 2:
//  - cells per region: products of the cells along each direction;
//  - DOFs: a structured block of n1 x n2 x n3 cells of degree p has
//    (p n1 + 1)(p n2 + 1)(p n3 + 1) nodes; the dam's three blocks share, per
//    joint, the p (T/h) + 1 nodes of the joint's edge on the rock (the rest of
//    the joint is duplicated); 3 DOFs per solid node, 1 per water node;
//  - volumes T W H and Lu W WL, wetted area W WL (round-off);
//  - 2 joints of (T/h)(H/h) faces and, at degree 2, the nodes of the joint,
//    (2T/h + 1)(2H/h + 1), less the 2T/h + 1 on its edge against the rock:
//    the support-point pairs the analysis uses;
//  - the scaled Jacobian: 1 for the boxes; after the shear x' = x + z tan(t)
//    of the rock (z <= 0; each rock cell is then a parallelepiped sheared by
//    t) the minimum is cos(t), in a rock cell (z < 0), for t = 30 and 60 deg.
// The report is computed identically on every rank; printed by rank 0.

#include <archdam/geometry/mesh.h>
#include <archdam/geometry/mesh_checks.h>
#include <archdam/output/mesh_report.h>

#include <deal.II/grid/grid_tools.h>
#include <deal.II/grid/tria.h>

#include "archdam_tests.h"
#include "gmsh_example.h"

#include <sstream>

using namespace dealii;
using namespace archdam;
using archdam::testing::check_relative;
using archdam::testing::log;
namespace ex = archdam::testing::gmsh_example;
using archdam::testing::yes;

namespace
{
  unsigned long long
  nodes(const unsigned int p, const unsigned int n1, const unsigned int n2, const unsigned int n3)
  {
    return (p * n1 + 1ull) * (p * n2 + 1) * (p * n3 + 1);
  }
} // namespace

int
main(int argc, char **argv)
{
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);

  geometry::MeshParameters p;
  p.source    = geometry::MeshSource::gmsh;
  p.gmsh_file = "gmsh_blocks_v4.msh";
  Triangulation<3> model;
  geometry::build_model_mesh(p, ex::directory, model);

  const unsigned int nz_dam = ex::nz_wet + ex::nz_dry;
  for (const unsigned int degree : {1u, 2u})
    {
      const auto r = output::make_mesh_report(model, degree);
      std::ostringstream text;
      r.print(text);
      log() << "--- degree " << degree << " ---\n" << text.str();

      const unsigned long long dam_nodes =
        ex::n_blocks * nodes(degree, ex::nx_dam, ex::ny_block, nz_dam) -
        (ex::n_blocks - 1) * (degree * ex::nx_dam + 1ull);
      const unsigned long long rock_nodes =
        nodes(degree, ex::nx_up + ex::nx_dam + ex::nx_down, ex::ny, ex::nz_rock);
      const unsigned long long water_nodes = nodes(degree, ex::nx_up, ex::ny, ex::nz_wet);
      log() << "Cells dam/rock/water " << ex::dam_cells << "/" << ex::rock_cells << "/"
            << ex::water_cells << ": "
            << yes(r.dam.cells == ex::dam_cells && r.rock.cells == ex::rock_cells &&
                   r.water.cells == ex::water_cells)
            << std::endl;
      log() << "DOFs dam 3 x " << dam_nodes << ", rock 3 x " << rock_nodes << ", water "
            << water_nodes << ": "
            << yes(r.dam.dofs == 3 * dam_nodes && r.rock.dofs == 3 * rock_nodes &&
                   r.water.dofs == water_nodes)
            << std::endl;
    }

  const auto r = output::make_mesh_report(model, 2);
  check_relative("Dam volume T W H [m^3]", r.dam_volume, ex::dam_volume, 1e-12);
  check_relative("Water volume Lu W WL [m^3]", r.water_volume, ex::water_volume, 1e-12);
  check_relative("Wetted area W WL [m^2]", r.wetted_area, ex::wetted_area, 1e-12);
  bool joints_ok = r.joint_faces.size() == 2;
  for (unsigned int k = 0; joints_ok && k < 2; ++k)
    joints_ok = r.joint_faces[k] == ex::joint_faces && r.joint_node_pairs[k] == ex::joint_node_pairs(2);
  log() << "Joints: 2 of " << ex::joint_faces << " faces and " << ex::joint_node_pairs(2)
        << " node pairs: " << yes(joints_ok) << std::endl;
  log() << "Minimum scaled Jacobian of the boxes 1: " << yes(std::abs(r.min_scaled_jacobian - 1) < 1e-12)
        << std::endl;

  for (const double degrees : {30., 60.})
    {
      const double     t = degrees * numbers::PI / 180;
      Triangulation<3> sheared;
      sheared.copy_triangulation(model);
      GridTools::transform(
        [t](const Point<3> &x) {
          return Point<3>(x[0] + std::tan(t) * std::min(x[2], 0.), x[1], x[2]);
        },
        sheared);
      const auto s = output::make_mesh_report(sheared, 1);
      check_relative("Rock sheared by " + std::to_string(int(degrees)) +
                       " deg: minimum scaled Jacobian (cos t)",
                     s.min_scaled_jacobian, std::cos(t), 1e-12);
      log() << "  worst cell in the rock, below z = 0: "
            << yes(s.worst_cell_material == 1 && s.worst_cell_center[2] < 0) << std::endl;
    }
}
