// The parametric arch dam with its joints as built (`Mesh/Arch dam/Joints =
// vertical`, doc/arch-dam-geometry.md §2): vertical joint planes, radial in
// plan at the crest, each block founded on a horizontal step of the canyon.
// Meshed as geometry/mesh.cc does (conforming, before the splitter), the
// reference dam with its rock and water on coarse rock and water cells.
//
//  A. The foundation steps: symmetric about the crown (block k and block
//     n - 1 - k, 1e-9 m), rising from the crown outwards, the crown blocks
//     on the canyon floor, and at each step the block's inner plane meets
//     the canyon wall at the dam's mid-thickness: there its point has
//     |y| = b(z_f) (the wall of doc/arch-dam-geometry.md §2, 1e-6 m; the
//     bisection's tolerance is far below).
//  B. The joints: every face shared by blocks k and k+1 has its four
//     vertices on the vertical plane through the crest arch's centre
//     (x_c(H), 0) at the crest angle u_k phi_a(H) (1e-9 m), and joint k has
//     (cells through the thickness) x (layers above the higher of the two
//     blocks' steps) faces: it reaches from the higher step to the crest.
//  C. The blocks on their steps: every dam cell of block k lies above its
//     step z_f(k) (1e-9 m), and its faces against the rock are either
//     horizontal at z_f(k) (the step, 1e-9 m) or on a joint plane (the
//     riser beside an inner block; B's tolerance), so no block rests on
//     another's rock in between.
//  D. The dam's volume against an independent integral of the geometry: the
//     horizontal section at z is bounded by the upstream and downstream
//     arcs and the two outermost planes of the blocks founded below z; its
//     area by Green's theorem on 4000 boundary points per arc, integrated
//     over z by 20-point Gauss in each interval between steps (the section
//     jumps at a step). The mesh's straight-sided cells replace the arcs by
//     chords: second order; 3e-3 as for the fanned layout's coarsest mesh
//     (arch_dam_volumes), measured 3.8e-5 here (the joint planes, the steps
//     and the vertical extent are exact; only the arcs are chords).
//  E. Cell quality: minimum scaled Jacobian at least 0.2, as for the
//     fanned mesh (doc/arch-dam-geometry.md §6).
// The test also writes arch_dam_model_vertical.txt, from which
// scripts/plot_arch_dam.py draws the layout's pictures.

#include <archdam/geometry/arch_dam_mesh.h>
#include <archdam/geometry/arch_dam_shape.h>
#include <archdam/geometry/ids.h>
#include <archdam/geometry/mesh_checks.h>

#include <deal.II/base/quadrature_lib.h>

#include "arch_dam_plot_data.h"
#include <deal.II/distributed/shared_tria.h>
#include <deal.II/grid/tria.h>

#include "archdam_tests.h"

#include <algorithm>
#include <cmath>
#include <map>
#include <set>
#include <vector>

using namespace dealii;
using namespace archdam;
using archdam::testing::check_below;
using archdam::testing::log;

namespace
{
  geometry::ArchDamParameters
  parameters()
  {
    geometry::ArchDamParameters p;
    p.joints          = geometry::JointLayout::vertical;
    p.rock_cell_size  = 120;
    p.water_cell_size = 100;
    return p;
  }

  /// The signed distance of @p x from the vertical plane of crest coordinate u.
  double
  plane_distance(const geometry::ArchDamGeometry &g, const double u, const Point<3> &x)
  {
    const double psi = u * g.abutment_angle(g.height()), x_H = g.arch_center_x(g.height());
    return (x[0] - x_H) * std::sin(psi) + x[1] * std::cos(psi);
  }

