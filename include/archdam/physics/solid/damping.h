#pragma once

#include <archdam/base/selection.h>

#include <deal.II/base/parameter_handler.h>

#include <string>

namespace archdam::physics::solid
{
  /// `Damping/Mode`: how the Rayleigh damping is given.
  enum class DampingMode
  {
    damping_ratio, ///< zeta at two frequencies
    coefficients   ///< alpha and beta
  };

  /// The names of DampingMode in the case file.
  inline const SelectionNames<DampingMode> &
  damping_mode_names()
  {
    static const SelectionNames<DampingMode> names{
      {"damping ratio", DampingMode::damping_ratio},
      {"coefficients", DampingMode::coefficients}};
    return names;
  }

  /**
   * Rayleigh damping D = alpha M + beta K (doc/theory/solid.md §4), with alpha and beta
   * given directly or derived from a damping ratio zeta reached at two
   * frequencies f1, f2: alpha = 2 zeta w1 w2 / (w1 + w2), beta = 2 zeta / (w1 + w2)
   * (Chopra, Dynamics of Structures, eq. 11.4.9).
   */
  struct DampingParameters
  {
    DampingMode mode             = DampingMode::damping_ratio;
    double      alpha            = 0.;
    double      beta             = 0.;
    double      ratio            = 0.05;
    double      first_frequency  = 1.;
    double      second_frequency = 10.;

    void
    add_parameters(dealii::ParameterHandler &prm);

    /// (alpha [1/s], beta [s]) for the chosen mode.
    std::pair<double, double>
    rayleigh_coefficients() const;
  };
} // namespace archdam::physics::solid
