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
//    The same run with Contact problem = joint by joint (block Gauss-Seidel,
//    §12): crest history to 1e-6 of its peak and every pair's gap at the end
//    to 1e-8 m of the all-pairs run.
// 3. A step whose contact problem does not converge (Maximum iterations = 2):
//    with On non-convergence = stop the run ends with a message naming the
//    time, the joint, the node pair's position and the residual; with
//    continue it reaches the end and counts the flagged steps in the summary.
// 4. The static stage by dynamic relaxation (Static solution = dynamic
//    relaxation, doc/theory/loading-sequence.md §1) against the one solve of
//    the mixed method with K (a second method for the same static problem),
//    where the static problem has one solution: joints that cannot open or
//    slide (linear), and frictionless joints without tensile strength (a
//    convex problem: one displacement field; its joints open by more than
//    1 mm). Static displacement to 1e-6 and 1e-5 of its largest component
//    (out-of-balance tolerance 1e-7 of the largest load); no pair opens, or
//    the law holds at rest. With the paper's law (where friction makes the
//    answer depend on the loading path) the law holds at rest and the
//    out-of-balance force is within its tolerance (1e-6). Maximum steps too
//    few: a message naming the out-of-balance force; a one solve that does
//    not converge: a message naming the relaxation as the remedy.

#include <archdam/analysis/simulation.h>
#include <archdam/base/input_error.h>

#include "archdam_tests.h"
#include "case_text.h"

