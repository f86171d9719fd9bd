// The ground-motion readers and GroundMotion, checked against references that
// do not come from the code under test:
//  1. every PEER .AT2 record in data/ground_motions: NPTS and DT against
//     a regular expression on the 4th header line, every sample and the PGA
//     against a plain scan of all numbers after the header;
//  2. a record with the older "n dt NPTS, DT" header and Windows line ends;
//  3. a two-column file written here from a known formula: samples,
//     interpolation, zero outside the record, units and scale factors;
//  4. GroundMotion from a prm string, with relative and absolute file names;
//  5. a single-column file with a given time step, typed values;
//  6. processing from the prm entries (Processing subsection): target PGA,
//     resampling and baseline correction, against their definitions;
//  7. a generated component (Source = generated): the same record as the
//     generator called directly with the same settings, the scale factor
//     applied, the vertical target scaled by 2/3 (the generator itself is
//     verified in motion_generation).

#include <archdam/loads/artificial_motion.h>
#include <archdam/loads/ground_motion.h>

#include <deal.II/base/mpi.h>
#include <deal.II/base/numbers.h>
#include <deal.II/base/parameter_handler.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <iomanip>
#include <iostream>
#include <regex>
#include <string>
#include <vector>

using namespace archdam::loads;

namespace
{
  /// Standard gravity, the unit of .AT2 files.
  constexpr double g = 9.80665;

  const std::string data_directory = SOURCE_DIR "/../data";

  void
  report(const std::string &what, const bool ok)
  {
    std::cout << what << ": " << (ok ? "OK" : "MISMATCH") << std::endl;
  }

  /// |a - b| <= tolerance.
  bool
  close(const double a, const double b, const double tolerance)
  {
    return std::abs(a - b) <= tolerance;
  }

  /// What an .AT2 file says, read without the code under test.
  struct At2Reference
  {
    std::size_t         npts = 0;
    double              dt   = 0.;
    std::vector<double> samples_in_g;
    double              pga_in_g = 0.;
  };

  /// NPTS and DT by a regular expression on line 4 (either PEER form), the
  /// samples by streaming every number that follows the header.
  At2Reference
  read_reference(const std::string &path)
  {
    std::ifstream in(path);
    std::string   line;
    for (unsigned int i = 0; i < 4; ++i)
      std::getline(in, line);
    const std::regex keyword_value(
      R"(NPTS\s*=\s*(\d+)\s*,\s*DT\s*=\s*([0-9.Ee+-]+))");
    const std::regex value_keyword(
      R"(^\s*(\d+)\s+([0-9.Ee+-]+)\s+NPTS\s*,\s*DT)");
    std::smatch  match;
    At2Reference reference;
    if (std::regex_search(line, match, keyword_value) ||
        std::regex_search(line, match, value_keyword))
      {
        reference.npts = std::stoul(match[1]);
        reference.dt   = std::stod(match[2]);
      }
    for (double x; in >> x;)
      {
        reference.samples_in_g.push_back(x);
        reference.pga_in_g = std::max(reference.pga_in_g, std::abs(x));
      }
    return reference;
  }

  /// read_at2() against read_reference(); prints one line.
  void
  check_at2(const std::string &path, const std::string &name)
  {
    const AccelerationRecord record    = read_at2(path);
    const At2Reference       reference = read_reference(path);
    const std::size_t        n         = record.times.size();

    bool ok = reference.npts > 1 && n == reference.npts &&
              record.values.size() == n && reference.samples_in_g.size() == n;
    // Samples k*DT, k = 0 ... NPTS-1; values in m/s^2. The tolerances are
    // round-off: k*DT and x*g are formed in other orders than here.
    const double pga = reference.pga_in_g * g;
    for (std::size_t k = 0; ok && k < n; ++k)
      ok =
        close(record.times[k], k * reference.dt, 1e-12 * n * reference.dt) &&
        close(record.values[k], reference.samples_in_g[k] * g, 1e-12 * pga) &&
        close(record.value(k * reference.dt),
              reference.samples_in_g[k] * g,
              1e-12 * pga);
    ok = ok && close(record.peak(), pga, 1e-12 * pga) &&
         close(record.duration(), (n - 1) * reference.dt, 1e-12) &&
         record.source == path;

    std::cout << std::left << std::setw(28) << name
              << " NPTS = " << std::setw(5) << n << " DT = " << std::setw(6)
              << std::setprecision(4)
              << (n > 1 ? record.times[1] - record.times[0] : 0.)
              << " PGA = " << std::showpoint << std::setw(6)
              << record.peak() / g << std::noshowpoint << " g  "
              << (ok ? "OK" : "MISMATCH") << std::endl;
  }

