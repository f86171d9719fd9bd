#include <archdam/base/input_error.h>
#include <archdam/base/number_text.h>
#include <archdam/loads/design_spectrum.h>
#include <archdam/loads/record_io.h>

#include <deal.II/base/utilities.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <sstream>

namespace archdam::loads
{


  TargetSpectrum
  TargetSpectrum::nb35047(const double pga,
                          const double characteristic_period,
                          const double beta_max)
  {
    if (!(pga > 0) || !std::isfinite(pga))
      throw InputError("Design spectrum: the peak ground acceleration must be "
                       "positive, it is " +
                       number_text(pga / standard_gravity) + " g.");
    if (!(characteristic_period >= 0.1) || !std::isfinite(characteristic_period))
      throw InputError("Design spectrum: the characteristic period T_g must be "
                       "at least 0.1 s (the end of the rising branch), it is " +
                       number_text(characteristic_period) + " s.");
    if (!(beta_max >= 1) || !std::isfinite(beta_max))
      throw InputError("Design spectrum: the maximum amplification beta_max "
                       "must be at least 1, it is " +
                       number_text(beta_max) + ".");
    TargetSpectrum s;
    s.peak    = pga;
    s.t_g     = characteristic_period;
    s.plateau = beta_max;
    return s;
  }



  TargetSpectrum
  TargetSpectrum::table(const double                                  pga,
                        const std::vector<std::pair<double, double>> &points)
  {
    if (!(pga > 0) || !std::isfinite(pga))
      throw InputError("Spectrum table: the peak ground acceleration must be "
                       "positive, it is " +
                       number_text(pga / standard_gravity) + " g.");
    if (points.size() < 2)
      throw InputError("Spectrum table: it needs at least 2 points (T: beta), "
                       "it has " +
                       std::to_string(points.size()) + ".");
    for (std::size_t i = 0; i < points.size(); ++i)
      {
        const auto [T, beta] = points[i];
        if (!(T >= 0) || !std::isfinite(T))
          throw InputError("Spectrum table: point " + std::to_string(i + 1) +
                           " has period " + number_text(T) +
                           " s; periods must be at least 0.");
        if (i > 0 && !(T > points[i - 1].first))
          throw InputError("Spectrum table: point " + std::to_string(i + 1) +
                           " has period " + number_text(T) +
                           " s, not larger than the previous one; periods "
                           "must increase strictly.");
        if (!(beta > 0) || !std::isfinite(beta))
          throw InputError("Spectrum table: point " + std::to_string(i + 1) +
                           " has beta = " + number_text(beta) +
                           "; beta must be positive.");
      }
    TargetSpectrum s;
    s.is_table     = true;
    s.peak         = pga;
    s.table_points = points;
    return s;
  }



  double
  TargetSpectrum::amplification(const double T) const
  {
    if (is_table)
      {
        const auto &p = table_points;
        if (T <= p.front().first)
          return p.front().second;
        if (T >= p.back().first)
          return p.back().second;
        const std::size_t k =
          std::upper_bound(p.begin(),
                           p.end(),
                           T,
                           [](const double t, const auto &point) {
                             return t < point.first;
                           }) -
          p.begin();
        const double w = (T - p[k - 1].first) / (p[k].first - p[k - 1].first);
        return (1. - w) * p[k - 1].second + w * p[k].second;
      }

    // NB 35047-2015 (see the header).
    double beta = 0.;
    if (T <= 0.1)
      beta = 1. + 10. * (plateau - 1.) * std::max(T, 0.);
    else if (T <= t_g)
      beta = plateau;
    else
      beta = plateau * std::pow(t_g / T, 0.6);
    return std::max(beta, 0.2 * plateau);
  }



  double
  TargetSpectrum::acceleration(const double T) const
  {
    return peak * amplification(T);
  }



  double
  TargetSpectrum::pga() const
  {
    return peak;
  }



  TargetSpectrum
  TargetSpectrum::scaled(const double factor) const
  {
    TargetSpectrum s = *this;
    s.peak *= factor;
    return s;
  }



  std::string
  TargetSpectrum::description() const
  {
    char text[200];
    if (is_table)
      std::snprintf(text,
                    sizeof(text),
                    "spectrum table (%zu points), PGA %.3f g",
                    table_points.size(),
                    peak / standard_gravity);
    else
      std::snprintf(text,
                    sizeof(text),
                    "NB 35047-2015, PGA %.3f g, T_g %.2f s, beta_max %.2f",
                    peak / standard_gravity,
                    t_g,
                    plateau);
    return text;
  }



  std::vector<std::pair<double, double>>
  parse_spectrum_table(const std::string &text, const std::string &context)
  {
    std::vector<std::pair<double, double>> points;
    std::istringstream                     entries(text);
    unsigned int                           n = 0;
    for (std::string entry; std::getline(entries, entry, ';');)
      {
        ++n;
        entry = dealii::Utilities::trim(entry);
        if (entry.empty())
          continue;
        const auto colon = entry.find(':');
        const auto read  = [&](const std::string &word, double &x) {
          const std::string w   = dealii::Utilities::trim(word);
          char             *end = nullptr;
          x                     = std::strtod(w.c_str(), &end);
          return !w.empty() && *end == '\0' && std::isfinite(x);
        };
        double T = 0., beta = 0.;
        if (colon == std::string::npos || !read(entry.substr(0, colon), T) ||
            !read(entry.substr(colon + 1), beta))
          throw InputError(context + "spectrum table entry " +
                           std::to_string(n) + " reads '" + entry +
                           "', expected 'period: beta' with two numbers, as "
                           "in '0: 1; 0.1: 2.5; 0.4: 2.5; 3: 0.6'.");
        points.emplace_back(T, beta);
      }
    return points;
  }
} // namespace archdam::loads
