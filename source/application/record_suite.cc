#include <archdam/analysis/simulation.h>
#include <archdam/application/python_script.h>
#include <archdam/application/record_suite.h>
#include <archdam/base/input_error.h>
#include <archdam/base/on_rank_zero.h>
#include <archdam/output/atomic_file.h>
#include <archdam/output/run_lock.h>
#include <archdam/loads/response_spectrum.h>
#include <archdam/output/summary.h>

#include <boost/property_tree/json_parser.hpp>
#include <boost/property_tree/ptree.hpp>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <functional>
#include <iomanip>
#include <limits>
#include <memory>
#include <ostream>
#include <sstream>

namespace archdam::application
{
  using namespace dealii;

  SuiteStatistics
  suite_statistics(const std::vector<double> &values)
  {
    SuiteStatistics s;
    if (values.empty())
      return s;
    const double n = values.size();
    for (const double v : values)
      s.mean += v;
    s.mean /= n;
    s.largest = *std::max_element(values.begin(), values.end());
    if (values.size() > 1)
      {
        double squares = 0.;
        for (const double v : values)
          squares += (v - s.mean) * (v - s.mean);
        s.standard_deviation = std::sqrt(squares / (n - 1.));
      }
    s.mean_plus_sd = s.mean + s.standard_deviation;
    s.design       = values.size() >= 7 ? s.mean : s.largest;
    return s;
  }

  double
  scale_to_target(const loads::GroundMotion   &motion,
                  const loads::TargetSpectrum &target,
                  const double                 damping,
                  const double                 period_min,
                  const double                 period_max,
                  const unsigned int           n)
  {
    const auto          periods = loads::log_spaced_periods(period_min, period_max, n);
    std::vector<double> log_horizontal(periods.size(), 0.);
    unsigned int        horizontal = 0;
    for (unsigned int d = 0; d < 2; ++d)
      if (motion.has_component(d))
        {
          ++horizontal;
          const auto spectrum = loads::response_spectrum(motion.record(d), periods, damping);
          for (unsigned int i = 0; i < periods.size(); ++i)
            log_horizontal[i] += std::log(spectrum.pseudo_acceleration[i]);
        }
    if (horizontal == 0)
      throw InputError("Record suite: Scale to target needs a horizontal (x or y) component in "
                       "every record.");
    double mean = 0.;
    for (unsigned int i = 0; i < periods.size(); ++i)
      mean += std::log(target.acceleration(periods[i])) - log_horizontal[i] / horizontal;
    return std::exp(mean / periods.size());
  }

  namespace
  {
    bool
    ends_with(const std::string &text, const std::string &end)
    {
      return text.size() >= end.size() && text.compare(text.size() - end.size(), end.size(), end) == 0;
    }

    bool
    starts_with(const std::string &text, const std::string &start)
    {
      return text.rfind(start, 0) == 0;
    }

    /// Whether the summary entry at @p path is a peak a suite compares.
    bool
    is_suite_peak(const std::string &path)
    {
      if (starts_with(path, "dynamic/joints/joint "))
        return ends_with(path, "/peak opening [m]") || ends_with(path, "/peak slip [m]");
      if (starts_with(path, "peaks/"))
        return ends_with(path, "/value");
      if (starts_with(path, "stress envelope/"))
        return ends_with(path, "max major principal stress [Pa]/value") ||
               ends_with(path, "DCR/largest") || ends_with(path, "/longest CID [s]") ||
               ends_with(path, "/overstressed share of the area");
      return false;
    }
  } // namespace

