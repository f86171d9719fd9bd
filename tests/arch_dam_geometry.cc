// The documented arch dam geometry (doc/arch-dam-geometry.md) meets its
// engineering specification: the reference dam's crown thicknesses, crest
// length, canyon widths, abutment thickening, overhang and arch radii, the
// joints' radial planes and the closed-form horizontal section area.
//
// Every reference below is computed here from the prm numbers alone (or by a
// second method), never from ArchDamGeometry's own intermediate results:
//  - distances between points of ArchDamGeometry::dam_point() against the
//    thickness laws T_c(z) = T_0 + (T_H - T_0) z/H and kappa(z) T_c(z);
//  - the crest length as the arc length of the crest's mid-thickness line,
//    integrated numerically (composite Gauss-Legendre of |dP/du|, dP/du by
//    central differences) against the prm value 304.8 m;
//  - the canyon half-width where the mid-thickness line ends against
//    b(z) = b_0 + (b_H - b_0)(z/H)^m with b_H = R_H sin(L_c / (2 R_H));
//  - the arch radius as the circumradius of three points of the mid-thickness
//    line against R(z) = R_0 + (R_H - R_0) z/H, and the joints as lines
//    through that circumcentre;
//  - the closed-form section area 2 R T_c phi_a (1 + (kappa - 1)/3) against
//    Green's theorem (area = -closed integral of x dy) around the section's
//    boundary, integrated numerically.
// Tolerances: the closed forms are exact, so only round-off (1e-12 relative
// for distances of points computed with a few trigonometric functions) and
// the numerical integration remain: a 16 x 20-point Gauss rule on smooth
// integrands is exact to round-off, and central differences with step 1e-6
// have a relative error of order 1e-12 (step^2 times the third derivative,
// plus round-off eps/step ~ 1e-10); 1e-8 covers both with a margin.

#include <archdam/geometry/arch_dam_shape.h>

#include <deal.II/base/quadrature_lib.h>

#include "arch_dam_reference.h"
#include "archdam_tests.h"

#include <cmath>
#include <functional>

using namespace dealii;
using namespace archdam;
using archdam::testing::check_below;
using archdam::testing::check_relative;
using archdam::testing::log;

using archdam::testing::bilinear_area;
using archdam::testing::integrate;
using archdam::testing::scaled_jacobian;

namespace
{

  // Centre and radius of the circle through three points of a horizontal plane.
  std::pair<Point<2>, double>
  circle(const Point<3> &a, const Point<3> &b, const Point<3> &c)
  {
    const double ax = a[0], ay = a[1], bx = b[0], by = b[1], cx = c[0], cy = c[1];
    const double d  = 2 * (ax * (by - cy) + bx * (cy - ay) + cx * (ay - by));
    const double ux = ((ax * ax + ay * ay) * (by - cy) + (bx * bx + by * by) * (cy - ay) +
                       (cx * cx + cy * cy) * (ay - by)) /
                      d;
    const double uy = ((ax * ax + ay * ay) * (cx - bx) + (bx * bx + by * by) * (ax - cx) +
                       (cx * cx + cy * cy) * (bx - ax)) /
                      d;
    return {Point<2>(ux, uy), std::hypot(ax - ux, ay - uy)};
  }
} // namespace

