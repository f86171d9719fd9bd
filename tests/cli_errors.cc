// The command line reports every user error with one clear message naming the
// file, line and parameter (or option), and exit code 1 (issue "core", must
// show 2). Each case below is an input a user can really get wrong; the test
// prints the exit code and the message as the user sees it.

#include <cstdlib>

#include "case_text.h"
#include "command_line_tests.h"

using archdam::testing::run_archdam;
using archdam::testing::write_input;

namespace
{
  // A valid short case to which the overrides below are applied.
  const std::string good_case =
    archdam::testing::case_text::short_box_case("    set Cells in y = 1\n");
} // namespace

int
main(int argc, char **argv)
{
  dealii::Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);

  write_input("good.prm", good_case);
  write_input("unknown_parameter.prm", "subsection Time integration\n  set Time stp = 0.01\nend\n");
  write_input("unknown_section.prm", "subsection Time integraton\n  set Time step = 0.01\nend\n");
  write_input("malformed_value.prm", "subsection Time integration\n  set Time step = 0.01s\nend\n");
  write_input("out_of_range.prm", "subsection Finite element\n  set Degree = 3\nend\n");
  write_input("missing_end.prm", "subsection Time integration\n  set Time step = 0.01\n");
  write_input("unstable.prm",
              "subsection Time integration\n  set Beta1 = 0.5\n  set Beta2 = 0.1\nend\n");
  write_input("bad_monitor.prm", "subsection Monitors\n  set Points = crest 5, 20, 30\nend\n");

  run_archdam("a missing case file", {"no_such_case.prm"});
  run_archdam("no case file at all", {});
  run_archdam("an unknown option", {"good.prm", "--verbose"});
  run_archdam("an unknown parameter", {"unknown_parameter.prm"});
  run_archdam("an unknown section", {"unknown_section.prm"});
  run_archdam("a malformed value", {"malformed_value.prm"});
  run_archdam("a value out of range", {"out_of_range.prm"});
  run_archdam("a subsection without end", {"missing_end.prm"});
  run_archdam("an unstable Newmark scheme", {"unstable.prm"});
  run_archdam("a malformed monitor point", {"bad_monitor.prm"});
  run_archdam("--set: unknown parameter", {"good.prm", "--set", "Output/Field interval=3"});
  run_archdam("--set: unknown section", {"good.prm", "--set", "Outptu/Progress=true"});
  run_archdam("--set: malformed value", {"good.prm", "--set", "Output/Progress=maybe"});
  run_archdam("--set: no '='", {"good.prm", "--set", "Output/Progress"});
  run_archdam("--set: no section", {"good.prm", "--set", "Progress=true"});
  run_archdam("--set without argument", {"good.prm", "--set"});
  // A fixed data folder: the message names every folder searched, and the
  // default one is the source tree's, different on every machine.
  setenv("ARCHDAM_DATA_DIR", "no_data_folder", 1);
  run_archdam("a missing ground-motion file",
      {"good.prm", "--set", "Ground motion/Component x/File=no_such_record.AT2"});
  unsetenv("ARCHDAM_DATA_DIR");
  run_archdam("a monitor point outside the mesh",
              {"good.prm", "--set", "Monitors/Points=far: 0, 0, 1000"});
  run_archdam("an end time without ground motion",
              {"good.prm", "--set", "Time integration/End time=0"});
  run_archdam("a valid case runs", {"good.prm", "--set", "Time integration/Time step=0.01"});
  run_archdam("the free-field check of a case on massless rock",
              {"good.prm", "--free-field-check"});
  run_archdam("the free-field check with --resume", {"good.prm", "--free-field-check", "--resume"});
  run_archdam("--record without a name", {"good.prm", "--record"});
  run_archdam("--record of a case without a record suite", {"good.prm", "--record", "elcentro"});
  run_archdam("--gather of a case without a record suite", {"good.prm", "--gather"});
  run_archdam("--gather with --record", {"good.prm", "--gather", "--record", "elcentro"});
  run_archdam("--record with --mesh-only", {"good.prm", "--record", "elcentro", "--mesh-only"});
  run_archdam("--record given twice", {"good.prm", "--record", "elcentro", "--record", "rinaldi"});
  run_archdam("--gather with --resume", {"good.prm", "--gather", "--resume"});

  // --help: every option of the usage lines has a line of its own, with an
  // example and where the documentation is; --version: ArchDam's version and
  // those of the libraries it runs on, one a line.
  const auto standard_output = [](const std::vector<const char *> &argv) {
    std::ostringstream out, err;
    const int code = archdam::run_command_line(argv.size(), argv.data(), out, err);
    return std::make_pair(code, out.str());
  };
  const auto [help_code, help] = standard_output({"archdam", "--help"});
  bool every_option = true;
  for (const std::string option :
       {"--set", "--mesh-only", "--resume", "--free-field-check", "--record", "--gather",
        "--print-parameters", "--help", "--version"})
    every_option = every_option && help.find("\n  " + option) != std::string::npos;
  archdam::testing::log() << "* --help\n  exit code " << help_code
                          << "\n  every option on a line of its own: "
                          << (every_option ? "yes" : "NO") << "\n  an example: "
                          << (help.find("Example") != std::string::npos ? "yes" : "NO")
                          << "\n  where the documentation is: "
                          << (help.find("doc/user-guide.md") != std::string::npos ? "yes" : "NO")
                          << "\n" << std::endl;
  const auto [version_code, version] = standard_output({"archdam", "--version"});
  std::istringstream lines(version);
  std::string        line, names;
  while (std::getline(lines, line))
    names += line.substr(0, line.find(' ')) + (line.find(' ') + 1 < line.size() ? " x.y" : "") +
             "; ";
  archdam::testing::log() << "* --version\n  exit code " << version_code << "\n  " << names
                          << "\n" << std::endl;
}
