#include <archdam/application/motion_command.h>
#include <archdam/application/python_script.h>
#include <archdam/base/case_file.h>
#include <archdam/base/data_files.h>
#include <archdam/base/input_error.h>
#include <archdam/base/number_text.h>
#include <archdam/base/version.h>
#include <archdam/loads/artificial_motion.h>
#include <archdam/loads/design_spectrum.h>
#include <archdam/loads/ground_motion.h>
#include <archdam/loads/record_io.h>
#include <archdam/loads/record_processing.h>
#include <archdam/loads/response_spectrum.h>

#include <deal.II/base/exceptions.h>
#include <deal.II/base/mpi.h>
#include <deal.II/base/parameter_handler.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <map>
#include <optional>
#include <set>
#include <sstream>
#include <string>
#include <vector>

namespace archdam
{
  using namespace loads;

  namespace
  {
    const char *usage = R"(archdam-motion: generate, convert, scale and inspect ground motions.

Usage:
  archdam-motion generate [generation] [processing] [output]
  archdam-motion convert INPUT [input] [processing] [target] [output]
  archdam-motion scale INPUT --pga G [input] [output]
  archdam-motion inspect INPUT [input] [processing] [target] [output]
  archdam-motion case CASE.prm [--component x|y|z] [target] [output]
  archdam-motion --help | --version

Every command prints a summary of the motion (PGA, PGV, PGD, end velocity
and displacement, Arias intensity, significant duration, spectral values).
`case` shows a ground-motion component of an analysis case file as the
analysis uses it (read or generated, then processed). Accelerations in g.

Input options (INPUT is a record file; a relative name is looked for in the
working directory, then in the data folder, ARCHDAM_DATA_DIR or the shipped
data/: ground_motions/RSN6_IMPVALL.I_I-ELC180.AT2 is a shipped record):
  --format F          auto | AT2 | two-column | single-column (default auto:
                      AT2 if the name ends in .AT2, else two-column)
  --units U           g | m/s^2 | cm/s^2, for text files (default g)
  --dt S              sample spacing of a single-column file, s
  --scale F           factor applied to the record (default 1)

Generation options (target: NB 35047-2015 design spectrum, or --table):
  --pga G             design peak ground acceleration, g (default 0.1)
  --tg S              characteristic period T_g, s (default 0.4)
  --beta-max B        plateau of the spectrum (default 2.5, arch dams)
  --table "T: b; ..." user spectrum instead, b = S_a / PGA
  --duration S        (default 20)       --dt S        time step (default 0.01)
  --rise S            end of the envelope's rise (default 2)
  --strong-end S      end of its strong part (default 12)
  --decay C           its decay coefficient, 1/s (default 0.3)
  --seed N            random seed (default 1): the same seed, the same motion
  --component C       x | y | z: independent motions; z matches the target
                      times --vertical-factor (default 2/3)
  --damping Z         damping ratio of the matched spectrum (default 0.05)
  --periods A:B       matched period range, s (default 0.04:4)
  --tolerance E       stop when within E everywhere (default 0.05)
  --iterations N      at most N corrections (default 100)
  --no-pga-match      do not bring the peak to the PGA

Processing options (applied in this order):
  --window A:B        keep the part from A s to B s (B = 0: to the end),
                      shifted to start at 0
  --taper S           half-cosine ramps of S s at both ends of the window
  --resample DT       resample to the time step DT (anti-aliased if coarser)
  --highpass HZ       zero-phase Butterworth high-pass corner
  --lowpass HZ        zero-phase Butterworth low-pass corner
  --order N           order of each pass (default 4)
  --baseline          baseline correction: velocity and displacement end at 0
  --baseline-degree N degree of its polynomial (default 6)
  --target-pga G      scale so that the peak acceleration is G

Target options (convert, inspect, case): --pga G with --tg, --beta-max or
  --table draws that target on the plot and reports the match.

Output options:
  --csv FILE          time [s], acceleration [m/s^2] (a two-column input file)
  --at2 FILE          PEER .AT2 file, in g
  --histories FILE    CSV: time, acceleration, velocity, displacement (SI)
  --spectrum FILE     CSV: period, SD, PSV, PSA (and the target's PSA)
  --plot FILE         the plot FILE (PNG: histories, and the spectrum against
                      the target) and its data (FILE's name with
                      .histories.csv and .spectrum.csv), drawn with
                      /usr/bin/python3 and matplotlib (without them, the
                      command that draws it is printed)
  --spectrum-damping Z  damping of the spectrum written and plotted (0.05)
  --title TEXT        title of the plot and of the AT2 header

Errors in the input give one message and exit code 1.
)";

