#include <archdam/base/input_error.h>
#include <archdam/loads/static_loads.h>

#include <deal.II/base/utilities.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>

namespace archdam::loads
{
  using namespace dealii;

  std::pair<double, double>
  TemperatureTable::at(const double z) const
  {
    if (elevation.size() == 1)
      return {mean[0], difference[0]};
    const auto   upper = std::upper_bound(elevation.begin() + 1, elevation.end() - 1, z);
    const auto   i     = std::size_t(upper - elevation.begin());
    const double w     = (z - elevation[i - 1]) / (elevation[i] - elevation[i - 1]);
    return {mean[i - 1] + w * (mean[i] - mean[i - 1]),
            difference[i - 1] + w * (difference[i] - difference[i - 1])};
  }

  TemperatureTable
  parse_temperature_table(const std::string &text)
  {
    TemperatureTable table;
    for (const std::string &row : Utilities::split_string_list(text, ';'))
      {
        const auto bad = [&](const std::string &why) {
          return InputError("Static loads/Temperature change: '" + row + "': " + why +
                            " (expected 'z: T_m, T_d; ...', the elevation in m, the mean "
                            "change and the difference between the upstream and the "
                            "downstream face in degrees C; doc/theory/temperature.md §1).");
        };
        const auto number = [&](const std::string &word) {
          char        *end   = nullptr;
          const double value = std::strtod(word.c_str(), &end);
          if (word.empty() || end == word.c_str() || *end != '\0' || !std::isfinite(value))
            throw bad("'" + word + "' is not a finite number");
          return value;
        };
        const auto colon = row.find(':');
        if (colon == std::string::npos)
          throw bad("no ':' after the elevation");
        const auto values = Utilities::split_string_list(row.substr(colon + 1), ',');
        if (values.size() != 2)
          throw bad("need two values after the ':'");
        const double z = number(Utilities::trim(row.substr(0, colon)));
        if (!table.empty() && !(z > table.elevation.back()))
          throw bad("the elevations must increase from row to row");
        table.elevation.push_back(z);
        table.mean.push_back(number(values[0]));
        table.difference.push_back(number(values[1]));
        // A change of a hundred degrees is no climate's: a unit or sign slip.
        if (std::abs(table.mean.back()) > 100 || std::abs(table.difference.back()) > 100)
          throw bad("a change of more than 100 degrees C");
      }
    return table;
  }

  void
  StaticLoadParameters::add_parameters(ParameterHandler &prm)
  {
    prm.add_parameter("Gravity", gravity, "Apply the self-weight of the dam (in the static stage, and from there on "
                      "in the dynamic stage; without a static stage the dynamic "
                      "stage starts unloaded at rest).",
                      Patterns::Bool());
    prm.add_parameter("Gravitational acceleration", g, "g [m/s^2].",
                      Patterns::Double(0.));
    prm.add_parameter("Gravity on foundation", gravity_on_rock,
                      "Also apply the self-weight of the rock (usually not: its "
                      "in-situ stress predates the dam).",
                      Patterns::Bool());
    prm.add_parameter("Hydrostatic pressure", hydrostatic,
                      "Apply the hydrostatic water pressure on the wetted dam "
                      "face and rock up to the water level (Reservoir section), "
                      "unless the reservoir model is none.",
                      Patterns::Bool());
    prm.add_parameter(
      "Temperature change", temperature_change,
      "The dam's temperature change since grouting (closure), as a table over the "
      "elevation: 'z: T_m, T_d; z: T_m, T_d; ...' with z [m] increasing, T_m the "
      "mean change over the thickness and T_d the linear difference between the "
      "faces, upstream minus downstream [degrees C]; linear in z between the rows, "
      "the dam's elevations within the table. The change at a point is "
      "T_m + T_d (1/2 - s), s the through-thickness coordinate (0 on the upstream, "
      "1 on the downstream face), with Materials/Concrete/Thermal expansion "
      "coefficient; applied after grouting with the water (doc/theory/temperature.md). "
      "Empty: none.",
      Patterns::Anything());
  }
} // namespace archdam::loads
