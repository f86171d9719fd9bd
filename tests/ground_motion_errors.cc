// Malformed ground-motion input: each case must throw archdam::InputError with
// a message that names the file (and the line, where there is one) and the
// problem. The files are written into the working directory and named
// relatively, so that the messages are the same on every machine. The data
// folder (ARCHDAM_DATA_DIR, base/data_files.h) is gm_data here: a relative
// name is looked for in the case file's folder, then there, and the message
// of a file in neither names both.

#include <archdam/loads/ground_motion.h>
#include <archdam/loads/record_io.h>

#include <deal.II/base/mpi.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <functional>
#include <iostream>
#include <string>

#include "archdam_tests.h"

using namespace archdam::loads;
using archdam::testing::expect_input_error;

namespace
{
  void
  write(const std::string &name, const std::string &text)
  {
    std::ofstream(name) << text;
  }

  /// The PEER header with @p line4 as its 4th line.
  std::string
  at2_header(const std::string &line4)
  {
    return "PEER NGA STRONG MOTION DATABASE RECORD\n"
           "Test event, 1/1/2000, Test station, 90\n"
           "ACCELERATION TIME SERIES IN UNITS OF G\n" +
           line4 + "\n";
  }

  /// GroundMotion with one x component, its format and units given by
  /// name as archdam-motion's --format and --units are (record_format(),
  /// record_units(): a case file's names are checked by their patterns).
  void
  ground_motion_x(const std::string &file,
                  const std::string &format,
                  const std::string &units,
                  const std::string &base_directory = "")
  {
    const std::string context = record_file_context(0, file);
    GroundMotionParameters p;
    p.components[0].file   = file;
    p.components[0].format = record_format(format, context);
    p.components[0].units  = record_units(units, context);
    const GroundMotion motion(p, base_directory);
  }
} // namespace



