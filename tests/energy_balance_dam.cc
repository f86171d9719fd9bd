// The energy balance of the whole system (doc/verification.md, "Energy balance":
// input work = kinetic + strain + damping + radiated + contact, closed to a
// stated fraction; analysis/energy_balance.h): the coarse arch dam of
// foundation_arch_dam_water (4 blocks, 3 joints in frictional contact,
// compressible water with an absorbing bottom and the upstream truncation,
// 5 % Rayleigh damping), gravity and hydrostatic pressure first, then the
// first 3 s of El Centro in the stream direction, on a massless foundation
// (relative formulation) and on a massed foundation with the MTF (total
// motion, the reference case's model).
//
// Reference: the balance itself. With the average acceleration rule the
// equations of the dam (at t_n and t_{n+1}, the joint forces included) and
// of the water (integrated in time) averaged over a step and multiplied by
// the step's increments give the step's balance exactly, whatever the
// contact history, so it closes to the round-off of the direct solves:
// 1e-8 (the forces of the joints enter through their solver's relative
// displacements, exact to the same round-off). It can fail: leaving the
// water's terms out (its energy, and what it radiates at the upstream
// truncation and into the absorbing bottom) must open it by more than 1e-3
// (the water takes a share of the input through the dam face; on massed
// rock the input is mostly the rock's own: its waves and their damping).
// The contact work is not checked here: on this coarse mesh (pair forces of
// whole cell faces) it is negative on massless rock, the joints' opening
// and closing steps releasing more than friction takes (doc/verification.md,
// "Energy balance").

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
    // The joints' default closure (dissipative) without the position
    // correction (doc/theory/joints.md §11): the correction's own term holds
    // the solid's part of its work, not the water's (it moves the coupled
    // system's pressures too: with it the balance closes to 1.8e-4 massless
    // and 3.3e-7 massed), so the scheme's balance is checked without it.
    return testing::arch_dam_case(foundation, "results_energy_" + foundation) +
           "\nsubsection Contraction joints\n  set Position correction = false\nend\n";
  }
} // namespace

int
main(int argc, char **argv)
{
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  auto &log = testing::log();
  for (const std::string foundation : {"massless", "massed"})
    {
      std::ostringstream   quiet;
      const Parameters     p = parameters_from_string(model(foundation));
      analysis::Simulation sim(p, MPI_COMM_WORLD, quiet);
      sim.run();
      const auto e = sim.recorder<archdam::analysis::EnergyBalance>()->terms();
      log << "arch dam, water, joints, " << foundation << " foundation:" << std::endl;
      testing::check_below("  balance error", e.balance_error(), 1e-8);
      auto dry = e;
      dry.water = dry.water_radiated = 0.;
      log << "  balance without the water's terms open by more than 1e-3: "
          << (dry.balance_error() > 1e-3 ? "yes" : "NO") << std::endl;
      if (std::getenv("ENERGY_BALANCE_NUMBERS")) // the terms, for the verification report
        std::cerr << foundation << ": input " << e.input << " kinetic " << e.kinetic << " strain "
                << e.strain << " damping " << e.damping << " contact " << e.contact
                  << " (normal " << e.contact_normal << ")"
                << " water " << e.water << " water radiated " << e.water_radiated
                << " error " << e.balance_error() << " dry error " << dry.balance_error()
                << "\n  " << sim.recorder<archdam::analysis::EnergyBalance>()->line() << std::endl;
    }
}
