// The command line reports every user error with one clear message naming the
// file, line and parameter (or option), and exit code 1 (issue "core", must
// show 2). Each case below is an input a user can really get wrong; the test
// prints the exit code and the message as the user sees it.

#include <archdam/application/command_line.h>

#include <fstream>

#include "archdam_tests.h"

namespace
{
  // Rank 0 writes the input files; the others wait for them (two ranks
  // writing one file while the other reads it would give them different
  // cases).
  void
  write(const std::string &name, const std::string &text)
  {
    if (dealii::Utilities::MPI::this_mpi_process(MPI_COMM_WORLD) == 0)
      std::ofstream(name) << text;
    MPI_Barrier(MPI_COMM_WORLD);
  }

  void
  run(const std::string &what, std::vector<std::string> args)
  {
    args.insert(args.begin(), "archdam");
    std::vector<const char *> argv;
    for (const auto &a : args)
      argv.push_back(a.c_str());
    std::ostringstream out, err;
    const int code = archdam::run_command_line(argv.size(), argv.data(), out, err);
    archdam::testing::log() << "* " << what << "\n  exit code " << code << "\n  "
                            << err.str() << std::endl;
  }

  // A valid short case to which the overrides below are applied.
  const char *good_case = R"(
subsection Mesh
  subsection Box
    set Rock depth = 0
    set Cells in y = 1
  end
end
subsection Finite element
  set Degree = 1
end
subsection Time integration
  set End time = 0.02
end
subsection Output
  set Directory = results
  set Field output interval = 0
  set Progress = false
  set Timer summary = false
end
)";
} // namespace

int
main(int argc, char **argv)
{
  dealii::Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);

  write("good.prm", good_case);
  write("unknown_parameter.prm", "subsection Time integration\n  set Time stp = 0.01\nend\n");
  write("unknown_section.prm", "subsection Time integraton\n  set Time step = 0.01\nend\n");
  write("malformed_value.prm", "subsection Time integration\n  set Time step = 0.01s\nend\n");
  write("out_of_range.prm", "subsection Finite element\n  set Degree = 3\nend\n");
  write("missing_end.prm", "subsection Time integration\n  set Time step = 0.01\n");
  write("unstable.prm", "subsection Time integration\n  set Beta1 = 0.5\n  set Beta2 = 0.1\nend\n");
  write("bad_monitor.prm", "subsection Monitors\n  set Points = crest 5, 20, 30\nend\n");

  run("a missing case file", {"no_such_case.prm"});
  run("no case file at all", {});
  run("an unknown option", {"good.prm", "--verbose"});
  run("an unknown parameter", {"unknown_parameter.prm"});
  run("an unknown section", {"unknown_section.prm"});
  run("a malformed value", {"malformed_value.prm"});
  run("a value out of range", {"out_of_range.prm"});
  run("a subsection without end", {"missing_end.prm"});
  run("an unstable Newmark scheme", {"unstable.prm"});
  run("a malformed monitor point", {"bad_monitor.prm"});
  run("--set: unknown parameter", {"good.prm", "--set", "Output/Field interval=3"});
  run("--set: unknown section", {"good.prm", "--set", "Outptu/Progress=true"});
  run("--set: malformed value", {"good.prm", "--set", "Output/Progress=maybe"});
  run("--set: no '='", {"good.prm", "--set", "Output/Progress"});
  run("--set: no section", {"good.prm", "--set", "Progress=true"});
  run("--set without argument", {"good.prm", "--set"});
  run("a missing ground-motion file",
      {"good.prm", "--set", "Ground motion/Component x/File=no_such_record.AT2"});
  run("a monitor point outside the mesh", {"good.prm", "--set", "Monitors/Points=far: 0, 0, 1000"});
  run("an end time without ground motion", {"good.prm", "--set", "Time integration/End time=0"});
  run("a valid case runs", {"good.prm", "--set", "Time integration/Time step=0.01"});
}