    /// Options that take a value; the others are flags.
    const std::set<std::string> value_options = {
      "--format",   "--units",        "--dt",          "--scale",
      "--pga",      "--tg",           "--beta-max",    "--table",
      "--duration", "--rise",         "--strong-end",  "--decay",
      "--seed",     "--component",    "--damping",     "--periods",
      "--tolerance", "--iterations",  "--vertical-factor",
      "--window",   "--taper",        "--resample",    "--highpass",
      "--lowpass",  "--order",        "--baseline-degree",
      "--target-pga", "--csv",        "--at2",         "--histories",
      "--spectrum", "--plot",         "--spectrum-damping", "--title"};
    const std::set<std::string> flag_options = {"--baseline", "--no-pga-match"};

    const std::set<std::string> input_group = {"--format", "--units", "--dt", "--scale"};
    const std::set<std::string> processing_group = {"--window",  "--taper",
                                                    "--resample", "--highpass",
                                                    "--lowpass", "--order",
                                                    "--baseline", "--baseline-degree",
                                                    "--target-pga"};
    const std::set<std::string> target_group = {"--pga", "--tg", "--beta-max", "--table"};
    const std::set<std::string> generation_group = {
      "--pga",        "--tg",        "--beta-max",  "--table",     "--duration",
      "--dt",         "--rise",      "--strong-end", "--decay",    "--seed",
      "--component",  "--damping",   "--periods",   "--tolerance", "--iterations",
      "--vertical-factor", "--no-pga-match"};
    const std::set<std::string> output_group = {"--csv",      "--at2",
                                                "--histories", "--spectrum",
                                                "--plot",     "--spectrum-damping",
                                                "--title"};

    /// Numbers in this command's reports: 4 significant digits.
    std::string
    str(const double x, const int digits = 4)
    {
      return number_text(x, digits);
    }

    /// The parsed command line.
    struct Options
    {
      std::string                        command;
      std::vector<std::string>           positional;
      std::map<std::string, std::string> values;

      bool
      has(const std::string &name) const
      {
        return values.count(name) > 0;
      }

      std::string
      text(const std::string &name, const std::string &fallback) const
      {
        return has(name) ? values.at(name) : fallback;
      }

      double
      number(const std::string &name, const double fallback) const
      {
        if (!has(name))
          return fallback;
        const std::string &word = values.at(name);
        char              *end  = nullptr;
        const double       x    = std::strtod(word.c_str(), &end);
        if (word.empty() || *end != '\0' || !std::isfinite(x))
          throw InputError(name + ": '" + word + "' is not a number.");
        return x;
      }

      unsigned int
      integer(const std::string &name, const unsigned int fallback) const
      {
        if (!has(name))
          return fallback;
        const std::string &word = values.at(name);
        char              *end  = nullptr;
        const long         n    = std::strtol(word.c_str(), &end, 10);
        if (word.empty() || *end != '\0' || n < 0 || n > 4294967295L)
          throw InputError(name + ": '" + word +
                           "' is not a whole number from 0 to 4294967295.");
        return static_cast<unsigned int>(n);
      }

