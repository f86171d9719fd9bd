// The coarse arch dam with water and frictional joints shared by the
// whole-system tests (foundation_arch_dam_water, energy_balance_dam): 4
// blocks (3 joints, mu = 1, c = 0), one linear cell across each block and
// through the thickness, 3 layers; compressible water with a partly
// absorbing bottom; 5 % Rayleigh damping; 3 s of El Centro (180) in the
// stream direction; the foundation model given.
#pragma once

#include <archdam/geometry/arch_dam.h>

#include <sstream>
#include <string>

namespace archdam::testing
{
  inline std::string
  arch_dam_water_case(const std::string &foundation, const std::string &directory)
  {
    const geometry::ArchDamGeometry dam{geometry::ArchDamParameters{}};
    std::ostringstream              heel;
    heel << dam.crown_upstream_face(1.) - 0.5 << ", 0, 1";
    return R"(
subsection Mesh
  set Source = arch dam
  subsection Arch dam
    set Number of blocks = 4
    set Cells across each block = 1
    set Cells through thickness = 1
    set Cells over height = 3
    set Rock cell size = 120
    set Water cell size = 100
  end
end
subsection Finite element
  set Degree = 1
end
subsection Foundation
  set Model = )" + foundation + R"(
end
subsection Reservoir
  set Model = compressible
  set Bottom reflection coefficient = 0.8
  set Pressure points = heel: )" + heel.str() + R"(
end
subsection Contraction joints
  set Model = frictional contact
  set Friction coefficient = 1
  set Cohesion = 0
  set On non-convergence = stop
  set Monitor points = crown: 5, 0, 234
end
subsection Damping
  set Mode = damping ratio
  set Damping ratio = 0.05
  set First frequency = 2
  set Second frequency = 15
end
subsection Time integration
  set Time step = 0.01
  set End time = 3
end
subsection Ground motion
  subsection Component x
    set File = )" SOURCE_DIR R"(/../../shared/data/ground_motions/RSN6_IMPVALL.I_I-ELC180.AT2
  end
end
subsection Monitors
  set Points = crest: 5, 0, 234; base: 24, 0, 1
  set Quantities = displacement
end
subsection Output
  set Directory = )" + directory + R"(
  set Field output interval = 0
  set Progress = false
  set Timer summary = false
end
)";
  }
} // namespace archdam::testing
