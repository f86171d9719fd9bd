// A coarse arch dam mesh, generated and copied into a
// parallel::shared::Triangulation as geometry/mesh.cc does: blocks, joints,
// boundary ids, volumes and cell quality (issue 3, must show 2, 3 and 4; run
// serially and under mpirun -np 2 with the same output).
//
// The mesh is conforming (the splitter separates joints and water later), so
// every joint face is one face shared by a cell of block k and a cell of block
// k+1; the test checks that, and that the faces lie on the documented joint
// surfaces (radial lines phi = u_k phi_a(z) seen from the arch centre).
// Each rank checks its locally owned cells; counts and areas are summed over
// the ranks.
//
// References (computed here from the prm numbers and the geometry's formulas):
//  - 14 blocks (ids 10..23), 13 joints, each joint made of (cells through the
//    thickness) x (cells over the height) faces: every block reaches from the
//    base to the crest;
//  - block k on the left bank side of block k+1 looking downstream (+y);
//  - boundary ids: each on its documented surface (bottom z = -H, sides
//    x = -H, x = 48 + H, |y| = b_H + H, water surface z = 202, reservoir end
//    x = -606, id 5 only where no rock is below or beside the water), ids 0-2
//    on solid cells and 3-5 on water cells, and no id-0 face on a truncation;
//  - areas. Exact (round-off, 1e-9) where the mesh represents the surface
//    exactly: the bottom rectangle, the side planes y = +-Y, the downstream
//    plane x = 48 + H minus the canyon |y| < b(z) (b linear in z, so the
//    straight cell edges follow it), the reservoir's end |y| < b(z),
//    z in [0, 202], and its bottom beyond the rock (a trapezoid between the
//    straight canyon walls at z = 0). The upstream truncation plane x = -H is
//    cut by the canyon walls y_w(z), curved in z, which the cells interpolate
//    linearly between their levels: the area error is at most
//    2 * sum over the layers of h^3 max|y_w''| / 12 (linear interpolation
//    error integrated over each layer), a bound computed here with y_w''
//    from finite differences. The water surface is bounded by the dam's
//    upstream face at z = 202, which the cells replace by chords: the missing
//    area is about n r^2 dphi^3 / 12 for n chords of angle dphi on radius r;
//    twice that (the face is not exactly circular) is the tolerance;
//  - dam and water volume against the integrals of arch_dam_volumes (1e-2:
//    the coarsest mesh there, coarser than this one, is within 3e-3);
//  - minimum scaled Jacobian at least 0.2, as for the default mesh
//    (arch_dam_default).

#include <archdam/geometry/arch_dam_mesh.h>
#include <archdam/geometry/arch_dam_shape.h>
#include <archdam/geometry/ids.h>

#include <deal.II/base/quadrature_lib.h>
#include <deal.II/distributed/shared_tria.h>
#include <deal.II/grid/tria.h>
#include <deal.II/grid/tria_accessor.h>
#include <deal.II/grid/tria_iterator.h>

#include "arch_dam_reference.h"
#include "archdam_tests.h"

#include <array>
#include <cmath>
#include <functional>
#include <vector>

using namespace dealii;
using namespace archdam;
using archdam::testing::check_below;
using archdam::testing::check_relative;
using archdam::testing::log;

using archdam::testing::bilinear_area;
using archdam::testing::integrate;
using archdam::testing::scaled_jacobian;
using archdam::testing::yes;

namespace
{



  double
  sum(const double v)
  {
    return Utilities::MPI::sum(v, MPI_COMM_WORLD);
  }

} // namespace

