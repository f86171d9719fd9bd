// Benchmark (issue: reservoir, doc/performance.md §2): the one-time set-up and the
// cost per dynamic step of the same arch dam with an empty reservoir and with
// compressible water, in one process run (this machine is shared: the two
// cases run back to back, several times alternating, and the medians are
// reported).
//
//   bench_reservoir_cost [--rounds R] [--steps N] [--cells-over-height n]
//
// Each case is a whole Simulation::run() (dynamic stage only, no static
// stage, no field output) of N steps of El Centro in x; the figures are the
// stage wall times of its summary: "setup" (mesh, DOFs, M, K, and for the
// water G, H, Q, S), "dynamic: factorization" (Kbar: Cholesky without water,
// LDL^T of the symmetric indefinite coupled matrix with it), and the wall
// time per step (load + Newmark step + monitors).

#include <archdam/analysis/simulation.h>
#include <archdam/parameters/parameters.h>

#include <deal.II/base/mpi.h>

#include <boost/property_tree/json_parser.hpp>
#include <boost/property_tree/ptree.hpp>

#include <algorithm>
#include <iomanip>
#include <iostream>
#include <map>
#include <sstream>

using namespace archdam;

namespace
{
  double
  median(std::vector<double> v)
  {
    std::sort(v.begin(), v.end());
    return v[v.size() / 2];
  }
} // namespace

int
main(int argc, char **argv)
{
  dealii::Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  unsigned int rounds = 3, steps = 20, cells_over_height = 6;
  for (int i = 1; i + 1 < argc; i += 2)
    {
      const std::string a = argv[i];
      if (a == "--rounds")
        rounds = std::stoi(argv[i + 1]);
      else if (a == "--steps")
        steps = std::stoi(argv[i + 1]);
      else if (a == "--cells-over-height")
        cells_over_height = std::stoi(argv[i + 1]);
    }
  const bool root = dealii::Utilities::MPI::this_mpi_process(MPI_COMM_WORLD) == 0;

  std::map<std::string, std::map<std::string, std::vector<double>>> figures;
  std::map<std::string, double>                                      dofs;
  for (unsigned int r = 0; r < rounds; ++r)
    for (const std::string model : {"none", "compressible"})
      {
        std::ostringstream prm;
        prm << "subsection Mesh\n set Source = arch dam\n subsection Arch dam\n"
            << "  set Cells over height = " << cells_over_height << "\n"
            << "  set Number of blocks = 8\n  set Cells across each block = 1\n"
            << "  set Cells through thickness = 2\n  set Rock cell size = 80\n"
            << "  set Water cell size = 60\n end\nend\n"
            << "subsection Reservoir\n set Model = " << model << "\nend\n"
            << "subsection Analysis\n set Stages = dynamic\nend\n"
            << "subsection Time integration\n set Time step = 0.01\n set End time = "
            << 0.01 * steps << "\nend\n"
            << "subsection Ground motion\n subsection Component x\n  set File = "
            << "ground_motions/RSN6_IMPVALL.I_I-ELC180.AT2\n end\nend\n"
            << "subsection Output\n set Directory = bench_reservoir\n"
            << " set Field output interval = 0\n set Progress = false\n"
            << " set Timer summary = false\nend\n";
        const Parameters     p = parameters_from_string(prm.str());
        std::ostringstream   screen;
        analysis::Simulation sim(p, MPI_COMM_WORLD, screen);
        sim.run();
        dofs[model] = sim.model().space().dof_handler.n_dofs();
        if (root)
          {
            boost::property_tree::ptree summary;
            boost::property_tree::read_json("bench_reservoir/summary.json", summary);
            auto &f = figures[model];
            f["set-up (mesh, DOFs, operators) [s]"].push_back(
              summary.get<double>("wall time [s].setup"));
            f["Kbar + factorization [s]"].push_back(
              summary.get<double>("wall time [s].dynamic: factorization"));
            f["per step [s]"].push_back(summary.get<double>("dynamic.wall time per step [s]"));
          }
        MPI_Barrier(MPI_COMM_WORLD);
      }
  if (root)
    {
      std::cout << "arch dam, 8 blocks, " << cells_over_height << " cells over the height, Q2, "
                << steps << " steps, medians of " << rounds << " alternating rounds, "
                << dealii::Utilities::MPI::n_mpi_processes(MPI_COMM_WORLD) << " MPI process(es)"
                << std::endl;
      for (const auto &[name, values] : figures["none"])
        {
          const double empty = median(values), water = median(figures["compressible"][name]);
          std::cout << std::left << std::setw(40) << name << std::setprecision(4)
                    << " empty " << empty << " (" << dofs["none"] << " DOFs), water " << water
                    << " (" << dofs["compressible"] << " DOFs), ratio " << water / empty
                    << std::endl;
        }
    }
}