  void
  check_peer_records()
  {
    std::cout << "PEER records in data/ground_motions" << std::endl;
    std::vector<std::string> names;
    for (const auto &entry : std::filesystem::directory_iterator(
           data_directory + "/ground_motions"))
      if (entry.path().extension() == ".AT2")
        names.push_back(entry.path().filename().string());
    std::sort(names.begin(), names.end());
    for (const std::string &name : names)
      check_at2(data_directory + "/ground_motions/" + name, name);
    report("at least 10 records found", names.size() >= 10);
  }

  /// The earlier PEER header form, written with Windows line ends.
  void
  check_older_peer_header()
  {
    std::cout << "\nOlder PEER header form, CRLF line ends" << std::endl;
    std::ofstream("gm_older_peer.AT2")
      << "PACIFIC ENGINEERING AND ANALYSIS STRONG-MOTION DATA\r\n"
      << " IMPERIAL VALLEY 10/15/79 2319, EL CENTRO ARRAY 6, 230\r\n"
      << " ACCELERATION TIME HISTORY IN UNITS OF G\r\n"
      << "    7 0.00500 NPTS, DT\r\n"
      << " .10000E-01 -.20000E-01  .30000E-01 -.40000E-01\r\n"
      << " .50000E-01 -.60000E-01  .70000E-01\r\n";
    check_at2("gm_older_peer.AT2", "gm_older_peer.AT2");
  }

  /// 150 cm/s^2 at 1.5 Hz: the signal written to the two-column file.
  double
  sine_in_cm(const double t)
  {
    return 150. * std::sin(2. * dealii::numbers::PI * 1.5 * t);
  }

  /// Irregular sample times from t0 = 0.3 s (steps 0.05 +- 0.02 s).
  std::vector<double>
  sine_times()
  {
    std::vector<double> times;
    for (unsigned int i = 0; i <= 40; ++i)
      times.push_back(0.3 + 0.05 * i + 0.01 * std::sin(3. * i));
    return times;
  }

  /// The two-column file: comments, blank lines and all three separators.
  void
  write_sine_file(const std::string &name)
  {
    const std::vector<double> times = sine_times();
    std::ofstream             out(name);
    out << std::setprecision(17) << "# time (s), acceleration (cm/s^2)\n\n";
    for (unsigned int i = 0; i < times.size(); ++i)
      {
        const char *separator[] = {", ", "\t", "   "};
        out << (i % 3 == 2 ? "  " : "") << times[i] << separator[i % 3]
            << sine_in_cm(times[i]) << '\n';
        if (i == 20)
          out << "  # half way\n\n";
      }
  }