  std::vector<std::pair<std::string, double>>
  run_peaks(const std::string &summary_file)
  {
    boost::property_tree::ptree tree;
    try
      {
        boost::property_tree::read_json(summary_file, tree);
      }
    catch (const std::exception &e)
      {
        throw InputError("Record suite: cannot read the run's results '" + summary_file +
                         "': " + e.what());
      }
    std::vector<std::pair<std::string, double>> peaks;
    const std::function<void(const boost::property_tree::ptree &, const std::string &)> walk =
      [&](const boost::property_tree::ptree &node, const std::string &path) {
        for (const auto &[key, child] : node)
          {
            const std::string here = path.empty() ? key : path + "/" + key;
            if (!child.empty())
              walk(child, here);
            else if (is_suite_peak(here))
              peaks.emplace_back(here, std::abs(child.get_value<double>()));
          }
      };
    walk(tree, "");
    return peaks;
  }

  namespace
  {
    /// The overrides that run record @p r of a suite: the record replaces
    /// the case's motion (scaled by its own scales times @p factor) and
    /// writes into @p folder/NAME; the record's own run is not a suite.
    std::vector<std::string>
    record_overrides(const std::vector<std::string> &overrides,
                     const std::string              &folder,
                     const analysis::SuiteRecord              &r,
                     const double                    factor)
    {
      std::vector<std::string> o = overrides;
      for (unsigned int d = 0; d < 3; ++d)
        {
          const std::string component = "Ground motion/Component " + std::string(1, "xyz"[d]) + "/";
          std::ostringstream scale;
          scale << std::setprecision(17) << factor * r.scale[d];
          o.push_back(component + "Source=file");
          o.push_back(component + "File=" + r.file[d]);
          o.push_back(component + "Scale factor=" + scale.str());
        }
      o.push_back("Output/Directory=" + folder + "/" + r.name);
      o.push_back("Record suite/Records=");
      return o;
    }

    /// The factor that Scale to target gives record @p r (1 without it).
    double
    factor_to_target(const std::string              &case_file,
                     const std::vector<std::string> &overrides,
                     const Parameters               &p,
                     const analysis::SuiteRecord              &r)
    {
      if (!p.suite.scale_to_target)
        return 1.;
      const Parameters as_given =
        read_parameters(case_file, record_overrides(overrides, p.output.directory, r, 1.));
      const auto settings =
        p.ground_motion.generated.settings(0, "Ground motion, Generated motion: ");
      return scale_to_target(loads::GroundMotion(as_given.ground_motion, as_given.base_directory),
                             settings.target, settings.damping, p.suite.period_min,
                             p.suite.period_max);
    }

    /// InputError unless the run in @p record_parameters' output folder is
    /// record @p name's finished run: its summary.json has the dynamic
    /// stage's results, no "stopped" (a run interrupted or diverged), and
    /// names the same directions as the record, each with the peak
    /// acceleration of the record as the suite scales it (to 1e-9; the
    /// summary keeps 12 digits).
    void
    check_record_run(const Parameters  &record_parameters,
                     const std::string &name,
                     const std::string &case_file)
    {
      const std::string &folder       = record_parameters.output.directory;
      const std::string  summary_file = folder + "/summary.json";
      const std::string  again =
        "archdam " + std::filesystem::path(case_file).filename().string() + " --record " + name;
      boost::property_tree::ptree tree;
      try
        {
          boost::property_tree::read_json(summary_file, tree);
        }
      catch (const std::exception &e)
        {
          throw InputError("Record suite: the results of record '" + name + "' cannot be read: " +
                           e.what());
        }
      if (const auto reason = tree.get_optional<std::string>("stopped.reason"))
        throw InputError("Record suite: the run of record '" + name + "' in '" + folder +
                         "' stopped before its end (" + *reason + "). Continue it: " + again +
                         " --resume.");
      if (!tree.get_child_optional("dynamic"))
        throw InputError("Record suite: the run of record '" + name + "' in '" + folder +
                         "' did not end (its summary.json has no \"dynamic\" results): run "
                         "it, " + again + ", or continue it from its checkpoint, " + again +
                         " --resume.");
      const loads::GroundMotion motion(record_parameters.ground_motion,
                                       record_parameters.base_directory);
      for (unsigned int d = 0; d < 3; ++d)
        {
          const std::string key = std::string("ground motion.") + "xyz"[d] + ".PGA [m/s^2]";
          const auto        pga = tree.get_optional<double>(key);
          const double expected = motion.has_component(d) ? motion.record(d).peak() : 0.;
          if (pga.value_or(0.) == expected ||
              (pga && std::abs(*pga - expected) <= 1e-9 * expected))
            continue;
          std::ostringstream what;
          what << std::setprecision(6) << "Record suite: the run in '" << folder
               << "' was not made under record '" << name << "' as the suite scales it (its "
               << "peak acceleration in " << "xyz"[d] << ": "
               << (pga ? std::to_string(*pga) + " m/s^2" : std::string("no motion"))
               << ", the record's: "
               << (motion.has_component(d) ? std::to_string(expected) + " m/s^2" :
                                             std::string("no motion"))
               << "). Run it again: " << again << ".";
          throw InputError(what.str());
        }
    }