      /// "A:B" as two numbers.
      std::pair<double, double>
      range(const std::string &name, const std::pair<double, double> &fallback) const
      {
        if (!has(name))
          return fallback;
        const std::string &word  = values.at(name);
        const auto         colon = word.find(':');
        char              *end1 = nullptr, *end2 = nullptr;
        const std::string  a = word.substr(0, colon);
        const std::string  b = colon == std::string::npos ? "" : word.substr(colon + 1);
        const double       x = std::strtod(a.c_str(), &end1);
        const double       y = std::strtod(b.c_str(), &end2);
        if (colon == std::string::npos || a.empty() || b.empty() || *end1 != '\0' ||
            *end2 != '\0' || !std::isfinite(x) || !std::isfinite(y))
          throw InputError(name + ": '" + word + "' is not a range A:B of two numbers.");
        return {x, y};
      }
    };

    Options
    parse(const std::vector<std::string> &args)
    {
      Options o;
      o.command = args.front();
      for (std::size_t i = 1; i < args.size(); ++i)
        {
          std::string name = args[i], value;
          if (name.rfind("--", 0) != 0 || name == "--")
            {
              o.positional.push_back(name);
              continue;
            }
          const auto eq = name.find('=');
          const bool inline_value = eq != std::string::npos;
          if (inline_value)
            {
              value = name.substr(eq + 1);
              name  = name.substr(0, eq);
            }
          if (flag_options.count(name))
            {
              if (inline_value)
                throw InputError(name + " takes no value.");
            }
          else if (value_options.count(name))
            {
              if (!inline_value)
                {
                  if (i + 1 == args.size())
                    throw InputError(name + " needs a value.");
                  value = args[++i];
                }
            }
          else
            throw InputError("Unknown option '" + name +
                             "' (archdam-motion --help lists them).");
          if (o.values.count(name))
            throw InputError(name + " is given twice.");
          o.values[name] = value;
        }
      return o;
    }

    /// Only options of @p groups may appear with this command.
    void
    check_allowed(const Options &o, const std::vector<const std::set<std::string> *> &groups)
    {
      for (const auto &[name, value] : o.values)
        {
          bool allowed = false;
          for (const auto *g : groups)
            allowed = allowed || g->count(name);
          if (!allowed)
            throw InputError("Option " + name + " does not apply to '" + o.command +
                             "' (archdam-motion --help).");
        }
    }

    void
    expect_positional(const Options &o, const std::size_t n, const std::string &what)
    {
      if (o.positional.size() < n)
        throw InputError("'" + o.command + "' needs " + what +
                         " (archdam-motion --help).");
      if (o.positional.size() > n)
        throw InputError("'" + o.command + "': unexpected argument '" +
                         o.positional[n] + "'.");
    }

    unsigned int
    component_index(const Options &o)
    {
      const std::string c = o.text("--component", "x");
      if (c == "x" || c == "y" || c == "z")
        return c[0] - 'x';
      throw InputError("--component: '" + c + "' is not x, y or z.");
    }

    /// The target spectrum of --pga, --tg, --beta-max, --table (if --pga or
    /// @p required).
    std::optional<TargetSpectrum>
    target_from(const Options &o, const bool required)
    {
      if (!required && !o.has("--pga"))
        {
          for (const std::string name : {"--tg", "--beta-max", "--table"})
            if (o.has(name))
              throw InputError(name + " describes a target spectrum, which "
                               "also needs its --pga.");
          return std::nullopt;
        }
      const double pga = o.number("--pga", 0.1) * standard_gravity;
      if (o.has("--table"))
        {
          if (o.has("--tg") || o.has("--beta-max"))
            throw InputError("--table replaces the NB 35047 spectrum: --tg and "
                             "--beta-max do not apply.");
          return TargetSpectrum::table(pga, parse_spectrum_table(o.text("--table", ""), "--table: "));
        }
      return TargetSpectrum::nb35047(pga, o.number("--tg", 0.4), o.number("--beta-max", 2.5));
    }

