#pragma once

// The project's Python scripts (scripts/: plots, the run report) run from the
// command lines with Debian's /usr/bin/python3 and matplotlib.

#include <iosfwd>
#include <string>
#include <vector>

namespace archdam::application
{
  /// The command line running scripts/@p script with @p arguments (each
  /// but the options "--name" quoted, so that a printed command can be
  /// pasted as it is).
  std::string
  python_command(const std::string &script, const std::vector<std::string> &arguments);

  /// Run python_command(@p script, @p arguments) quietly; false where
  /// /usr/bin/python3 or the script is missing or the script fails.
  bool
  run_python_script(const std::string &script, const std::vector<std::string> &arguments);

  /// Write the run report @p folder/report.html with scripts/run_report.py
  /// (a run's results, or a record suite's) and say so on @p out; where
  /// Python or matplotlib is missing, print the command that writes it.
  void
  write_report(const std::string &folder, std::ostream &out);
} // namespace archdam::application