  void
  check_two_column()
  {
    std::cout << "\nTwo-column file, 150 cm/s^2 sine at irregular times"
              << std::endl;
    write_sine_file("gm_sine.txt");
    const std::vector<double> t = sine_times();
    const std::size_t         n = t.size();

    // Read in cm/s^2 (0.01 m/s^2) with scale factor 2: the samples are
    // 3 m/s^2 * sin(...). Tolerances of 1e-12 * 3 m/s^2 cover round-off only.
    const AccelerationRecord record = read_two_column("gm_sine.txt", 0.01, 2.);
    std::vector<double>      a(n);
    double                   peak = 0.;
    for (std::size_t k = 0; k < n; ++k)
      {
        a[k] = 0.02 * sine_in_cm(t[k]);
        peak = std::max(peak, std::abs(a[k]));
      }
    const double tolerance = 1e-12 * 3.;

    bool samples = record.times.size() == n && record.values.size() == n;
    for (std::size_t k = 0; samples && k < n; ++k)
      // 17 significant digits read back to the same double exactly.
      samples =
        record.times[k] == t[k] && close(record.values[k], a[k], tolerance);
    report("41 samples, times as written, values 0.02 * (cm/s^2 column)",
           samples);
    if (!samples)
      return;

    // The data are piecewise linear between samples, and linear interpolation
    // reproduces a linear function exactly: at midpoints and quarter points
    // the value is the same mean of the neighbouring samples, up to round-off
    // in the interval weights (~1e-16 relative), far below 1e-12.
    bool interpolation = true;
    for (std::size_t k = 0; k + 1 < n; ++k)
      {
        const double h = t[k + 1] - t[k];
        interpolation  = interpolation &&
                        close(record.value(t[k] + 0.5 * h),
                              0.5 * (a[k] + a[k + 1]),
                              tolerance) &&
                        close(record.value(t[k] + 0.25 * h),
                              0.75 * a[k] + 0.25 * a[k + 1],
                              tolerance);
      }
    report("interpolation exact at midpoints and quarter points",
           interpolation);
    report("samples returned at both ends",
           record.value(t[0]) == record.values[0] &&
             record.value(t[n - 1]) == record.values[n - 1]);
    report("zero before the first and after the last sample",
           record.value(0.) == 0. && record.value(t[0] - 1e-9) == 0. &&
             record.value(t[n - 1] + 1e-9) == 0. && record.value(100.) == 0.);
    report("duration = last time", record.duration() == t[n - 1]);
    report("peak = max |sample|", close(record.peak(), peak, tolerance));

    // Unit factors and scale factors multiply the file's column.
    const AccelerationRecord as_si = read_two_column("gm_sine.txt", 1.);
    const AccelerationRecord in_g_flipped =
      read_two_column("gm_sine.txt", g, -0.5);
    bool factors = true;
    for (std::size_t k = 0; k < n; ++k)
      factors = factors &&
                close(as_si.values[k], sine_in_cm(t[k]), 1e-12 * 150.) &&
                close(in_g_flipped.values[k],
                      -0.5 * g * sine_in_cm(t[k]),
                      1e-12 * 150. * g);
    report("unit factor 1 and g, scale factor -0.5", factors);
  }

  void
  check_ground_motion()
  {
    std::cout << "\nGroundMotion from parameters" << std::endl;
    const At2Reference rinaldi =
      read_reference(data_directory + "/ground_motions/Rinaldi228.AT2");
    const std::vector<double> t_sine = sine_times();
    const std::string         sine_path =
      std::filesystem::absolute("gm_sine.txt").string();

    GroundMotionParameters   parameters;
    dealii::ParameterHandler prm;
    prm.enter_subsection("Ground motion");
    parameters.add_parameters(prm);
    prm.leave_subsection();
    prm.parse_input_from_string("subsection Ground motion\n"
                                "  subsection Component x\n"
                                "    set File = ground_motions/Rinaldi228.AT2\n"
                                "    set Scale factor = 0.5\n"
                                "  end\n"
                                "  subsection Component z\n"
                                "    set File   = " +
                                sine_path +
                                "\n"
                                "    set Units  = cm/s^2\n"
                                "    set Scale factor = -1\n"
                                "  end\n"
                                "end\n");
    const auto &[x, y, z] = parameters.components;
    report("parsed x: File, Format auto, Units g, Scale factor 0.5",
           x.file == "ground_motions/Rinaldi228.AT2" &&
             x.format == RecordFormat::automatic && x.units == RecordUnits::g &&
             x.scale == 0.5);
    report("parsed y: no file", y.file.empty() && y.scale == 1.);
    report("parsed z: absolute File, Units cm/s^2, Scale factor -1",
           z.file == sine_path && z.units == RecordUnits::cm_per_s2 && z.scale == -1.);

    // x is relative: it must be found under base_directory.
    const GroundMotion motion(parameters, data_directory);
    report("components x and z, not y",
           motion.has_component(0) && !motion.has_component(1) &&
             motion.has_component(2) && !motion.empty());
    report("duration = (NPTS - 1) DT of the longer record",
           close(motion.duration(), (rinaldi.npts - 1) * rinaldi.dt, 1e-12));

    // x: 0.5 g times the record; z: -0.01 m/s^2 times the cm/s^2 column.
    const double pga       = 0.5 * g * rinaldi.pga_in_g;
    const double t_sample  = 123 * rinaldi.dt;
    const double t_between = 500.5 * rinaldi.dt;
    const auto   a_sample  = motion.acceleration(t_sample);
    const auto   a_between = motion.acceleration(t_between);
    const auto   a_sine    = motion.acceleration(t_sine[7]);
    report("x at a sample: 0.5 g * record",
           close(a_sample[0],
                 0.5 * g * rinaldi.samples_in_g[123],
                 1e-12 * pga));
    report("x between samples: mean of the two",
           close(a_between[0],
                 0.25 * g *
                   (rinaldi.samples_in_g[500] + rinaldi.samples_in_g[501]),
                 1e-12 * pga));
    report("y is zero", a_sample[1] == 0. && a_between[1] == 0.);
    report("z: -0.01 * cm/s^2 column inside its record, zero after it",
           close(a_sine[2], -0.01 * sine_in_cm(t_sine[7]), 1e-12 * 1.5) &&
             a_between[2] == 0.);
    report("record(0) is the resolved file",
           motion.record(0).source ==
             data_directory + "/ground_motions/Rinaldi228.AT2");

    // A relative name with base_directory "" is taken from the working
    // directory; .txt means two-column in Format auto. Units m/s^2 and g.
    GroundMotionParameters here;
    here.components[1].file  = "gm_sine.txt";
    here.components[1].units = RecordUnits::m_per_s2;
    here.components[2].file  = "gm_sine.txt";
    here.components[2].scale = 2.;
    // the column (up to 150) read as g and doubled is near 300 g: refused with the
    // default Largest plausible PGA (5 g) as a units error, read without it
    bool refused = false;
    try
      {
        const GroundMotion limited(here, "");
      }
    catch (const archdam::InputError &e)
      {
        refused = std::string(e.what()).find(" g, above Ground motion/Largest plausible PGA = 5 g") !=
                  std::string::npos;
      }
    report("a component of about 300 g refused with the default Largest plausible PGA (5 g)",
           refused);
    here.largest_pga = 0.;
    const GroundMotion from_cwd(here, "");
    const auto         a_here = from_cwd.acceleration(t_sine[3]);
    report("relative name with base_directory \"\": working directory",
           from_cwd.has_component(1) && from_cwd.has_component(2) &&
             from_cwd.record(1).source == "gm_sine.txt");
    report("Units m/s^2: 1 * column; Units g, Scale factor 2: 2 g * column",
           close(a_here[1], sine_in_cm(t_sine[3]), 1e-12 * 150.) &&
             close(a_here[2], 2. * g * sine_in_cm(t_sine[3]), 1e-12 * 3000.));

    const GroundMotion none(GroundMotionParameters(), "");
    report("no files: empty, duration 0, zero acceleration",
           none.empty() && none.duration() == 0. &&
             none.acceleration(1.).norm() == 0.);
  }

