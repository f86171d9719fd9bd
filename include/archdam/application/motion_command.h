#pragma once

#include <iosfwd>

namespace archdam
{
  /**
   * The `archdam-motion` command, which generates, converts, scales and
   * inspects ground motions (MPI must be initialized by the caller; it runs
   * on one process, the others do nothing):
   *
   *   archdam-motion generate [generation] [processing] [output]
   *   archdam-motion convert INPUT [input] [processing] [output]
   *   archdam-motion scale INPUT --pga G [input] [output]
   *   archdam-motion inspect INPUT [input] [processing] [target] [output]
   *   archdam-motion case CASE.prm [--component x|y|z] [target] [output]
   *   archdam-motion --help | help SUBCOMMAND
   *
   * (the options are listed by --help). Every command prints a summary of the
   * motion (samples, PGA, PGV, PGD, end velocity and displacement, Arias
   * intensity, significant duration, spectral values) and writes what the
   * output options ask for: --csv (two columns, readable as input), --at2,
   * --histories (acceleration, velocity, displacement), --spectrum, and
   * --plot: the data of the plot (histories and spectrum against the target)
   * with the command that draws it from them (scripts/plot_motion.py), for
   * the user to run.
   *
   * User errors (InputError, deal.II exceptions while reading a case file)
   * are reported on @p err as one message and give exit code 1; anything
   * else unexpected gives exit code 2.
   */
  int
  run_motion_command(int                argc,
                     const char *const *argv,
                     std::ostream      &out,
                     std::ostream      &err);
} // namespace archdam
