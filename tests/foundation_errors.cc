// Bad foundation input ends with a message naming the problem (InputError):
// - the MTF needs interior points j c_a dt inside the rock (doc/theory/foundation.md §5),
//   a time step too long for the rock's depth is reported;
// - the MTF's stabilization rate times the step (gamma per step) above 0.5;
// - the viscous boundary without springs cannot carry the static stage;
// - the free field's band limit must be positive (doc/theory/foundation.md §4);
// - and what must be accepted: a dam flush with the rock's side boundary,
//   whose MTF points run along the rock's top face under the dam.

#include <archdam/analysis/simulation.h>
#include <archdam/base/input_error.h>

#include "archdam_tests.h"

using namespace dealii;
using namespace archdam;

namespace
{
  std::string
  model(const std::string &foundation, const std::string &extent = "10",
        const std::string &time_step = "0.01")
  {
    return R"(
subsection Mesh
  subsection Box
    set Rock depth = 10
    set Rock extent = )" + extent + R"(
    set Rock cell size = 10
  end
end
subsection Finite element
  set Degree = 1
end
subsection Foundation
  set Model = massed
)" + foundation + R"(
end
subsection Time integration
  set Time step = )" + time_step + R"(
  set End time = 0.05
end
subsection Output
  set Field output interval = 0
  set Progress = false
  set Timer summary = false
end
)";
  }

  void
  expect_error(const std::string &what, const std::string &foundation)
  {
    std::ostringstream quiet;
    try
      {
        const Parameters     p = parameters_from_string(model(foundation));
        analysis::Simulation sim(p, MPI_COMM_WORLD, quiet);
        sim.run();
        testing::log() << what << ": NO error" << std::endl;
      }
    catch (const InputError &e)
      {
        testing::log() << what << ":" << std::endl << "  " << e.what() << std::endl;
      }
  }

  /// The model runs: the MTF's points of a boundary node on the edge where
  /// the rock's side meets its top under the dam lie on the rock's top face,
  /// in the rock's closure.
  void
  expect_run(const std::string &what, const std::string &foundation, const std::string &extent,
             const std::string &time_step)
  {
    std::ostringstream quiet;
    try
      {
        const Parameters     p = parameters_from_string(model(foundation, extent, time_step));
        analysis::Simulation sim(p, MPI_COMM_WORLD, quiet);
        sim.run();
        testing::log() << what << ": yes" << std::endl;
      }
    catch (const InputError &e)
      {
        testing::log() << what << ": NO" << std::endl << "  " << e.what() << std::endl;
      }
  }
} // namespace

int
main(int argc, char **argv)
{
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  // rock c_p = 3156 m/s: 2 c_p dt = 63 m, the rock is 10 m deep below the dam
  expect_error("MTF with a time step too long for the rock", "  set Transmitting boundary = MTF");
  expect_error("MTF stabilization above 0.5 per step",
               "  set Transmitting boundary = MTF\n  set Stabilization rate = 60");
  expect_error("viscous boundary without springs, static stage",
               "  set Transmitting boundary = viscous");
  expect_error("free field through the damped rock with a band limit of 0 Hz",
               "  set Transmitting boundary = MTF\n  set Band limit = 0");
  // 2 c_p dt = 3.2 m, within the 10 m of rock below the dam; the dam's end
  // faces are flush with the rock's sides.
  expect_run("MTF under a dam flush with the rock's side boundary (Rock extent = 0) runs",
             "  set Transmitting boundary = MTF", "0", "0.0005");
}
