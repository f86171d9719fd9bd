// The shape of the double-curvature arch dam in its canyon: the crown
// cantilever, the horizontal arches, the canyon and the model's extents as
// functions of the elevation (doc/arch-dam-geometry.md gives every formula),
// and the checks that the parameters give a dam that fits its canyon.

#include <archdam/base/number_text.h>
#include <archdam/geometry/arch_dam_shape.h>

#include <algorithm>
#include <cmath>
#include <string>

namespace archdam::geometry
{
  using namespace dealii;

  ArchDamGeometry::ArchDamGeometry(const ArchDamParameters &p)
    : prm(p)
    , crest_half_width(0.)
  {
    const double H = p.height;
    if (!(H > 0) || !(p.crest_length > 0) || !(p.crown_thickness_crest > 0) ||
        !(p.crown_thickness_base > 0) || !(p.arch_radius_crest > 0) ||
        !(p.arch_radius_base > 0) || !(p.canyon_width_base > 0))
      arch_dam_input_error("Height, Crest length, crown thicknesses, arch radii and Canyon "
                           "width at base must be positive.");
    if (p.n_blocks < 1 || p.cells_across_block < 1 || p.cells_through < 1 ||
        p.cells_over_height < 1)
      arch_dam_input_error("the numbers of blocks and cells must be at least 1.");
    const double half_angle = p.crest_length / (2 * p.arch_radius_crest);
    if (half_angle >= 0.5 * M_PI * 0.95)
      arch_dam_input_error("the crest arch spans " + number_text(2 * half_angle * 180 / M_PI) +
                           " degrees (Crest length / Arch radius at crest); it must stay "
                           "below 171.");
    crest_half_width = p.arch_radius_crest * std::sin(half_angle);
    if (p.water_level < 0 || p.water_level > H)
      arch_dam_input_error("Water level (" + number_text(p.water_level) +
                           " m) must lie between 0 and Height (" + number_text(H) + " m).");

    // The arch at every elevation: the canyon must be narrower than the arch's
    // diameter (the mid-thickness line meets the wall), and the downstream face
    // radius must stay positive.
    for (unsigned int n = 0; n <= 1000; ++n)
      {
        const double z = H * n / 1000.;
        const double b = canyon_half_width(z);
        const double R = arch_radius(z);
        if (!(b < 0.99 * R))
          arch_dam_input_error("at elevation " + number_text(z) + " m the canyon half-width (" +
                               number_text(b) + " m) is not below the arch radius (" +
                               number_text(R) +
                               " m): the arch cannot reach the canyon walls. Increase the "
                               "arch radii or narrow the canyon.");
        if (!(R - 0.5 * arch_thickness(1., z) > 0.05 * R))
          arch_dam_input_error("at elevation " + number_text(z) + " m the arch (radius " +
                               number_text(R) + " m) is too thick at the abutments (" +
                               number_text(arch_thickness(1., z)) +
                               " m): its downstream face would pass the arch centre. Reduce "
                               "the abutment thickening or the crown thickness, or increase "
                               "the arch radius.");
      }

    if (has_rock())
      {
        // The dam must lie inside the rock block.
        for (unsigned int n = 0; n <= 100; ++n)
          for (const double u : {-1., 0., 1.})
            for (const double s : {0., 1.})
              {
                const Point<3>    q = dam_point(u, s, H * n / 100.);
                const std::string where =
                  !(q[0] > rock_upstream_x())   ? "upstream" :
                  !(q[0] < rock_downstream_x()) ? "downstream" :
                  !(std::abs(q[1]) < rock_side_y()) ? "to the sides" : "";
                if (!where.empty())
                  arch_dam_input_error("the dam reaches beyond the foundation block at (" +
                                       number_text(q[0]) + ", " + number_text(q[1]) + ", " +
                                       number_text(q[2]) +
                                       ") m; increase Foundation extent " + where + ".");
              }
      }
    if (has_water())
      for (unsigned int n = 0; n <= 100; ++n)
        if (!(crown_upstream_face(p.water_level * n / 100.) > reservoir_end_x()))
          arch_dam_input_error("the reservoir is shorter than the dam's upstream overhang; "
                               "increase Reservoir length.");

    // The blocks' foundation steps (vertical joints): the lowest elevation
    // at which the inner plane's mid-thickness point lies within the canyon
    // (|u'| <= 1), by bisection; the canyon widens upwards, so above it the
    // plane stays within.
    floors.assign(p.n_blocks, 0.);
    if (p.joints == JointLayout::vertical)
      for (unsigned int k = 0; k < p.n_blocks; ++k)
        {
          const double u_a = 1. - 2. * k / p.n_blocks, u_b = 1. - 2. * (k + 1) / p.n_blocks;
          if (u_a > 0 && u_b < 0)
            continue; // the crown block
          const double u_in   = std::abs(u_a) < std::abs(u_b) ? u_a : u_b;
          const auto   inside = [&](const double z) {
            double phi;
            return plane_angle(u_in, 0.5, z, phi) && std::abs(phi) <= abutment_angle(z);
          };
          if (inside(0.))
            continue;
          double low = 0., high = H;
          for (unsigned int n = 0; n < 60; ++n)
            (inside(0.5 * (low + high)) ? high : low) = 0.5 * (low + high);
          floors[k] = high;
        }
  }