    /// Write suite.csv and suite.json into @p folder from the records' runs
    /// in its subfolders (@p factors: each record's factor to the target).
    void
    write_suite_statistics(const std::string              &folder,
                           const std::vector<analysis::SuiteRecord> &records,
                           const std::vector<double>      &factors,
                           std::ostream                   &out)
    {
      // Every record's peaks, in the order of the first record's summary.
      std::vector<std::vector<std::pair<std::string, double>>> peaks;
      for (const auto &r : records)
        peaks.push_back(run_peaks(folder + "/" + r.name + "/summary.json"));
      std::ostringstream csv;
      csv << "quantity";
      for (const auto &r : records)
        csv << ',' << r.name;
      csv << ",mean,largest,standard deviation,mean + 1 sd,design value\n"
          << std::setprecision(std::numeric_limits<double>::max_digits10);
      output::Summary summary;
      summary.set("records", records.size());
      for (unsigned int k = 0; k < records.size(); ++k)
        {
          const auto &r = records[k];
          for (unsigned int d = 0; d < 3; ++d)
            if (!r.file[d].empty())
              {
                const std::string key = "record/" + r.name + "/" + std::string(1, "xyz"[d]);
                summary.set(key + "/file", r.file[d]);
                summary.set(key + "/scale", r.scale[d]);
              }
          summary.set("record/" + r.name + "/factor to the target", factors[k]);
        }
      summary.set("design value", records.size() >= 7 ? "the mean (seven records or more)" :
                                                        "the largest (fewer than seven records)");
      for (unsigned int i = 0; i < peaks[0].size(); ++i)
        {
          const std::string  &name = peaks[0][i].first;
          std::vector<double> values;
          for (unsigned int k = 0; k < records.size(); ++k)
            {
              const auto found = std::find_if(peaks[k].begin(), peaks[k].end(),
                                              [&](const auto &e) { return e.first == name; });
              if (found == peaks[k].end())
                throw InputError("Record suite: the run of record '" + records[k].name +
                                 "' has no '" + name + "' in its summary.json, the first "
                                 "record's has.");
              values.push_back(found->second);
            }
          const auto s = suite_statistics(values);
          csv << name;
          for (const double v : values)
            csv << ',' << v;
          csv << ',' << s.mean << ',' << s.largest << ',' << s.standard_deviation << ','
              << s.mean_plus_sd << ',' << s.design << '\n';
          const std::string key = "peaks/" + name + "/";
          for (unsigned int k = 0; k < records.size(); ++k)
            summary.set(key + records[k].name, values[k]);
          summary.set(key + "mean", s.mean);
          summary.set(key + "largest", s.largest);
          summary.set(key + "standard deviation", s.standard_deviation);
          summary.set(key + "mean + 1 sd", s.mean_plus_sd);
          summary.set(key + "design value", s.design);
        }
      output::write_atomically(folder + "/suite.csv", [&](std::ostream &f) { f << csv.str(); });
      summary.write(folder + "/suite.json");
      out << "Record suite: " << records.size() << " records; every peak over them in " << folder
          << "/suite.csv and suite.json (doc/user-guide.md, \"Record suites\")" << std::endl;
    }
  } // namespace