    ProcessingParameters
    processing_from(const Options &o)
    {
      ProcessingParameters p;
      const auto window = o.range("--window", {0., 0.});
      p.start_time      = window.first;
      p.end_time        = window.second;
      p.taper           = o.number("--taper", 0.);
      p.time_step       = o.number("--resample", 0.);
      p.high_pass       = o.number("--highpass", 0.);
      p.low_pass        = o.number("--lowpass", 0.);
      p.filter_order    = o.integer("--order", 4);
      p.baseline        = o.has("--baseline");
      p.baseline_degree = o.integer("--baseline-degree", 6);
      p.target_pga      = o.number("--target-pga", 0.);
      if (o.has("--baseline-degree") && !p.baseline)
        throw InputError("--baseline-degree needs --baseline.");
      if (o.has("--target-pga") && !(p.target_pga > 0))
        throw InputError("--target-pga must be positive.");
      for (const std::string name : {"--taper", "--resample", "--highpass", "--lowpass"})
        if (o.has(name) && !(o.number(name, 0.) > 0))
          throw InputError(name + " must be positive.");
      return p;
    }

    AccelerationRecord
    read_input(const Options &o, const std::string &path)
    {
      GroundMotionParameters::Component c;
      // A relative INPUT is looked for in the working directory, then in the
      // data folder, as a case file's records are (base/data_files.h).
      c.file = find_input_file(path, "", "INPUT", "the working directory");
      // No parameter pattern checks the names given to --format and --units:
      // record_format() and record_units() refuse any other, naming the file.
      const std::string context = record_file_context(0, c.file);
      c.format    = record_format(o.text("--format", "auto"), context);
      c.units     = record_units(o.text("--units", "g"), context);
      c.time_step = o.number("--dt", 0.);
      c.scale     = o.number("--scale", 1.);
      if (o.has("--dt") && c.format != RecordFormat::single_column)
        throw InputError("--dt gives the spacing of a single-column file; use "
                         "it with --format single-column.");
      GroundMotionParameters p;
      p.components[0] = c;
      // GroundMotion reads, checks and reports exactly as the analysis does.
      return GroundMotion(p, "").record(0);
    }

    /// Arias intensity pi/(2g) int a^2 dt (exact for piecewise-linear a) and
    /// the times at which its running value reaches 5 % and 95 %.
    void
    arias(const AccelerationRecord &r, double &intensity, double &t5, double &t95)
    {
      std::vector<double> cumulative(r.times.size(), 0.);
      for (std::size_t k = 0; k + 1 < r.times.size(); ++k)
        {
          const double a0 = r.values[k], a1 = r.values[k + 1];
          cumulative[k + 1] = cumulative[k] + (r.times[k + 1] - r.times[k]) *
                                                (a0 * a0 + a0 * a1 + a1 * a1) / 3.;
        }
      intensity        = M_PI / (2. * standard_gravity) * cumulative.back();
      const auto cross = [&](const double fraction) {
        const double level = fraction * cumulative.back();
        for (std::size_t k = 0; k + 1 < cumulative.size(); ++k)
          if (cumulative[k + 1] >= level)
            {
              const double w = (cumulative[k + 1] > cumulative[k]) ?
                                 (level - cumulative[k]) / (cumulative[k + 1] - cumulative[k]) :
                                 0.;
              return r.times[k] + w * (r.times[k + 1] - r.times[k]);
            }
        return r.times.back();
      };
      t5  = cross(0.05);
      t95 = cross(0.95);
    }

    /// Periods of the written and plotted spectra.
    std::vector<double>
    output_periods()
    {
      return log_spaced_periods(0.02, 10., 121);
    }

