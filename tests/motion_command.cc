// The archdam-motion command (application/motion_command.h): every user
// error gives one message and exit code 1; what it writes is checked against
// independent readings of the same data:
//  - AT2 -> CSV: the CSV read back equals the AT2 record read by read_at2 to
//    the CSV's 10 significant digits (tolerance 1e-9 of the PGA);
//  - AT2 resampled -> AT2: NPTS and DT of the new header, values equal to the
//    library's resample() of the record to the 7 decimals of the E format
//    (relative rounding 5e-8, tolerance 1e-7 of the PGA);
//  - scale to 0.5 g: the written record's peak is 0.5 g (to 1e-7);
//  - generate: the AT2 written equals generate_artificial_motion() with the
//    same settings (to 1e-7 of the PGA), and its PGA is the target;
//  - single-column input in cm/s^2, and `case` on a case file, against
//    values typed here and read_at2;
//  - the plot: the command writes its data and draws it with
//    /usr/bin/python3 and matplotlib (installed with the project); the file
//    it makes is a PNG (its 8-byte signature); the plot itself is looked at
//    in doc/ground-motion.md.
// The summaries the command prints for users are not part of this output.

#include <archdam/application/motion_command.h>
#include <archdam/loads/artificial_motion.h>
#include <archdam/loads/record_io.h>
#include <archdam/loads/record_processing.h>

#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>

#include "archdam_tests.h"
#include "command_line_tests.h"

using namespace archdam::loads;
using archdam::run_motion_command;
using archdam::testing::check_below;
using archdam::testing::log;

namespace
{
  const std::string &data = archdam::testing::ground_motions;
  const double       g    = 9.80665;

  /// Run the command; print what a user sees on errors, return the exit code.
  int
  run(const std::string &what, std::vector<std::string> args, const bool show = true)
  {
    std::string err;
    const int   code = archdam::testing::run_in_process(run_motion_command, "archdam-motion",
                                                      std::move(args), err);
    if (show)
      log() << "* " << what << "\n  exit code " << code << "\n  " << err << std::endl;
    else
      log() << "* " << what << ": exit code " << code << (code == 0 ? "" : "\n  " + err)
            << std::endl;
    return code;
  }

  double
  max_difference(const AccelerationRecord &a, const AccelerationRecord &b)
  {
    if (a.values.size() != b.values.size())
      return 1e300;
    double d = 0;
    for (std::size_t k = 0; k < a.values.size(); ++k)
      d = std::max({d, std::abs(a.values[k] - b.values[k]), std::abs(a.times[k] - b.times[k])});
    return d;
  }
} // namespace

