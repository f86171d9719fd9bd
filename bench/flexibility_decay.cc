// Benchmark (issue "fast steps", lever 1; doc/performance.md §9): how the
// flexibility of the joints' node pairs, W = B Kbar^{-1} B^T (the contact
// problem's matrix, doc/theory/joints.md §4), decays with the distance
// between two pairs, on the case's own mesh.
//
//   bench_flexibility_decay [CASE.prm] [--static] [--set Section/Name=value ...]
//
// With --static, W = B K^{-1} B^T with the static stage's K (with the water's
// rows when the case has water), where no mass makes it local.
//
// The case (default prm/paper_235m_dam.prm: Q2 2 x 2 x 9, compressible
// water, massed rock, dt = 5 ms) is set up as the dynamic stage sets it up
// (Simulation::make_integrator(): Kbar with the water, factorized once), and
// W is built as the mixed solver builds it on its first solve. For pairs i, j
// the coupling is r_ij = |W_ij| / sqrt(|W_ii| |W_jj|), |.| the Frobenius norm
// of the 3 x 3 blocks. Printed: r_ij's largest and median value over the
// pairs in bins of their distance, and by how many joints apart they are;
// with the time to build W and the peak memory. A coupling that falls below
// the contact problem's own tolerance (1e-8 relative) beyond some distance
// makes W sparse there; one that does not must stay coupled.

#include <archdam/analysis/simulation.h>
#include <archdam/joints/joint_solver.h>
#include <archdam/parameters/parameters.h>
#include <archdam/physics/reservoir/coupled_system.h>
#include <archdam/time/factorized_operator.h>

#include <deal.II/base/mpi.h>
#include <deal.II/base/timer.h>

#include <algorithm>
#include <cmath>
#include <iomanip>
#include <iostream>
#include <map>
#include <sstream>

#include "bench_common.h"

using namespace archdam;

namespace
{
  /// Largest and median of @p v (sorted here).
  std::pair<double, double>
  largest_and_median(std::vector<double> &v)
  {
    if (v.empty())
      return {0., 0.};
    std::sort(v.begin(), v.end());
    return {v.back(), v[v.size() / 2]};
  }
} // namespace

int
main(int argc, char **argv)
{
  dealii::Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  bool static_stage = false;
  const auto [file, overrides] =
    bench::case_arguments(argc, argv, "prm/paper_235m_dam.prm", [&](const std::string &a, int &) {
      static_stage = static_stage || a == "--static";
      return a == "--static";
    });
  auto &out = bench::screen();

  const Parameters     p = read_parameters(file, overrides);
  std::ostringstream   quiet;
  analysis::Simulation sim(p, MPI_COMM_WORLD, quiet);
  dealii::Timer        clock;
  const auto          &model = sim.setup_model();
  AssertThrow(model.joint_pairs(), dealii::ExcMessage("The case has no joints in contact."));
  const auto &pairs = *model.joint_pairs();
  out << file << ": " << model.space().dof_handler.n_dofs() << " DOFs, " << pairs.size()
      << " node pairs; setup " << std::setprecision(3) << clock.wall_time() << " s\n";

  // The dynamic stage's Kbar (factorized as the stage factorizes it), or the
  // static stage's K (plainly: W then comes column by column).
  clock.restart();
  std::unique_ptr<time::NewmarkIntegrator> integrator;
  SparseMatrix                             with_water;
  time::FactorizedOperator                 static_factor;
  if (static_stage)
    {
      if (model.fluid())
        physics::reservoir::linear_combination(with_water, {{1., &model.stiffness()},
                                                            {1., &model.fluid()->Q},
                                                            {1., &model.fluid()->G}});
      static_factor.factorize(model.fluid() ? with_water : model.stiffness(), true);
    }
  else
    integrator = sim.make_integrator();
  out << "factorization of " << (static_stage ? "K" : "Kbar") << ": " << clock.wall_time()
      << " s\n";
  // The mixed solver builds W on its first solve: one solve of an unloaded
  // step.
  joints::MixedJointSolver solver(p.joints, pairs,
                                  static_stage ? 1. : integrator->displacement_factor(),
                                  static_stage ? static_factor : integrator->effective_factor());
  Vector r, x;
  model.space().reinit(r);
  model.space().reinit(x);
  clock.restart();
  solver.solve(r, std::vector<double>(3 * pairs.size(), 0.), x);
  const std::vector<double> &C = solver.flexibility();
  out << "W (" << 3 * pairs.size() << " unknowns) built in " << solver.build_time
      << " s; peak resident memory " << bench::memory_gb("VmHWM") << " GB\n";

  const unsigned int m     = 3 * pairs.size();
  const auto         block = [&](const unsigned int i, const unsigned int j) {
    double s = 0.;
    for (unsigned int a = 0; a < 3; ++a)
      for (unsigned int b = 0; b < 3; ++b)
        s += std::pow(C[static_cast<std::size_t>(3 * j + b) * m + 3 * i + a], 2);
    return std::sqrt(s);
  };
  std::vector<double> own(pairs.size());
  for (unsigned int i = 0; i < pairs.size(); ++i)
    own[i] = block(i, i);

  const std::vector<double> edges = {0, 5, 10, 15, 20, 30, 45, 60, 90, 135, 200, 1e9};
  std::vector<std::vector<double>>          by_distance(edges.size() - 1);
  std::map<unsigned int, std::vector<double>> by_joints;
  for (unsigned int i = 0; i < pairs.size(); ++i)
    for (unsigned int j = 0; j < pairs.size(); ++j)
      if (i != j)
        {
          const double r = block(i, j) / std::sqrt(own[i] * own[j]);
          const double d = pairs[i].position.distance(pairs[j].position);
          const auto   k = std::upper_bound(edges.begin(), edges.end(), d) - edges.begin() - 1;
          by_distance[k].push_back(r);
          by_joints[std::abs(int(pairs[i].joint) - int(pairs[j].joint))].push_back(r);
        }

  out << "\n|W_ij| / sqrt(|W_ii| |W_jj|) against the distance between the pairs\n"
      << "  distance [m]      pairs of pairs     largest      median\n";
  for (unsigned int k = 0; k + 1 < edges.size(); ++k)
    {
      const std::size_t n = by_distance[k].size();
      const auto [largest, median] = largest_and_median(by_distance[k]);
      std::ostringstream range;
      range << edges[k] << " - " << (edges[k + 1] > 1e8 ? std::string("") :
                                                          std::to_string(int(edges[k + 1])));
      out << "  " << std::left << std::setw(16) << range.str() << std::right << std::setw(14)
          << n << std::setw(12) << std::setprecision(3) << largest << std::setw(12) << median
          << "\n";
    }
  out << "\nthe same by how many joints apart the two pairs are\n"
      << "  joints apart      pairs of pairs     largest      median\n";
  for (auto &[apart, values] : by_joints)
    {
      const std::size_t n = values.size();
      const auto [largest, median] = largest_and_median(values);
      out << "  " << std::left << std::setw(16) << apart << std::right << std::setw(14) << n
          << std::setw(12) << std::setprecision(3) << largest << std::setw(12) << median << "\n";
    }
  return 0;
}
