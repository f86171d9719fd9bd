#pragma once

#include <deal.II/base/parameter_handler.h>

#include <string>

namespace archdam::geometry
{
  /// `Mesh/Arch dam/Joints`: how the contraction joints run
  /// (doc/arch-dam-geometry.md §2).
  enum class JointLayout
  {
    /// Vertical planes, radial in plan at the crest; each block founded on
    /// a horizontal step of the canyon (as built).
    vertical,
    /// Radial to the arch at every elevation, every block on the canyon
    /// floor (the joints lean with the abutments).
    fanned
  };

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
    JointLayout  joints              = JointLayout::fanned;
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

  /// The InputError for arch-dam parameters that give no valid dam or mesh:
  /// @p what, after the name of their section (`Mesh/Arch dam`).
  [[noreturn]] void
  arch_dam_input_error(const std::string &what);
} // namespace archdam::geometry
