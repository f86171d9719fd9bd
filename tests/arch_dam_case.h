// The coarse arch dam shared by the whole-system tests: 4 blocks, one linear
// cell across each block and through the thickness, 3 layers, rock cells of
// 120 m; 5 % Rayleigh damping; El Centro (180) in the stream direction; the
// foundation model given; displacement monitors at the crown's crest and
// base. With water (foundation_arch_dam_water, energy_balance_dam,
// checkpoint_resume): 3 joints in frictional contact (mu = 1, c = 0) and
// compressible water with a partly absorbing bottom. Empty
// (foundation_arch_dam): no water and glued joints.
#pragma once

#include <archdam/analysis/simulation.h>
#include <archdam/geometry/arch_dam_shape.h>

#include <sstream>
#include <string>

#include "archdam_tests.h"
#include "case_text.h"

namespace archdam::testing
{
  enum class Reservoir
  {
    water_and_frictional_joints,
    empty_and_glued_joints
  };

  /// The case text of the coarse arch dam on the @p foundation model, its
  /// results in @p directory, the first @p end_time [s] of the motion, run
  /// until the motion has reached the free surface whole (on massed rock
  /// that is later, by the wave's way up from the model's bottom).
  inline std::string
  arch_dam_case(const std::string &foundation, const std::string &directory,
                const Reservoir reservoir = Reservoir::water_and_frictional_joints,
                const double end_time = 3)
  {
    const bool        water = reservoir == Reservoir::water_and_frictional_joints;
    const std::string dam   = "    set Number of blocks = 4\n    set Rock cell size = 120\n" +
                            std::string(water ? "    set Water cell size = 100\n" :
                                                "    set Water level = 0\n");
    std::string text = case_text::coarse_arch_dam_mesh(3, dam) + case_text::linear_elements +
                       "\nsubsection Foundation\n  set Model = " + foundation + "\nend\n";
    if (water)
      {
        const geometry::ArchDamGeometry dam{geometry::ArchDamParameters{}};
        std::ostringstream              heel;
        heel << "  set Bottom reflection coefficient = 0.8\n  set Pressure points = heel: "
             << dam.crown_upstream_face(1.) - 0.5 << ", 0, 1\n";
        text += case_text::compressible_reservoir(heel.str()) + R"(
subsection Contraction joints
  set Model = frictional contact
  set Friction coefficient = 1
  set Cohesion = 0
  set On non-convergence = stop
  set Monitor points = crown: 5, 0, 234
end
)";
      }
    return text + R"(
subsection Damping
  set Mode = damping ratio
  set Damping ratio = 0.05
  set First frequency = 2
  set Second frequency = 15
end
)" + case_text::time_integration(0.01, 0.) +
           case_text::el_centro_x("    subsection Processing\n      set End time = " +
                                  std::to_string(end_time) + "\n    end\n") +
           case_text::displacement_monitors("crest: 5, 0, 234; base: 24, 0, 1") +
           case_text::quiet_output(directory, 0);
  }

  /// The crown's response in a run of the case: the stream displacement of
  /// the crest after the static stage, its peak relative to the base in the
  /// dynamic stage (the dam's own deformation: a massed model moves as a
  /// whole with the ground), and how often Kbar was factorized.
  struct CrownResponse
  {
    double       static_crest = 0., peak_relative = 0.;
    unsigned int factorizations = 0;
  };

  inline CrownResponse
  crown_response(const analysis::Simulation &sim)
  {
    const auto   &names = sim.recorder<archdam::output::MonitorHistories>()->columns();
    const auto    crest = column(names, "crest.ux [m]"), base = column(names, "base.ux [m]");
    CrownResponse r;
    r.static_crest = sim.recorder<archdam::output::MonitorHistories>()->rows().front()[crest];
    for (const auto &row : sim.recorder<archdam::output::MonitorHistories>()->rows())
      r.peak_relative = std::max(r.peak_relative, std::abs(row[crest] - row[base]));
    const auto calls = sim.timers().get_summary_data(dealii::TimerOutput::n_calls);
    r.factorizations =
      calls.count("dynamic: factorization") ? calls.at("dynamic: factorization") : 0;
    return r;
  }
} // namespace archdam::testing
