// A record suite (issue "evaluation", must show 3; doc/user-guide.md,
// "Record suites"): the coarse arch dam with 13 frictional joints
// (prm/arch_dam_joints_coarse.prm) run under three real records of the data
// folder, each with its scales, 0.3 s of each (a short window keeps the test
// quick): El Centro 1940 (x and y scaled by 2), Rinaldi 1994 (three
// components, y reversed, the vertical halved) and Sylmar 1994 (x and y).
// Checked against references outside the suite's own arithmetic:
//  - suite.csv's per-record values against each record's own summary.json,
//    and its mean, largest, sample standard deviation, mean + 1 sd and design
//    value (the largest, fewer than seven records) recomputed here from
//    those summaries (1e-14 of the row's largest value: the file holds 17
//    digits);
//  - each record's scale: its run's PGA in g against the largest |value| of
//    the AT2 file read here times the scale (1e-12), and Sylmar's run has no
//    vertical motion;
//  - the Rinaldi record run alone, as a case with its files and scales set
//    in Ground motion, gives the suite's Rinaldi column (openings of
//    round-off size, below 1e-12 m, as zero; serially 1e-9 relative, the two
//    runs agreeing exactly; under MPI 1e-6: MUMPS's parallel factorization
//    assembles the processes' contributions in the order they arrive, so two
//    runs of one case differ at round-off, and the coupled dam-water
//    matrix's delayed pivots can make even the factors' sizes differ (3.70e6
//    against 3.66e6 entries in one pair of runs, whose joint 11 then opened
//    by 2.74e-4 m in both, 6e-9 apart));
//  - the records as independent jobs: Rinaldi run alone as the suite's
//    record (--record), the two others' runs copied from the suite's folder,
//    and the statistics gathered from the three (--gather) give the suite's
//    own suite.csv (the copied columns identical, the rest as above); an
//    unknown record, a record not yet run, another record's run in a
//    record's folder, a run that stopped before its end and a record's run
//    under way are refused, each with its message;
//  - the statistics of seven given values (1 to 7): mean 4, sample standard
//    deviation sqrt(28/6), design value the mean (1e-15);
//  - the suite's report.html links to the records' own reports;
//  - Scale to target: the factor brings the record's horizontal spectrum
//    (the geometric mean of x and y) to the target on average in log over
//    the period range, recomputed here from the scaled components' spectra
//    (1e-12); twice the record gives half the factor (1e-12); a suite with
//    Scale to target applies it (suite.json's factor 1e-11, its run's PGA
//    the file's times scale and factor, 1e-10).

#include <archdam/analysis/simulation.h>
#include <archdam/loads/response_spectrum.h>
#include <archdam/application/record_suite.h>
#include <archdam/base/input_error.h>
#include <archdam/output/run_lock.h>
#include <archdam/parameters/parameters.h>

#include "archdam_tests.h"

#include <boost/property_tree/json_parser.hpp>
#include <boost/property_tree/ptree.hpp>

#include <cmath>
#include <filesystem>
#include <regex>
#include <fstream>
#include <sstream>

using namespace dealii;
using namespace archdam;

namespace
{
  const std::string case_file = SOURCE_DIR "/../prm/arch_dam_joints_coarse.prm";

  const std::vector<std::string> common = {"Time integration/End time=0.3",
                                           "Evaluation/Evaluate=true",
                                           "Evaluation/Tensile strength=1e6",
                                           "Output/Field output interval=0",
                                           "Output/Progress=false",
                                           "Output/Timer summary=false"};

  /// Largest |value| of a PEER AT2 file (4 header lines, then values in g).
  double
  largest_in_file(const std::string &name)
  {
    std::ifstream in(testing::ground_motions + name);
    std::string   line;
    for (unsigned int i = 0; i < 4; ++i)
      std::getline(in, line);
    double largest = 0., v;
    while (in >> v)
      largest = std::max(largest, std::abs(v));
    return largest;
  }

  /// The rows of a CSV file, split at commas.
  std::vector<std::vector<std::string>>
  read_csv(const std::string &file)
  {
    std::vector<std::vector<std::string>> rows;
    std::ifstream                         in(file);
    for (std::string line; std::getline(in, line);)
      rows.push_back(Utilities::split_string_list(line, ','));
    return rows;
  }

