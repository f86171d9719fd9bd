// A run killed at any moment leaves only valid result files, and nothing it
// had written before is lost (output/atomic_file.h; issue "reliability",
// must show 2).
//
// The test runs the `archdam` application as a child process on a short
// dynamic case (a box dam of two blocks on a fixed base, 2000 steps under a
// sine ground motion, fields every 25 steps as VTU and HDF5, monitors every
// step): once uninterrupted, the reference, then three times killed with
// SIGKILL when its histories reach a chosen number of rows (drawn with a fixed
// seed, so that the kill falls at different stages of a step: a history
// append, a field write). After each kill:
//  - every file left in the output directory parses: CSV (complete rows of
//    numbers, as many as the header), JSON, XML (PVD, PVTU, VTU, XDMF), HDF5;
//    an interrupted write may leave only a `*.tmp` file, which no index names;
//  - histories.csv is a prefix of the reference's, byte for byte, with at
//    least the rows seen before the kill;
//  - solution.pvd names a prefix of the reference's outputs, every output of
//    a step before the last recorded one included;
//  - summary.json, written at the end only, is absent.
// Then once interrupted with SIGINT (Ctrl-C) and continued with --resume.
// Serial only: the test kills one process (under mpirun the whole job would
// be killed the same way, and every file is written by rank 0 or per rank).

#include <deal.II/base/hdf5.h>

#include <boost/property_tree/json_parser.hpp>

#include "archdam_tests.h"
#include "case_text.h"
#include "child_process.h"
#include "result_files.h"

#include <csignal>
#include <filesystem>
#include <iostream>
#include <random>
#include <sys/wait.h>

namespace fs = std::filesystem;
using archdam::testing::count_lines;
using archdam::testing::read_file;
using archdam::testing::yes;

namespace
{
  const unsigned int n_steps = 2000, field_interval = 25;

  namespace case_text = archdam::testing::case_text;
  const std::string case_file = case_text::two_block_box_shaken_by_record_txt(
                                  "    set Rock depth = 0\n") +
                                case_text::linear_elements +
                                case_text::time_integration(0.001, 2) + R"(
subsection Monitors
  set Points = crest: 5, 10, 20
  set Quantities = displacement, principal stress
end
subsection Output
  set Field output interval = 25
  set Field formats = vtu, hdf5
  set Progress = false
  set Timer summary = false
end
)";

  /// Start `archdam case.prm` writing to @p directory; its output goes to
  /// @p directory.log.
  pid_t
  start(const std::string &directory)
  {
    return archdam::testing::start_child(
      {ARCHDAM_EXECUTABLE, "case.prm", "--set", "Output/Directory=" + directory},
      directory + ".log");
  }

  /// Every result file in @p directory parses; "" or the first problem.
  std::string
  invalid_file(const fs::path &directory, unsigned int &n_checked)
  {
    n_checked = 0;
    for (const auto &entry : fs::directory_iterator(directory))
      {
        const auto  name = entry.path().filename().string();
        const auto  ext  = entry.path().extension().string();
        std::string problem;
        // Files being written (.tmp) are not results yet; the run lock
        // (output/run_lock.h) is not one at all.
        if (ext == ".tmp" || name == ".archdam.lock")
          continue;
        if (ext == ".csv")
          {
            const auto h = archdam::testing::read_csv_history(entry.path());
            problem      = h.problem;
          }
        else if (ext == ".json")
          {
            boost::property_tree::ptree tree;
            problem = archdam::testing::json_problem(entry.path(), tree);
          }
        else if (ext == ".pvd" || ext == ".pvtu" || ext == ".vtu" || ext == ".xdmf")
          try
            {
              boost::property_tree::ptree tree;
              boost::property_tree::read_xml(entry.path(), tree);
            }
          catch (const std::exception &e)
            {
              problem = e.what();
            }
        else if (ext == ".h5")
          try
            {
              dealii::HDF5::File file(entry.path(), dealii::HDF5::File::FileAccessMode::open);
            }
          catch (...)
            {
              problem = "does not open as HDF5";
            }
        else
          problem = "unexpected file";
        if (!problem.empty())
          return name + ": " + problem;
        ++n_checked;
      }
    return "";
  }

  /// The DataSet lines of a PVD file.
  std::vector<std::string>
  pvd_entries(const fs::path &pvd)
  {
    std::vector<std::string> entries;
    std::stringstream        s(read_file(pvd));
    for (std::string line; std::getline(s, line);)
      if (line.find("<DataSet") != std::string::npos)
        entries.push_back(line);
    return entries;
  }
} // namespace