  void
  run_record_suite(const std::string              &case_file,
                   const std::vector<std::string> &overrides,
                   const Parameters               &p,
                   const MPI_Comm                  comm,
                   std::ostream                   &out,
                   const SuiteRun                  run,
                   const std::string              &only,
                   const bool                      resume)
  {
    const auto         records = p.suite.parse();
    const bool         talk    = Utilities::MPI::this_mpi_process(comm) == 0;
    const std::string &folder  = p.output.directory;
    if (run == SuiteRun::one_record &&
        std::none_of(records.begin(), records.end(),
                     [&](const analysis::SuiteRecord &r) { return r.name == only; }))
      {
        std::string names;
        for (const auto &r : records)
          names += (names.empty() ? "" : ", ") + r.name;
        throw InputError("--record " + only + ": the suite (Record suite/Records) has no record '" +
                         only + "'; its records: " + names + ".");
      }
    if (resume && run != SuiteRun::one_record)
      throw InputError("--resume continues one run from its checkpoint; a record suite "
                       "(Record suite/Records) runs every record anew. Resume one record's "
                       "run with --record NAME --resume.");
    std::vector<double> factors;
    // --gather holds every record's folder until the statistics are written,
    // so that no record's run replaces its results in between.
    std::vector<std::unique_ptr<output::RunLock>> gathered;
    for (unsigned int k = 0; k < records.size(); ++k)
      {
        const auto &r = records[k];
        if (run == SuiteRun::one_record && r.name != only)
          continue;
        factors.push_back(factor_to_target(case_file, overrides, p, r));
        const Parameters record_parameters =
          read_parameters(case_file, record_overrides(overrides, folder, r, factors.back()));
        const std::string &record_folder = record_parameters.output.directory;
        if (run == SuiteRun::gather)
          {
            on_rank_zero(comm, [&]() {
              if (!std::filesystem::exists(record_folder + "/summary.json"))
                throw InputError("Record suite: --gather found no results of record '" + r.name +
                                 "' (no '" + record_folder + "/summary.json'). Run it first: archdam " +
                                 std::filesystem::path(case_file).filename().string() +
                                 " --record " + r.name + ".");
            });
            try
              {
                gathered.push_back(std::make_unique<output::RunLock>(
                  record_folder, record_parameters.analysis.case_name, comm));
              }
            catch (const InputError &e)
              {
                throw InputError("Record suite: --gather: the run of record '" + r.name +
                                 "' is still under way; gather once it has ended. (" + e.what() +
                                 ")");
              }
            on_rank_zero(comm, [&]() { check_record_run(record_parameters, r.name, case_file); });
            continue;
          }
        // The record's folder is one run's at a time: a record running as a
        // job of its own is neither run again nor gathered before its end.
        const output::RunLock lock(record_folder, record_parameters.analysis.case_name, comm);
        if (talk)
          {
            out << "Record suite: record " << k + 1 << " of " << records.size() << ", " << r.name
                << " (results in " << record_folder << ")" << std::endl;
            if (p.suite.scale_to_target)
              out << "  scaled to the target over " << p.suite.period_min << " to "
                  << p.suite.period_max << " s by " << factors.back() << std::endl;
          }
        analysis::Simulation simulation(record_parameters, comm, out);
        simulation.run(resume);
        if (talk && p.output.report)
          write_report(record_folder, out);
      }
    if (run == SuiteRun::one_record)
      return;
    on_rank_zero(comm, [&]() {
      write_suite_statistics(folder, records, factors, out);
      if (p.output.report)
        write_report(folder, out);
    });
  }
} // namespace archdam::application
