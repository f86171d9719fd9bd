#pragma once

#include <iosfwd>

namespace archdam
{
  /**
   * The `archdam` command (MPI must be initialized by the caller):
   *   archdam CASE.prm [--set "Section/Name=value"]...   run a case
   *   archdam CASE.prm --mesh-only    build the model mesh, print its report,
   *                                  write it as VTU with summary.json, stop
   *   archdam --print-parameters [text|json|xml|latex]  the parameter reference
 *                                  (text: a parameter file showing each entry's
 *                                  documentation, allowed values and default)
   *   archdam --help
   * User errors (InputError, deal.II exceptions thrown while reading input)
   * are reported on @p err as one message and give exit code 1; anything
   * else unexpected gives exit code 2.
   */
  int
  run_command_line(int argc, const char *const *argv, std::ostream &out, std::ostream &err);
} // namespace archdam
