#pragma once

#include <stdexcept>
#include <string>

namespace archdam
{
  /**
   * A problem with what the user gave the program: a parameter value, a file, a
   * mesh. Thrown with a message that names the offending thing (file, line,
   * parameter) so that main() can print it as it is and exit with code 1,
   * without a stack dump. Programming errors stay deal.II assertions.
   */
  class InputError : public std::runtime_error
  {
  public:
    explicit InputError(const std::string &message)
      : std::runtime_error(message)
    {}
  };
} // namespace archdam