    void
    summarize(std::ostream                        &out,
              const AccelerationRecord            &r,
              const std::optional<TargetSpectrum> &target,
              const double                         damping,
              const std::pair<double, double>     &match_range)
    {
      const MotionHistories h  = integrate(r);
      double                dt = 0.;
      const bool            uniform = r.is_uniform(&dt);
      double pgv = 0., pgd = 0.;
      for (std::size_t k = 0; k < h.times.size(); ++k)
        {
          pgv = std::max(pgv, std::abs(h.velocity[k]));
          pgd = std::max(pgd, std::abs(h.displacement[k]));
        }
      double ia = 0., t5 = 0., t95 = 0.;
      arias(r, ia, t5, t95);

      out << r.source << "\n  " << r.times.size() << " samples, "
          << (uniform ? "time step " + str(dt) + " s" : std::string("irregular times"))
          << ", from " << str(r.times.front()) << " s to " << str(r.times.back()) << " s\n"
          << "  PGA " << str(r.peak() / standard_gravity) << " g at " << str(r.time_of_peak())
          << " s, PGV " << str(100. * pgv) << " cm/s, PGD " << str(100. * pgd) << " cm\n"
          << "  at the end: velocity " << str(100. * h.velocity.back(), 3) << " cm/s, displacement "
          << str(100. * h.displacement.back(), 3) << " cm\n"
          << "  Arias intensity " << str(ia) << " m/s, significant duration (5-95 %) "
          << str(t95 - t5) << " s (" << str(t5) << " s to " << str(t95) << " s)\n";
      const std::vector<double> T = {0.1, 0.2, 0.5, 1., 2.};
      const ResponseSpectrum    s = response_spectrum(r, T, damping);
      out << "  PSA at " << str(100. * damping) << " % damping:";
      for (std::size_t i = 0; i < T.size(); ++i)
        out << (i ? "," : "") << " " << str(T[i]) << " s " << str(s.pseudo_acceleration[i] / standard_gravity, 3)
            << " g";
      out << "\n";
      if (target)
        {
          const std::vector<double> P =
            log_spaced_periods(match_range.first, match_range.second, 100);
          const ResponseSpectrum m = response_spectrum(r, P, damping);
          unsigned int           within = 0;
          double                 worst  = 0.;
          for (std::size_t i = 0; i < P.size(); ++i)
            {
              const double e = m.pseudo_acceleration[i] / target->acceleration(P[i]) - 1.;
              within += std::abs(e) <= 0.1;
              worst = std::max(worst, std::abs(e));
            }
          out << "  target " << target->description() << ": within +-10 % at "
              << within << " of " << P.size() << " periods from " << str(P.front()) << " s to "
              << str(P.back()) << " s, largest deviation " << str(100. * worst, 3) << " %\n";
        }
    }

    void
    write_histories(const std::string &path, const AccelerationRecord &r)
    {
      const MotionHistories h = integrate(r);
      std::ofstream         f = open_for_writing(path);
      f << "time [s],acceleration [m/s^2],velocity [m/s],displacement [m]\n";
      char line[128];
      for (std::size_t k = 0; k < h.times.size(); ++k)
        {
          std::snprintf(line, sizeof(line), "%.10g,%.10g,%.10g,%.10g\n", h.times[k],
                        h.acceleration[k], h.velocity[k], h.displacement[k]);
          f << line;
        }
    }

    void
    write_spectrum(const std::string                   &path,
                   const AccelerationRecord            &r,
                   const std::optional<TargetSpectrum> &target,
                   const double                         damping)
    {
      const ResponseSpectrum s = response_spectrum(r, output_periods(), damping);
      std::ofstream          f = open_for_writing(path);
      f << "period [s],SD [m],PSV [m/s],PSA [m/s^2]" << (target ? ",target PSA [m/s^2]" : "")
        << "\n";
      char line[160];
      for (std::size_t i = 0; i < s.periods.size(); ++i)
        {
          std::snprintf(line, sizeof(line), "%.6g,%.8g,%.8g,%.8g", s.periods[i],
                        s.displacement[i], s.pseudo_velocity[i], s.pseudo_acceleration[i]);
          f << line;
          if (target)
            {
              std::snprintf(line, sizeof(line), ",%.8g", target->acceleration(s.periods[i]));
              f << line;
            }
          f << "\n";
        }
    }

