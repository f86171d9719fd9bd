#pragma once

#include <archdam/base/input_error.h>

#include <deal.II/base/mpi.h>

#include <functional>
#include <string>

namespace archdam
{
  /**
   * Run @p work (creating a directory, writing a file) on rank 0 of @p comm
   * only. If it throws InputError, every rank throws it: a rank that went on
   * alone would wait forever in the next collective call for the one that
   * stopped. Collective.
   */
  inline void
  on_rank_zero(const MPI_Comm comm, const std::function<void()> &work)
  {
    std::string problem;
    if (dealii::Utilities::MPI::this_mpi_process(comm) == 0)
      try
        {
          work();
        }
      catch (const InputError &e)
        {
          problem = e.what();
        }
    problem = dealii::Utilities::MPI::broadcast(comm, problem, 0);
    if (!problem.empty())
      throw InputError(problem);
  }
} // namespace archdam
