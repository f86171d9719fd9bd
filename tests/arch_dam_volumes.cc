// Dam volume, water volume and wetted area of the generated arch dam mesh
// converge to an independent integration of the documented geometry (issue 3,
// must show 2).
//
// Meshes: the reference dam with 1, 2, 4 and 8 cells across each block and
// through the thickness and 4, 8, 16, 32 cells over the height (rock and water
// cells coarse: they do not change the dam or the water region).
// Measured on each mesh:
//  - dam and water volume: the sum of the cell measures (exact volumes of the
//    trilinear cells);
//  - wetted area: the sum of the areas of the dam faces that touch water,
//    each the area of the bilinear face, integrated with a 4 x 4 Gauss rule.
// References, from the geometry's formulas only (no mesh):
//  - dam volume: integral over z in [0, H] of the section area
//    2 R T_c phi_a (1 + (kappa - 1)/3) (arch_dam_geometry checks this closed
//    form against Green's theorem);
//  - water volume: integral over z in [0, WL] of the reservoir's plan area,
//    by Green's theorem (area = |closed integral of x dy|) around its
//    boundary: the dam's upstream face (integrated numerically), the two
//    straight canyon walls from the dam's upstream abutment corners, and the
//    upstream truncation x = x_r;
//  - wetted area: the double integral of |dP/du x dP/dz| over the upstream
//    face P(u, 0, z), u in [-1, 1], z in [0, WL].
// All integrals use composite Gauss-Legendre rules (16 panels x 20 points per
// direction) and central differences with step 1e-6, accurate to ~1e-10:
// far below the mesh differences.
// Expected: the mesh interpolates the curved faces with (bi/tri)linear cells
// whose vertices lie on the exact surfaces, a second-order approximation, so
// each halving of the cell size divides the difference by about 4. Checks:
// the difference shrinks at every refinement, the observed order on the last
// refinement is at least 1.5, and on the finest mesh the relative difference
// is below 1e-4 (the order-2 prediction from the coarsest mesh's difference,
// about 3e-3 / 4^3 = 5e-5, with a margin of 2).

#include <archdam/geometry/arch_dam_mesh.h>
#include <archdam/geometry/arch_dam_shape.h>
#include <archdam/geometry/ids.h>

#include <deal.II/base/quadrature_lib.h>
#include <deal.II/grid/tria.h>
#include <deal.II/grid/tria_accessor.h>
#include <deal.II/grid/tria_iterator.h>

#include "arch_dam_reference.h"
#include "archdam_tests.h"

#include <cmath>
#include <functional>
#include <vector>

using namespace dealii;
using namespace archdam;
using archdam::testing::log;

using archdam::testing::bilinear_area;
using archdam::testing::integrate;
using archdam::testing::scaled_jacobian;

namespace
{


  struct Measures
  {
    unsigned int n_dam = 0;
    double       dam_volume = 0, water_volume = 0, wetted_area = 0;
  };

  Measures
  measure(const geometry::ArchDamParameters &p)
  {
    Triangulation<3> tria;
    geometry::generate_arch_dam(p, tria);
    Measures m;
    for (const auto &cell : tria.active_cell_iterators())
      if (ids::is_dam(cell->material_id()))
        {
          ++m.n_dam;
          m.dam_volume += cell->measure();
          for (unsigned int f = 0; f < 6; ++f)
            if (!cell->face(f)->at_boundary() &&
                cell->neighbor(f)->material_id() == ids::water)
              {
                std::array<Point<3>, 4> v;
                for (unsigned int i = 0; i < 4; ++i)
                  v[i] = cell->face(f)->vertex(i);
                m.wetted_area += bilinear_area(v);
              }
        }
      else if (cell->material_id() == ids::water)
        m.water_volume += cell->measure();
    return m;
  }
} // namespace

