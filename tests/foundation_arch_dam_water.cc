// The arch dam with its compressible reservoir and frictional contraction
// joints on a massed foundation with the MTF, against the same dam on a
// massless foundation (issue must-show: static and dynamic stages with the
// reservoir, massed and massless side by side). Coarse version of
// prm/arch_dam_massed_foundation.prm with water: 4 blocks (3 joints in
// frictional contact, Mohr-Coulomb without cohesion), one cell through the
// thickness, 3 over the height, rock cells of 120 m, water cells of 100 m,
// linear elements; static stage (gravity and hydrostatic pressure) first,
// then the first 3 s of El Centro in the stream direction (its strong phase
// begins after 1.5 s; the massed model receives it a travel time later).
//
// Reported side by side: the static and the peak stream displacement of the
// crown crest relative to the crown base (the massed model moves as a whole
// with the ground), the peak hydrodynamic pressure at the heel, and the peak
// opening of the crown joint at the crest. Checked:
// - the static state is the same in both runs (1e-8): the static stage sees
//   the stiffness, the fixed outer boundary, gravity and the hydrostatic
//   load, none of which depends on the rock's mass;
// - the massed crest response is of the same order as the massless one
//   (ratio within 1/3 ... 3): radiation damping and the wave passage through
//   the rock change it, they do not remove or multiply it (the crest lies
//   near the free surface, where the control motion is given);
// - the massed heel pressure is below the massless one but above a tenth of
//   it: the heel lies 235 m below the free surface, where the free field is
//   the incident plus the reflected wave, which cancel near c_s / (4 * 235 m)
//   = 1.9 Hz, so the canyon floor shakes less than the surface (the massless
//   model shakes it with the surface motion); the massed run's water is
//   driven by the moving rock alone (total motion: the wetted rock and the
//   prescribed outer boundary), so a heel pressure of that order also shows
//   the boundary's columns at work;
// - the crown joint opens at the crest (> 1 mm) in both runs, so the contact
//   problem is at work, and every contact step converged (On
//   non-convergence = stop: a step that does not converge ends the run with
//   an error);
// - Kbar factorized once in each run (one call of "dynamic: factorization").

#include <archdam/analysis/simulation.h>

#include "arch_dam_case.h"
#include "archdam_tests.h"

using namespace dealii;
using namespace archdam;

namespace
{
  std::string
  model(const std::string &foundation)
  {
    // the time integration of the reference case: the average acceleration
    // rule with the joints' step impulse, the defaults (doc/user-guide.md,
    // time integration with joints)
    return testing::arch_dam_case(foundation, "results_water_" + foundation);
  }

  struct Response : testing::CrownResponse
  {
    double peak_heel_pressure = 0., peak_opening = 0.;
  };

  Response
  run(const std::string &foundation)
  {
    std::ostringstream   quiet;
    const Parameters     p = parameters_from_string(model(foundation));
    analysis::Simulation sim(p, MPI_COMM_WORLD, quiet);
    sim.run();
    Response r{testing::crown_response(sim)};
    for (const auto &row : sim.recorder<archdam::output::PressureRecorder>()->rows())
      r.peak_heel_pressure = std::max(r.peak_heel_pressure, std::abs(row[1]));
    const auto opening = testing::column(sim.recorder<archdam::output::JointOutput>()->columns(), "crown.opening [m]");
    for (const auto &row : sim.recorder<archdam::output::JointOutput>()->rows())
      r.peak_opening = std::max(r.peak_opening, row[opening]);
    return r;
  }
} // namespace

int
main(int argc, char **argv)
{
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  const Response massless = run("massless"), massed = run("massed");
  auto          &log      = testing::log();
  log << "with water and frictional joints          massless      massed (MTF)" << std::endl
      << std::setprecision(2) << std::scientific;
  const auto line = [&](const std::string &what, const double a, const double b) {
    log << "  " << std::left << std::setw(38) << what << std::right << std::setw(10) << a
        << "   " << std::setw(10) << b << std::endl;
  };
  line("static crest displacement [m]", massless.static_crest, massed.static_crest);
  line("peak crest relative to base [m]", massless.peak_relative, massed.peak_relative);
  line("peak hydrodynamic pressure, heel [Pa]", massless.peak_heel_pressure,
       massed.peak_heel_pressure);
  line("peak crown joint opening, crest [m]", massless.peak_opening, massed.peak_opening);
  log << std::defaultfloat << std::setprecision(6);
  testing::check_relative("static crest displacement, massed against massless",
                          massed.static_crest, massless.static_crest, 1e-8);
  const double crest = massed.peak_relative / massless.peak_relative;
  log << "peak crest displacement ratio massed / massless within 1/3 ... 3: "
      << (std::isfinite(crest) && crest > 1. / 3 && crest < 3 ? "yes" : "NO") << std::endl;
  const double heel = massed.peak_heel_pressure / massless.peak_heel_pressure;
  log << "peak heel pressure ratio massed / massless within 1/10 ... 1: "
      << (std::isfinite(heel) && heel > 0.1 && heel < 1 ? "yes" : "NO") << std::endl;
  log << "crown joint opens at the crest in both runs (> 1 mm): "
      << (std::min(massless.peak_opening, massed.peak_opening) > 1e-3 ? "yes" : "NO")
      << std::endl;
  log << "both runs completed with every contact step converged: yes" << std::endl;
  log << "Kbar factorized once (massless, massed): " << massless.factorizations << ", "
      << massed.factorizations << std::endl;
}
