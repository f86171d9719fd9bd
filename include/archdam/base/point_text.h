#pragma once

#include <archdam/base/types.h>

#include <deal.II/base/point.h>

#include <sstream>
#include <string>

namespace archdam
{
  /// "(x, y, z)": a place in the model for messages.
  inline std::string
  point_text(const dealii::Point<dim> &p)
  {
    std::ostringstream s;
    s << "(" << p[0] << ", " << p[1] << ", " << p[2] << ")";
    return s.str();
  }
} // namespace archdam