int
main(int argc, char **argv)
{
  dealii::Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  // A copy in the working directory: messages name files relatively, the
  // same on every machine.
  const std::string pacoima = "motion_pacoima.AT2";
  std::filesystem::copy_file(data + "RSN77_SFERN_PUL164.AT2", pacoima,
                             std::filesystem::copy_options::overwrite_existing);

  {
    const char        *args[] = {"archdam-motion", "--version"};
    std::ostringstream out, err;
    const int          code = run_motion_command(2, args, out, err);
    log() << "* --version: exit code " << code << ", names the program: "
          << (out.str().rfind("archdam-motion ", 0) == 0 ? "yes" : "NO") << std::endl;
  }

  log() << "Errors" << std::endl;
  run("no command", {});
  run("unknown command", {"plot", pacoima});
  run("unknown option", {"inspect", pacoima, "--colour", "red"});
  run("option without its value", {"inspect", pacoima, "--plot"});
  run("value not a number", {"generate", "--pga", "0.3g"});
  run("option given twice", {"generate", "--seed", "1", "--seed", "2"});
  run("option of another command", {"convert", pacoima, "--seed", "3", "--csv", "a.csv"});
  run("convert without an output", {"convert", pacoima});
  run("scale without --pga", {"scale", pacoima, "--csv", "a.csv"});
  run("inspect without a file", {"inspect"});
  run("two input files", {"inspect", pacoima, pacoima});
  // A fixed data folder: the default one differs between machines.
  setenv("ARCHDAM_DATA_DIR", "motion_data", 1);
  run("missing input file", {"inspect", "no_such_record.AT2"});
  unsetenv("ARCHDAM_DATA_DIR");
  run("--dt for an AT2 file", {"inspect", pacoima, "--dt", "0.01"});
  run("--tg without --pga", {"inspect", pacoima, "--tg", "0.4"});
  run("--table with --tg", {"generate", "--table", "0: 1; 1: 2", "--tg", "0.3"});
  run("malformed --window", {"inspect", pacoima, "--window", "5-10"});
  run("window beyond the record", {"inspect", pacoima, "--window", "5:60"});
  run("low-pass above Nyquist", {"inspect", pacoima, "--lowpass", "80"});
  run("component w", {"generate", "--component", "w"});
  run("vertical factor for x", {"generate", "--vertical-factor", "0.5"});
  run("envelope longer than the motion", {"generate", "--duration", "10"});
  run("T_g below 0.1 s", {"generate", "--tg", "0.05"});
  run("spectrum damping 1.5", {"inspect", pacoima, "--spectrum-damping", "1.5"});
  run("a generated motion of 1e9 s", {"generate", "--duration", "1e9"});
  run("a generated motion of 1e5 s", {"generate", "--duration", "1e5"});
  run("an output in a folder that does not exist",
      {"inspect", pacoima, "--csv", "no_such_folder/a.csv"});
  std::ofstream("motion_irregular.txt") << "0 0.1\n0.01 0.2\n0.025 0.1\n0.03 0\n";
  run("AT2 from a record with irregular times",
      {"convert", "motion_irregular.txt", "--at2", "a.AT2"});
  run("case file missing", {"case", "no_such_case.prm"});
  std::ofstream("motion_empty_case.prm") << "subsection Output\n  set Directory = results\nend\n";
  run("case without ground motion", {"case", "motion_empty_case.prm"});

  log() << "\nHelp" << std::endl;
  {
    const char        *args[] = {"archdam-motion", "--help"};
    std::ostringstream out, err;
    const int          code = run_motion_command(2, args, out, err);
    log() << "--help: exit code " << code << ", lists the commands: "
          << (out.str().find("archdam-motion generate") != std::string::npos &&
                  out.str().find("archdam-motion case") != std::string::npos ?
                "yes" :
                "NO")
          << std::endl;
  }

  log() << "\nOutputs" << std::endl;
  const AccelerationRecord original = read_at2(pacoima);
  const double             pga      = original.peak();

  run("convert AT2 -> CSV", {"convert", pacoima, "--csv", "motion_pacoima.csv"}, false);
  check_below("  CSV read back (m/s^2) against read_at2: max difference / PGA",
              max_difference(read_two_column("motion_pacoima.csv", 1.0), original) / pga, 1e-9);

  run("convert with --resample 0.02 -> AT2",
      {"convert", pacoima, "--resample", "0.02", "--at2", "motion_pacoima_02.AT2"}, false);
  const AccelerationRecord coarse = read_at2("motion_pacoima_02.AT2");
  double                   dt     = 0;
  log() << "  header: NPTS = " << coarse.values.size() << " (expected 2086), DT = 0.02: "
        << (coarse.is_uniform(&dt) && std::abs(dt - 0.02) < 1e-12 ? "yes" : "NO") << std::endl;
  check_below("  values against resample(record, 0.02): max difference / PGA",
              max_difference(coarse, resample(original, 0.02)) / pga, 1e-7);

  run("scale to 0.5 g -> AT2", {"scale", pacoima, "--pga", "0.5", "--at2", "motion_scaled.AT2"},
      false);
  check_below("  |peak - 0.5 g| / 0.5 g",
              std::abs(read_at2("motion_scaled.AT2").peak() - 0.5 * g) / (0.5 * g), 1e-7);

  run("generate PGA 0.3 g, T_g 0.4 s, 10 s, seed 3 -> AT2",
      {"generate", "--pga", "0.3", "--tg", "0.4", "--duration", "10", "--strong-end", "7",
       "--seed", "3", "--at2", "motion_generated.AT2"},
      false);
  GenerationSettings settings;
  settings.target              = TargetSpectrum::nb35047(0.3 * g, 0.4, 2.5);
  settings.duration            = 10;
  settings.envelope.strong_end = 7;
  settings.seed                = 3;
  const AccelerationRecord generated = generate_artificial_motion(settings);
  const AccelerationRecord written   = read_at2("motion_generated.AT2");
  check_below("  AT2 against generate_artificial_motion(same settings): max difference / PGA",
              max_difference(written, generated) / (0.3 * g), 1e-7);
  check_below("  |PGA - 0.3 g| / 0.3 g", std::abs(written.peak() - 0.3 * g) / (0.3 * g), 1e-7);

  std::ofstream("motion_single.txt") << "# cm/s^2 at 0.02 s\n10\n-20.5\n\n30\n# end\n5\n";
  run("single-column file in cm/s^2, dt 0.02 -> CSV",
      {"convert", "motion_single.txt", "--format", "single-column", "--units", "cm/s^2", "--dt",
       "0.02", "--csv", "motion_single.csv"},
      false);
  const AccelerationRecord single   = read_two_column("motion_single.csv", 1.0);
  const AccelerationRecord expected = uniform_record({0.10, -0.205, 0.30, 0.05}, 0.02);
  check_below("  samples 0.1, -0.205, 0.3, 0.05 m/s^2 at 0, 0.02, 0.04, 0.06 s: max difference",
              max_difference(single, expected), 1e-12);

  std::ofstream("motion_case.prm") << "subsection Mesh\n  subsection Box\n    set Height = 30\n"
                                      "  end\nend\n"
                                      "subsection Ground motion\n"
                                      "  subsection Component y\n"
                                      "    set File = motion_pacoima.AT2\n"
                                      "    set Scale factor = -0.5\n"
                                      "  end\n"
                                      "end\n";
  run("case: component y of a case file -> CSV",
      {"case", "motion_case.prm", "--component", "y", "--csv", "motion_case_y.csv"}, false);
  AccelerationRecord half = original;
  for (double &a : half.values)
    a *= -0.5;
  check_below("  CSV against -0.5 x read_at2: max difference / PGA",
              max_difference(read_two_column("motion_case_y.csv", 1.0), half) / pga, 1e-9);
  run("case: component x, which the case does not have",
      {"case", "motion_case.prm", "--component", "x"});

  {
    // Nothing left by an earlier run counts; the output stream, which the
    // other runs leave out, says what was written.
    for (const char *name :
         {"motion_pacoima.png", "motion_pacoima.histories.csv", "motion_pacoima.spectrum.csv"})
      std::filesystem::remove(name);
    const char *args[] = {"archdam-motion", "inspect", pacoima.c_str(), "--plot",
                          "motion_pacoima.png"};
    std::ostringstream out, err;
    const int          code    = run_motion_command(5, args, out, err);
    const std::string  text    = out.str();
    log() << "* inspect with a plot: exit code " << code << "\n  data written: "
          << (std::filesystem::exists("motion_pacoima.histories.csv") &&
                  std::filesystem::exists("motion_pacoima.spectrum.csv") ?
                "yes" :
                "NO")
          << ", the plot said written: "
          << (text.find("wrote motion_pacoima.png") != std::string::npos ? "yes" : "NO")
          << std::endl;
  }
  std::ifstream png("motion_pacoima.png", std::ios::binary);
  char          signature[8] = {};
  png.read(signature, 8);
  log() << "  PNG drawn: "
        << (png && std::string(signature + 1, 3) == "PNG" && signature[0] == char(0x89) ? "yes" :
                                                                                          "NO")
        << std::endl;
}
