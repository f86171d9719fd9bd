#pragma once

#include <deal.II/base/parameter_handler.h>

#include <string>
#include <utility>
#include <vector>

namespace archdam::loads
{
  /**
   * The dam's temperature change since grouting as a function of the
   * elevation (doc/theory/temperature.md §1): at each row the elevation z,
   * the mean change over the thickness T_m and the linear difference between
   * the faces T_d (upstream face minus downstream face), linear in z between
   * the rows. Empty: no temperature load.
   */
  struct TemperatureTable
  {
    std::vector<double> elevation, mean, difference;

    bool
    empty() const
    {
      return elevation.empty();
    }

    /// T_m(z) and T_d(z) for z within the table's elevations.
    std::pair<double, double>
    at(double z) const;
  };

  /// The table of `Static loads/Temperature change`, "z: T_m, T_d; ..." with
  /// the elevations increasing; an InputError names what is wrong.
  TemperatureTable
  parse_temperature_table(const std::string &text);

  /// The `Static loads` subsection (doc/theory/loading-sequence.md §1).
  struct StaticLoadParameters
  {
    bool        gravity         = true;
    double      g               = 9.81;
    bool        gravity_on_rock = false;
    bool        hydrostatic     = true;
    std::string temperature_change;

    void
    add_parameters(dealii::ParameterHandler &prm);
  };
} // namespace archdam::loads
