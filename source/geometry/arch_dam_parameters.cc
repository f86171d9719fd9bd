// The parameters of the parametric arch dam (`Mesh/Arch dam`; every default is
// explained in doc/arch-dam-geometry.md).

#include <archdam/base/input_error.h>
#include <archdam/base/selection.h>
#include <archdam/geometry/arch_dam_parameters.h>

namespace archdam::geometry
{
  using namespace dealii;

  void
  ArchDamParameters::add_parameters(ParameterHandler &prm)
  {
    const auto positive = Patterns::Double(0., Patterns::Double::max_double_value);
    const auto nonneg   = Patterns::Double(0.);

    prm.add_parameter("Height", height,
                      "Dam height H [m]: the crest's elevation above the dam base "
                      "(z = 0, the lowest point of the crown cantilever).",
                      positive);
    prm.add_parameter("Crest length", crest_length,
                      "Arc length of the crest arch [m], measured along its "
                      "mid-thickness line from abutment to abutment.",
                      positive);
    prm.add_parameter("Crown thickness at crest", crown_thickness_crest,
                      "Thickness of the crown cantilever at the crest [m].", positive);
    prm.add_parameter("Crown thickness at base", crown_thickness_base,
                      "Thickness of the crown cantilever at the base [m]; it varies "
                      "linearly with elevation in between.",
                      positive);
    prm.add_parameter("Upstream overhang", upstream_overhang,
                      "How far the crown cantilever's upstream face bulges upstream "
                      "at mid-height [m], beyond the line from the heel to the crest "
                      "(its face is a parabola in z).",
                      Patterns::Double());
    prm.add_parameter("Crest setback", crest_setback,
                      "Horizontal distance from the heel to the crest's upstream "
                      "edge [m], positive downstream.",
                      Patterns::Double());
    prm.add_parameter("Arch radius at crest", arch_radius_crest,
                      "Radius of the crest arch's mid-thickness line [m]; the "
                      "radius varies linearly with elevation.",
                      positive);
    prm.add_parameter("Arch radius at base", arch_radius_base,
                      "Radius of the base arch's mid-thickness line [m].", positive);
    prm.add_parameter("Abutment thickening at crest", abutment_thickening_crest,
                      "Thickness of the crest arch at the abutments divided by its "
                      "crown thickness [-]; along an arch the thickness grows with "
                      "the square of the arch angle.",
                      Patterns::Double(0.5, 5.));
    prm.add_parameter("Abutment thickening at base", abutment_thickening_base,
                      "The same ratio for the base arch [-]; it varies linearly "
                      "with elevation in between.",
                      Patterns::Double(0.5, 5.));
    prm.add_parameter("Canyon width at base", canyon_width_base,
                      "Width of the canyon at the dam base [m], where the arch's "
                      "mid-thickness line meets the canyon walls. At the crest the "
                      "width follows from the crest length and radius.",
                      positive);
    prm.add_parameter("Canyon shape exponent", canyon_shape_exponent,
                      "m in the canyon's half-width b(z) = b0 + (bH - b0) (z/H)^m: "
                      "1 = straight walls, below 1 = U-shaped, above 1 = gorge "
                      "opening near the top [-].",
                      Patterns::Double(0.1, 10.));
    prm.add_parameter("Number of blocks", n_blocks,
                      "Cantilever blocks between radial contraction joints; block k "
                      "(material id 10+k) counts from the left bank looking "
                      "downstream (+y).",
                      Patterns::Integer(1, 89));
    add_selection(prm, "Joints", joints,
                  SelectionNames<JointLayout>{{"vertical", JointLayout::vertical},
                                              {"fanned", JointLayout::fanned}},
                  "How the contraction joints run (doc/arch-dam-geometry.md §2). vertical: "
                  "as built, vertical planes radial in plan at the crest, each block founded "
                  "on a horizontal step excavated in the canyon where its inner joint meets "
                  "the canyon wall; fanned: radial to the arch at every elevation, every "
                  "block on the canyon floor (the joints lean with the abutments).");
    prm.add_parameter("Cells across each block", cells_across_block,
                      "Cells along the arch in each block.", Patterns::Integer(1, 100));
    prm.add_parameter("Cells through thickness", cells_through,
                      "Cells through the dam thickness.", Patterns::Integer(1, 100));
    prm.add_parameter("Cells over height", cells_over_height,
                      "Cell layers from the dam base to the crest; one layer "
                      "boundary lies at the water level.",
                      Patterns::Integer(1, 1000));
    prm.add_parameter("Foundation depth", foundation_depth,
                      "Depth of the rock below the dam base, in dam heights [-]; "
                      "0 = no rock: the dam's base and abutments are then fixed "
                      "(boundary id 1).",
                      nonneg);
    prm.add_parameter("Foundation extent upstream", foundation_upstream,
                      "Rock extent upstream of the heel of the crown cantilever, in "
                      "dam heights [-].",
                      positive);
    prm.add_parameter("Foundation extent downstream", foundation_downstream,
                      "Rock extent downstream of the toe of the crown cantilever, in "
                      "dam heights [-].",
                      positive);
    prm.add_parameter("Foundation extent to the sides", foundation_sides,
                      "Rock extent beyond the canyon's half-width at the crest, on "
                      "each side, in dam heights [-].",
                      positive);
    prm.add_parameter("Rock cell size", rock_cell_size,
                      "Largest rock cell edge away from the dam [m]; cells grow by "
                      "at most 1.5 from the dam outwards. 10 Hz with 8 nodes per "
                      "shear wavelength and quadratic elements needs "
                      "c_s / (10 Hz) / 4 (45 m for the default rock).",
                      positive);
    prm.add_parameter("Water level", water_level,
                      "Reservoir level above the dam base [m]; 0 = empty reservoir "
                      "(no water cells).",
                      nonneg);
    prm.add_parameter("Reservoir length", reservoir_length,
                      "Length of the reservoir upstream of the heel, in multiples of "
                      "the water depth [-].",
                      positive);
    prm.add_parameter("Water cell size", water_cell_size,
                      "Largest water cell edge [m]; 10 Hz with 8 nodes per acoustic "
                      "wavelength and quadratic elements needs c / (10 Hz) / 4 "
                      "(36 m for c = 1440 m/s).",
                      positive);
  }

  void
  arch_dam_input_error(const std::string &what)
  {
    throw InputError("Mesh/Arch dam: " + what);
  }
} // namespace archdam::geometry
