#pragma once

#include <deal.II/base/mpi.h>

#include <string>

namespace archdam::output
{
  /**
   * One run at a time in an output directory. Two runs writing the same
   * histories, summary and checkpoints would interleave their rows and leave
   * files that belong to neither; so a run (and a resumed run) holds an
   * exclusive lock on DIRECTORY/.archdam.lock from its start to its end, and a
   * second run that finds it held stops before writing anything, naming the
   * directory and the run that holds it (case, process, host, start time),
   * which the holder wrote into the file.
   *
   * The lock is the operating system's (flock): it is released when the run
   * ends, however it ends, even when killed, so a stale file never blocks a
   * later run. Rank 0 holds it for all ranks. Collective.
   */
  class RunLock
  {
  public:
    RunLock(const std::string &directory, const std::string &case_name, MPI_Comm comm);
    ~RunLock();

    RunLock(const RunLock &) = delete;
    RunLock &
    operator=(const RunLock &) = delete;

  private:
    int fd = -1;
  };
} // namespace archdam::output
