#include <archdam/geometry/ids.h>
#include <archdam/physics/foundation/foundation.h>

#include <cmath>

namespace archdam::physics::foundation
{
  using namespace dealii;

  void
  FoundationParameters::add_parameters(ParameterHandler &prm)
  {
    add_selection(prm, "Model", model, model_names(),
                  "Foundation model: massless = rock stiffness without "
                  "inertia, outer boundary fixed, uniform ground motion "
                  "(relative formulation); massed = rock inertia, total "
                  "motion, vertically propagating plane waves that "
                  "reproduce the ground motion at the free surface, and "
                  "the transmitting boundary below.");
    add_selection(prm, "Transmitting boundary", transmitting_boundary,
                  transmitting_boundary_names(),
                  "Outer boundary (bottom and sides) of the massed "
                  "foundation: MTF = Liao's multi-transmitting formula on "
                  "the scattered motion; viscous = Lysmer dashpots (and "
                  "springs, see Spring distance) with free-field forces; "
                  "fixed = free-field motion prescribed (reflects).");
    prm.add_parameter("MTF order", mtf_order,
                      "Order N of the multi-transmitting formula.",
                      Patterns::Integer(1, 4));
    prm.add_parameter("Artificial speed", artificial_speed,
                      "Artificial transmitting speed c_a of the MTF [m/s]; 0 = "
                      "the rock's P-wave speed for the component normal to the "
                      "boundary and its S-wave speed for the tangential ones.",
                      Patterns::Double(0.));
    prm.add_parameter("Stabilization rate", stabilization_rate,
                      "Drift stabilization of the MTF as a rate [1/s]: with "
                      "gamma = rate * time step, the j-th term is multiplied "
                      "by (1 + gamma)^(-j). A rate, so that the boundary's "
                      "artificial decay does not change with the time step; "
                      "2 /s is gamma = 0.01 at dt = 5 ms (gamma 0.01 - 0.05 "
                      "per step usual).",
                      Patterns::Double(0.));
    prm.add_parameter("Spring distance", spring_distance,
                      "Distance R [m] from the scattering source to the viscous "
                      "boundary; springs G/R (normal) and G/(2R) (tangential) "
                      "per unit area are added to the dashpots; 0 = dashpots "
                      "only.",
                      Patterns::Double(0.));
    add_selection(prm, "Free field", free_field, free_field_rock_names(),
                  "The free field the outer boundary of the massed foundation "
                  "prescribes: 'through the damped rock' = the control motion "
                  "deconvolved through the rock's own Rayleigh damping, so that "
                  "the free surface moves as the control motion; 'undamped' = "
                  "that of an undamped half-space, which the damped rock "
                  "attenuates on its way up (doc/theory/foundation.md §4).");
    prm.add_parameter("Band limit", band_limit,
                      "Frequency [Hz] above which the deconvolution through the "
                      "damped rock leaves the damping out (a smooth step to "
                      "twice it): there it would amplify the incident wave "
                      "by about exp(w^2 beta depth / (2 c)), and those "
                      "frequencies reach the surface damped by the rock.",
                      Patterns::Double(0., Patterns::Double::max_double_value));
  }

  std::set<types::boundary_id>
  FoundationParameters::fixed_boundaries() const
  {
    if (prescribes_boundary_motion())
      return {ids::foundation_bottom, ids::foundation_sides};
    return {};
  }

  double
  shear_wave_speed(const solid::ElasticMaterial &m)
  {
    return std::sqrt(m.mu() / m.density);
  }

  double
  pressure_wave_speed(const solid::ElasticMaterial &m)
  {
    return std::sqrt((m.lambda() + 2 * m.mu()) / m.density);
  }
} // namespace archdam::physics::foundation