    /// The plot @p path (a PNG: the histories, and the spectrum against the
    /// target): its data next to it (the name with .histories.csv and
    /// .spectrum.csv), drawn from them by scripts/plot_motion.py with
    /// /usr/bin/python3 and matplotlib; where these are missing, or drawing
    /// fails, the command that draws it is printed instead.
    void
    write_plot_data(std::ostream                        &out,
                    const std::string                   &path,
                    const AccelerationRecord            &r,
                    const std::optional<TargetSpectrum> &target,
                    const double                         damping,
                    const std::string                   &title,
                    const std::string                   &match_range)
    {
      const std::string histories =
        std::filesystem::path(path).replace_extension(".histories.csv").string();
      const std::string spectrum =
        std::filesystem::path(path).replace_extension(".spectrum.csv").string();
      write_histories(histories, r);
      write_spectrum(spectrum, r, target, damping);
      std::vector<std::string> arguments = {"--histories", histories, "--spectrum", spectrum,
                                            "--output",    path,      "--title",    title,
                                            "--damping",   str(damping)};
      if (!match_range.empty())
        arguments.insert(arguments.end(), {"--match-range", match_range});
      out << "wrote " << histories << " and " << spectrum << "\n";
      if (application::run_python_script("plot_motion.py", arguments))
        out << "wrote " << path << "\n";
      else
        out << "the plot " << path << " needs /usr/bin/python3 with matplotlib; draw it with\n  "
            << application::python_command("plot_motion.py", arguments) << "\n";
    }

    /// --spectrum-damping, checked before anything is computed or printed.
    double
    spectrum_damping(const Options &o)
    {
      const double damping = o.number("--spectrum-damping", 0.05);
      if (!(damping >= 0 && damping < 1))
        throw InputError("--spectrum-damping must be at least 0 and below 1.");
      return damping;
    }

    void
    write_outputs(std::ostream                        &out,
                  const Options                       &o,
                  const AccelerationRecord            &r,
                  const std::optional<TargetSpectrum> &target,
                  const std::string                   &match_range)
    {
      const double      damping = spectrum_damping(o);
      // the record's file name, not its whole path
      const std::string title =
        o.text("--title", std::filesystem::path(r.source).filename().string());
      if (o.has("--csv"))
        {
          write_two_column(o.text("--csv", ""), r, title);
          out << "wrote " << o.text("--csv", "") << "\n";
        }
      if (o.has("--at2"))
        {
          write_at2(o.text("--at2", ""), r, "ArchDam archdam-motion", title);
          out << "wrote " << o.text("--at2", "") << "\n";
        }
      if (o.has("--histories"))
        {
          write_histories(o.text("--histories", ""), r);
          out << "wrote " << o.text("--histories", "") << "\n";
        }
      if (o.has("--spectrum"))
        {
          write_spectrum(o.text("--spectrum", ""), r, target, damping);
          out << "wrote " << o.text("--spectrum", "") << "\n";
        }
      if (o.has("--plot"))
        write_plot_data(out, o.text("--plot", ""), r, target, damping, title, match_range);
    }

    bool
    any_output(const Options &o)
    {
      for (const std::string name : {"--csv", "--at2", "--histories", "--spectrum", "--plot"})
        if (o.has(name))
          return true;
      return false;
    }

