// Benchmark (issue: joints, doc/performance.md §2): the cost of the frictional
// contraction joints on the same arch dam and motion, in one process run.
//
//   bench_joints [--rounds R] [--steps N] [--cells-over-height n]
//                [--cells-through-thickness n] [--degree p]
//                [--monolithic-steps M] [--position-tolerance T]
//
// Cases (each a whole Simulation::run(), dynamic stage only, from rest, no
// field output; El Centro in x scaled by 2 so that joints open and slide):
// - glued: the joints tied (the monolithic dam), Kbar factorized once;
// - mixed: frictional contact by the mixed method (doc/theory/joints.md §3) with the
//   predictor and corrector (two back-substitutions per step, C from
//   multi-column solves);
// - condensed: the mixed method condensed on the pairs (Kbar factorized with
//   the pair DOFs last: one back-substitution per step, C from the Schur
//   complement), compared with the predictor and corrector by the peak
//   opening of every joint;
// - corrected: the condensed mixed method with the position correction of
//   the step impulse (Contraction joints/Position correction,
//   doc/theory/joints.md §11: one more backward substitution in the steps
//   that correct), against the condensed one without it (every case with
//   the closure of these measurements, Closure = velocities); its Position
//   tolerance is T if given (this case's offsets are micrometres: a small T
//   makes it correct as often as the reference case does), else the default;
// - neighbouring: the mixed method with the paper's sparse approximation of
//   C (only pairs on the same or adjacent joints coupled; C is still built in
//   full, so it saves no build time here), compared with the exact C by the
//   peak opening of every joint;
// - monolithic: the same law on the full system, refactorized at every
//   contact iteration (with the trapezoidal pair forces, the only ones it
//   has; the other cases take the default step impulse), for M steps only (it is slow) and at most 30 contact
//   iterations per step (On non-convergence = continue), so its cost per
//   step is a lower bound.
// Reported: wall time per step of the dynamic stage without the one-time
// build of C, and joints-on / joints-off (target <= 1.3); mixed / monolithic
// per step (target: mixed >= 10x faster); the time to build C and its share
// of the dynamic stage; average and maximum contact iterations per step.
// The cases alternate over R rounds; medians are reported.

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

  struct Size
  {
    unsigned int steps = 100, monolithic_steps = 10, over_height = 4, through = 1, degree = 1;
    double       position_tolerance = 0.; ///< 0: the default
  };

  std::string
  case_text(const std::string &name, const Size &s)
  {
    const unsigned int steps = name == "monolithic" ? s.monolithic_steps : s.steps;
    std::ostringstream tolerance; // 1e-9 as written, which std::to_string is not
    if (name == "corrected" && s.position_tolerance > 0.)
      tolerance << " set Position tolerance = " << s.position_tolerance << "\n";
    std::ostringstream prm;
    prm << "subsection Mesh\n set Source = arch dam\n subsection Arch dam\n"
        << "  set Cells over height = " << s.over_height << "\n"
        << "  set Cells across each block = 1\n"
        << "  set Cells through thickness = " << s.through << "\n end\nend\n"
        << "subsection Finite element\n set Degree = " << s.degree << "\nend\n"
        << "subsection Contraction joints\n set Model = "
        << (name == "glued" ? "glued" : "frictional contact") << "\n"
        << " set Solver = " << (name == "monolithic" ? "monolithic" : "mixed") << "\n"
        << " set Flexibility coupling = "
        << (name == "neighbouring" ? "neighbouring joints" : "all joints") << "\n"
        << " set Mixed method solves = "
        << (name == "condensed" || name == "corrected" ? "condensed on the pairs" :
                                                         "predictor and corrector")
        << "\n set Closure = velocities\n set Position correction = "
        << (name == "corrected" ? "true" : "false") << "\n"
        << tolerance.str()
        << " set Friction coefficient = 0.7\n set Cohesion = 0\n set Tensile strength = 5e5\n"
        // The default penalty (1e8 x the largest diagonal entry) leaves the
        // penalized matrix of this dam too ill-conditioned to factorize.
        // The monolithic reference holds positions only: the trapezoidal
        // pair forces (the others take the default step impulse).
        << (name == "monolithic" ? " set Contact in time = trapezoidal\n"
                                   " set Maximum iterations = 30\n"
                                   " set On non-convergence = continue\n"
                                   " set Penalty factor = 1e4\n" :
                                   "")
        << "end\n"
        << "subsection Analysis\n set Stages = dynamic\nend\n"
        << "subsection Static loads\n set Gravity = false\nend\n" // from rest, unloaded
        << "subsection Time integration\n set Time step = 0.01\n set End time = "
        << 0.01 * steps << "\nend\n"
        << "subsection Ground motion\n subsection Component x\n  set File = "
        << "ground_motions/RSN6_IMPVALL.I_I-ELC180.AT2\n"
        << "  set Scale factor = 2\n end\nend\n"
        << "subsection Output\n set Directory = bench_joints_output\n"
        << " set Field output interval = 0\n set Progress = false\n"
        << " set Timer summary = false\nend\n";
    return prm.str();
  }
} // namespace

