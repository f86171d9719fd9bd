#include <archdam/loads/acceleration_record.h>

#include <deal.II/base/exceptions.h>

#include <algorithm>
#include <cmath>

namespace archdam::loads
{
  double
  AccelerationRecord::value(const double t) const
  {
    Assert(times.size() >= 2 && values.size() == times.size(),
           dealii::ExcMessage("An acceleration record needs at least two "
                              "samples, one value per time."));
    // The ground is at rest before and after the record.
    if (t < times.front() || t > times.back())
      return 0.;
    // k: the first sample after t, searched among times[1 .. n-1] so that
    // t == times.back() falls in the last interval.
    const std::size_t k =
      std::upper_bound(times.begin() + 1, times.end() - 1, t) - times.begin();
    const double w = (t - times[k - 1]) / (times[k] - times[k - 1]);
    // This form returns the samples exactly at w = 0 and w = 1.
    return (1. - w) * values[k - 1] + w * values[k];
  }



  double
  AccelerationRecord::duration() const
  {
    Assert(!times.empty(), dealii::ExcMessage("The record has no samples."));
    return times.back();
  }



  double
  AccelerationRecord::peak() const
  {
    double peak = 0.;
    for (const double a : values)
      peak = std::max(peak, std::abs(a));
    return peak;
  }



  double
  AccelerationRecord::time_of_peak() const
  {
    Assert(!times.empty(), dealii::ExcMessage("The record has no samples."));
    std::size_t k_peak = 0;
    for (std::size_t k = 1; k < values.size(); ++k)
      if (std::abs(values[k]) > std::abs(values[k_peak]))
        k_peak = k;
    return times[k_peak];
  }



  bool
  AccelerationRecord::is_uniform(double *dt) const
  {
    if (times.size() < 2)
      return false;
    const std::size_t n    = times.size() - 1;
    const double      step = (times[n] - times[0]) / n;
    for (std::size_t k = 1; k < n; ++k)
      if (std::abs(times[k] - times[0] - k * step) > 1e-6 * step)
        return false;
    if (dt != nullptr)
      *dt = step;
    return true;
  }



  AccelerationRecord
  uniform_record(const std::vector<double> &values,
                 const double               dt,
                 const std::string         &source,
                 const double               t0)
  {
    Assert(dt > 0, dealii::ExcMessage("The time step must be positive."));
    AccelerationRecord record;
    record.source = source;
    record.values = values;
    record.times.resize(values.size());
    for (std::size_t k = 0; k < values.size(); ++k)
      record.times[k] = t0 + k * dt;
    return record;
  }
} // namespace archdam::loads
