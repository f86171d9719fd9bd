// Helpers of the tests that run ArchDam's command lines (archdam,
// archdam-motion) in their own process, as a user runs them.
#pragma once

#include <archdam/application/command_line.h>

#include <fstream>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

#include "archdam_tests.h"

namespace archdam::testing
{
  /// Rank 0 writes @p text into the file @p name; the others wait for it (two
  /// ranks writing one file while the other reads it would give them
  /// different cases).
  inline void
  write_input(const std::string &name, const std::string &text)
  {
    if (dealii::Utilities::MPI::this_mpi_process(MPI_COMM_WORLD) == 0)
      std::ofstream(name) << text;
    MPI_Barrier(MPI_COMM_WORLD);
  }

  /// Run `program args...` through its entry point @p entry (main's
  /// arguments, then the output and error streams); its exit code, and in
  /// @p err what it wrote to the error stream.
  template <typename Entry>
  int
  run_in_process(const Entry &entry, const std::string &program, std::vector<std::string> args,
                 std::string &err)
  {
    args.insert(args.begin(), program);
    std::vector<const char *> argv;
    for (const auto &a : args)
      argv.push_back(a.c_str());
    std::ostringstream out, error;
    const int          code = entry(argv.size(), argv.data(), out, error);
    err                     = error.str();
    return code;
  }

  /// Run `archdam args...` and print @p what, the exit code and the error
  /// message as the user sees them.
  inline void
  run_archdam(const std::string &what, std::vector<std::string> args)
  {
    std::string err;
    const int   code = run_in_process(run_command_line, "archdam", std::move(args), err);
    log() << "* " << what << "\n  exit code " << code << "\n  " << err << std::endl;
  }
} // namespace archdam::testing
