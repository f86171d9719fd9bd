#pragma once

#include <chrono>

namespace archdam
{
  /// The wall time since @p start [s].
  inline double
  seconds_since(const std::chrono::steady_clock::time_point start)
  {
    return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  }

  /// The wall time of @p work [s].
  template <typename Work>
  double
  seconds_of(Work &&work)
  {
    const auto start = std::chrono::steady_clock::now();
    work();
    return seconds_since(start);
  }
} // namespace archdam
