#pragma once

#include <sstream>
#include <string>

namespace archdam
{
  /// @p x as a message shows it: the shortest form with @p digits significant
  /// digits (the stream's default, 6).
  inline std::string
  number_text(const double x, const int digits = 6)
  {
    std::ostringstream s;
    s.precision(digits);
    s << x;
    return s.str();
  }
} // namespace archdam
