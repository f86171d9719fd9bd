// The arch dam on a massed foundation with the MTF against the same dam on a
// massless foundation (issue must-show: massed and massless side by side),
// empty reservoir, glued joints (foundation_arch_dam_water: with water and
// joints in frictional contact). A coarse version of
// prm/arch_dam_massed_foundation.prm (4 blocks, one cell through the
// thickness, rock cells of 120 m, linear elements), 2 s of the El Centro
// record in the stream direction, static stage (gravity) first.
//
// Reported side by side: the peak stream displacement of the crown crest
// relative to the crown base (the dam's own deformation; the massed model
// moves as a whole with the ground), and the static crest displacement, which
// must be the same in both (the static stage sees only stiffness and the
// fixed outer boundary). Checked:
// - both runs finite, the massed crest response the same order as the
//   massless one (ratio within 1/3 ... 3: radiation damping and the wave
//   passage change it, they do not remove it or multiply it);
// - Kbar factorized once in each run (one call of "dynamic: factorization").

#include <archdam/analysis/simulation.h>

#include "arch_dam_case.h"
#include "archdam_tests.h"

using namespace dealii;
using namespace archdam;

namespace
{
  testing::CrownResponse
  run(const std::string &foundation)
  {
    std::ostringstream   quiet;
    const Parameters     p = parameters_from_string(
      testing::arch_dam_case(foundation, "results_" + foundation,
                             testing::Reservoir::empty_and_glued_joints, 2));
    analysis::Simulation sim(p, MPI_COMM_WORLD, quiet);
    sim.run();
    return testing::crown_response(sim);
  }
} // namespace

int
main(int argc, char **argv)
{
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  const auto massless = run("massless"), massed = run("massed");
  auto          &log      = testing::log();
  log << "crown crest, stream direction    massless      massed (MTF)" << std::endl
      << std::setprecision(3) << std::scientific
      << "  static displacement [m]     " << std::setw(10) << massless.static_crest << "   "
      << std::setw(10) << massed.static_crest << std::endl
      << "  peak relative to base [m]   " << std::setw(10) << massless.peak_relative << "   "
      << std::setw(10) << massed.peak_relative << std::defaultfloat << std::setprecision(6)
      << std::endl;
  testing::check_relative("static crest displacement, massed against massless",
                          massed.static_crest, massless.static_crest, 1e-8);
  const double ratio = massed.peak_relative / massless.peak_relative;
  log << "peak ratio massed / massless within 1/3 ... 3: "
      << (std::isfinite(ratio) && ratio > 1. / 3 && ratio < 3 ? "yes" : "NO") << std::endl;
  log << "Kbar factorized once (massless, massed): " << massless.factorizations << ", "
      << massed.factorizations << std::endl;
}