  /// GroundMotionParameters parsed from @p text (the "Ground motion" section).
  GroundMotionParameters
  parse(const std::string &text)
  {
    GroundMotionParameters   parameters;
    dealii::ParameterHandler prm;
    prm.enter_subsection("Ground motion");
    parameters.add_parameters(prm);
    prm.leave_subsection();
    prm.parse_input_from_string(text);
    return parameters;
  }

  void
  check_single_column()
  {
    std::cout << "\nSingle-column file, time step 0.025 s, cm/s^2" << std::endl;
    std::ofstream("gm_single.txt") << "# acceleration in cm/s^2\n12.5\n-3\n\n  40 \n0\n";
    const AccelerationRecord r = read_single_column("gm_single.txt", 0.025, 0.01, 2.);
    const std::vector<double> expected = {0.25, -0.06, 0.8, 0.};
    bool ok = r.values.size() == 4 && r.source == "gm_single.txt";
    for (std::size_t k = 0; ok && k < 4; ++k)
      ok = close(r.values[k], expected[k], 1e-15) && close(r.times[k], 0.025 * k, 1e-15);
    report("4 samples 2 * 0.01 * (12.5, -3, 40, 0) m/s^2 at k * 0.025 s", ok);

    const GroundMotionParameters p = parse("subsection Ground motion\n"
                                           "  subsection Component z\n"
                                           "    set File = gm_single.txt\n"
                                           "    set Format = single-column\n"
                                           "    set Time step = 0.025\n"
                                           "    set Units = m/s^2\n"
                                           "  end\n"
                                           "end\n");
    const GroundMotion motion(p, "");
    report("GroundMotion, Format single-column: a_z(0.0375 s) = (-3 + 40)/2 m/s^2",
           close(motion.acceleration(0.0375)[2], 18.5, 1e-13));
  }

