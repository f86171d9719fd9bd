#pragma once

#include <stdexcept>
#include <string>

namespace archdam
{
  /**
   * A run that cannot go on although its input was read without complaint:
   * a time step whose solution is no longer physical (time/divergence_check.h).
   * The results up to the last good step are written before it is thrown; the
   * command line prints the message as it is and exits with code 1.
   */
  class RunStopped : public std::runtime_error
  {
  public:
    RunStopped(const std::string &message, const double time, const unsigned int step)
      : std::runtime_error(message)
      , time(time)
      , step(step)
    {}

    /// Time and index of the step that failed.
    double       time;
    unsigned int step;
  };
} // namespace archdam
