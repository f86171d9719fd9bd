// Sections of case text (prm) that the tests write their cases from. Each
// returns complete subsections; a test joins those it needs with its own.
#pragma once

#include <sstream>
#include <string>

#include "archdam_tests.h"
#include "gmsh_example.h"

namespace archdam::testing::case_text
{
  /// Linear elements (Q1).
  inline const std::string linear_elements = R"(
subsection Finite element
  set Degree = 1
end
)";

  /// The parametric arch dam meshed coarsely: one cell across each block and
  /// through the thickness, @p cells_over_height layers; @p lines ("set ..."
  /// lines of the Arch dam subsection) change more.
  inline std::string
  coarse_arch_dam_mesh(const unsigned int cells_over_height, const std::string &lines = "")
  {
    return R"(
subsection Mesh
  set Source = arch dam
  subsection Arch dam
    set Cells across each block = 1
    set Cells through thickness = 1
    set Cells over height = )" +
           std::to_string(cells_over_height) + "\n" + lines + R"(
  end
end
)";
  }

  /// Ground motion in x: the two-column record @p file in m/s^2.
  inline std::string
  two_column_record_x(const std::string &file)
  {
    return "\nsubsection Ground motion\n  subsection Component x\n    set File = " + file +
           "\n    set Format = two-column\n    set Units = m/s^2\n  end\nend\n";
  }

  /// The box dam of two blocks (x 0...10 m, y 0...20 m, z 0...20 m, 1 x 2 x 2
  /// cells), @p lines ("set ...") adding to its Box subsection, shaken in x by
  /// the two-column record "record.txt" in m/s^2.
  inline std::string
  two_block_box_shaken_by_record_txt(const std::string &lines = "")
  {
    return R"(
subsection Mesh
  subsection Box
    set Length = 10
    set Width = 20
    set Height = 20
    set Number of blocks = 2
    set Cells in x = 1
    set Cells in y = 2
    set Cells in z = 2
)" + lines + "  end\nend\n" + two_column_record_x("record.txt");
  }

  /// The box dam of two blocks, 4 m x 6 m x 12 m on a fixed base, 2 x 2 x 4
  /// cells.
  inline const std::string tall_box_on_fixed_base = R"(
subsection Mesh
  subsection Box
    set Length = 4
    set Width = 6
    set Height = 12
    set Number of blocks = 2
    set Rock depth = 0
    set Cells in x = 2
    set Cells in y = 2
    set Cells in z = 4
  end
end
)";

  inline const std::string no_gravity = R"(
subsection Static loads
  set Gravity = false
end
)";

  /// The Gmsh example of prm/ (gmsh_example.h): 3 blocks, rock and water.
  inline std::string
  gmsh_example_mesh()
  {
    return "\nsubsection Mesh\n  set Source = gmsh\n  subsection Gmsh\n    set File = " +
           gmsh_example::v4 + "\n  end\nend\n";
  }

  /// Linear elastic concrete (Poisson's ratio 0) of Young's modulus @p E
  /// [Pa] and density @p rho [kg/m^3], under gravity @p g [m/s^2].
  inline std::string
  concrete_under_gravity(const double E, const double rho, const double g)
  {
    std::ostringstream s;
    s << "\nsubsection Materials\n  subsection Concrete\n    set Young's modulus = " << E
      << "\n    set Poisson's ratio = 0\n    set Density = " << rho
      << "\n  end\nend\nsubsection Static loads\n  set Gravity = true\n"
      << "  set Gravitational acceleration = " << g << "\nend\n";
    return s.str();
  }

  /// Compressible water; @p lines ("set ...") add to the Reservoir subsection.
  inline std::string
  compressible_reservoir(const std::string &lines = "")
  {
    return "\nsubsection Reservoir\n  set Model = compressible\n" + lines + "end\n";
  }

  /// Steps of @p dt to @p end_time [s].
  inline std::string
  time_integration(const double dt, const double end_time)
  {
    std::ostringstream s;
    s << "\nsubsection Time integration\n  set Time step = " << dt
      << "\n  set End time = " << end_time << "\nend\n";
    return s.str();
  }

  /// The El Centro record of the shared data (PEER RSN6, Imperial Valley
  /// 1940) in its horizontal @p component, "180" or "270".
  inline std::string
  el_centro_file(const std::string &component)
  {
    return ground_motions + "RSN6_IMPVALL.I_I-ELC" + component + ".AT2";
  }

  /// El Centro (180) in the stream direction x; @p lines ("set ...") add to
  /// its component subsection, e.g. a scale factor.
  inline std::string
  el_centro_x(const std::string &lines = "")
  {
    return "\nsubsection Ground motion\n  subsection Component x\n    set File = " +
           el_centro_file("180") + "\n" + lines + "  end\nend\n";
  }

  /// Displacement monitors at @p points ("name: x, y, z; ...").
  inline std::string
  displacement_monitors(const std::string &points)
  {
    return "\nsubsection Monitors\n  set Points = " + points +
           "\n  set Quantities = displacement\nend\n";
  }

  /// Results into @p directory, fields every @p field_interval steps (0:
  /// none), nothing on the screen but what the run must report.
  inline std::string
  quiet_output(const std::string &directory, const unsigned int field_interval)
  {
    return "\nsubsection Output\n  set Directory = " + directory +
           "\n  set Field output interval = " + std::to_string(field_interval) +
           "\n  set Progress = false\n  set Timer summary = false\nend\n";
  }

  /// A short valid case for the command line: the box dam on a fixed base,
  /// @p lines ("set ...") adding to its Box subsection, linear elements, 0.02
  /// s without ground motion, results in "results" without fields.
  inline std::string
  short_box_case(const std::string &lines)
  {
    return "\nsubsection Mesh\n  subsection Box\n    set Rock depth = 0\n" + lines +
           "  end\nend\n" + linear_elements +
           "\nsubsection Time integration\n  set End time = 0.02\nend\n" +
           quiet_output("results", 0);
  }
} // namespace archdam::testing::case_text