int
main(int argc, char **argv)
{
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);

  geometry::ArchDamParameters p;
  p.rock_cell_size  = 200.;
  p.water_cell_size = 200.;
  const geometry::ArchDamGeometry g(p);
  const double                    H = p.height, WL = p.water_level, h = 1e-6;

  // --- references ---
  const double V_dam = integrate([&](const double z) { return g.dam_section_area(z); }, 0., H);

  const double x_r       = g.reservoir_end_x();
  const auto   water_area = [&](const double z) {
    const auto x_dy = [&](const double u) {
      return g.dam_point(u, 0., z)[0] *
             (g.dam_point(u + h, 0., z)[1] - g.dam_point(u - h, 0., z)[1]) / (2 * h);
    };
    const auto segment = [](const Point<3> &a, const Point<3> &b) {
      return 0.5 * (a[0] + b[0]) * (b[1] - a[1]);
    };
    const Point<3> c_plus = g.dam_point(1., 0., z), c_minus = g.dam_point(-1., 0., z);
    const Point<3> w_plus  = g.upstream_canyon_wall(+1, x_r, z);
    const Point<3> w_minus = g.upstream_canyon_wall(-1, x_r, z);
    // face from u = -1 to +1, wall +, truncation, wall -
    return std::abs(integrate(x_dy, -1., 1.) + segment(c_plus, w_plus) +
                    segment(w_plus, w_minus) + segment(w_minus, c_minus));
  };
  const double V_water = integrate(water_area, 0., WL);

  const double A_wet = integrate(
    [&](const double z) {
      return integrate(
        [&](const double u) {
          const Tensor<1, 3> pu = (g.dam_point(u + h, 0., z) - g.dam_point(u - h, 0., z)) / (2 * h);
          const Tensor<1, 3> pz = (g.dam_point(u, 0., z + h) - g.dam_point(u, 0., z - h)) / (2 * h);
          return cross_product_3d(pu, pz).norm();
        },
        -1., 1.);
    },
    0., WL);

  log() << std::setprecision(6) << "References (numerical integration of the geometry):\n"
        << "  dam volume " << V_dam << " m^3, water volume " << V_water
        << " m^3, wetted area " << A_wet << " m^2" << std::endl;

  // --- meshes ---
  const char *names[3] = {"dam volume", "water volume", "wetted area"};
  const double refs[3] = {V_dam, V_water, A_wet};
  std::vector<std::array<double, 3>> diffs;
  for (unsigned int r = 0; r < 4; ++r)
    {
      const unsigned int n  = 1u << r;
      p.cells_across_block  = n;
      p.cells_through       = n;
      p.cells_over_height   = 4 * n;
      const Measures m      = measure(p);
      const double   val[3] = {m.dam_volume, m.water_volume, m.wetted_area};
      std::array<double, 3> d;
      log() << "Mesh " << r << " (" << n << " across each block, " << n << " through, "
            << 4 * n << " over the height; " << m.n_dam << " dam cells): relative differences";
      for (unsigned int i = 0; i < 3; ++i)
        {
          d[i] = std::abs(val[i] - refs[i]) / refs[i];
          log() << ' ' << names[i] << ' ' << std::scientific << std::setprecision(1) << d[i];
        }
      log() << std::defaultfloat << std::endl;
      diffs.push_back(d);
    }

  for (unsigned int i = 0; i < 3; ++i)
    {
      bool shrinking = true;
      for (unsigned int r = 1; r < diffs.size(); ++r)
        shrinking = shrinking && diffs[r][i] < diffs[r - 1][i];
      const double order = std::log2(diffs[2][i] / diffs[3][i]);
      log() << names[i] << ": difference shrinks at every refinement: "
            << (shrinking ? "yes" : "NO") << "; observed order on the last refinement "
            << std::fixed << std::setprecision(1) << order
            << ", at least 1.5: " << (order >= 1.5 ? "yes" : "NO")
            << "; finest difference below 1e-4: " << (diffs[3][i] < 1e-4 ? "yes" : "NO")
            << std::defaultfloat << std::endl;
    }
}