#include <algorithm>
#include <array>
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

  // 2b. the same run joint by joint (doc/theory/joints.md §12, a second
  // solver of the same contact problem, red-black over the joints and, under
  // MPI, the joints of a colour on the processes in turn)
  {
    const Parameters q = parameters_from_string(
      model(law + "\n  set Contact problem = joint by joint", "law_by_joint"));
    analysis::Simulation by_joint(q, MPI_COMM_WORLD, quiet);
    by_joint.run();
    const auto reference = crest_history(sim), swept = crest_history(by_joint);
    double     crest_peak = 0., crest_difference = 0., gap_difference = 0.;
    for (unsigned int k = 0; k < reference.size(); ++k)
      {
        crest_peak       = std::max(crest_peak, std::abs(reference[k]));
        crest_difference = std::max(crest_difference, std::abs(swept[k] - reference[k]));
      }
    for (unsigned int i = 0; i < joints.pairs.size(); ++i)
      gap_difference =
        std::max(gap_difference, std::abs(by_joint.joint_state()->gap(i) - joints.gap(i)));
    log << "the same run joint by joint against all pairs at once:" << std::endl;
    testing::check_below("  max |crest u_x difference| / peak crest u_x", crest_difference / crest_peak,
                         1e-6);
    testing::check_below("  largest difference of a pair's gap at the end [m]", gap_difference,
                         1e-8);
    log << "  steps handed to all pairs at once: "
        << testing::summary_number("law_by_joint/summary.json", "handed over") << std::endl;
  }

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
  const std::string message = testing::input_error_message([&] {
    const Parameters     q = parameters_from_string(model(few, "stop", "dynamic"));
    analysis::Simulation stopped(q, MPI_COMM_WORLD, quiet);
    stopped.run();
  });
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

  // 4. the static stage by dynamic relaxation against the one solve
  {
    const std::string relaxation = "\n  set Static solution = dynamic relaxation\n"
                                   "  subsection Dynamic relaxation\n"
                                   "    set Frequency = RELAX_FREQUENCY\n"
                                   "    set Tolerance = RELAX_TOLERANCE\n    set Maximum steps = 20000\n"
                                   "  end";
    const auto relaxed = [&](const double frequency, const double tolerance) {
      std::ostringstream f, t;
      f << frequency;
      t << tolerance;
      return std::regex_replace(std::regex_replace(relaxation, std::regex("RELAX_FREQUENCY"), f.str()),
                                std::regex("RELAX_TOLERANCE"), t.str());
    };
    // What a static state is compared by, independent of how the processes
    // number the DOFs: every pair's force and relative displacement (sorted
    // by the pair's position) and the crest monitor's displacement.
    struct StaticState
    {
      std::vector<std::array<double, 9>> pairs; // x, y, z, f (3), w (3)
      Tensor<1, 3>                       crest;
      double                             largest_gap = 0.;
      LawCheck                           law;
    };
    const auto static_state = [&](const std::string &joints, const std::string &directory,
                                  const double frequency) {
      std::string text = joints;
      if (frequency > 0.)
        text += relaxed(frequency, 1e-7);
      const Parameters     q = parameters_from_string(model(text, directory, "static"));
      analysis::Simulation s(q, MPI_COMM_WORLD, quiet);
      s.run();
      const auto &j = *s.joint_state();
      StaticState r;
      for (unsigned int i = 0; i < j.pairs.size(); ++i)
        {
          const auto &x = j.pairs[i].position;
          r.pairs.push_back({{x[0], x[1], x[2], j.force[3 * i], j.force[3 * i + 1], j.force[3 * i + 2],
                             j.w[3 * i], j.w[3 * i + 1], j.w[3 * i + 2]}});
          r.largest_gap = std::max(r.largest_gap, j.gap(i));
        }
      std::sort(r.pairs.begin(), r.pairs.end());
      r.crest = s.model().monitors().displacement(0, s.static_displacement());
      r.law   = check_law(j, 0.);
      return r;
    };
    // max |a - b| over entries [first, first + 3) of every pair, relative to max |a|
    const auto pair_difference = [](const StaticState &a, const StaticState &b, const unsigned int first) {
      double largest = 0., difference = 0.;
      for (unsigned int i = 0; i < a.pairs.size(); ++i)
        for (unsigned int k = first; k < first + 3; ++k)
          {
            largest    = std::max(largest, std::abs(a.pairs[i][k]));
            difference = std::max(difference, std::abs(a.pairs[i][k] - b.pairs[i][k]));
          }
      return difference / largest;
    };
    log << "the static stage by dynamic relaxation against the one solve:" << std::endl;
    struct Case
    {
      std::string name, joints;
      double      frequency, tolerance;
      bool        zero_strength; // the law of check_law() (c = 0, sigma_t = 0, mu = 0)
    };
    const std::string strong_law = "  set Model = frictional contact\n  set Tensile strength = 1e12\n"
                                   "  set Cohesion = 1e12";
    const std::string frictionless = "  set Model = frictional contact\n  set Friction coefficient = 0\n"
                                     "  set Cohesion = 0\n  set Tensile strength = 0";
    for (const Case &c : {Case{"strong joints", strong_law, 2., 1e-6, false},
                          Case{"frictionless joints", frictionless, 0.5, 1e-5, true}})
      {
        const StaticState one     = static_state(c.joints, "one_solve", 0.);
        const StaticState settled = static_state(c.joints, "relaxed", c.frequency);
        log << "  " << c.name << " (largest opening " << (one.largest_gap > 1e-3 ? "above" : "below")
            << " 1 mm):" << std::endl;
        testing::check_below("    crest: |u difference| / |u|",
                             (settled.crest - one.crest).norm() / one.crest.norm(), c.tolerance);
        testing::check_below("    pair forces: max difference / largest", pair_difference(one, settled, 3),
                             c.tolerance);
        if (c.zero_strength)
          {
            testing::check_below("    pair relative displacements: max difference / largest",
                                 pair_difference(one, settled, 6), c.tolerance);
            testing::check_below("    law at rest: penetration or open loaded pair [m]",
                                 settled.law.gap, 1e-9);
            testing::check_below("    law at rest: tension or shear beyond friction",
                                 settled.law.force, 1e-6);
          }
        else
          testing::check_below("    largest opening of a pair [m]", settled.largest_gap, 1e-9);
      }
    LawCheck at_rest;
    {
      const Parameters     q = parameters_from_string(model(law + relaxed(1., 1e-6), "relaxed_law", "static"));
      analysis::Simulation s(q, MPI_COMM_WORLD, quiet);
      s.run();
      at_rest = check_law(*s.joint_state(), mu);
    }
    log << "  the paper's law:" << std::endl;
    testing::check_below("    law at rest: penetration or open loaded pair [m]", at_rest.gap, 1e-9);
    testing::check_below("    law at rest: tension or shear beyond friction", at_rest.force, 1e-6);
    const double out_of_balance = testing::summary_number(
      "relaxed_law/summary.json", "out-of-balance force relative to the largest load");
    log << "    out-of-balance force at most the tolerance (1e-6 of the largest load): "
        << (out_of_balance >= 0. && out_of_balance <= 1e-6 ? "yes" : "NO") << std::endl;
    const std::string stop = testing::input_error_message([&] {
      const Parameters q = parameters_from_string(model(
        law + std::regex_replace(relaxed(1., 1e-6), std::regex("20000"), "5"), "too_few", "static"));
      analysis::Simulation s(q, MPI_COMM_WORLD, quiet);
      s.run();
    });
    // The one solve that does not converge names the relaxation as the remedy.
    const std::string one_solve_stop = testing::input_error_message([&] {
      const Parameters q =
        parameters_from_string(model(law + "\n  set Maximum iterations = 2", "one_solve_stop", "static"));
      analysis::Simulation s(q, MPI_COMM_WORLD, quiet);
      s.run();
    });
    log << "  one solve not converged: the message names the static stage and the relaxation: "
        << (one_solve_stop.find("static stage") != std::string::npos &&
                one_solve_stop.find("Static solution = dynamic relaxation") != std::string::npos ?
              "yes" :
              "NO: " + one_solve_stop)
        << std::endl;
    log << "  Maximum steps = 5: a message naming the out-of-balance force and the setting: "
        << (stop.find("has not come to rest in 5 steps") != std::string::npos &&
                stop.find("out-of-balance force") != std::string::npos &&
                stop.find("Maximum steps") != std::string::npos ?
              "yes" :
              "NO: " + stop)
        << std::endl;
  }
}
