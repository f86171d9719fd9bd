// Helpers of the tests that run ArchDam's command line in their own process,
// as a user runs `archdam`.
#pragma once

#include <archdam/application/command_line.h>

#include <fstream>
#include <sstream>
#include <string>
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

  /// Run `archdam args...` and print @p what, the exit code and the error
  /// message as the user sees them.
  inline void
  run_archdam(const std::string &what, std::vector<std::string> args)
  {
    args.insert(args.begin(), "archdam");
    std::vector<const char *> argv;
    for (const auto &a : args)
      argv.push_back(a.c_str());
    std::ostringstream out, err;
    const int          code = run_command_line(argv.size(), argv.data(), out, err);
    log() << "* " << what << "\n  exit code " << code << "\n  " << err.str() << std::endl;
  }
} // namespace archdam::testing
