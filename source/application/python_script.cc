#include <archdam/application/python_script.h>

#include <cstdlib>
#include <filesystem>
#include <ostream>

namespace archdam::application
{
  namespace
  {
    const std::string python = "/usr/bin/python3";

    /// @p s as one word of a shell command line.
    std::string
    shell_quote(const std::string &s)
    {
      std::string q = "'";
      for (const char c : s)
        q += (c == '\'') ? std::string("'\\''") : std::string(1, c);
      return q + "'";
    }

    std::string
    script_path(const std::string &script)
    {
      return std::string(ARCHDAM_SCRIPTS_DIR) + "/" + script;
    }
  } // namespace

  std::string
  python_command(const std::string &script, const std::vector<std::string> &arguments)
  {
    std::string command = python + " " + shell_quote(script_path(script));
    for (const auto &a : arguments)
      command += " " + (a.rfind("--", 0) == 0 ? a : shell_quote(a));
    return command;
  }

  bool
  run_python_script(const std::string &script, const std::vector<std::string> &arguments)
  {
    std::error_code ec;
    return std::filesystem::exists(python, ec) &&
           std::filesystem::exists(script_path(script), ec) &&
           std::system((python_command(script, arguments) + " > /dev/null 2>&1").c_str()) == 0;
  }

  void
  write_report(const std::string &folder, std::ostream &out)
  {
    if (run_python_script("run_report.py", {folder}))
      out << "Report: " << folder << "/report.html (open it in a browser)" << std::endl;
    else
      out << "The report needs /usr/bin/python3 with matplotlib; write it with\n  "
          << python_command("run_report.py", {folder}) << std::endl;
  }
} // namespace archdam::application