int
main()
{
  std::ofstream("case.prm") << case_file;
  {
    std::ofstream r("record.txt");
    for (unsigned int k = 0; k <= 2 * n_steps / 10; ++k)
      r << 0.01 * k << " " << 0.5 * std::sin(12. * 0.01 * k) << "\n";
  }

  // The reference: the whole run.
  fs::remove_all("reference");
  int status = 0;
  waitpid(start("reference"), &status, 0);
  const auto reference_csv = read_file("reference/histories.csv");
  const auto reference_pvd = pvd_entries("reference/solution.pvd");
  std::cout << "uninterrupted run: exit code " << WEXITSTATUS(status) << ", "
            << count_lines("reference/histories.csv") - 1 << " history rows (expected "
            << n_steps + 1 << "), " << reference_pvd.size() << " field outputs (expected "
            << 1 + n_steps / field_interval << ")" << std::endl;

  // The checks below can fail: a history cut in the middle of a row, and an
  // index cut in the middle, are rejected.
  fs::create_directories("cut");
  std::ofstream("cut/histories.csv")
    << reference_csv.substr(0, reference_csv.find('\n', reference_csv.size() / 2) + 5);
  const auto reference_pvd_text = read_file("reference/solution.pvd");
  std::ofstream("cut/solution.pvd") << reference_pvd_text.substr(0, reference_pvd_text.size() / 2);
  unsigned int n_cut = 0;
  std::cout << "a history cut inside a row is rejected: "
            << yes(!archdam::testing::read_csv_history("cut/histories.csv").valid)
            << "\nan index cut in the middle is rejected: "
            << yes(!archdam::testing::pvd_problem("cut", "solution.pvd", n_cut).empty())
            << std::endl;

  std::mt19937                                rng(2026);
  std::uniform_int_distribution<unsigned int> draw(50, n_steps - 100);
  for (unsigned int k = 0; k < 3; ++k)
    {
      const unsigned int target    = draw(rng);
      const std::string  directory = "killed_" + std::to_string(k);
      fs::remove_all(directory);
      const pid_t pid = start(directory);
      // Wait until the histories hold `target` rows (header + rows lines); a
      // run that ends before the kill is reported below.
      const auto watched =
        archdam::testing::watch_lines(pid, directory + "/histories.csv", target + 1);
      const unsigned int seen = watched.lines;
      status                  = watched.status;
      kill(pid, SIGKILL);
      waitpid(pid, &status, 0);
      std::cout << "* killed after at least " << target << " history rows: "
                << yes(WIFSIGNALED(status) && WTERMSIG(status) == SIGKILL) << std::endl;

      unsigned int n_checked = 0;
      const auto   problem   = invalid_file(directory, n_checked);
      std::cout << "  every result file left parses: " << yes(problem.empty()) << problem
                << std::endl;

      const auto csv = read_file(directory + "/histories.csv");
      std::cout << "  histories.csv is a prefix of the uninterrupted run's: "
                << yes(reference_csv.compare(0, csv.size(), csv) == 0)
                << "\n  with at least the rows seen before the kill: "
                << yes(count_lines(directory + "/histories.csv") >= seen) << std::endl;

      // Fields of every step before the last recorded one are complete (a
      // step appends its history row before writing its fields); the static
      // stage's output comes first.
      const auto         pvd          = pvd_entries(directory + "/solution.pvd");
      const unsigned int last_step    = count_lines(directory + "/histories.csv") - 2;
      const unsigned int at_least     = 1 + (last_step == 0 ? 0 : (last_step - 1) / field_interval);
      bool               prefix       = pvd.size() <= reference_pvd.size();
      for (unsigned int i = 0; prefix && i < pvd.size(); ++i)
        prefix = pvd[i] == reference_pvd[i];
      unsigned int n_files = 0;
      const auto   named   = archdam::testing::pvd_problem(directory, "solution.pvd", n_files);
      std::cout << "  solution.pvd names a prefix of the uninterrupted run's outputs: "
                << yes(prefix) << "\n  with every output before the last recorded step: "
                << yes(pvd.size() >= at_least)
                << "\n  every file it names exists and parses: " << yes(named.empty()) << named
                << "\n  summary.json absent (written at the end): "
                << yes(!fs::exists(directory + "/summary.json")) << std::endl;
    }

  // Ctrl-C (SIGINT) in the dynamic stage ("user holes, second round", item
  // 20): the run ends after its step with exit code 1 and a message naming
  // the step, the results and how to continue; summary.json says why; the
  // histories hold every step up to it, as the uninterrupted run's; and
  // --resume continues from the checkpoint it wrote to the uninterrupted
  // run's histories, byte for byte.
  {
    const unsigned int target    = draw(rng);
    const std::string  directory = "interrupted";
    fs::remove_all(directory);
    const pid_t pid     = start(directory);
    const auto  watched = archdam::testing::watch_lines(pid, directory + "/histories.csv", target + 1);
    kill(pid, SIGINT);
    waitpid(pid, &status, 0);
    const std::string log = read_file(directory + ".log");
    std::cout << "* interrupted (SIGINT) after at least " << target
              << " history rows:\n  exit code 1, not killed: "
              << yes(!watched.ended && WIFEXITED(status) && WEXITSTATUS(status) == 1)
              << "\n  the message names the step, the results and --resume: "
              << yes(log.find("archdam: run stopped: interrupted after step") != std::string::npos &&
                     log.find("--resume continues the run") != std::string::npos)
              << std::endl;
    boost::property_tree::ptree summary;
    unsigned int                step = 0;
    try
      {
        boost::property_tree::read_json(directory + "/summary.json", summary);
        step = summary.get<unsigned int>("stopped.step");
      }
    catch (const std::exception &)
      {}
    // The last row seen holds step lines - 2 (a header, then step 0); the
    // signal may arrive as that step ends, so the run stops after it or later.
    const unsigned int last_seen = watched.lines - 2;
    const auto         csv       = read_file(directory + "/histories.csv");
    std::cout << "  summary.json names the step it stopped after (at least the last row seen): "
              << yes(step >= last_seen) << "\n  histories.csv: every step up to it ("
              << (step >= last_seen ? "yes" : "NO")
              << "), a prefix of the uninterrupted run's: "
              << yes(count_lines(directory + "/histories.csv") == step + 2 &&
                     reference_csv.compare(0, csv.size(), csv) == 0)
              << std::endl;
    const pid_t resumed = archdam::testing::start_child(
      {ARCHDAM_EXECUTABLE, "case.prm", "--set", "Output/Directory=" + directory, "--resume"},
      directory + "_resumed.log");
    waitpid(resumed, &status, 0);
    std::cout << "  --resume: exit code " << WEXITSTATUS(status)
              << ", histories.csv the uninterrupted run's, byte for byte: "
              << yes(read_file(directory + "/histories.csv") == reference_csv) << std::endl;
  }
}
