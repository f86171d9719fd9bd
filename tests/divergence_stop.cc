// A dynamic step whose solution is no longer physical stops the run
// (doc/user-guide.md, "When a run stops"; time/divergence_check.h): exit
// code 1, a message with the time, the step and where (node position and
// region), and the results up to the last good step kept and readable.
//
// 1. A real instability: a box dam on a massed foundation whose MTF runs at
//    c_a dt / h = 2.8 (Q2 cells of 10 m, dt = 4 ms, c_p = 3.5 km/s), beyond
//    the S <= 1 the formula needs (doc/theory/foundation.md §6), without its drift
//    stabilization and without damping. The scattered motion grows at the
//    outer boundary until a displacement passes the model size: the stop
//    must come before the end, name a node of the outer boundary (x = -40 or
//    50 m, y = -40 or 60 m, z = -40 m) in the rock, and a displacement
//    beyond the bound it states.
// 2. A sample of 1e300 m/s^2 at t = 0.05 s in a two-column record (a finite
//    number, so the reader takes it), the dam on a fixed base with dt =
//    0.01 s: step 5 loads it with -M iota 1e300, its displacement is of order
//    1e300 beta2 dt^2 m, far beyond the model size (the bounding-box
//    diagonal, 30 m): the stop must name step 5, t = 0.05 s and a node of
//    the dam.
// 3. A sample of 1e308 m/s^2 at t = 0.03 s: M iota 1e308 overflows to
//    infinity and the solve gives non-finite values: the stop must name step
//    3, t = 0.03 s and a value that is not a finite number.
// 4. The same record without the absurd sample runs to its end.
// Reference for the results left: the histories hold exactly the rows
// t = 0, dt, ..., up to the step before the stop (from the record alone in 2
// and 3; from summary.json's "stopped" entry in 1), every row complete;
// summary.json is valid JSON with the "stopped" entry (absent in 4);
// solution.pvd and every file it names parse.

#include "case_text.h"
#include "command_line_tests.h"
#include "result_files.h"

#include <deal.II/base/point.h>

#include <fstream>
#include <functional>
#include <regex>

using archdam::testing::log;
using archdam::testing::write_input;
using archdam::testing::yes;

namespace
{
  /// A record sampled every 0.01 s to @p duration: @p amplitude sin(20 t)
  /// m/s^2, with @p bad at @p t_bad (t_bad < 0: none).
  std::string
  record(const double duration, const double amplitude, const double t_bad = -1,
         const std::string &bad = "")
  {
    std::ostringstream r;
    r << std::setprecision(10);
    for (int k = 0; 0.01 * k <= duration + 1e-9; ++k)
      {
        const double t = 0.01 * k;
        r << t << " ";
        if (t_bad >= 0 && std::abs(t - t_bad) < 1e-9)
          r << bad << "\n";
        else
          r << amplitude * std::sin(20 * t) << "\n";
      }
    return r.str();
  }

  /// The box dam (x 0...10 m, y 0...20 m, z 0...20 m) with @p model text.
  std::string
  case_text(const std::string &model, const unsigned int field_interval = 2)
  {
    using namespace archdam::testing::case_text;
    // The records' absurd samples reach the divergence check: the PGA limit,
    // which would refuse them before the run as a units error, is off.
    return two_block_box_shaken_by_record_txt() + displacement_monitors("crest: 5, 10, 20") +
           quiet_output("results", field_interval) +
           "subsection Ground motion\n  set Largest plausible PGA = 0\nend\n" + model;
  }

  const std::string fixed_base = R"(
subsection Mesh
  subsection Box
    set Rock depth = 0
  end
end
subsection Finite element
  set Degree = 1
end
subsection Time integration
  set Time step = 0.01
  set End time = 0.1
end
)";

  const std::string unstable_mtf = R"(
subsection Mesh
  subsection Box
    set Rock depth = 40
    set Rock extent = 40
    set Rock cell size = 10
  end
end
subsection Materials
  subsection Rock
    set Young's modulus = 25e9
    set Poisson's ratio = 0.25
    set Density = 2450
  end