  bool
  close(const double a, const double b, const double tol)
  {
    return std::abs(a - b) <= tol * std::max(std::abs(b), 1e-300);
  }
} // namespace

int
main(int argc, char **argv)
{
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  auto                            &log  = testing::log();
  const bool                       root = Utilities::MPI::this_mpi_process(MPI_COMM_WORLD) == 0;

  const std::vector<std::string> names = {"elcentro", "rinaldi", "sylmar"};
  std::vector<std::string>       overrides = common;
  overrides.push_back("Output/Directory=suite");
  overrides.push_back(
    "Record suite/Records="
    "elcentro: x = ground_motions/RSN6_IMPVALL.I_I-ELC180.AT2 * 2, "
    "y = ground_motions/RSN6_IMPVALL.I_I-ELC270.AT2 * 2; "
    "rinaldi: x = ground_motions/Rinaldi228.AT2, y = ground_motions/Rinaldi318.AT2 * -1, "
    "z = ground_motions/RinaldiUP.AT2 * 0.5; "
    "sylmar: x = ground_motions/RSN1084_NORTHR_SCS052.AT2, "
    "y = ground_motions/RSN1084_NORTHR_SCS142.AT2");
  const Parameters   p = read_parameters(case_file, overrides);
  std::ostringstream quiet;
  application::run_record_suite(case_file, overrides, p, MPI_COMM_WORLD, quiet);
  log << "records parsed: " << p.suite.parse().size() << std::endl;

  // The Rinaldi record alone, as an ordinary case.
  std::vector<std::string> alone = common;
  for (const auto &o : {"Output/Directory=rinaldi_alone",
                        "Ground motion/Component x/File=ground_motions/Rinaldi228.AT2",
                        "Ground motion/Component y/File=ground_motions/Rinaldi318.AT2",
                        "Ground motion/Component y/Scale factor=-1",
                        "Ground motion/Component z/File=ground_motions/RinaldiUP.AT2",
                        "Ground motion/Component z/Scale factor=0.5"})
    alone.emplace_back(o);
  const Parameters p_alone = read_parameters(case_file, alone);
  {
    analysis::Simulation simulation(p_alone, MPI_COMM_WORLD, quiet);
    simulation.run();
  }
  MPI_Barrier(MPI_COMM_WORLD);

  // The records as independent jobs (archdam CASE --record NAME, then
  // --gather): Rinaldi run by itself into jobs/, the two other records'
  // runs copied there from the suite's folder, then the statistics gathered.
  // (jobs/ anew: a folder left by an earlier run of the test would hold runs)
  if (root)
    std::filesystem::remove_all("jobs");
  MPI_Barrier(MPI_COMM_WORLD);
  std::vector<std::string> jobs = overrides;
  jobs.emplace_back("Output/Directory=jobs");
  const Parameters p_jobs = read_parameters(case_file, jobs);
  const auto       suite_run = [&](const application::SuiteRun run, const std::string &only) {
    try
      {
        application::run_record_suite(case_file, jobs, p_jobs, MPI_COMM_WORLD, quiet, run, only);
        return std::string("no error");
      }
    catch (const InputError &e)
      {
        return std::string("InputError: ") + e.what();
      }
  };
  log << "* --record of a record the suite does not have\n  "
      << suite_run(application::SuiteRun::one_record, "kobe") << std::endl;
  log << "--record rinaldi: " << suite_run(application::SuiteRun::one_record, "rinaldi")
      << std::endl;
  MPI_Barrier(MPI_COMM_WORLD);
  const bool rinaldi_only = std::filesystem::exists("jobs/rinaldi/summary.json") &&
                            !std::filesystem::exists("jobs/elcentro") &&
                            !std::filesystem::exists("jobs/suite.csv");
  log << "* --gather before every record has run\n  "
      << suite_run(application::SuiteRun::gather, "") << std::endl;
  const auto copy_run = [&](const std::string &from, const std::string &to) {
    if (root)
      {
        std::filesystem::remove_all("jobs/" + to);
        std::filesystem::copy("suite/" + from, "jobs/" + to);
      }
    MPI_Barrier(MPI_COMM_WORLD);
  };
  copy_run("sylmar", "elcentro");
  copy_run("sylmar", "sylmar");
  log << "* --gather with another record's run in a record's folder\n  "
      << suite_run(application::SuiteRun::gather, "") << std::endl;
  copy_run("elcentro", "elcentro");
  // a record's run that stopped before its end (its summary says why)
  if (root)
    {
      boost::property_tree::ptree stopped;
      boost::property_tree::read_json("jobs/elcentro/summary.json", stopped);
      stopped.put("stopped.reason", "interrupted (a signal) at t = 0.1 s");
      boost::property_tree::write_json("jobs/elcentro/summary.json", stopped);
    }
  MPI_Barrier(MPI_COMM_WORLD);
  log << "* --gather with a record's run that stopped before its end\n  "
      << suite_run(application::SuiteRun::gather, "") << std::endl;
  copy_run("elcentro", "elcentro");
  {
    // a record's run under way in its folder (here this process holds it,
    // as a job started elsewhere would)
    const output::RunLock running("jobs/sylmar", "arch_dam_joints_coarse", MPI_COMM_WORLD);
    log << "* --gather while a record's run is under way\n  "
        << std::regex_replace(suite_run(application::SuiteRun::gather, ""),
                              std::regex(R"(\(process [0-9]+ on [^,]*, started [^)]*\))"),
                              "(process ..., started ...)")
        << std::endl;
  }
  const std::string gathered = suite_run(application::SuiteRun::gather, "");

  // Scale to target: a suite of the Rinaldi record alone, scaled to the
  // target spectrum of Ground motion/Generated motion (the default, NB
  // 35047, PGA 0.1 g) over 0.1 to 0.8 s.
  std::vector<std::string> targeted = common;
  for (const auto &o : {"Output/Directory=targeted", "Output/Report=false",
                        "Record suite/Records=rinaldi: x = ground_motions/Rinaldi228.AT2, "
                        "y = ground_motions/Rinaldi318.AT2 * -1, z = ground_motions/RinaldiUP.AT2 * 0.5",
                        "Record suite/Scale to target=true", "Record suite/Shortest period=0.1",
                        "Record suite/Longest period=0.8"})
    targeted.emplace_back(o);
  const Parameters p_targeted = read_parameters(case_file, targeted);
  application::run_record_suite(case_file, targeted, p_targeted, MPI_COMM_WORLD, quiet);
  const auto   settings = p_targeted.ground_motion.generated.settings(0, "");
  const double factor   = application::scale_to_target(
    loads::GroundMotion(p_alone.ground_motion, p_alone.base_directory), settings.target,
    settings.damping, 0.1, 0.8);
  // its definition, recomputed here: the scaled record's horizontal
  // spectrum (the geometric mean of x and y) over the target, averaged in
  // log over 40 periods evenly spaced in log T, is 1
  const loads::GroundMotion rinaldi(p_alone.ground_motion, p_alone.base_directory);
  const auto                periods = loads::log_spaced_periods(0.1, 0.8, 40);
  double                    log_ratio = 0.;
  for (unsigned int d = 0; d < 2; ++d)
    {
      auto scaled = rinaldi.record(d);
      for (double &a : scaled.values)
        a *= factor;
      const auto spectrum = loads::response_spectrum(scaled, periods, settings.damping);
      for (unsigned int i = 0; i < periods.size(); ++i)
        log_ratio += 0.5 * std::log(spectrum.pseudo_acceleration[i] /
                                    settings.target.acceleration(periods[i]));
    }
  // linear in the record: twice the record, half the factor
  std::vector<std::string> doubled = alone;
  for (const auto &o : {"Ground motion/Component x/Scale factor=2",
                        "Ground motion/Component y/Scale factor=-2",
                        "Ground motion/Component z/Scale factor=1"})
    doubled.emplace_back(o);
  const Parameters p_doubled      = read_parameters(case_file, doubled);
  const double     factor_doubled = application::scale_to_target(
    loads::GroundMotion(p_doubled.ground_motion, p_doubled.base_directory), settings.target,
    settings.damping, 0.1, 0.8);
  MPI_Barrier(MPI_COMM_WORLD);
  if (!root)
    return 0;
  {
    boost::property_tree::ptree suite, run;
    boost::property_tree::read_json("targeted/suite.json", suite);
    boost::property_tree::read_json("targeted/rinaldi/summary.json", run);
    const auto at = [](const boost::property_tree::ptree &t, const std::string &path) {
      return t.get<double>(boost::property_tree::ptree::path_type(path, '|'));
    };
    log << "scale to target: the mean log ratio of the scaled spectrum to the target is 0 "
           "(1e-12): "
        << testing::yes(std::abs(log_ratio / periods.size()) < 1e-12)
        << "\n  twice the record, half the factor (1e-12): "
        << testing::yes(close(factor_doubled, factor / 2., 1e-12))
        << "\n  the suite's factor is this one (1e-11): "
        << testing::yes(close(at(suite, "record|rinaldi|factor to the target"), factor, 1e-11))
        << "\n  its run's PGA in x and z: the file's times the factor and the record's scale "
           "(1e-10): "
        << testing::yes(close(at(run, "ground motion|x|PGA [g]"),
                              factor * largest_in_file("Rinaldi228.AT2"), 1e-10) &&
                        close(at(run, "ground motion|z|PGA [g]"),
                              0.5 * factor * largest_in_file("RinaldiUP.AT2"), 1e-10))
        << std::endl;
  }

  // Each record's scale, from its run's summary against the file.
  const auto pga = [](const std::string &record, const char axis) {
    boost::property_tree::ptree summary;
    boost::property_tree::read_json("suite/" + record + "/summary.json", summary);
    return summary.get<double>(boost::property_tree::ptree::path_type(
      std::string("ground motion|") + axis + "|PGA [g]", '|'));
  };
  log << "El Centro x at twice the file's PGA: "
      << testing::yes(close(pga("elcentro", 'x'), 2 * largest_in_file("RSN6_IMPVALL.I_I-ELC180.AT2"), 1e-12))
      << "\nRinaldi y reversed, the file's PGA: "
      << testing::yes(close(pga("rinaldi", 'y'), largest_in_file("Rinaldi318.AT2"), 1e-12))
      << "\nRinaldi z at half the file's PGA: "
      << testing::yes(close(pga("rinaldi", 'z'), 0.5 * largest_in_file("RinaldiUP.AT2"), 1e-12))
      << "\nSylmar x at the file's PGA: "
      << testing::yes(close(pga("sylmar", 'x'), largest_in_file("RSN1084_NORTHR_SCS052.AT2"), 1e-12))
      << std::endl;
  boost::property_tree::ptree sylmar;
  boost::property_tree::read_json("suite/sylmar/summary.json", sylmar);
  log << "Sylmar has no vertical motion: "
      << testing::yes(!sylmar.get_child_optional(boost::property_tree::ptree::path_type(
        "ground motion|z", '|')))
      << std::endl;

  // suite.csv against the records' summaries.
  const auto rows = read_csv("suite/suite.csv");
  log << "suite.csv header:";
  for (const auto &cell : rows.empty() ? std::vector<std::string>() : rows[0])
    log << " [" << cell << "]";
  log << std::endl;
  std::vector<std::vector<std::pair<std::string, double>>> peaks;
  for (const auto &name : names)
    peaks.push_back(application::run_peaks("suite/" + name + "/summary.json"));
  const auto rinaldi_alone = application::run_peaks("rinaldi_alone/summary.json");
  unsigned int n_joint_openings = 0, n_slips = 0, n_dcr = 0, n_rows_ok = 0, n_alone_ok = 0;
  const double same_run = Utilities::MPI::n_mpi_processes(MPI_COMM_WORLD) > 1 ? 1e-6 : 1e-9;
  bool same_quantities = rows.size() == peaks[0].size() + 1;
  for (unsigned int i = 0; same_quantities && i < peaks[0].size(); ++i)
    {
      const auto &row = rows[i + 1];
      const auto &name = peaks[0][i].first;
      same_quantities = row.size() == 9 && row[0] == name && rinaldi_alone[i].first == name;
      for (unsigned int k = 0; k < 3 && same_quantities; ++k)
        same_quantities = peaks[k][i].first == name;
      if (!same_quantities)
        break;
      n_joint_openings += name.find("peak opening") != std::string::npos;
      n_slips += name.find("peak slip") != std::string::npos;
      n_dcr += name.find("DCR/largest") != std::string::npos;
      // recomputed here: mean, largest, sample standard deviation
      const double a = peaks[0][i].second, b = peaks[1][i].second, c = peaks[2][i].second;
      const double mean    = (a + b + c) / 3.;
      const double largest = std::max({a, b, c});
      const double sd =
        std::sqrt(((a - mean) * (a - mean) + (b - mean) * (b - mean) + (c - mean) * (c - mean)) / 2.);
      const std::vector<double> expected = {a, b, c, mean, largest, sd, mean + sd, largest};
      bool                      ok       = true;
      // to round-off at the row's scale (a standard deviation of equal
      // values is 0 or a few ulps of them, depending on the order of sums)
      for (unsigned int k = 0; k < expected.size(); ++k)
        ok = ok && std::abs(std::stod(row[k + 1]) - expected[k]) <= 1e-14 * largest;
      n_rows_ok += ok;
      if (!ok)
        {
          log << "  differs: " << name << ":";
          for (unsigned int k = 0; k < expected.size(); ++k)
            log << " " << row[k + 1] << " (" << expected[k] << ")";
          log << std::endl;
        }
      n_alone_ok += std::abs(rinaldi_alone[i].second - b) <= std::max(same_run * std::abs(b), 1e-12);
    }
  log << "the records' summaries hold the same peaks, in the rows of suite.csv: "
      << testing::yes(same_quantities) << "\npeaks compared: joint openings " << n_joint_openings
      << ", slips " << n_slips << ", DCR " << n_dcr << ", all " << peaks[0].size()
      << "\nrows whose values and statistics match the summaries: " << n_rows_ok
      << "\nRinaldi alone gives the suite's Rinaldi column: " << n_alone_ok << " of "
      << peaks[0].size() << std::endl;

  // The gathered suite.csv is the whole suite's: the same rows, the
  // elcentro and sylmar columns identical (the same runs), the rest within
  // the tolerance of two runs of one case (above).
  const auto   jobs_rows = read_csv("jobs/suite.csv");
  unsigned int n_gathered_ok = 0;
  for (unsigned int i = 1; i < rows.size() && i < jobs_rows.size(); ++i)
    {
      bool ok = jobs_rows[i].size() == rows[i].size() && jobs_rows[i][0] == rows[i][0] &&
                jobs_rows[i][1] == rows[i][1] && jobs_rows[i][3] == rows[i][3];
      for (unsigned int k = 1; ok && k < rows[i].size(); ++k)
        {
          const double a = std::stod(jobs_rows[i][k]), b = std::stod(rows[i][k]);
          ok = std::abs(a - b) <= std::max(same_run * std::abs(b), 1e-12);
        }
      n_gathered_ok += ok;
    }
  log << "--record rinaldi ran that record alone (no other record, no statistics): "
      << testing::yes(rinaldi_only) << "\n--gather of the three runs: " << gathered
      << "; its suite.csv rows that are the whole suite's: " << n_gathered_ok << " of "
      << rows.size() - 1 << ", with the same header: "
      << testing::yes(!jobs_rows.empty() && jobs_rows[0] == rows[0]) << std::endl;

  boost::property_tree::ptree suite;
  boost::property_tree::read_json("suite/suite.json", suite);
  log << "suite.json: " << suite.get<std::string>("records") << " records, design value "
      << suite.get<std::string>("design value") << std::endl;

  // The suite's report links to each record's, which is there.
  std::ifstream      report("suite/report.html");
  std::ostringstream text;
  text << report.rdbuf();
  bool linked = !text.str().empty();
  for (const auto &name : names)
    linked = linked && text.str().find("href=\"" + name + "/report.html\"") != std::string::npos &&
             std::ifstream("suite/" + name + "/report.html").good();
  log << "the suite's report.html links to each record's report.html, which is there: "
      << testing::yes(linked) << std::endl;

  const auto s = application::suite_statistics({3., 1., 7., 5., 2., 6., 4.});
  log << "seven values 1 to 7: mean 4, sd sqrt(28/6), mean + sd, design value the mean: "
      << testing::yes(close(s.mean, 4., 1e-15) && close(s.largest, 7., 0.) &&
                      close(s.standard_deviation, std::sqrt(28. / 6.), 1e-15) &&
                      close(s.mean_plus_sd, 4. + std::sqrt(28. / 6.), 1e-15) && s.design == s.mean)
      << std::endl;
}
