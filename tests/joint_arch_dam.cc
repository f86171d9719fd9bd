// The arch dam with its 13 contraction joints in frictional contact (issue
// joints, must-show 3): the parametric dam (14 blocks) on a coarse linear
// mesh (one cell across each block and through the thickness, four over the
// height), massless rock, gravity in the static stage, then 0.5 s of the El
// Centro record in the stream direction, scaled by 2.
//
// 1. Joints too strong to open or slide (sigma_t = c = 1e12 Pa) against the
//    glued dam, where the two faces of every joint are tied by constraints (a
//    second method on the same mesh): crest displacement history to 1e-6 of
//    its peak, no pair opens.
// 2. The paper's joint law (mu = 0.7, c = 0, sigma_t = 0.5 MPa, doc/theory/joints.md
//    §2): every contact solve converges (static and dynamic); the node pairs
//    are the joint faces' nodes off the grouted edge on the rock,
//    13 x (5 x 2 - 2) = 104; after each stage every pair satisfies the law,
//    checked here from its forces and gap: no penetration and no opening of
//    a loaded pair beyond 1e-9 m, no tension (with c = 0 a pair in tension
//    has no shear capacity, Table 1), shear force within mu |f_xi| (relative
//    1e-6 of the largest pair force); the joints open; the joint outputs:
//    the PVD series lists one VTU per field output and every file exists,
//    the joint history has one row per step plus the start.
// 3. A step whose contact problem does not converge (Maximum iterations = 2):
//    with On non-convergence = stop the run ends with a message naming the
//    time, the joint, the node pair's position and the residual; with
//    continue it reaches the end and counts the flagged steps in the summary.

#include <archdam/analysis/simulation.h>
#include <archdam/base/input_error.h>

#include "archdam_tests.h"
#include "case_text.h"

#include <filesystem>
#include <fstream>
#include <regex>

using namespace dealii;
using namespace archdam;

namespace
{
  std::string
  model(const std::string &joints, const std::string &directory,
        const std::string &stages = "static, dynamic")
  {
    // Without the static stage the dam starts unloaded at rest (no gravity).
    const std::string loads =
      stages.find("static") == std::string::npos ? "\nsubsection Static loads\n  set Gravity = false\nend\n" : "";
    return "\nsubsection Analysis\n  set Stages = " + stages + "\nend\n" + loads +
           testing::case_text::coarse_arch_dam_mesh(4) + testing::case_text::linear_elements +
           "\nsubsection Contraction joints\n" + joints + "\nend\n" +
           testing::case_text::time_integration(0.01, 0.5) +
           testing::case_text::el_centro_x("    set Scale factor = 2\n") +
           testing::case_text::displacement_monitors("crest: 5, 0, 234") +
           testing::case_text::quiet_output(directory, 10);
  }

  /// Largest violation of the law over all pairs (test's own reading of
  /// doc/theory/joints.md §2 with c = 0 and zero residual strength): penetration or
  /// a loaded pair that is open [m]; tension and shear beyond friction,
  /// relative to the largest pair force.
  struct LawCheck
  {
    double gap = 0., force = 0.;
  };

  LawCheck
  check_law(const joints::JointSolver &s, const double mu)
  {
    LawCheck     c;
    double       largest = 0.;
    const double *f      = s.force.data();
    for (unsigned int i = 0; i < s.pairs.size(); ++i)
      largest = std::max(largest, std::abs(f[3 * i]) + std::hypot(f[3 * i + 1], f[3 * i + 2]));
    for (unsigned int i = 0; i < s.pairs.size(); ++i)
      {
        const double fx = f[3 * i], ft = std::hypot(f[3 * i + 1], f[3 * i + 2]);
        const double gap = s.gap(i);
        c.gap = std::max(c.gap, -gap); // penetration
        if (fx != 0. || ft != 0.)
          c.gap = std::max(c.gap, gap); // a loaded pair must be closed
        c.force = std::max({c.force, fx / largest, (ft + mu * fx) / largest});
      }
    return c;
  }

  std::vector<double>
  crest_history(const analysis::Simulation &sim)
  {
    const auto          col = testing::column(sim.recorder<archdam::output::MonitorHistories>()->columns(), "crest.ux [m]");
    std::vector<double> h;
    for (const auto &row : sim.recorder<archdam::output::MonitorHistories>()->rows())
      h.push_back(row[col]);
    return h;
  }
} // namespace