  /// The area of the dam's horizontal section at z with the blocks
  /// [first, last] (Green's theorem on the boundary polygon).
  double
  section_area(const geometry::ArchDamGeometry &g, const double z, const unsigned int first,
               const unsigned int last)
  {
    const unsigned int n   = g.parameters().n_blocks;
    const double       u_a = 1. - 2. * first / n, u_b = 1. - 2. * (last + 1) / n;
    // arch coordinate u' of the planes at z on arc s
    const auto arch_u = [&](const double u, const double s) {
      const Point<3> q = g.column_point(u, s, z);
      return g.arch_angle(q) / g.abutment_angle(z);
    };
    std::vector<Point<3>> boundary;
    const unsigned int    m = 4000;
    for (const double s : {0., 1.})
      {
        const double a = arch_u(s == 0. ? u_a : u_b, s), b = arch_u(s == 0. ? u_b : u_a, s);
        for (unsigned int i = 0; i <= m; ++i)
          boundary.push_back(g.dam_point(a + (b - a) * i / m, s, z));
      }
    double twice = 0;
    for (unsigned int i = 0; i < boundary.size(); ++i)
      {
        const Point<3> &p = boundary[i], &q = boundary[(i + 1) % boundary.size()];
        twice += p[0] * q[1] - q[0] * p[1];
      }
    return std::abs(twice) / 2;
  }
} // namespace

