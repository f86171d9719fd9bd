// The default arch dam mesh (the paper case's reference dam) is a production
// mesh (doc/performance.md §3) and is well shaped (issue 3, must show 3).
//
// Checks, each against a reference computed here:
//  - at least two cells through the dam thickness and across each block,
//    counted by walking the mesh (not read from the parameters);
//  - rock and water resolved to 10 Hz with at least 8 nodes per wavelength:
//    a quadratic cell of edge h has nodes h/2 apart, so every edge must be at
//    most lambda/4 = c/(10 Hz)/4, with the shear wave speed c_s = sqrt(mu/rho)
//    of the default rock of physics/solid/materials.h and c = 1440 m/s in water;
//    the longest edge of every rock and water cell is compared with it;
//  - the minimum scaled Jacobian over all cells is at least 0.2
//    (doc/arch-dam-geometry.md: the threshold below which hexahedra are
//    commonly called poor; quadratic elasticity stays accurate above it). The
//    scaled Jacobian of a hexahedron is the smallest, over its 8 corners and
//    its centre, of det(e1, e2, e3) for the unit edge vectors at the corner
//    (at the centre: the unit principal axes), the standard definition of the
//    Verdict library (Knupp 2000); it is computed here from the vertices.
// Printed for the record: cells per region and an estimate of the quadratic
// (Q2) degrees of freedom: 3 per solid node and 1 per water node, counted
// from the distinct vertices, edges, faces and cells of each region, plus 3
// per node duplicated on the joints (all joint nodes except those on the
// joint's edge against the rock).
//
// The test also writes arch_dam_model.txt (boundary faces, joint faces and
// the geometry's curves) for scripts/plot_arch_dam.py, which draws the
// pictures of doc/arch-dam-geometry.md.

#include <archdam/geometry/arch_dam_mesh.h>
#include <archdam/geometry/arch_dam_shape.h>
#include <archdam/geometry/ids.h>
#include <archdam/physics/solid/materials.h>

#include <deal.II/grid/tria.h>
#include <deal.II/grid/tria_accessor.h>
#include <deal.II/grid/tria_iterator.h>

#include "arch_dam_plot_data.h"
#include "arch_dam_reference.h"
#include "archdam_tests.h"

#include <cmath>
#include <fstream>
#include <map>
#include <set>
#include <tuple>

using namespace dealii;
using namespace archdam;
using archdam::testing::log;

using archdam::testing::bilinear_area;
using archdam::testing::integrate;
using archdam::testing::scaled_jacobian;

namespace
{

  double
  longest_edge(const Triangulation<3>::active_cell_iterator &cell)
  {
    double h = 0;
    for (unsigned int l = 0; l < 12; ++l)
      h = std::max(h, cell->line(l)->measure());
    return h;
  }

} // namespace

