#include <archdam/base/input_error.h>
#include <archdam/physics/solid/damping.h>

#include <cmath>

namespace archdam::physics::solid
{
  using namespace dealii;

  void
  DampingParameters::add_parameters(ParameterHandler &prm)
  {
    add_selection(prm, "Mode", mode, damping_mode_names(),
                  "How Rayleigh damping is given: 'damping ratio' (zeta at "
                  "two frequencies) or 'coefficients' (alpha and beta).");
    prm.add_parameter("Mass proportional coefficient", alpha,
                      "Rayleigh alpha [1/s] (Mode = coefficients).",
                      Patterns::Double(0.));
    prm.add_parameter("Stiffness proportional coefficient", beta,
                      "Rayleigh beta [s] (Mode = coefficients).",
                      Patterns::Double(0.));
    prm.add_parameter("Damping ratio", ratio,
                      "Fraction of critical damping zeta reached at both "
                      "frequencies (Mode = damping ratio).",
                      Patterns::Double(0., 1.));
    prm.add_parameter("First frequency", first_frequency,
                      "Lower frequency f1 [Hz] with damping ratio zeta.",
                      Patterns::Double(0., Patterns::Double::max_double_value));
    prm.add_parameter("Second frequency", second_frequency,
                      "Upper frequency f2 [Hz] with damping ratio zeta.",
                      Patterns::Double(0., Patterns::Double::max_double_value));
  }

  std::pair<double, double>
  DampingParameters::rayleigh_coefficients() const
  {
    if (mode == DampingMode::coefficients)
      return {alpha, beta};
    if (!(first_frequency < second_frequency))
      throw InputError("Damping: 'First frequency' (" + std::to_string(first_frequency) +
                       " Hz) must be below 'Second frequency' (" +
                       std::to_string(second_frequency) + " Hz).");
    const double w1 = 2 * M_PI * first_frequency, w2 = 2 * M_PI * second_frequency;
    return {2 * ratio * w1 * w2 / (w1 + w2), 2 * ratio / (w1 + w2)};
  }
} // namespace archdam::physics::solid
