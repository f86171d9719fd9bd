// The data file of scripts/plot_arch_dam.py, written by the geometry tests
// of the parametric arch dam (arch_dam_default, arch_dam_vertical_joints).
#pragma once

#include <archdam/geometry/arch_dam_shape.h>
#include <archdam/geometry/ids.h>

#include <deal.II/grid/tria.h>
#include <deal.II/grid/tria_accessor.h>
#include <deal.II/grid/tria_iterator.h>

#include <fstream>
#include <iomanip>
#include <string>

namespace archdam::testing
{
  /// The model's faces and the geometry's curves into @p file, for
  /// scripts/plot_arch_dam.py (the pictures of doc/arch-dam-geometry.md).
  inline void
  write_arch_dam_plot_data(const geometry::ArchDamGeometry &g, const dealii::Triangulation<3> &tria,
                           const std::string &file)
  {
    using namespace dealii;
    std::ofstream out(file);
    out << std::setprecision(8);
    out << "# arch dam model for scripts/plot_arch_dam.py\n"
        << "# face <material> <tag> x0 y0 z0 ... x3 y3 z3 (vertices in cyclic order); tag = the\n"
        << "#   boundary id of a boundary face, 100+k for a face of joint k, 200 for a dam face\n"
        << "#   against water, 201 for a dam face against rock\n"
        << "# arch <z> <s> x y ... (s = 0 upstream face, 0.5 mid-thickness, 1 downstream face)\n"
        << "# crown <z> <x upstream face> <x downstream face>\n"
        << "# canyon <z> <half-width b(z)>\n";
    const unsigned int cyclic[4] = {0, 1, 3, 2};
    for (const auto &cell : tria.active_cell_iterators())
      for (unsigned int f = 0; f < 6; ++f)
        {
          int tag = -1;
          if (cell->face(f)->at_boundary())
            tag = cell->face(f)->boundary_id();
          else if (ids::is_dam(cell->material_id()))
            {
              const auto m = cell->neighbor(f)->material_id();
              if (m == cell->material_id() + 1)
                tag = 100 + cell->material_id() - ids::first_dam_block;
              else if (m == ids::water)
                tag = 200;
              else if (m == ids::rock)
                tag = 201;
            }
          if (tag < 0)
            continue;
          out << "face " << int(cell->material_id()) << ' ' << tag;
          for (const unsigned int v : cyclic)
            out << ' ' << cell->face(f)->vertex(v);
          out << '\n';
        }
    const double H = g.height();
    for (const double zeta : {0., 0.25, 0.5, 0.75, 1.})
      for (const double s : {0., 0.5, 1.})
        {
          out << "arch " << zeta * H << ' ' << s;
          for (unsigned int n = 0; n <= 60; ++n)
            {
              const Point<3> p = g.dam_point(1. - 2. * n / 60, s, zeta * H);
              out << ' ' << p[0] << ' ' << p[1];
            }
          out << '\n';
        }
    for (unsigned int n = 0; n <= 100; ++n)
      {
        const double z = H * n / 100;
        out << "crown " << z << ' ' << g.crown_upstream_face(z) << ' '
            << g.crown_downstream_face(z) << '\n';
        out << "canyon " << z << ' ' << g.canyon_half_width(z) << '\n';
      }
  }
} // namespace archdam::testing