int
main(int argc, char **argv)
{
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  const auto                       p = parameters();
  const geometry::ArchDamGeometry  g(p);
  const unsigned int               n = p.n_blocks;

  // A. the steps
  log() << "--- A. foundation steps ---" << std::endl;
  double symmetry = 0, wall = 0;
  bool   rising   = true;
  for (unsigned int k = 0; k < n; ++k)
    {
      const double z_f = g.block_floor(k);
      log() << "block " << k << ": step at " << std::fixed << std::setprecision(2) << z_f << " m"
            << std::defaultfloat << std::endl;
      symmetry = std::max(symmetry, std::abs(z_f - g.block_floor(n - 1 - k)));
      if (k + 1 < n / 2)
        rising = rising && z_f >= g.block_floor(k + 1);
      if (z_f > 0)
        {
          const double   u_in = k < n / 2 ? 1. - 2. * (k + 1) / n : 1. - 2. * k / n;
          const Point<3> q    = g.column_point(u_in, 0.5, z_f);
          wall                = std::max(wall, std::abs(std::abs(q[1]) - g.canyon_half_width(z_f)));
        }
    }
  check_below("A. |z_f(k) - z_f(n - 1 - k)| [m]", symmetry, 1e-9);
  log() << "A. steps rise from the crown outwards, crown blocks on the floor: "
        << (rising && g.block_floor(n / 2) == 0. && g.block_floor(n / 2 - 1) == 0. ? "yes" : "NO")
        << std::endl;
  check_below("A. at each step, ||y| - b(z_f)| of the inner plane's mid-thickness point [m]",
              wall, 1e-6);

  parallel::shared::Triangulation<dim> tria(MPI_COMM_WORLD);
  {
    Triangulation<dim> serial;
    geometry::generate_arch_dam(p, serial);
    tria.copy_triangulation(serial);
    if (Utilities::MPI::this_mpi_process(MPI_COMM_WORLD) == 0)
      archdam::testing::write_arch_dam_plot_data(g, serial, "arch_dam_model_vertical.txt");
  }

  // B and C: joints and blocks
  const auto block = [](const types::material_id m) { return m - ids::first_dam_block; };
  std::map<unsigned int, unsigned int> joint_faces;
  double                               off_plane = 0, below_step = 0, off_step = 0;
  unsigned int                         rock_faces_off = 0;
  for (const auto &cell : tria.active_cell_iterators())
    if (cell->is_locally_owned() && ids::is_dam(cell->material_id()))
      {
        const unsigned int k = block(cell->material_id());
        for (const unsigned int v : cell->vertex_indices())
          below_step = std::max(below_step, g.block_floor(k) - cell->vertex(v)[2]);
        for (const unsigned int f : cell->face_indices())
          {
            if (cell->face(f)->at_boundary())
              continue;
            const auto nb = cell->neighbor(f);
            if (ids::is_dam(nb->material_id()) && block(nb->material_id()) == k + 1)
              {
                ++joint_faces[k];
                for (unsigned int v = 0; v < 4; ++v)
                  off_plane = std::max(off_plane, std::abs(plane_distance(
                                                    g, 1. - 2. * (k + 1) / n, cell->face(f)->vertex(v))));
              }
            if (nb->material_id() == ids::rock)
              {
                // horizontal at the step, or on one of the block's planes
                double step = 0, plane = HUGE_VAL;
                for (unsigned int v = 0; v < 4; ++v)
                  step = std::max(step, std::abs(cell->face(f)->vertex(v)[2] - g.block_floor(k)));
                for (const double u : {1. - 2. * k / n, 1. - 2. * (k + 1) / n})
                  {
                    double d = 0;
                    for (unsigned int v = 0; v < 4; ++v)
                      d = std::max(d, std::abs(plane_distance(g, u, cell->face(f)->vertex(v))));
                    plane = std::min(plane, d);
                  }
                if (step < 1e-9)
                  off_step = std::max(off_step, step);
                else if (!(plane < 1e-9))
                  ++rock_faces_off;
              }
          }
      }
  log() << "--- B. joints ---" << std::endl;
  for (unsigned int k = 0; k + 1 < n; ++k)
    {
      const unsigned int faces = Utilities::MPI::sum(joint_faces[k], MPI_COMM_WORLD);
      log() << "joint " << k << ": " << faces << " faces" << std::endl;
    }
  check_below("B. largest distance of a joint face's vertex from its plane [m]",
              Utilities::MPI::max(off_plane, MPI_COMM_WORLD), 1e-9);
  log() << "--- C. blocks on their steps ---" << std::endl;
  check_below("C. largest depth of a block's vertex below its step [m]",
              Utilities::MPI::max(below_step, MPI_COMM_WORLD), 1e-9);
  log() << "C. faces against the rock neither on the step nor on a joint plane: "
        << Utilities::MPI::sum(rock_faces_off, MPI_COMM_WORLD) << std::endl;

  // D. volume
  log() << "--- D. dam volume ---" << std::endl;
  double mesh_volume = 0;
  for (const auto &cell : tria.active_cell_iterators())
    if (cell->is_locally_owned() && ids::is_dam(cell->material_id()))
      mesh_volume += cell->measure();
  mesh_volume = Utilities::MPI::sum(mesh_volume, MPI_COMM_WORLD);
  std::set<double> breaks{0., g.height()};
  for (unsigned int k = 0; k < n; ++k)
    breaks.insert(g.block_floor(k));
  const QGauss<1> gauss(20);
  double          volume = 0;
  for (auto it = breaks.begin(); std::next(it) != breaks.end(); ++it)
    {
      const double a = *it, b = *std::next(it);
      unsigned int first = 0, last = n - 1;
      while (g.block_floor(first) > a)
        ++first;
      while (g.block_floor(last) > a)
        --last;
      for (unsigned int q = 0; q < gauss.size(); ++q)
        volume += gauss.weight(q) * (b - a) * section_area(g, a + (b - a) * gauss.point(q)[0], first, last);
    }
  log() << "D. the geometry's volume " << std::setprecision(6) << volume << " m^3, the mesh's "
        << mesh_volume << " m^3" << std::defaultfloat << std::endl;
  check_below("D. |V_mesh - V| / V", std::abs(mesh_volume - volume) / volume, 3e-3);
  log() << "D. measured " << std::setprecision(2) << std::scientific
        << std::abs(mesh_volume - volume) / volume << std::defaultfloat
        << "; the fanned layout's volume (doc/arch-dam-geometry.md §2) "
        << std::setprecision(6) << [&] {
             double v = 0;
             const QGauss<1> q(40);
             for (unsigned int i = 0; i < q.size(); ++i)
               v += q.weight(i) * g.height() * g.dam_section_area(q.point(i)[0] * g.height());
             return v;
           }()
        << " m^3" << std::defaultfloat << std::endl;

  // E. quality
  double worst = HUGE_VAL;
  for (const auto &cell : tria.active_cell_iterators())
    if (cell->is_locally_owned())
      worst = std::min(worst, geometry::scaled_jacobian(cell));
  worst = Utilities::MPI::min(worst, MPI_COMM_WORLD);
  log() << "--- E. cell quality ---" << std::endl;
  log() << "E. minimum scaled Jacobian " << std::fixed << std::setprecision(2) << worst
        << (worst >= 0.2 ? " (at least 0.2: yes)" : " (at least 0.2: NO)") << std::defaultfloat
        << std::endl;
  return 0;
}
