#include <archdam/base/input_error.h>
#include <archdam/geometry/ids.h>
#include <archdam/physics/solid/damping.h>

#include <cmath>

namespace archdam::physics::solid
{
  using namespace dealii;

  const SelectionNames<DampingMode> &
  damping_mode_names(const bool rock)
  {
    static const SelectionNames<DampingMode> dam{
      {"damping ratio", DampingMode::damping_ratio},
      {"stiffness proportional", DampingMode::stiffness_proportional},
      {"coefficients", DampingMode::coefficients}};
    static const SelectionNames<DampingMode> with_same = [] {
      auto names = dam;
      names.insert(names.begin(), {"same as the dam", DampingMode::same_as_dam});
      return names;
    }();
    return rock ? with_same : dam;
  }

  const SelectionNames<MassDamping> &
  mass_damping_names()
  {
    static const SelectionNames<MassDamping> names{
      {"relative to the ground", MassDamping::relative}, {"total velocity", MassDamping::total}};
    return names;
  }

  void
  RayleighDamping::add_parameters(ParameterHandler &prm, const bool rock)
  {
    add_selection(prm, "Mode", mode, damping_mode_names(rock),
                  std::string("How the Rayleigh damping is given: 'damping ratio' (zeta at "
                              "two frequencies), 'stiffness proportional' (zeta at the first "
                              "frequency, no mass term) or 'coefficients' (alpha and beta)") +
                    (rock ? "; 'same as the dam' takes the dam's coefficients." : "."));
    prm.add_parameter("Mass proportional coefficient", alpha,
                      "Rayleigh alpha [1/s] (Mode = coefficients).",
                      Patterns::Double(0.));
    prm.add_parameter("Stiffness proportional coefficient", beta,
                      "Rayleigh beta [s] (Mode = coefficients).",
                      Patterns::Double(0.));
    prm.add_parameter("Damping ratio", ratio,
                      "Fraction of critical damping zeta reached at both "
                      "frequencies (Mode = damping ratio) or at the first one "
                      "(Mode = stiffness proportional).",
                      Patterns::Double(0., 1.));
    prm.add_parameter("First frequency", first_frequency,
                      "Lower frequency f1 [Hz] with damping ratio zeta.",
                      Patterns::Double(0., Patterns::Double::max_double_value));
    prm.add_parameter("Second frequency", second_frequency,
                      "Upper frequency f2 [Hz] with damping ratio zeta (Mode = damping ratio).",
                      Patterns::Double(0., Patterns::Double::max_double_value));
  }

  std::pair<double, double>
  RayleighDamping::coefficients(const std::string &section) const
  {
    const double w1 = 2 * M_PI * first_frequency, w2 = 2 * M_PI * second_frequency;
    switch (mode)
      {
        case DampingMode::coefficients:
          return {alpha, beta};
        case DampingMode::stiffness_proportional:
          return {0., 2 * ratio / w1};
        case DampingMode::damping_ratio:
          if (!(first_frequency < second_frequency))
            throw InputError(section + ": 'First frequency' (" + std::to_string(first_frequency) +
                             " Hz) must be below 'Second frequency' (" +
                             std::to_string(second_frequency) + " Hz).");
          return {2 * ratio * w1 * w2 / (w1 + w2), 2 * ratio / (w1 + w2)};
        case DampingMode::same_as_dam:
          break;
      }
    throw InputError(section + ": Mode = same as the dam has no coefficients of its own.");
  }

  void
  DampingParameters::add_parameters(ParameterHandler &prm)
  {
    RayleighDamping::add_parameters(prm, false);
    add_selection(prm, "Mass proportional term", mass_term, mass_damping_names(),
                  "On massed rock, the velocity the dam's mass-proportional "
                  "damping alpha M acts on: 'relative to the ground' = v - v_r, "
                  "v_r the free field's mean velocity over the dam-rock "
                  "interface, so that the dam moving rigidly with the ground "
                  "is not damped; 'total velocity' = v, which drags the dam "
                  "as it moves with the ground (doc/theory/solid.md §4). On "
                  "massless rock the motion is relative and both are the same.");
    prm.enter_subsection("Rock");
    rock.add_parameters(prm, true);
    prm.leave_subsection();
  }

  void
  DampingParameters::check() const
  {
    rayleigh_coefficients();
    rock_coefficients();
  }

  std::pair<double, double>
  DampingParameters::rayleigh_coefficients() const
  {
    return coefficients("Damping");
  }

  std::pair<double, double>
  DampingParameters::rock_coefficients() const
  {
    return rock.mode == DampingMode::same_as_dam ? rayleigh_coefficients() :
                                                   rock.coefficients("Damping/Rock");
  }

  bool
  DampingParameters::uniform() const
  {
    return rock_coefficients() == rayleigh_coefficients();
  }

  std::pair<double, double>
  DampingParameters::of(const types::material_id id) const
  {
    return ids::is_dam(id) ? rayleigh_coefficients() : rock_coefficients();
  }
} // namespace archdam::physics::solid