    int
    generate(const Options &o, std::ostream &out)
    {
      check_allowed(o, {&generation_group, &processing_group, &output_group});
      expect_positional(o, 0, "no file argument");
      const unsigned int d = component_index(o);

      ArtificialMotionParameters p;
      p.pga               = o.number("--pga", 0.1);
      p.characteristic_period = o.number("--tg", 0.4);
      p.beta_max          = o.number("--beta-max", 2.5);
      if (o.has("--table"))
        {
          if (o.has("--tg") || o.has("--beta-max"))
            throw InputError("--table replaces the NB 35047 spectrum: --tg and "
                             "--beta-max do not apply.");
          p.spectrum = TargetSpectrumKind::table;
          p.table    = o.text("--table", "");
        }
      p.duration            = o.number("--duration", 20.);
      p.time_step           = o.number("--dt", 0.01);
      p.envelope.rise_end   = o.number("--rise", 2.);
      p.envelope.strong_end = o.number("--strong-end", 12.);
      p.envelope.decay      = o.number("--decay", 0.3);
      p.seed                = o.integer("--seed", 1);
      p.damping             = o.number("--damping", 0.05);
      p.vertical_factor     = o.text("--vertical-factor", "2/3");
      const auto periods    = o.range("--periods", {0.04, 4.});
      p.period_min          = periods.first;
      p.period_max          = periods.second;
      p.tolerance           = o.number("--tolerance", 0.05);
      p.max_iterations      = o.integer("--iterations", 100);
      p.match_pga           = !o.has("--no-pga-match");
      if (o.has("--vertical-factor") && d != 2)
        throw InputError("--vertical-factor applies to --component z only.");
      spectrum_damping(o);
      // Earthquake motions last seconds to minutes; beyond these the
      // generation would only run out of memory or time.
      if (!(p.duration > 0 && p.duration <= 1000) ||
          !(p.time_step > 0 && p.duration / p.time_step <= 1e6))
        throw InputError("--duration " + str(p.duration) + " s at --dt " + str(p.time_step) +
                         " s: a generated motion lasts at most 1000 s and has at most 1e6 "
                         "samples (an earthquake's strong motion lasts seconds to a minute).");

      const GenerationSettings settings = p.settings(d, "");
      GenerationReport         report;
      AccelerationRecord       r = generate_artificial_motion(settings, &report);
      const ProcessingParameters processing = processing_from(o);
      if (processing.any())
        r = process(r, processing, "");

      out << "Generated in " << report.iterations << " iteration(s): 5 %-damped spectrum within "
          << "+-10 % of the target at " << str(100. * report.fraction_within_10_percent, 3)
          << " % of the " << report.periods.size() << " matched periods, largest deviation "
          << str(100. * report.max_error, 3) << " %\n";
      summarize(out, r, settings.target, settings.damping, periods);
      write_outputs(out, o, r, settings.target,
                    str(periods.first) + ":" + str(periods.second));
      return 0;
    }

    int
    convert_or_inspect(const Options &o, std::ostream &out)
    {
      check_allowed(o, {&input_group, &processing_group, &target_group, &output_group});
      expect_positional(o, 1, "the record file INPUT");
      const std::optional<TargetSpectrum> target = target_from(o, false);
      const ProcessingParameters          processing = processing_from(o);
      if (o.command == "convert" && !any_output(o))
        throw InputError("'convert' writes nothing without an output option "
                         "(--csv, --at2, --histories, --spectrum, --plot).");
      AccelerationRecord r = read_input(o, o.positional[0]);
      if (processing.any())
        r = process(r, processing, "");
      summarize(out, r, target, spectrum_damping(o), {0.04, 4.});
      write_outputs(out, o, r, target, "");
      return 0;
    }

    int
    scale(const Options &o, std::ostream &out)
    {
      const std::set<std::string> pga_option = {"--pga"};
      check_allowed(o, {&input_group, &pga_option, &output_group});
      if (!o.has("--pga"))
        throw InputError("'scale' needs the target peak acceleration: --pga G.");
      expect_positional(o, 1, "the record file INPUT");
      if (!any_output(o))
        throw InputError("'scale' writes nothing without an output option "
                         "(--csv, --at2, --histories, --spectrum, --plot).");
      const double pga = o.number("--pga", 0.);
      AccelerationRecord r = read_input(o, o.positional[0]);
      const double factor = pga * standard_gravity / r.peak();
      r                   = scale_to_pga(r, pga * standard_gravity);
      out << "Scaled by " << str(factor, 6) << "\n";
      summarize(out, r, std::nullopt, spectrum_damping(o), {0.04, 4.});
      write_outputs(out, o, r, std::nullopt, "");
      return 0;
    }