  bool
  ArchDamGeometry::plane_angle(const double u, const double s, const double z, double &phi) const
  {
    // The point P(phi) = (x_c(z) - r cos phi, r sin phi) of the arc s, with
    // r = R(z) + T(phi / phi_a(z), z)(1/2 - s), lies on the plane through
    // (x_c(H), 0) along (-cos psi, sin psi) where the 2-D cross product
    // f(phi) = (P_x - x_c(H)) sin psi + P_y cos psi vanishes; f grows with phi
    // over the dam.
    const double psi = u * abutment_angle(prm.height), x_H = arch_center_x(prm.height);
    const double x_c = arch_center_x(z), phi_a = abutment_angle(z);
    const auto   f   = [&](const double angle) {
      const double r = arch_radius(z) + arch_thickness(angle / phi_a, z) * (0.5 - s);
      return (x_c - r * std::cos(angle) - x_H) * std::sin(psi) + r * std::sin(angle) * std::cos(psi);
    };
    double low = -1.5, high = 1.5;
    if (!(f(low) < 0 && f(high) > 0))
      return false;
    for (unsigned int n = 0; n < 80 && high - low > 1e-15; ++n)
      (f(0.5 * (low + high)) > 0 ? high : low) = 0.5 * (low + high);
    phi = 0.5 * (low + high);
    return true;
  }

  Point<3>
  ArchDamGeometry::column_point(const double u, const double s, const double z) const
  {
    if (prm.joints == JointLayout::fanned)
      return dam_point(u, s, z);
    double phi;
    if (!plane_angle(u, s, z, phi))
      arch_dam_input_error("the vertical joint plane at the crest coordinate u = " +
                           number_text(u) + " does not meet the arch at elevation " +
                           number_text(z) + " m; use Joints = fanned or a wider arch.");
    return dam_point(phi / abutment_angle(z), s, z);
  }

  double
  ArchDamGeometry::block_floor(const unsigned int k) const
  {
    return floors[k];
  }

  double
  ArchDamGeometry::crown_upstream_face(const double z) const
  {
    const double zeta = z / prm.height;
    return prm.crest_setback * zeta - 4 * prm.upstream_overhang * zeta * (1 - zeta);
  }

  double
  ArchDamGeometry::crown_thickness(const double z) const
  {
    const double zeta = z / prm.height;
    return prm.crown_thickness_base +
           (prm.crown_thickness_crest - prm.crown_thickness_base) * zeta;
  }

  double
  ArchDamGeometry::crown_downstream_face(const double z) const
  {
    return crown_upstream_face(z) + crown_thickness(z);
  }

  double
  ArchDamGeometry::arch_radius(const double z) const
  {
    const double zeta = z / prm.height;
    return prm.arch_radius_base + (prm.arch_radius_crest - prm.arch_radius_base) * zeta;
  }

  double
  ArchDamGeometry::arch_center_x(const double z) const
  {
    return crown_upstream_face(z) + 0.5 * crown_thickness(z) + arch_radius(z);
  }

