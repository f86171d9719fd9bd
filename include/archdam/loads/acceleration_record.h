#pragma once

#include <string>
#include <vector>

namespace archdam::loads
{
  /**
   * A sampled acceleration history in m/s^2 (SI, doc/theory/conventions.md §3).
   *
   * Between samples the acceleration is linear: this is the definition of the
   * motion everywhere in ArchDam (the analysis interpolates it, the response
   * spectrum integrates it exactly, velocity and displacement are its exact
   * integrals).
   */
  struct AccelerationRecord
  {
    /// The file it came from, as it was given to the reader, or a short
    /// description of how it was made ("generated: ...").
    std::string source;
    /// Sample times in s, strictly increasing; times[0] may be > 0.
    std::vector<double> times;
    /// Accelerations at the sample times, in m/s^2.
    std::vector<double> values;

    /**
     * Piecewise-linear interpolation between samples. Before times.front()
     * and after times.back() the ground is at rest: the value is 0.
     */
    double
    value(const double t) const;

    /// End of the record, times.back(), in s.
    double
    duration() const;

    /// Peak absolute value, max |value|, in m/s^2.
    double
    peak() const;

    /// Time of the peak absolute value (the first one if it repeats), in s.
    double
    time_of_peak() const;

    /**
     * Whether the samples are equally spaced, t_k = t_0 + k dt with
     * |t_k - t_0 - k dt| <= 1e-6 dt for every k; if so and @p dt is given,
     * *dt receives the spacing (t_n - t_0)/n.
     */
    bool
    is_uniform(double *dt = nullptr) const;
  };

  /**
   * A record with @p values at t_k = t0 + k dt (equally spaced samples).
   */
  AccelerationRecord
  uniform_record(const std::vector<double> &values,
                 const double               dt,
                 const std::string         &source = "",
                 const double               t0     = 0.);
} // namespace archdam::loads
