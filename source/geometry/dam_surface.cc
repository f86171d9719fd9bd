#include <archdam/geometry/dam_surface.h>
#include <archdam/geometry/ids.h>

#include <cmath>

namespace archdam::geometry
{
  std::string
  name(const SurfacePart part)
  {
    switch (part)
      {
        case SurfacePart::upstream:
          return "upstream";
        case SurfacePart::downstream:
          return "downstream";
        case SurfacePart::crest:
          return "crest";
        default:
          return "side";
      }
  }

  SurfacePart
  surface_part(const dealii::Tensor<1, dim> &n)
  {
    if (n[2] > std::abs(n[0]) && n[2] > std::abs(n[1]))
      return SurfacePart::crest;
    if (n[0] <= -0.1)
      return SurfacePart::upstream;
    if (n[0] >= 0.1)
      return SurfacePart::downstream;
    return SurfacePart::side;
  }

  bool
  on_dam_surface(const dealii::types::boundary_id id)
  {
    return id == ids::free_surface_solid || id == ids::solid_interface;
  }
} // namespace archdam::geometry