int
main(int argc, char **argv)
{
  dealii::Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);

  std::cout << "File missing or unreadable" << std::endl;
  expect_input_error("missing file", [] { read_at2("gm_missing.AT2"); });
  expect_input_error("missing file, two-column",
                     [] { read_two_column("gm_missing.txt", 1.); });
  std::filesystem::create_directory("gm_folder.AT2");
  expect_input_error("a directory instead of a file",
                     [] { read_at2("gm_folder.AT2"); });
  setenv("ARCHDAM_DATA_DIR", "gm_data", 1);
  expect_input_error("missing file, relative to base_directory", [] {
    ground_motion_x("gm_missing.AT2", "auto", "g", "gm_base");
  });
  expect_input_error("missing file, relative to the working directory", [] {
    ground_motion_x("gm_missing.AT2", "auto", "g", "");
  });
  // Found in the data folder (read, and empty), and in the case file's
  // folder first when both have it.
  // Fresh folders: a copy left in gm_base by an earlier run of this test
  // would be found first.
  std::filesystem::remove_all("gm_data");
  std::filesystem::remove_all("gm_base");
  std::filesystem::create_directories("gm_data/ground_motions");
  std::filesystem::create_directories("gm_base/ground_motions");
  write("gm_data/ground_motions/gm_in_data.AT2", "");
  expect_input_error("a file found in the data folder", [] {
    ground_motion_x("ground_motions/gm_in_data.AT2", "auto", "g", "gm_base");
  });
  write("gm_base/ground_motions/gm_in_data.AT2", "");
  expect_input_error("a file in the case folder and in the data folder", [] {
    ground_motion_x("ground_motions/gm_in_data.AT2", "auto", "g", "gm_base");
  });

  std::cout << "\nEmpty files" << std::endl;
  write("gm_empty.AT2", "");
  expect_input_error("empty AT2 file", [] { read_at2("gm_empty.AT2"); });
  write("gm_empty.txt", "");
  expect_input_error("empty two-column file",
                     [] { read_two_column("gm_empty.txt", 1.); });

  std::cout << "\nAT2 header" << std::endl;
  write("gm_short_header.AT2",
        "PEER NGA STRONG MOTION DATABASE RECORD\n"
        "Test event, 1/1/2000, Test station, 90\n");
  expect_input_error("file ends inside the 4-line header",
                     [] { read_at2("gm_short_header.AT2"); });
  write("gm_no_npts.AT2",
        "PEER NGA STRONG MOTION DATABASE RECORD\n"
        "ACCELERATION TIME SERIES IN UNITS OF G\n"
        "  .1000E-01  .2000E-01  .3000E-01\n"
        "  .4000E-01  .5000E-01  .6000E-01\n");
  expect_input_error("3-line header: line 4 is data, no NPTS and DT",
                     [] { read_at2("gm_no_npts.AT2"); });
  write("gm_npts_not_integer.AT2",
        at2_header("NPTS=   4.5, DT=   .0100 SEC") + "  .1  .2  .3  .4\n");
  expect_input_error("NPTS not a whole number",
                     [] { read_at2("gm_npts_not_integer.AT2"); });
  write("gm_no_dt.AT2", at2_header("NPTS=   4, SEC") + "  .1  .2  .3  .4\n");
  expect_input_error("DT missing", [] { read_at2("gm_no_dt.AT2"); });
  write("gm_dt_zero.AT2",
        at2_header("NPTS=   4, DT=   .0000 SEC") + "  .1  .2  .3  .4\n");
  expect_input_error("DT = 0", [] { read_at2("gm_dt_zero.AT2"); });
  write("gm_dt_negative.AT2",
        at2_header("    4 -.0100 NPTS, DT") + "  .1  .2  .3  .4\n");
  expect_input_error("DT < 0 (older header form)",
                     [] { read_at2("gm_dt_negative.AT2"); });

  std::cout << "\nAT2 data" << std::endl;
  write("gm_too_few.AT2",
        at2_header("NPTS=   6, DT=   .0100 SEC") + "  .1  .2  .3\n  .4  .5\n");
  expect_input_error("NPTS = 6, 5 values (file cut short)",
                     [] { read_at2("gm_too_few.AT2"); });
  write("gm_too_many.AT2",
        at2_header("NPTS=   4, DT=   .0100 SEC") + "  .1  .2  .3\n  .4  .5\n");
  expect_input_error("NPTS = 4, 5 values", [] { read_at2("gm_too_many.AT2"); });
  write("gm_not_a_number.AT2",
        at2_header("NPTS=   6, DT=   .0100 SEC") +
          "  .1000E-01  .2000E-01  .3000E-01\n  .4000E-01  .5OOOE-01  .6\n");
  expect_input_error("letter O for zero on line 6",
                     [] { read_at2("gm_not_a_number.AT2"); });
  write("gm_one_sample.AT2",
        at2_header("NPTS=   1, DT=   .0100 SEC") + "  .1000E-01\n");
  expect_input_error("NPTS = 1", [] { read_at2("gm_one_sample.AT2"); });

  std::cout << "\nTwo-column files" << std::endl;
  write("gm_not_a_number.txt", "# t a\n0.0, 0.1\n0.1, abc\n0.2, 0.3\n");
  expect_input_error("text in the acceleration column on line 3",
                     [] { read_two_column("gm_not_a_number.txt", 1.); });
  write("gm_nan.txt", "0.0 0.1\n0.1 nan\n");
  expect_input_error("nan on line 2",
                     [] { read_two_column("gm_nan.txt", 1.); });
  write("gm_three_columns.txt", "0.0 0.1\n0.1 0.2 0.3\n");
  expect_input_error("three columns on line 2",
                     [] { read_two_column("gm_three_columns.txt", 1.); });
  write("gm_equal_times.txt", "0.0 0.1\n0.1 0.2\n\n0.1 0.3\n");
  expect_input_error("time repeated on line 4",
                     [] { read_two_column("gm_equal_times.txt", 1.); });
  write("gm_decreasing_times.txt", "0.0\t0.1\n0.2\t0.2\n0.15\t0.3\n");
  expect_input_error("time going back on line 3",
                     [] { read_two_column("gm_decreasing_times.txt", 1.); });
  write("gm_one_sample.txt", "# time, acceleration\n\n0.0, 0.1\n");
  expect_input_error("one sample",
                     [] { read_two_column("gm_one_sample.txt", 1.); });
  write("gm_only_comments.txt", "# time, acceleration\n# nothing yet\n\n");
  expect_input_error("comments only",
                     [] { read_two_column("gm_only_comments.txt", 1.); });

  std::cout << "\nParameters" << std::endl;
  write("gm_good.txt", "0.0 0.1\n0.1 0.2\n");
  expect_input_error("unit not recognized",
                     [] { ground_motion_x("gm_good.txt", "auto", "ft/s^2"); });
  expect_input_error("format not recognized",
                     [] { ground_motion_x("gm_good.txt", "CSV", "g"); });
  expect_input_error("Units other than g for an AT2 file", [] {
    ground_motion_x("gm_one_sample.AT2", "AT2", "cm/s^2");
  });
  expect_input_error("reader errors pass through GroundMotion",
                     [] { ground_motion_x("gm_too_few.AT2", "auto", "g"); });

  std::cout << "\nSingle-column files" << std::endl;
  write("gm_single_pairs.txt", "# a\n0.1\n0.2 0.3\n");
  expect_input_error("two numbers on line 3", [] {
    read_single_column("gm_single_pairs.txt", 0.01, 1.);
  });
  write("gm_single_text.txt", "0.1\n0.2\nzero\n");
  expect_input_error("text on line 3",
                     [] { read_single_column("gm_single_text.txt", 0.01, 1.); });
  write("gm_single_one.txt", "# a\n0.1\n");
  expect_input_error("one sample", [] { read_single_column("gm_single_one.txt", 0.01, 1.); });
  expect_input_error("time step -0.01 s",
                     [] { read_single_column("gm_single_text.txt", -0.01, 1.); });
  expect_input_error("Format single-column without Time step",
                     [] { ground_motion_x("gm_single_one.txt", "single-column", "g"); });

  std::cout << "\nGenerated motions" << std::endl;
  const auto generated = [](const std::function<void(ArtificialMotionParameters &)> &change) {
    GroundMotionParameters p;
    p.components[0].source = MotionSource::generated;
    change(p.generated);
    const GroundMotion motion(p, "");
  };
  expect_input_error("strong part ends after the motion",
                     [&] { generated([](auto &g) { g.duration = 10; }); });
  expect_input_error("rise ends after the strong part", [&] {
    generated([](auto &g) { g.envelope.rise_end = 5, g.envelope.strong_end = 4; });
  });
  const auto table = TargetSpectrumKind::table;
  expect_input_error("Target spectrum = table without a table",
                     [&] { generated([&](auto &g) { g.spectrum = table; }); });
  expect_input_error("malformed spectrum table", [&] {
    generated([&](auto &g) { g.spectrum = table, g.table = "0: 1; 0.2; 1: 2"; });
  });
  expect_input_error("spectrum table periods decreasing", [&] {
    generated([&](auto &g) { g.spectrum = table, g.table = "0: 1; 0.5: 2.5; 0.2: 2.5"; });
  });
  expect_input_error("Characteristic period 0", [&] {
    generated([](auto &g) { g.characteristic_period = 0; });
  });
  expect_input_error("shortest matched period below 3 time steps", [&] {
    generated([](auto &g) { g.time_step = 0.02; });
  });
  expect_input_error("longest matched period above half the duration", [&] {
    generated([](auto &g) { g.period_max = 15; });
  });
  expect_input_error("damping ratio 1", [&] { generated([](auto &g) { g.damping = 1; }); });
  expect_input_error("vertical factor that is not a number", [] {
    GroundMotionParameters p;
    p.components[2].source      = MotionSource::generated;
    p.generated.vertical_factor = "two thirds";
    const GroundMotion motion(p, "");
  });

  std::cout << "\nProcessing" << std::endl;
  const auto processed = [](const std::string                                &file,
                            const std::function<void(ProcessingParameters &)> &change) {
    GroundMotionParameters p;
    p.components[0].file = file;
    change(p.components[0].processing);
    const GroundMotion motion(p, "");
  };
  write("gm_irregular.txt", "0 0.1\n0.01 0.2\n0.025 0.1\n0.03 0\n0.04 0.1\n");
  expect_input_error("window ends after the record",
                     [&] { processed("gm_irregular.txt", [](auto &q) { q.end_time = 1; }); });
  expect_input_error("filter on irregular times", [&] {
    processed("gm_irregular.txt", [](auto &q) { q.high_pass = 0.5; });
  });
  expect_input_error("low-pass corner above the Nyquist frequency of the resampled record", [&] {
    processed("gm_irregular.txt", [](auto &q) { q.time_step = 0.01, q.low_pass = 60; });
  });
}
