#pragma once

#include <archdam/geometry/arch_dam_parameters.h>

#include <deal.II/base/point.h>

#include <vector>

namespace archdam::geometry
{
  /**
   * The documented geometry as plain functions (doc/arch-dam-geometry.md). The
   * generator, the tests' independent integrations and the plots all use these.
   *
   * Dam coordinates: u in [-1, 1] is the arch angle divided by the abutment
   * angle (u = +1 at the +y abutment, the left bank looking downstream), s in
   * [0, 1] goes through the thickness (0 upstream face, 1 downstream face), z
   * in [0, H] is the elevation. Block k (k = 0 ... n-1, left to right looking
   * downstream, i.e. from +y to -y) is 1 - 2(k+1)/n <= u <= 1 - 2k/n.
   */
  class ArchDamGeometry
  {
  public:
    explicit ArchDamGeometry(const ArchDamParameters &p);

    const ArchDamParameters &
    parameters() const
    {
      return prm;
    }

    /// H.
    double
    height() const
    {
      return prm.height;
    }

    // --- crown cantilever (y = 0) ---
    /// x_u(z) = o_c z/H - 4 delta (z/H)(1 - z/H).
    double
    crown_upstream_face(double z) const;
    /// T_c(z) = T_0 + (T_H - T_0) z/H.
    double
    crown_thickness(double z) const;
    /// x_d(z) = x_u(z) + T_c(z).
    double
    crown_downstream_face(double z) const;

    // --- horizontal arches ---
    /// R(z) = R_0 + (R_H - R_0) z/H, radius of the arch's mid-thickness line.
    double
    arch_radius(double z) const;
    /// x_c(z) = x_u(z) + T_c(z)/2 + R(z): the arch centre (y = 0).
    double
    arch_center_x(double z) const;
    /// b(z) = b_0 + (b_H - b_0) (z/H)^m, b_H = R_H sin(L_c / (2 R_H)).
    double
    canyon_half_width(double z) const;
    /// phi_a(z) = asin(b(z) / R(z)): the mid-thickness line meets the canyon
    /// wall |y| = b(z).
    double
    abutment_angle(double z) const;
    /// kappa(z) = kappa_0 + (kappa_H - kappa_0) z/H.
    double
    abutment_thickening(double z) const;
    /// T(u, z) = T_c(z) (1 + (kappa(z) - 1) u^2).
    double
    arch_thickness(double u, double z) const;
    /// The dam point (u, s, z): phi = u phi_a(z), r = R(z) + T(u, z)(1/2 - s),
    /// (x_c(z) - r cos(phi), r sin(phi), z).
    dealii::Point<3>
    dam_point(double u, double s, double z) const;
    /// The point of the dam's grid column u (u in [-1, 1]) on the arc s at
    /// elevation z. Fanned joints: dam_point(u, s, z). Vertical joints: the
    /// point of the arc s (the circle of radius R(z) + T(u', z)(1/2 - s)
    /// about the arch centre at z) on the vertical plane through the crest
    /// arch's centre (x_c(H), 0) at the crest angle u phi_a(H), u' its arch
    /// coordinate at z; for z at or above the column's foundation step
    /// (doc/arch-dam-geometry.md §2).
    dealii::Point<3>
    column_point(double u, double s, double z) const;
    /// The elevation of block k's foundation: 0 with fanned joints; with
    /// vertical joints the elevation at which its inner joint plane (the
    /// one nearer the crown) meets the canyon wall at the dam's
    /// mid-thickness line (arch coordinate |u'| = 1), 0 if it does so below
    /// the canyon floor or the block holds the crown.
    double
    block_floor(unsigned int k) const;
    /// Arch angle of a point seen from the arch centre at its elevation:
    /// atan2(y, x_c(z) - x). A point of joint k has angle u_k phi_a(z).
    double
    arch_angle(const dealii::Point<3> &p) const;
    /// u of joint k, between blocks k and k+1 (k = 0 ... n-2): 1 - 2(k+1)/n.
    double
    joint_u(unsigned int k) const;
    /// Horizontal area of the dam at elevation z:
    /// 2 R T_c phi_a (1 + (kappa(z) - 1)/3).
    double
    dam_section_area(double z) const;

    // --- model extents (planes) ---
    /// Foundation bottom z = -d H (0 if there is no rock).
    double
    rock_bottom() const;
    /// Upstream truncation of the rock: x = x_u(0) - e_u H.
    double
    rock_upstream_x() const;
    /// Downstream truncation of the rock: x = x_u(0) + T_0 + e_d H.
    double
    rock_downstream_x() const;
    /// Lateral truncation of the rock: |y| = b(H) + e_s H.
    double
    rock_side_y() const;
    /// Upstream truncation of the reservoir: x = x_u(0) - (reservoir length) WL.
    double
    reservoir_end_x() const;
    /// The upstream end of the model: min(rock_upstream_x, reservoir_end_x)
    /// (only the reservoir end if there is no rock).
    double
    model_upstream_x() const;
    /// Water level WL (0: empty reservoir).
    double
    water_level() const
    {
      return prm.water_level;
    }
    bool
    has_rock() const
    {
      return prm.foundation_depth > 0;
    }
    bool
    has_water() const
    {
      return prm.water_level > 0;
    }

    /// Canyon wall upstream of the dam at elevation z in [0, H] and abscissa x
    /// (model_upstream_x() <= x <= upstream abutment corner): the straight line
    /// from the dam's upstream abutment corner dam_point(side, 0, z) to
    /// (model_upstream_x(), side b(z)); side = +1 or -1.
    dealii::Point<3>
    upstream_canyon_wall(int side, double x, double z) const;
    /// Canyon wall downstream of the dam: the straight line from
    /// dam_point(side, 1, z) to (rock_downstream_x(), side b(z)).
    dealii::Point<3>
    downstream_canyon_wall(int side, double x, double z) const;

  private:
    /// The arch angle phi at elevation z of the point of arc s on the
    /// vertical plane of crest coordinate u; false if the plane misses the
    /// arc within |phi| < 1.5 rad.
    bool
    plane_angle(double u, double s, double z, double &phi) const;

    ArchDamParameters   prm;
    double              crest_half_width; // b_H
    std::vector<double> floors;           // block_floor(k)
  };
} // namespace archdam::geometry
