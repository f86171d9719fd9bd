#pragma once

#include <archdam/base/types.h>

#include <deal.II/base/parameter_handler.h>
#include <deal.II/base/point.h>
#include <deal.II/grid/tria.h>

namespace archdam::geometry
{
  /**
   * Engineering description of a double-curvature arch dam in its canyon, with
   * the foundation rock and the reservoir (`Mesh/Arch dam`). The defaults are
   * the reference dam of the paper case: 235 m high, crest length 304.8 m,
   * crown thickness 10 m at the crest and 48 m at the base, 14 cantilever
   * blocks, water 202 m above the base. doc/arch-dam-geometry.md gives every
   * formula and the reason for every default.
   *
   * Axes (doc/theory/conventions.md §3): x downstream, y along the dam axis, z up;
   * z = 0 at the dam base (the lowest point of the crown cantilever), x = 0 at
   * the heel of the crown cantilever (its upstream face at z = 0), y = 0 in the
   * crown plane.
   */
  struct ArchDamParameters
  {
    // --- the dam ---
    double height                = 235.;  // H [m]: crest elevation above the base
    double crest_length          = 304.8; // L_c [m]: arc length of the crest arch's mid-thickness line
    double crown_thickness_crest = 10.;   // T_H [m]
    double crown_thickness_base  = 48.;   // T_0 [m]
    double upstream_overhang     = 15.;   // delta [m]: bulge of the crown's upstream face at mid-height
    double crest_setback         = 0.;    // o_c [m]: crest upstream edge downstream of the heel
    double arch_radius_crest     = 170.;  // R_H [m]: mid-thickness radius of the crest arch
    double arch_radius_base      = 80.;   // R_0 [m]: mid-thickness radius of the base arch
    double abutment_thickening_crest = 1.5; // kappa_H: arch thickness at the abutment / at the crown, crest arch
    double abutment_thickening_base  = 1.1; // kappa_0: the same for the base arch (linear in z between)
    // --- the canyon ---
    double canyon_width_base     = 80.;   // 2 b_0 [m]: canyon width at z = 0
    double canyon_shape_exponent = 1.;    // m: b(z) = b_0 + (b_H - b_0) (z/H)^m
    // --- blocks and dam cells ---
    unsigned int n_blocks            = 14;
    unsigned int cells_across_block  = 2;
    unsigned int cells_through       = 2;
    unsigned int cells_over_height   = 10;
    // --- foundation (multiples of the height H) and rock cells ---
    double foundation_depth      = 1.; // below z = 0; 0 = no rock (rigid foundation)
    double foundation_upstream   = 1.; // upstream of the heel
    double foundation_downstream = 1.; // downstream of the toe of the crown cantilever
    double foundation_sides      = 1.; // beyond the canyon's half-width at the crest
    double rock_cell_size        = 45.; // [m]
    // --- reservoir ---
    double water_level      = 202.; // [m] above z = 0; 0 = empty reservoir (no water cells)
    double reservoir_length = 3.;   // upstream of the heel, in multiples of the water depth
    double water_cell_size  = 35.;  // [m]

    /// Declare every entry in the CURRENT subsection of @p prm (the caller
    /// enters `Mesh/Arch dam`), bound to the members above.
    void
    add_parameters(dealii::ParameterHandler &prm);
  };

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
    ArchDamParameters prm;
    double            crest_half_width; // b_H
  };

  /**
   * Fill @p tria with a CONFORMING hexahedral mesh (shared vertices everywhere;
   * the splitter duplicates joint and fluid-solid vertices afterwards) of dam,
   * rock and water. Material ids: 10 + k for dam block k, 1 rock, 2 water.
   * Boundary ids (before splitting): 0 traction-free solid surface (dam
   * downstream face, crest, dam upstream face above the water, ground surface
   * and canyon walls in air), 1 foundation bottom (and, with no rock, the dam's
   * base and abutments, which are then fixed), 2 the four vertical truncation
   * faces of the rock, 3 reservoir free surface, 4 reservoir upstream
   * truncation, 5 reservoir bottom and banks where no rock is meshed. Faces
   * between two cells carry no id.
   *
   * Throws InputError for parameters that give no valid dam or mesh.
   */
  void
  generate_arch_dam(const ArchDamParameters &p, dealii::Triangulation<3> &tria);
} // namespace archdam::geometry