int
main(int argc, char **argv)
{
  dealii::Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  unsigned int                             rounds = 3;
  Size                                     size;
  for (int i = 1; i + 1 < argc; i += 2)
    {
      const std::string a = argv[i];
      if (a == "--position-tolerance")
        {
          size.position_tolerance = std::stod(argv[i + 1]);
          continue;
        }
      const unsigned int v = std::stoi(argv[i + 1]);
      if (a == "--rounds")
        rounds = v;
      else if (a == "--steps")
        size.steps = v;
      else if (a == "--monolithic-steps")
        size.monolithic_steps = v;
      else if (a == "--cells-over-height")
        size.over_height = v;
      else if (a == "--cells-through-thickness")
        size.through = v;
      else if (a == "--degree")
        size.degree = v;
    }
  const bool root = dealii::Utilities::MPI::this_mpi_process(MPI_COMM_WORLD) == 0;

  std::map<std::string, std::map<std::string, std::vector<double>>> f;
  unsigned int                                                      dofs = 0, pairs = 0;
  for (unsigned int r = 0; r < rounds; ++r)
    for (const std::string name :
         {"glued", "mixed", "condensed", "corrected", "neighbouring", "monolithic"})
      {
        const Parameters     p = parameters_from_string(case_text(name, size));
        std::ostringstream   screen;
        analysis::Simulation sim(p, MPI_COMM_WORLD, screen);
        sim.run();
        dofs = sim.model().space().dof_handler.n_dofs();
        if (sim.model().joint_pairs())
          pairs = sim.model().joint_pairs()->size();
        if (root)
          {
            boost::property_tree::ptree s;
            boost::property_tree::read_json("bench_joints_output/summary.json", s);
            const double steps = s.get<double>("dynamic.steps");
            const double build =
              s.get<double>("dynamic.time to build the flexibility matrix [s]", 0.);
            const double stage = s.get<double>("wall time [s].dynamic: steps");
            f[name]["per step"].push_back((stage - build) / steps);
            f[name]["C build"].push_back(build);
            f[name]["C share"].push_back(build / stage);
            f[name]["iterations average"].push_back(
              s.get<double>("dynamic.contact iterations per step.average", 0.));
            f[name]["iterations maximum"].push_back(
              s.get<double>("dynamic.contact iterations per step.maximum", 0.));
            f[name]["not converged"].push_back(s.get<double>("joints.steps not converged", 0.));
            for (unsigned int j = 0; j < 13; ++j)
              f[name]["opening " + std::to_string(j)].push_back(s.get<double>(
                "dynamic.joints.joint " + std::to_string(j) + ".peak opening [m]", 0.));
            f[name]["corrections"].push_back(
              s.get<double>("dynamic.joints.steps with a position correction", 0.) / steps);
            f[name]["correction share"].push_back(
              s.get<double>("dynamic.time per step [s].position correction", 0.) /
              f[name]["per step"].back());
            f[name]["factorization"].push_back(
              s.get<double>("wall time [s].dynamic: factorization"));
          }
        MPI_Barrier(MPI_COMM_WORLD);
      }
  if (!root)
    return 0;
  const auto m = [&](const std::string &c, const std::string &k) { return median(f[c][k]); };
  double largest = 0., difference = 0., condensed_difference = 0.;
  for (unsigned int j = 0; j < 13; ++j)
    {
      const std::string k = "opening " + std::to_string(j);
      largest             = std::max(largest, m("mixed", k));
      difference          = std::max(difference, std::abs(m("neighbouring", k) - m("mixed", k)));
      condensed_difference =
        std::max(condensed_difference, std::abs(m("condensed", k) - m("mixed", k)));
    }
  std::cout << std::setprecision(3) << "arch dam, 14 blocks, Q" << size.degree << ", "
            << size.over_height << " cells over the height, " << size.through
            << " through the thickness: " << dofs << " DOFs, " << pairs << " node pairs; "
            << size.steps << " steps (monolithic " << size.monolithic_steps
            << "), El Centro x 2; medians of " << rounds << " alternating rounds, "
            << dealii::Utilities::MPI::n_mpi_processes(MPI_COMM_WORLD) << " MPI process(es)\n"
            << "Kbar factorization [s]: glued " << m("glued", "factorization") << ", mixed "
            << m("mixed", "factorization") << ", condensed on the pairs (with the Schur "
            << "complement) " << m("condensed", "factorization") << "\n"
            << "per step [s]: glued " << m("glued", "per step") << ", mixed "
            << m("mixed", "per step") << ", monolithic " << m("monolithic", "per step")
            << " (" << m("monolithic", "not converged") << " of " << size.monolithic_steps
            << " steps stopped at 30 iterations)\n"
            << "joints on / joints off (mixed / glued): "
            << m("mixed", "per step") / m("glued", "per step") << " (target <= 1.3)\n"
            << "condensed on the pairs: per step " << m("condensed", "per step")
            << " s, joints on / joints off (condensed / glued): "
            << m("condensed", "per step") / m("glued", "per step")
            << " (target <= 1.3); build of C from the Schur complement " << m("condensed", "C build")
            << " s; contact iterations per step: average "
            << m("condensed", "iterations average") << "; largest difference of a joint's peak "
            << "opening from the predictor and corrector's " << condensed_difference << " m\n"
            << "condensed with the position correction: per step " << m("corrected", "per step")
            << " s, joints on / joints off (corrected / glued): "
            << m("corrected", "per step") / m("glued", "per step")
            << ", against the condensed without it: "
            << m("corrected", "per step") / m("condensed", "per step") << "; steps with a "
            << "correction " << 100. * m("corrected", "corrections") << " %, the correction's "
            << "solves " << 100. * m("corrected", "correction share") << " % of its time per step\n"
            << "monolithic / mixed per step: "
            << m("monolithic", "per step") / m("mixed", "per step") << " (target >= 10)\n"
            << "build of C [s]: " << m("mixed", "C build") << ", share of the dynamic stage "
            << 100. * m("mixed", "C share") << " %\n"
            << "contact iterations per step (mixed): average "
            << m("mixed", "iterations average") << ", maximum "
            << m("mixed", "iterations maximum") << ", steps not converged "
            << m("mixed", "not converged") << "\n"
            << "neighbouring-joint C: per step " << m("neighbouring", "per step")
            << " s; largest peak opening (exact C) " << largest
            << " m, largest difference of a joint's peak opening " << difference << " m ("
            << 100. * difference / largest << " %)\n";
}