int
main(int argc, char **argv)
{
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);

  geometry::ArchDamParameters p;
  p.cells_across_block = 1;
  p.cells_through      = 2;
  p.cells_over_height  = 5;
  p.rock_cell_size     = 120.;
  p.water_cell_size    = 120.;
  const geometry::ArchDamGeometry g(p);

  parallel::shared::Triangulation<3> tria(MPI_COMM_WORLD);
  {
    Triangulation<3> serial;
    geometry::generate_arch_dam(p, serial);
    tria.copy_triangulation(serial);
  }
  log() << "Coarse arch dam mesh: " << tria.n_global_active_cells() << " cells, "
        << tria.n_vertices() << " vertices" << std::endl;

  // --- planes of the model, from the prm numbers ---
  const double H = 235., D = 235., WL = 202., b0 = 40.;
  const double bH = 170. * std::sin(304.8 / (2 * 170.));
  const double X_ru = -H, X_rd = 48. + H, Y = bH + H, X_r = -3 * WL;
  const double eps  = 1e-6;
  const auto   on   = [&](const std::array<Point<3>, 4> &v, const unsigned int d, const double c) {
    for (const auto &x : v)
      if (std::abs(x[d] - c) > eps)
        return false;
    return true;
  };

  // --- blocks ---
  std::vector<double> block_volume(100, 0.), block_y(100, 0.);
  double              dam_volume = 0, water_volume = 0;
  for (const auto &cell : tria.active_cell_iterators())
    if (cell->is_locally_owned())
      {
        const auto m = cell->material_id();
        if (ids::is_dam(m))
          {
            block_volume[m - 10] += cell->measure();
            block_y[m - 10] += cell->measure() * cell->center()[1];
            dam_volume += cell->measure();
          }
        if (m == ids::water)
          water_volume += cell->measure();
      }
  Utilities::MPI::sum(block_volume, MPI_COMM_WORLD, block_volume);
  Utilities::MPI::sum(block_y, MPI_COMM_WORLD, block_y);
  unsigned int n_blocks = 0, highest = 0;
  bool         ordered  = true;
  for (unsigned int k = 0; k < 90; ++k)
    if (block_volume[k] > 0)
      {
        ++n_blocks;
        highest = k;
        if (k > 0 && !(block_y[k] / block_volume[k] < block_y[k - 1] / block_volume[k - 1]))
          ordered = false;
      }
  log() << "Blocks: " << n_blocks << " (material ids 10.." << 10 + highest
        << "), 14 expected: " << yes(n_blocks == 14 && highest == 13) << std::endl;
  log() << "Block centroids ordered from +y (block 0, left bank looking downstream) to -y: "
        << yes(ordered) << std::endl;

  // --- joints ---
  std::vector<double> joint_faces(100, 0.);
  double              off_surface = 0, unpaired = 0, misoriented = 0, skipping = 0;
  for (const auto &cell : tria.active_cell_iterators())
    if (cell->is_locally_owned() && ids::is_dam(cell->material_id()))
      for (unsigned int f = 0; f < 6; ++f)
        {
          if (cell->face(f)->at_boundary())
            continue;
          const auto nb = cell->neighbor(f);
          if (!ids::is_dam(nb->material_id()) || nb->material_id() == cell->material_id())
            continue;
          if (nb->material_id() != cell->material_id() + 1)
            {
              // faces between non-neighbouring blocks (counted from the lower block)
              skipping += nb->material_id() > cell->material_id();
              continue;
            }
          const unsigned int k = cell->material_id() - 10;
          joint_faces[k] += 1;
          // the same face seen from the neighbour: one face, two cells
          if (nb->face(cell->neighbor_face_no(f))->index() != cell->face(f)->index() ||
              nb->neighbor(cell->neighbor_face_no(f))->id() != cell->id())
            unpaired += 1;
          // on the radial surface of joint k
          for (unsigned int v = 0; v < 4; ++v)
            {
              const Point<3> x = cell->face(f)->vertex(v);
              if (std::abs(g.arch_angle(x) - g.joint_u(k) * g.abutment_angle(x[2])) > 1e-9)
                off_surface += 1;
            }
          // block k on the +y (larger arch angle) side of the face
          const double a_face = g.arch_angle(cell->face(f)->center());
          if (!(g.arch_angle(cell->center()) > a_face && g.arch_angle(nb->center()) < a_face))
            misoriented += 1;
        }
  Utilities::MPI::sum(joint_faces, MPI_COMM_WORLD, joint_faces);
  unsigned int n_joints = 0;
  bool         full     = true;
  for (unsigned int k = 0; k < 90; ++k)
    if (joint_faces[k] > 0)
      {
        ++n_joints;
        full = full && joint_faces[k] == p.cells_through * p.cells_over_height;
      }
  log() << "Joints: " << n_joints << ", 13 expected: " << yes(n_joints == 13) << std::endl;
  log() << "Every joint has " << p.cells_through << " x " << p.cells_over_height
        << " faces (through the thickness x over the height): " << yes(full) << std::endl;
  log() << "Faces between blocks that are not neighbours: " << sum(skipping)
        << ", none expected: " << yes(sum(skipping) == 0) << std::endl;
  log() << "Joint faces shared 1:1 by a cell of each block: " << yes(sum(unpaired) == 0)
        << std::endl;
  log() << "Joint face vertices off the radial joint surface phi = u_k phi_a(z) (1e-9 rad): "
        << sum(off_surface) << ", none expected: " << yes(sum(off_surface) == 0) << std::endl;
  log() << "Joint faces with block k on the +y side: " << yes(sum(misoriented) == 0)
        << std::endl;

  // --- boundary ids ---
  std::vector<double> n_id(7, 0.), area_id(7, 0.);
  double              misplaced = 0, wrong_side = 0, truncation_as_0 = 0;
  double              area_side = 0, area_down = 0, area_up = 0, area_5_bottom = 0;
  for (const auto &cell : tria.active_cell_iterators())
    if (cell->is_locally_owned())
      for (unsigned int f = 0; f < 6; ++f)
        if (cell->face(f)->at_boundary())
          {
            const auto              id = cell->face(f)->boundary_id();
            std::array<Point<3>, 4> v;
            for (unsigned int i = 0; i < 4; ++i)
              v[i] = cell->face(f)->vertex(i);
            const double a     = bilinear_area(v);
            const bool   water = cell->material_id() == ids::water;
            const bool   trunc = on(v, 2, -D) || on(v, 0, X_ru) || on(v, 0, X_rd) ||
                               on(v, 1, Y) || on(v, 1, -Y);
            if (id > 5)
              {
                n_id[6] += 1;
                continue;
              }
            n_id[id] += 1;
            area_id[id] += a;
            if (water != (id >= 3))
              wrong_side += 1;
            bool placed = true;
            switch (id)
              {
                case 0:
                  truncation_as_0 += trunc;
                  break;
                case 1:
                  placed = on(v, 2, -D);
                  break;
                case 2:
                  placed = on(v, 0, X_ru) || on(v, 0, X_rd) || on(v, 1, Y) || on(v, 1, -Y);
                  area_side += (on(v, 1, Y) || on(v, 1, -Y)) ? a : 0.;
                  area_down += on(v, 0, X_rd) ? a : 0.;
                  area_up += on(v, 0, X_ru) ? a : 0.;
                  break;
                case 3:
                  placed = on(v, 2, WL);
                  break;
                case 4:
                  placed = on(v, 0, X_r);
                  break;
                case 5:
                  placed = true;
                  for (const auto &x : v)
                    placed = placed && x[0] <= X_ru + eps;
                  area_5_bottom += on(v, 2, 0.) ? a : 0.;
                  break;
              }
            misplaced += !placed;
          }
  Utilities::MPI::sum(n_id, MPI_COMM_WORLD, n_id);
  Utilities::MPI::sum(area_id, MPI_COMM_WORLD, area_id);
  log() << "Boundary faces per id:";
  for (unsigned int id = 0; id < 6; ++id)
    log() << ' ' << id << ": " << n_id[id];
  log() << std::endl;
  log() << "Boundary faces with an id outside 0..5: " << n_id[6]
        << ", none expected: " << yes(n_id[6] == 0) << std::endl;
  bool all_present = true;
  for (unsigned int id = 0; id < 6; ++id)
    all_present = all_present && n_id[id] > 0;
  log() << "Ids 0, 1, 2, 3, 4 and 5 all present: " << yes(all_present) << std::endl;
  log() << "Faces off their id's surface: " << sum(misplaced)
        << ", none expected: " << yes(sum(misplaced) == 0) << std::endl;
  log() << "Solid ids (0-2) on water cells or water ids (3-5) on solid cells: " << sum(wrong_side)
        << ", none expected: " << yes(sum(wrong_side) == 0) << std::endl;
  log() << "Faces with id 0 on a truncation plane of the rock: " << sum(truncation_as_0)
        << ", none expected: " << yes(sum(truncation_as_0) == 0) << std::endl;

  // areas
  const double canyon_H = H * (b0 + bH); // integral of 2 b(z) over [0, H], b linear
  check_relative("Area id 1 (bottom, (x_rd - x_ru) 2Y) [m^2]", area_id[1],
                 (X_rd - X_ru) * 2 * Y, 1e-9);
  check_relative("Area id 2 on y = +-Y (2 (x_rd - x_ru)(H + D)) [m^2]", sum(area_side),
                 2 * (X_rd - X_ru) * (H + D), 1e-9);
  check_relative("Area id 2 on x = x_rd (2Y(H + D) - canyon) [m^2]", sum(area_down),
                 2 * Y * (H + D) - canyon_H, 1e-9);
  {
    // upstream plane: canyon walls y_w(z) at x = x_ru, interpolated linearly
    const auto yw = [&](const double z) { return g.upstream_canyon_wall(+1, X_ru, z)[1]; };
    const double ref = 2 * Y * (H + D) - 2 * integrate(yw, 0., H);
    double       max_d2 = 0;
    for (unsigned int n = 1; n < 1000; ++n)
      {
        const double z = H * n / 1000., dz = 1e-3;
        max_d2 = std::max(max_d2, std::abs(yw(z + dz) - 2 * yw(z) + yw(z - dz)) / (dz * dz));
      }
    // layers: 4 below the water (50.5 m) and 1 above (33 m)
    const double bound = 2 * (4 * std::pow(WL / 4, 3) + std::pow(H - WL, 3)) * max_d2 / 12;
    log() << "Area id 2 on x = x_ru: " << std::setprecision(7) << sum(area_up) << " m^2 (reference "
          << ref << "), difference within the interpolation bound " << std::setprecision(3)
          << bound << " m^2: " << yes(std::abs(sum(area_up) - ref) <= bound) << std::endl;
  }
  check_relative("Area id 4 (reservoir end, |y| < b(z), z < 202) [m^2]", area_id[4],
                 2 * b0 * WL + (bH - b0) * WL * WL / H, 1e-9);
  {
    const double w_ru = g.upstream_canyon_wall(+1, X_ru, 0.)[1];
    const double w_r  = g.upstream_canyon_wall(+1, X_r, 0.)[1];
    check_relative("Area id 5 at z = 0 (reservoir bottom beyond the rock) [m^2]",
                   sum(area_5_bottom), (X_ru - X_r) * (w_ru + w_r), 1e-9);
  }
  {
    // water surface: Green's theorem around the reservoir at z = WL
    const double h    = 1e-6;
    const auto   x_dy = [&](const double u) {
      return g.dam_point(u, 0., WL)[0] *
             (g.dam_point(u + h, 0., WL)[1] - g.dam_point(u - h, 0., WL)[1]) / (2 * h);
    };
    const auto segment = [](const Point<3> &a, const Point<3> &b) {
      return 0.5 * (a[0] + b[0]) * (b[1] - a[1]);
    };
    const Point<3> cp = g.dam_point(1., 0., WL), cm = g.dam_point(-1., 0., WL);
    const Point<3> wp = g.upstream_canyon_wall(+1, X_r, WL), wm = g.upstream_canyon_wall(-1, X_r, WL);
    const double   ref = std::abs(integrate(x_dy, -1., 1.) + segment(cp, wp) +
                                segment(wp, wm) + segment(wm, cm));
    const unsigned int n      = p.n_blocks * p.cells_across_block;
    const double       r      = g.arch_radius(WL) + 0.5 * g.arch_thickness(1., WL);
    const double       dphi   = 2 * g.abutment_angle(WL) / n;
    const double       chords = 2 * n * r * r * std::pow(dphi, 3) / 12;
    log() << "Area id 3 (water surface): " << std::setprecision(7) << area_id[3]
          << " m^2 (reference " << ref << "), difference within 2 n r^2 dphi^3/12 = "
          << std::setprecision(3) << chords << " m^2: "
          << yes(std::abs(area_id[3] - ref) <= chords) << std::endl;
  }

  // --- volumes ---
  const double V_dam = integrate([&](const double z) { return g.dam_section_area(z); }, 0., H);
  check_relative("Dam volume [m^3]", sum(dam_volume), V_dam, 1e-2);
  {
    const double h          = 1e-6;
    const auto   water_area = [&](const double z) {
      const auto x_dy = [&](const double u) {
        return g.dam_point(u, 0., z)[0] *
               (g.dam_point(u + h, 0., z)[1] - g.dam_point(u - h, 0., z)[1]) / (2 * h);
      };
      const auto segment = [](const Point<3> &a, const Point<3> &b) {
        return 0.5 * (a[0] + b[0]) * (b[1] - a[1]);
      };
      const Point<3> cp = g.dam_point(1., 0., z), cm = g.dam_point(-1., 0., z);
      const Point<3> wp = g.upstream_canyon_wall(+1, X_r, z), wm = g.upstream_canyon_wall(-1, X_r, z);
      return std::abs(integrate(x_dy, -1., 1.) + segment(cp, wp) + segment(wp, wm) +
                      segment(wm, cm));
    };
    check_relative("Water volume [m^3]", sum(water_volume), integrate(water_area, 0., WL), 1e-2);
  }

  // --- cell quality: worst cell, ties broken by position so that every run
  // reports the same cell ---
  std::vector<double> worst{2., 0., 0., 0.};
  const auto          better = [](const std::vector<double> &a, const std::vector<double> &b) {
    if (std::abs(a[0] - b[0]) > 1e-12)
      return a[0] < b[0];
    return std::make_tuple(a[2], a[1], a[3]) > std::make_tuple(b[2], b[1], b[3]);
  };
  for (const auto &cell : tria.active_cell_iterators())
    if (cell->is_locally_owned())
      {
        std::array<Point<3>, 8> x;
        for (unsigned int v = 0; v < 8; ++v)
          x[v] = cell->vertex(v);
        const Point<3>              c = cell->center();
        const std::vector<double> q{scaled_jacobian(x), c[0], c[1], c[2]};
        if (better(q, worst))
          worst = q;
      }
  for (const auto &q : Utilities::MPI::all_gather(MPI_COMM_WORLD, worst))
    if (better(q, worst))
      worst = q;
  log() << std::fixed << std::setprecision(2) << "Minimum scaled Jacobian " << worst[0]
        << " in the cell centred at (" << std::setprecision(0) << worst[1] << ", " << worst[2]
        << ", " << worst[3] << ") m, at least 0.2: " << yes(worst[0] >= 0.2) << std::endl;
}