int
main(int argc, char **argv)
{
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);

  const geometry::ArchDamParameters p;
  const geometry::ArchDamGeometry   g(p);
  const double                      H = 235., tol = 1e-8;

  log() << "Reference dam: crown cantilever" << std::endl;
  const auto thickness = [&](const double u, const double z) {
    return g.dam_point(u, 0., z).distance(g.dam_point(u, 1., z));
  };
  check_relative("  crown thickness at the crest [m]", thickness(0, H), 10., tol);
  check_relative("  crown thickness at the base [m]", thickness(0, 0), 48., tol);
  check_relative("  crown thickness at mid-height [m]", thickness(0, H / 2), 29., tol);
  check_below("  |x of the heel| [m]", std::abs(g.dam_point(0, 0, 0)[0]), 1e-12);
  check_below("  |x of the crest's upstream edge - setback 0| [m]",
              std::abs(g.dam_point(0, 0, H)[0]), 1e-12);
  check_relative("  upstream bulge at mid-height, -x [m]", -g.dam_point(0, 0, H / 2)[0], 15.,
                 tol);
  check_below("  |y| of the crown cantilever [m]",
              std::abs(g.dam_point(0, 0, 100)[1]) + std::abs(g.dam_point(0, 1, 100)[1]), 1e-12);

  log() << "Arches" << std::endl;
  const auto dPdu = [&](const double u, const double s, const double z) {
    const double h = 1e-6;
    return (g.dam_point(u + h, s, z) - g.dam_point(u - h, s, z)) / (2 * h);
  };
  const double crest_arc =
    integrate([&](const double u) { return dPdu(u, 0.5, H).norm(); }, -1., 1.);
  check_relative("  crest length along the mid-thickness line [m]", crest_arc, 304.8, tol);

  const double R0 = 80., RH = 170., b0 = 40., bH = RH * std::sin(304.8 / (2 * RH));
  for (const double z : {0., 58.75, 117.5, 176.25, 235.})
    {
      const double zeta = z / H;
      const auto [centre, R] =
        circle(g.dam_point(-0.7, 0.5, z), g.dam_point(0.1, 0.5, z), g.dam_point(0.9, 0.5, z));
      std::ostringstream what;
      what << "  z = " << z << ": ";
      check_relative(what.str() + "radius of the mid-thickness line [m]", R,
                     R0 + (RH - R0) * zeta, tol);
      const double b = b0 + (bH - b0) * zeta; // canyon shape exponent 1
      check_relative(what.str() + "y of the +y abutment (mid-thickness) [m]",
                     g.dam_point(1, 0.5, z)[1], b, tol);
      check_relative(what.str() + "-y of the -y abutment (mid-thickness) [m]",
                     -g.dam_point(-1, 0.5, z)[1], b, tol);
      const double kappa = 1.1 + (1.5 - 1.1) * zeta;
      const double Tc    = 48. + (10. - 48.) * zeta;
      check_relative(what.str() + "arch thickness at the abutments [m]", thickness(1, z),
                     kappa * Tc, tol);
      check_relative(what.str() + "arch thickness at u = 0.6 [m]", thickness(0.6, z),
                     Tc * (1 + (kappa - 1) * 0.36), tol);

      // joints: every point of joint k lies on the line from the arch centre
      // at angle u_k phi_a(z), phi_a = asin(b / R)
      double worst = 0;
      for (unsigned int k = 0; k + 1 < p.n_blocks; ++k)
        for (const double s : {0., 0.5, 1.})
          {
            const Point<3> q   = g.dam_point(1. - 2. * (k + 1) / p.n_blocks, s, z);
            const double   phi = std::atan2(q[1], centre[0] - q[0]);
            worst = std::max(worst, std::abs(phi - (1. - 2. * (k + 1) / p.n_blocks) *
                                                    std::asin(b / R)));
          }
      check_below(what.str() + "largest angle of a joint point off its radial line [rad]",
                  worst, tol);

      // section area: closed form against Green's theorem around the ring
      // (upstream face from u = -1 to 1, abutment +1 from s = 0 to 1,
      // downstream face from u = 1 to -1, abutment -1 from s = 1 to 0)
      const auto x_dy = [&](const double s, const double u) {
        const double h = 1e-6;
        return g.dam_point(u, s, z)[0] *
               (g.dam_point(u + h, s, z)[1] - g.dam_point(u - h, s, z)[1]) / (2 * h);
      };
      const auto segment = [&](const Point<3> &a, const Point<3> &c) {
        return 0.5 * (a[0] + c[0]) * (c[1] - a[1]); // exact for a straight segment
      };
      const double loop =
        integrate([&](const double u) { return x_dy(0., u); }, -1., 1.) +
        segment(g.dam_point(1, 0, z), g.dam_point(1, 1, z)) -
        integrate([&](const double u) { return x_dy(1., u); }, -1., 1.) +
        segment(g.dam_point(-1, 1, z), g.dam_point(-1, 0, z));
      check_relative(what.str() + "section area, closed form [m^2]", g.dam_section_area(z),
                     std::abs(loop), tol);
    }

  log() << "Blocks: block 0 on the left bank looking downstream (+y)" << std::endl;
  bool ordered = true;
  for (unsigned int k = 0; k < p.n_blocks; ++k)
    {
      // centre of block k in u, and its y at mid-height
      const double u = 1. - (2. * k + 1) / p.n_blocks;
      const double y = g.dam_point(u, 0.5, H / 2)[1];
      if (k > 0 && !(y < g.dam_point(1. - (2. * k - 1) / p.n_blocks, 0.5, H / 2)[1]))
        ordered = false;
      if (k == 0 && !(y > 0))
        ordered = false;
    }
  log() << "  block centres ordered from +y to -y: " << (ordered ? "yes" : "NO") << std::endl;

  log() << "Model extents" << std::endl;
  check_relative("  foundation bottom z [m]", g.rock_bottom(), -H, 1e-12);
  check_relative("  rock upstream truncation x [m]", g.rock_upstream_x(), -H, 1e-12);
  check_relative("  rock downstream truncation x [m]", g.rock_downstream_x(), 48. + H, 1e-12);
  check_relative("  rock lateral truncation |y| [m]", g.rock_side_y(), bH + H, 1e-12);
  check_relative("  reservoir upstream truncation x [m]", g.reservoir_end_x(), -3 * 202., 1e-12);
}