    int
    case_file(const Options &o, std::ostream &out)
    {
      std::set<std::string> component = {"--component"};
      check_allowed(o, {&component, &target_group, &output_group});
      expect_positional(o, 1, "the case file CASE.prm");
      const std::string path = o.positional[0];
      const CaseText    text = read_case_text(path);

      // Only the Ground motion section, the rest of the case is skipped.
      GroundMotionParameters   parameters;
      dealii::ParameterHandler prm;
      prm.enter_subsection("Ground motion");
      parameters.add_parameters(prm);
      prm.leave_subsection();
      try
        {
          std::istringstream in(text.text);
          prm.parse_input(in, path, "", true);
        }
      catch (const dealii::ExceptionBase &e)
        {
          std::ostringstream info;
          e.print_info(info);
          throw InputError(text.relocate(info.str()));
        }
      const GroundMotion motion(parameters,
                                std::filesystem::path(path).parent_path().string());

      std::vector<unsigned int> shown;
      if (o.has("--component"))
        {
          const unsigned int d = component_index(o);
          if (!motion.has_component(d))
            throw InputError("Case file '" + path + "' has no ground motion in " +
                             std::string(1, "xyz"[d]) + ".");
          shown.push_back(d);
        }
      else
        for (unsigned int d = 0; d < 3; ++d)
          if (motion.has_component(d))
            shown.push_back(d);
      if (shown.empty())
        throw InputError("Case file '" + path + "' has no ground motion.");
      if (shown.size() > 1 && any_output(o))
        throw InputError("Case file '" + path + "' has " + std::to_string(shown.size()) +
                         " ground-motion components; choose the one to write "
                         "with --component.");

      std::optional<TargetSpectrum> target = target_from(o, false);
      for (const unsigned int d : shown)
        {
          std::optional<TargetSpectrum> t = target;
          std::pair<double, double>     range{0.04, 4.};
          out << "Component " << "xyz"[d] << ": ";
          if (const GenerationReport *report = motion.generation_report(d))
            {
              // A generated component is shown against its own target.
              const GenerationSettings settings =
                parameters.generated.settings(d, "");
              if (!t)
                t = settings.target;
              range = {settings.period_min, settings.period_max};
              out << "generated in " << report->iterations << " iteration(s), ";
            }
          summarize(out, motion.record(d), t, spectrum_damping(o), range);
          write_outputs(out, o, motion.record(d), t,
                        str(range.first) + ":" + str(range.second));
        }
      return 0;
    }

    int
    run(const std::vector<std::string> &args, std::ostream &out)
    {
      if (args.empty())
        throw InputError("No command given: use generate, convert, scale, "
                         "inspect or case (archdam-motion --help).");
      if (args[0] == "--help" || args[0] == "-h" || args[0] == "help")
        {
          out << usage;
          return 0;
        }
      if (args[0] == "--version")
        {
          out << "archdam-motion " << version() << "\n";
          return 0;
        }
      const Options o = parse(args);
      if (o.command == "generate")
        return generate(o, out);
      if (o.command == "convert" || o.command == "inspect")
        return convert_or_inspect(o, out);
      if (o.command == "scale")
        return scale(o, out);
      if (o.command == "case")
        return case_file(o, out);
      throw InputError("Unknown command '" + o.command +
                       "': use generate, convert, scale, inspect or case "
                       "(archdam-motion --help).");
    }
  } // namespace



  int
  run_motion_command(const int          argc,
                     const char *const *argv,
                     std::ostream      &out,
                     std::ostream      &err)
  {
    // One process does the work; the others (under mpirun) wait for nothing.
    if (dealii::Utilities::MPI::this_mpi_process(MPI_COMM_WORLD) != 0)
      return 0;
    try
      {
        return run(std::vector<std::string>(argv + 1, argv + argc), out);
      }
    catch (const InputError &e)
      {
        err << "archdam-motion: error: " << e.what() << std::endl;
        return 1;
      }
    catch (const dealii::ExceptionBase &e)
      {
        std::ostringstream info;
        e.print_info(info);
        std::string message = info.str();
        for (char &c : message)
          if (c == '\n')
            c = ' ';
        err << "archdam-motion: error: " << message << std::endl;
        return 1;
      }
    catch (const std::exception &e)
      {
        err << "archdam-motion: internal error: " << e.what() << std::endl;
        return 2;
      }
  }
} // namespace archdam