end
subsection Foundation
  set Model = massed
  set MTF order = 2
  set Stabilization rate = 0
end
subsection Damping
  set Damping ratio = 0
end
subsection Time integration
  set Time step = 0.004
  set End time = 2
end
)";

  struct Expected
  {
    /// Step at which the run must stop; 0 = some step before the end (read
    /// from summary.json), -1 = it must not stop.
    int         step;
    double      dt;
    /// What the message must say about the value, and the region.
    std::string kind, region;
    /// Whether the node named is where it must be.
    std::function<bool(const dealii::Point<3> &)> place;
  };

  void
  run(const std::string &what, const std::string &model, const std::string &motion,
      const Expected &e)
  {
    log() << "* " << what << std::endl;
    write_input("record.txt", motion);
    write_input("case.prm", case_text(model, model == unstable_mtf ? 100 : 2));
    if (dealii::Utilities::MPI::this_mpi_process(MPI_COMM_WORLD) == 0)
      std::filesystem::remove_all("results");
    MPI_Barrier(MPI_COMM_WORLD);

    const char        *argv[] = {"archdam", "case.prm"};
    std::ostringstream out, err;
    const int          code  = archdam::run_command_line(2, argv, out, err);
    MPI_Barrier(MPI_COMM_WORLD); // rank 0 has written the results
    const bool         stops = e.step >= 0;
    log() << "  exit code " << code << " (expected " << (stops ? 1 : 0) << ")" << std::endl;

    boost::property_tree::ptree summary;
    const auto problem = archdam::testing::json_problem("results/summary.json", summary);
    log() << "  summary.json parses: " << yes(problem.empty()) << problem << std::endl;
    const int stop_step = summary.get("stopped.step", -1);
    if (stops)
      {
        const std::string message = err.str();
        log() << "  summary.json: stopped, and at the step the message names: "
              << yes(stop_step > 0 &&
                     message.find("in step " + std::to_string(stop_step) + " (") !=
                       std::string::npos)
              << std::endl;
        if (e.step > 0)
          log() << "  summary.json: stopped at step " << stop_step << ", t = "
                << summary.get("stopped.time [s]", -1.) << " s, last complete t = "
                << summary.get("stopped.last complete time [s]", -1.) << " s" << std::endl;
        else
          log() << "  stopped before the end: " << yes(stop_step > 0 && stop_step < 500)
                << std::endl;
        std::smatch m;
        const bool  found = std::regex_search(
          message, m,
          std::regex(R"(the solution diverged in step (\d+) \(t = ([-0-9.e+]+) s\): .* = )"
                     R"(([-+0-9.einfa]+) .* at the node \(([-0-9.e+]+), ([-0-9.e+]+), )"
                     R"(([-0-9.e+]+)\) m in ([a-z ]+[0-9]*))"));
        const bool at_time =
          found && std::abs(std::stod(m[2]) - stop_step * e.dt) < 1e-9 * (1 + stop_step);
        const dealii::Point<3> node = found ? dealii::Point<3>(std::stod(m[4]), std::stod(m[5]),
                                                               std::stod(m[6])) :
                                              dealii::Point<3>();
        log() << "  message starts 'archdam: run stopped: Time integration: the solution "
                 "diverged in step k (t = k dt s)': "
              << yes(message.rfind("archdam: run stopped: Time integration:", 0) == 0 &&
                     at_time)
              << "\n  names a node in " << e.region << " where it must be: "
              << yes(found && m[7].str().rfind(e.region, 0) == 0 && e.place(node))
              << "\n  says why, '" << e.kind
              << "': " << yes(message.find(e.kind) != std::string::npos) << std::endl;
        if (found && e.kind.find("size of the model") != std::string::npos)
          {
            std::smatch b;
            std::regex_search(message, b, std::regex(R"(size of the model, ([0-9.e+]+) m)"));
            log() << "  the value named is beyond the bound named: "
                  << yes(!b.empty() && std::abs(std::stod(m[3])) > std::stod(b[1]))
                  << std::endl;
          }
      }
    else if (problem.empty())
      log() << "  summary.json has no 'stopped' entry: "
            << yes(!summary.get_child_optional("stopped")) << std::endl;

    // The histories: the rows t = 0 ... (stop step - 1) dt, or all of them.
    const int  n_rows = stops ? std::max(stop_step, 0) : 11;
    const auto h      = archdam::testing::read_csv_history("results/histories.csv");
    bool       times  = h.valid && n_rows > 0 && static_cast<int>(h.rows.size()) == n_rows;
    for (int r = 0; times && r < n_rows; ++r)
      times = std::abs(h.rows[r][0] - e.dt * r) < 1e-9;
    log() << "  histories.csv parses: " << yes(h.valid) << h.problem
          << "\n  its rows are t = 0, dt, ... to the " << (stops ? "step before the stop" : "end")
          << ": " << yes(times)
          << std::endl;

    unsigned int n_files = 0;
    const auto   fields  = archdam::testing::pvd_problem("results", "solution.pvd", n_files);
    log() << "  solution.pvd and every file it names parse: " << yes(fields.empty()) << fields
          << std::endl;

    // The checkpoint of the last good step (output/checkpoint.h): its
    // manifest names the step before the stop, and a run resumed from it
    // stops again in the same step with the same message (a checkpoint that
    // held the failed step would stop one step later, or at once). The
    // resume is tried serially only: a second model built in the same
    // process may be divided among the ranks differently, which --resume
    // rejects; checkpoint_resume_mpi resumes in a new job, as a user does.
    if (stops)
      {
        std::ifstream     manifest("results/checkpoint/manifest.txt");
        const std::string text((std::istreambuf_iterator<char>(manifest)),
                               std::istreambuf_iterator<char>());
        log() << "  a checkpoint of the last good step (the one before the stop): "
              << yes(stop_step > 0 &&
                     text.find("\nstep = " + std::to_string(stop_step - 1) + "\n") !=
                       std::string::npos)
              << std::endl;
        if (dealii::Utilities::MPI::n_mpi_processes(MPI_COMM_WORLD) > 1)
          return;
        const char        *resume_argv[] = {"archdam", "case.prm", "--resume"};
        std::ostringstream resumed_out, resumed_err;
        const int code = archdam::run_command_line(3, resume_argv, resumed_out, resumed_err);
        MPI_Barrier(MPI_COMM_WORLD);
        log() << "  resumed from it, the run stops again in the same step with the same "
                 "message: "
              << yes(code == 1 && resumed_err.str() == err.str()) << std::endl;
        if (resumed_err.str() != err.str())
          log() << "    first run: " << err.str() << "    resumed:   " << resumed_err.str();
      }
  }
} // namespace