int
main(int argc, char **argv)
{
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);

  const geometry::ArchDamParameters p; // the defaults: the reference dam
  const geometry::ArchDamGeometry   g(p);
  Triangulation<3>                  tria;
  geometry::generate_arch_dam(p, tria);

  // --- cells per region and the Q2 DOF estimate ---
  std::set<unsigned int> sv, sl, sq, wv, wl, wq, rock_vertices, rock_lines;
  std::set<unsigned int> jv, jl, jq;
  unsigned int           n_dam = 0, n_rock = 0, n_water = 0;
  for (const auto &cell : tria.active_cell_iterators())
    {
      const bool water = cell->material_id() == ids::water;
      n_dam += ids::is_dam(cell->material_id());
      n_rock += cell->material_id() == ids::rock;
      n_water += water;
      for (unsigned int v = 0; v < 8; ++v)
        (water ? wv : sv).insert(cell->vertex_index(v));
      for (unsigned int l = 0; l < 12; ++l)
        (water ? wl : sl).insert(cell->line_index(l));
      for (unsigned int f = 0; f < 6; ++f)
        (water ? wq : sq).insert(cell->face_index(f));
      if (cell->material_id() == ids::rock)
        {
          for (unsigned int v = 0; v < 8; ++v)
            rock_vertices.insert(cell->vertex_index(v));
          for (unsigned int l = 0; l < 12; ++l)
            rock_lines.insert(cell->line_index(l));
        }
    }
  for (const auto &cell : tria.active_cell_iterators())
    if (ids::is_dam(cell->material_id()))
      for (unsigned int f = 0; f < 6; ++f)
        if (!cell->face(f)->at_boundary() &&
            cell->neighbor(f)->material_id() == cell->material_id() + 1)
          {
            jq.insert(cell->face_index(f));
            for (unsigned int v = 0; v < 4; ++v)
              if (!rock_vertices.count(cell->face(f)->vertex_index(v)))
                jv.insert(cell->face(f)->vertex_index(v));
            for (unsigned int l = 0; l < 4; ++l)
              if (!rock_lines.count(cell->face(f)->line(l)->index()))
                jl.insert(cell->face(f)->line(l)->index());
          }
  const unsigned int n_solid = n_dam + n_rock;
  const std::size_t  solid_nodes = sv.size() + sl.size() + sq.size() + n_solid;
  const std::size_t  water_nodes = wv.size() + wl.size() + wq.size() + n_water;
  const std::size_t  joint_nodes = jv.size() + jl.size() + jq.size();
  const std::size_t  dofs        = 3 * (solid_nodes + joint_nodes) + water_nodes;
  log() << "Reference arch dam mesh: " << tria.n_active_cells() << " cells (dam " << n_dam
        << ", rock " << n_rock << ", water " << n_water << "), " << tria.n_vertices()
        << " vertices" << std::endl;
  log() << "Q2 estimate: " << 3 * solid_nodes << " solid DOFs + " << 3 * joint_nodes
        << " on duplicated joint nodes + " << water_nodes << " water DOFs = " << dofs
        << std::endl;

  // --- dam resolution: cells through the thickness and across each block ---
  // Walk from each cell on the upstream face (face 2 not a dam cell) to the
  // downstream face, and from each cell on a block's +y side (face 0 not the
  // same block) across the block.
  unsigned int min_through = 1000, min_across = 1000;
  for (const auto &cell : tria.active_cell_iterators())
    if (ids::is_dam(cell->material_id()))
      {
        const auto walk = [&](const unsigned int from, const unsigned int to) {
          auto         c = cell;
          unsigned int n = 1;
          while (!c->face(to)->at_boundary() &&
                 c->neighbor(to)->material_id() == cell->material_id())
            c = c->neighbor(to), ++n;
          (void)from;
          return n;
        };
        if (cell->face(2)->at_boundary() || !ids::is_dam(cell->neighbor(2)->material_id()))
          min_through = std::min(min_through, walk(2, 3));
        if (cell->face(0)->at_boundary() ||
            cell->neighbor(0)->material_id() != cell->material_id())
          min_across = std::min(min_across, walk(0, 1));
      }
  log() << "Dam cells through the thickness (fewest): " << min_through
        << ", at least 2: " << (min_through >= 2 ? "yes" : "NO") << std::endl;
  log() << "Dam cells across each block (fewest): " << min_across
        << ", at least 2: " << (min_across >= 2 ? "yes" : "NO") << std::endl;

  // --- rock and water resolution at 10 Hz ---
  const physics::solid::MaterialParameters materials;
  const auto  &rock = materials.rock;
  const double c_s  = std::sqrt(rock.youngs_modulus / (2 * (1 + rock.poissons_ratio)) /
                               rock.density);
  const double h_rock = c_s / 10. / 4., h_water = 1440. / 10. / 4.;
  double       max_rock = 0, max_water = 0;
  for (const auto &cell : tria.active_cell_iterators())
    {
      if (cell->material_id() == ids::rock)
        max_rock = std::max(max_rock, longest_edge(cell));
      if (cell->material_id() == ids::water)
        max_water = std::max(max_water, longest_edge(cell));
    }
  log() << std::fixed << std::setprecision(1);
  log() << "Rock: longest cell edge " << max_rock << " m, allowed c_s/(10 Hz)/4 = " << h_rock
        << " m (c_s = " << c_s << " m/s): " << (max_rock <= h_rock ? "yes" : "NO")
        << std::endl;
  log() << "Water: longest cell edge " << max_water << " m, allowed 1440/(10 Hz)/4 = "
        << h_water << " m: " << (max_water <= h_water ? "yes" : "NO") << std::endl;

  // --- cell quality (ties between mirror-image cells broken by position) ---
  double   worst = 2;
  Point<3> where;
  int      worst_material = -1;
  for (const auto &cell : tria.active_cell_iterators())
    {
      std::array<Point<3>, 8> x;
      for (unsigned int v = 0; v < 8; ++v)
        x[v] = cell->vertex(v);
      const double   q = scaled_jacobian(x);
      const Point<3> c = cell->center();
      if (q < worst - 1e-12 ||
          (std::abs(q - worst) <= 1e-12 &&
           std::make_tuple(c[1], c[0], c[2]) > std::make_tuple(where[1], where[0], where[2])))
        worst = q, where = c, worst_material = cell->material_id();
    }
  log() << std::setprecision(2) << "Minimum scaled Jacobian " << worst << " in a cell of material "
        << worst_material << " centred at (" << std::setprecision(0) << where[0] << ", "
        << where[1] << ", " << where[2] << ") m, at least 0.2: "
        << (worst >= 0.2 ? "yes" : "NO") << std::endl;

  archdam::testing::write_arch_dam_plot_data(g, tria, "arch_dam_model.txt");
}