  void
  check_processing()
  {
    std::cout << "\nProcessing from parameters (Rinaldi 228)" << std::endl;
    const GroundMotionParameters p =
      parse("subsection Ground motion\n"
            "  subsection Component x\n"
            "    set File = ground_motions/Rinaldi228.AT2\n"
            "    subsection Processing\n"
            "      set Resample time step = 0.005\n"
            "      set Baseline correction = true\n"
            "      set Target PGA = 0.5\n"
            "    end\n"
            "  end\n"
            "end\n");
    const auto &q = p.components[0].processing;
    report("parsed: Resample time step 0.005, Baseline correction, Target PGA 0.5",
           q.time_step == 0.005 && q.baseline && q.target_pga == 0.5 && q.any());
    const GroundMotion        motion(p, data_directory);
    const AccelerationRecord &r = motion.record(0);
    double                    dt = 0.;
    report("resampled: equally spaced at 0.005 s, 3981 samples (19.9 s)",
           r.is_uniform(&dt) && close(dt, 0.005, 1e-12) && r.values.size() == 3981);
    report("peak = 0.5 g", close(r.peak(), 0.5 * g, 1e-12 * g));
    // End velocity and displacement by the exact rule for piecewise-linear a.
    double v = 0., d = 0., v_peak = 0., d_peak = 0.;
    for (std::size_t k = 0; k + 1 < r.times.size(); ++k)
      {
        const double h = r.times[k + 1] - r.times[k];
        d += h * v + h * h * (r.values[k] / 3 + r.values[k + 1] / 6);
        v += h * (r.values[k] + r.values[k + 1]) / 2;
        v_peak = std::max(v_peak, std::abs(v));
        d_peak = std::max(d_peak, std::abs(d));
      }
    report("baseline: |v_end| < 1e-8 peak v, |d_end| < 1e-8 peak d",
           std::abs(v) < 1e-8 * v_peak && std::abs(d) < 1e-8 * d_peak);
    report("the source is still the file",
           r.source == data_directory + "/ground_motions/Rinaldi228.AT2");
  }

  void
  check_generated()
  {
    std::cout << "\nGenerated components" << std::endl;
    const GroundMotionParameters p = parse("subsection Ground motion\n"
                                           "  subsection Component y\n"
                                           "    set Source = generated\n"
                                           "    set Scale factor = -1\n"
                                           "  end\n"
                                           "  subsection Component z\n"
                                           "    set Source = generated\n"
                                           "  end\n"
                                           "  subsection Generated motion\n"
                                           "    set Peak ground acceleration = 0.2\n"
                                           "    set Characteristic period = 0.3\n"
                                           "    set Duration = 10\n"
                                           "    set Strong motion end = 7\n"
                                           "    set Longest matched period = 3\n"
                                           "    set Seed = 11\n"
                                           "  end\n"
                                           "end\n");
    const GroundMotion motion(p, "");
    report("components y and z, not x",
           !motion.has_component(0) && motion.has_component(1) && motion.has_component(2));
    report("duration 10 s", close(motion.duration(), 10., 1e-12));
    report("generation reports for y and z only",
           motion.generation_report(0) == nullptr && motion.generation_report(1) != nullptr &&
             motion.generation_report(2) != nullptr);

    GenerationSettings s;
    s.target              = TargetSpectrum::nb35047(0.2 * g, 0.3, 2.5);
    s.duration            = 10.;
    s.envelope.strong_end = 7.;
    s.period_max          = 3.;
    s.seed                = 11;
    s.stream              = 1;
    const AccelerationRecord y = generate_artificial_motion(s);
    s.stream                   = 2;
    s.target                   = s.target.scaled(2. / 3.);
    const AccelerationRecord z = generate_artificial_motion(s);
    bool same_y = motion.record(1).values.size() == y.values.size();
    for (std::size_t k = 0; same_y && k < y.values.size(); ++k)
      same_y = motion.record(1).values[k] == -y.values[k];
    report("y: -1 times the generator's stream 1, bit for bit", same_y);
    report("z: the generator's stream 2 for 2/3 of the target, bit for bit",
           motion.record(2).values == z.values);
    report("PGA of y 0.2 g, of z 2/3 * 0.2 g",
           close(motion.record(1).peak(), 0.2 * g, 1e-9 * g) &&
             close(motion.record(2).peak(), 0.2 * g * 2. / 3., 1e-9 * g));
  }
} // namespace



int
main(int argc, char **argv)
{
  dealii::Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  check_peer_records();
  check_older_peer_header();
  check_two_column();
  check_ground_motion();
  check_single_column();
  check_processing();
  check_generated();
}