int
main(int argc, char **argv)
{
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  auto                            &log = testing::log();
  std::ostringstream               quiet;

  // 1. strong joints against the glued dam
  std::vector<double> glued, strong;
  {
    const Parameters     p = parameters_from_string(model("  set Model = glued", "glued"));
    analysis::Simulation sim(p, MPI_COMM_WORLD, quiet);
    sim.run();
    glued = crest_history(sim);
  }
  double strong_opening = 0.;
  {
    const Parameters p = parameters_from_string(
      model("  set Model = frictional contact\n  set Tensile strength = 1e12\n"
            "  set Cohesion = 1e12",
            "strong"));
    analysis::Simulation sim(p, MPI_COMM_WORLD, quiet);
    sim.run();
    strong = crest_history(sim);
    for (unsigned int i = 0; i < sim.joint_state()->pairs.size(); ++i)
      strong_opening = std::max(strong_opening, sim.joint_state()->gap(i));
  }
  double peak = 0., difference = 0.;
  for (unsigned int k = 0; k < glued.size(); ++k)
    {
      peak       = std::max(peak, std::abs(glued[k]));
      difference = std::max(difference, std::abs(strong[k] - glued[k]));
    }
  log << "strong joints against the glued dam:" << std::endl;
  testing::check_below("  max |crest u_x difference| / peak crest u_x", difference / peak, 1e-6);
  testing::check_below("  largest opening of a pair [m]", strong_opening, 1e-9);

  // 2. the paper's law
  const std::string law = "  set Model = frictional contact\n  set Friction coefficient = 0.7\n"
                          "  set Cohesion = 0\n  set Tensile strength = 5e5";
  const double      mu  = 0.7;
  LawCheck          after_static;
  {
    const Parameters p = parameters_from_string(model(law, "law_static", "static"));
    analysis::Simulation sim(p, MPI_COMM_WORLD, quiet);
    sim.run();
    after_static = check_law(*sim.joint_state(), mu);
  }
  // The static contact problem (104 pairs from zero forces; under gravity
  // alone about a third of them open and most others slip as the blocks
  // lean): the active set does not settle from the all-stick start, the
  // Gauss-Seidel sweeps bring it near, and the active set with Newton steps
  // for the slipping pairs then converges superlinearly (91 iterations in
  // all). The damped fixed point for the slip direction that the Newton
  // step replaced needed 9,425 iterations here.
  const double static_iterations = testing::summary_number("law_static/summary.json",
                                                                 "contact iterations");
  const Parameters     p = parameters_from_string(model(law, "law"));
  analysis::Simulation sim(p, MPI_COMM_WORLD, quiet);
  sim.run();
  const auto &joints = *sim.joint_state();
  log << "the paper's joint law:" << std::endl
      << "  node pairs: " << joints.pairs.size() << " (13 x (5 x 2 - 2) = 104)" << std::endl
      << "  joints with pairs: " << joints.pairs.n_joints() << std::endl;
  const LawCheck after_dynamic = check_law(joints, mu);
  testing::check_below("  law after the static stage: penetration or open loaded pair [m]",
                       after_static.gap, 1e-9);
  testing::check_below("  law after the static stage: tension or shear beyond friction",
                       after_static.force, 1e-6);
  log << "  static contact problem converged in at most 200 iterations: "
      << (static_iterations > 0 && static_iterations <= 200 ? "yes" : "NO (" + std::to_string(static_iterations) + ")")
      << std::endl;
  testing::check_below("  law after the dynamic stage: penetration or open loaded pair [m]",
                       after_dynamic.gap, 1e-9);
  testing::check_below("  law after the dynamic stage: tension or shear beyond friction",
                       after_dynamic.force, 1e-6);

  // Every solve converged: with On non-convergence = stop (the default) the
  // run would have ended with a message otherwise.
  log << "  every contact solve converged (the run reached its end time): "
      << (std::abs(sim.state().time - 0.5) < 1e-9 ? "yes" : "NO") << std::endl;
  const auto &rows = sim.recorder<archdam::output::JointOutput>()->rows();
  log << "  joint history rows: " << rows.size() << " (50 steps + the start)" << std::endl;
  double largest_opening = 0.;
  for (unsigned int i = 0; i < joints.pairs.size(); ++i)
    largest_opening = std::max(largest_opening, joints.gap(i));
  log << "  some joint open at the end (gap > 1 mm): " << (largest_opening > 1e-3 ? "yes" : "NO")
      << std::endl;

  // the joint VTU series: one dataset per field output, every file there
  if (Utilities::MPI::this_mpi_process(MPI_COMM_WORLD) == 0)
    {
      std::ifstream      pvd("law/joints_dynamic.pvd");
      std::stringstream  text;
      text << pvd.rdbuf();
      const std::string s = text.str();
      const std::regex  dataset("file=\"([^\"]+)\"");
      unsigned int      n = 0, present = 0;
      for (auto it = std::sregex_iterator(s.begin(), s.end(), dataset);
           it != std::sregex_iterator(); ++it, ++n)
        present += std::filesystem::exists("law/" + (*it)[1].str());
      log << "  joints_dynamic.pvd datasets: " << n << " (t = 0, 0.1, ..., 0.5), files present: "
          << present << std::endl;
    }

  // 3. a step that does not converge
  const std::string few = law + "\n  set Maximum iterations = 2";
  std::string       message;
  try
    {
      const Parameters     q = parameters_from_string(model(few, "stop", "dynamic"));
      analysis::Simulation stopped(q, MPI_COMM_WORLD, quiet);
      stopped.run();
    }
  catch (const InputError &e)
    {
      message = e.what();
    }
  const auto has = [&](const std::string &s) { return message.find(s) != std::string::npos; };
  log << "non-convergence, stop: a message naming the time, joint, pair position and residual: "
      << (has("t = ") && has("joint ") && has("node pair at (") && has("law residual") &&
              has("did not converge") ?
            "yes" :
            "NO")
      << std::endl;
  {
    const Parameters q = parameters_from_string(
      model(few + "\n  set On non-convergence = continue", "flagged", "dynamic"));
    analysis::Simulation flagged(q, MPI_COMM_WORLD, quiet);
    flagged.run();
    const double count = testing::summary_number("flagged/summary.json", "steps not converged");
    log << "non-convergence, continue: reaches the end time: "
        << (std::abs(flagged.state().time - 0.5) < 1e-9 ? "yes" : "NO")
        << ", flagged steps counted in summary.json: "
        << (count > 0 ? "yes" : "NO")
        << std::endl;
  }
}
