#include <archdam/base/input_error.h>
#include <archdam/parameters/analysis_parameters.h>

#include <deal.II/base/utilities.h>

#include <cmath>
#include <set>
#include <sstream>

namespace archdam::analysis
{
  using namespace dealii;

  void
  AnalysisParameters::add_parameters(ParameterHandler &prm)
  {
    prm.add_parameter("Case name", case_name,
                      "Name of the case in the summary; empty = the parameter "
                      "file's name without extension.",
                      Patterns::Anything());
    prm.add_parameter("Stages", stages,
                      "Stages to run, in this order: static (gravity), modal "
                      "(natural frequencies and mode shapes, see Modal analysis), "
                      "dynamic (ground motion, starting from the static state).",
                      Patterns::MultipleSelection("static|modal|dynamic"));
  }

  bool
  AnalysisParameters::runs(const std::string &stage) const
  {
    for (const auto &s : Utilities::split_string_list(stages, ','))
      if (s == stage)
        return true;
    return false;
  }

  void
  ModalParameters::add_parameters(ParameterHandler &prm)
  {
    prm.add_parameter("Number of modes", n_modes,
                      "How many of the lowest natural modes the modal stage computes.",
                      Patterns::Integer(1, 1000));
    prm.add_parameter("Tolerance", tolerance,
                      "Relative tolerance of the eigensolver on each eigenpair.",
                      Patterns::Double(1e-15, 1e-3));
    prm.add_parameter("Write mode shapes", write_mode_shapes,
                      "Write the mode shapes to modes.vtu (one displacement field per "
                      "mode) in the output directory.",
                      Patterns::Bool());
  }

  void
  RecordSuiteParameters::add_parameters(ParameterHandler &prm)
  {
    prm.add_parameter(
      "Records", records,
      "The same case run under several records, one after another, each into "
      "its own folder Output/Directory/NAME, then the statistics of every peak "
      "over the records in Output/Directory/suite.csv and suite.json "
      "(doc/user-guide.md, \"Record suites\"). 'NAME: x = FILE * SCALE, y = "
      "FILE * SCALE, z = FILE * SCALE; NAME: ...': a name of letters, digits, "
      "'-' and '_', then the record of each direction it shakes (a direction "
      "not named has no motion; '* SCALE' may be left out: 1), found as "
      "Ground motion/Component x/File is; each record replaces the case's "
      "Ground motion components (Source = file, File, Scale factor), their "
      "Format, Units and Processing kept. Empty: no suite, one run.",
      Patterns::Anything());
    prm.add_parameter(
      "Scale to target", scale_to_target,
      "Scale each record of the suite, on top of its own scales, by the one factor that "
      "brings its horizontal 5 % spectrum to the target spectrum of Ground motion/Generated "
      "motion over the period range: the geometric mean over 40 periods spaced evenly in log T "
      "of target / record, the record's horizontal spectrum being the geometric mean of its x "
      "and y components' (the one of them it has); the vertical gets the same factor "
      "(doc/user-guide.md, \"Record suites\").",
      Patterns::Bool());
    prm.add_parameter("Shortest period", period_min,
                      "The period range of Scale to target: its shortest period [s] (practice: "
                      "about 0.2 times the dam's first period).",
                      Patterns::Double(0.));
    prm.add_parameter("Longest period", period_max,
                      "The period range of Scale to target: its longest period [s] (practice: "
                      "about 1.5 times the dam's first period).",
                      Patterns::Double(0.));
  }

  void
  RecordSuiteParameters::check() const
  {
    if (scale_to_target && !(period_min > 0. && period_min < period_max))
      {
        std::ostringstream text;
        text << "Record suite: Scale to target needs 0 < Shortest period < Longest period, got "
             << period_min << " and " << period_max << " s.";
        throw InputError(text.str());
      }
  }

  std::vector<SuiteRecord>
  RecordSuiteParameters::parse() const
  {
    std::vector<SuiteRecord> suite;
    std::set<std::string>    names;
    for (const auto &entry : Utilities::split_string_list(records, ';'))
      {
        const auto colon = entry.find(':');
        const auto refuse = [&](const std::string &what) {
          throw InputError("Record suite/Records: '" + entry + "': " + what +
                           " (expected 'NAME: x = FILE * SCALE, y = FILE * SCALE, z = FILE * "
                           "SCALE', records separated by ';').");
        };
        if (colon == std::string::npos)
          refuse("no ':' after the record's name");
        SuiteRecord r;
        r.name = Utilities::trim(entry.substr(0, colon));
        if (r.name.empty() ||
            r.name.find_first_not_of("abcdefghijklmnopqrstuvwxyzABCDEFGHIJKLMNOPQRSTUVWXYZ"
                                     "0123456789-_") != std::string::npos)
          refuse("the name '" + r.name + "' is not made of letters, digits, '-' and '_'");
        if (!names.insert(r.name).second)
          refuse("the name '" + r.name + "' is given twice");
        std::array<bool, 3> given = {{false, false, false}};
        for (const auto &component : Utilities::split_string_list(entry.substr(colon + 1), ','))
          {
            const auto eq = component.find('=');
            const auto axis = Utilities::trim(component.substr(0, eq));
            if (eq == std::string::npos || axis.size() != 1 ||
                std::string("xyz").find(axis) == std::string::npos)
              refuse("'" + component + "' does not start with 'x =', 'y =' or 'z ='");
            const unsigned int d = std::string("xyz").find(axis);
            if (given[d])
              refuse("direction " + axis + " is given twice");
            given[d]              = true;
            const std::string rhs = component.substr(eq + 1);
            const auto        star = rhs.find('*');
            r.file[d]             = Utilities::trim(rhs.substr(0, star));
            if (r.file[d].empty())
              refuse("direction " + axis + " names no file");
            if (star != std::string::npos)
              {
                const std::string text = Utilities::trim(rhs.substr(star + 1));
                std::size_t       used = 0;
                try
                  {
                    r.scale[d] = std::stod(text, &used);
                  }
                catch (const std::exception &)
                  {
                    used = 0;
                  }
                if (used == 0 || used != text.size() || !std::isfinite(r.scale[d]) ||
                    r.scale[d] == 0. || std::abs(r.scale[d]) > 1e3)
                  refuse("the scale of direction " + axis + ", '" + text +
                         "', is not a number from -1000 to 1000 other than 0");
              }
          }
        if (!given[0] && !given[1] && !given[2])
          refuse("no direction is given a record");
        suite.push_back(r);
      }
    return suite;
  }
} // namespace archdam::analysis