int
main(int argc, char **argv)
{
  dealii::Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  const auto on_outer_boundary = [](const dealii::Point<3> &x) {
    const auto at = [](const double a, const double b) { return std::abs(a - b) < 1e-6; };
    return at(x[0], -40) || at(x[0], 50) || at(x[1], -40) || at(x[1], 60) || at(x[2], -40);
  };
  const auto in_dam = [](const dealii::Point<3> &x) {
    return x[0] >= -1e-9 && x[0] <= 10 + 1e-9 && x[1] >= -1e-9 && x[1] <= 20 + 1e-9 &&
           x[2] >= -1e-9 && x[2] <= 20 + 1e-9;
  };
  run("MTF at c_a dt / h = 2.8 without stabilization or damping", unstable_mtf,
      record(2, 0.5), {0, 0.004, "exceeds the size of the model", "the rock", on_outer_boundary});
  run("a sample of 1e300 m/s^2 at t = 0.05 s", fixed_base, record(0.2, 0.05, 0.05, "1e300"),
      {5, 0.01, "exceeds the size of the model", "dam block", in_dam});
  run("a sample of 1e308 m/s^2 at t = 0.03 s", fixed_base, record(0.2, 0.05, 0.03, "1e308"),
      {3, 0.01, "(not a finite number)", "dam block", in_dam});
  run("the same record without the absurd sample", fixed_base, record(0.2, 0.05),
      {-1, 0.01, "", "", {}});
}