  double
  ArchDamGeometry::canyon_half_width(const double z) const
  {
    const double zeta = std::min(std::max(z / prm.height, 0.), 1.);
    const double b0   = 0.5 * prm.canyon_width_base;
    return b0 + (crest_half_width - b0) * std::pow(zeta, prm.canyon_shape_exponent);
  }

  double
  ArchDamGeometry::abutment_angle(const double z) const
  {
    return std::asin(canyon_half_width(z) / arch_radius(z));
  }

  double
  ArchDamGeometry::abutment_thickening(const double z) const
  {
    const double zeta = z / prm.height;
    return prm.abutment_thickening_base +
           (prm.abutment_thickening_crest - prm.abutment_thickening_base) * zeta;
  }

  double
  ArchDamGeometry::arch_thickness(const double u, const double z) const
  {
    return crown_thickness(z) * (1 + (abutment_thickening(z) - 1) * u * u);
  }

  Point<3>
  ArchDamGeometry::dam_point(const double u, const double s, const double z) const
  {
    const double phi = u * abutment_angle(z);
    const double r   = arch_radius(z) + arch_thickness(u, z) * (0.5 - s);
    return Point<3>(arch_center_x(z) - r * std::cos(phi), r * std::sin(phi), z);
  }

  double
  ArchDamGeometry::arch_angle(const Point<3> &p) const
  {
    const double z = std::min(std::max(p[2], 0.), prm.height);
    return std::atan2(p[1], arch_center_x(z) - p[0]);
  }

  double
  ArchDamGeometry::joint_u(const unsigned int k) const
  {
    return 1. - 2. * (k + 1) / prm.n_blocks;
  }

  double
  ArchDamGeometry::dam_section_area(const double z) const
  {
    // Ring area: integral over phi of (r_u^2 - r_d^2)/2 = R T(u) (r_u + r_d = 2R),
    // with d phi = phi_a du and the mean of 1 + (kappa-1) u^2 over [-1,1].
    return 2 * arch_radius(z) * crown_thickness(z) * abutment_angle(z) *
           (1 + (abutment_thickening(z) - 1) / 3.);
  }

  double
  ArchDamGeometry::rock_bottom() const
  {
    return -prm.foundation_depth * prm.height;
  }

  double
  ArchDamGeometry::rock_upstream_x() const
  {
    return crown_upstream_face(0.) - prm.foundation_upstream * prm.height;
  }

  double
  ArchDamGeometry::rock_downstream_x() const
  {
    return crown_downstream_face(0.) + prm.foundation_downstream * prm.height;
  }

  double
  ArchDamGeometry::rock_side_y() const
  {
    return crest_half_width + prm.foundation_sides * prm.height;
  }

  double
  ArchDamGeometry::reservoir_end_x() const
  {
    return crown_upstream_face(0.) - prm.reservoir_length * prm.water_level;
  }

  double
  ArchDamGeometry::model_upstream_x() const
  {
    if (!has_rock())
      return reservoir_end_x();
    if (!has_water())
      return rock_upstream_x();
    return std::min(rock_upstream_x(), reservoir_end_x());
  }

  Point<3>
  ArchDamGeometry::upstream_canyon_wall(const int side, const double x, const double z) const
  {
    const Point<3> a  = dam_point(side > 0 ? 1. : -1., 0., z);
    const double   xe = model_upstream_x();
    const double   ye = (side > 0 ? 1. : -1.) * canyon_half_width(z);
    return Point<3>(x, a[1] + (ye - a[1]) * (x - a[0]) / (xe - a[0]), z);
  }

  Point<3>
  ArchDamGeometry::downstream_canyon_wall(const int side, const double x, const double z) const
  {
    const Point<3> a  = dam_point(side > 0 ? 1. : -1., 1., z);
    const double   xe = rock_downstream_x();
    const double   ye = (side > 0 ? 1. : -1.) * canyon_half_width(z);
    return Point<3>(x, a[1] + (ye - a[1]) * (x - a[0]) / (xe - a[0]), z);
  }
} // namespace archdam::geometry
