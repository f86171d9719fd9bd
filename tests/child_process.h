// The `archdam` application run as a child process, watched through the
// files it writes and killed (killed_run, checkpoint_resume).
#pragma once

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <string>
#include <sys/wait.h>
#include <thread>
#include <unistd.h>
#include <vector>

namespace archdam::testing
{
  /// The whole of @p file, byte for byte ("" if it does not exist).
  inline std::string
  read_file(const std::filesystem::path &file)
  {
    std::ifstream in(file, std::ios::binary);
    return std::string((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  }

  inline unsigned int
  count_lines(const std::filesystem::path &file)
  {
    const auto text = read_file(file);
    return std::count(text.begin(), text.end(), '\n');
  }

  /// Start @p args (the program's path first) as a child process in its own
  /// process group (a kill of the group takes mpiexec and its ranks), its
  /// standard output and error into the file @p log.
  inline pid_t
  start_child(std::vector<std::string> args, const std::string &log)
  {
    const pid_t pid = fork();
    if (pid == 0)
      {
        setpgid(0, 0);
        if (!std::freopen(log.c_str(), "w", stdout))
          _exit(127);
        // one open file for both: with two, a later write to stdout would
        // overwrite what stderr appended (the error message)
        dup2(fileno(stdout), fileno(stderr));
        std::vector<char *> argv;
        for (auto &a : args)
          argv.push_back(a.data());
        argv.push_back(nullptr);
        execv(argv[0], argv.data());
        std::_Exit(127);
      }
    return pid;
  }

  /// What watch_lines saw of a child.
  struct Watched
  {
    unsigned int lines  = 0;
    bool         ended  = false;
    int          status = 0; ///< the child's wait status if it ended
  };

  /// Wait until the file @p file the child @p pid writes holds @p lines lines,
  /// or the child ends.
  inline Watched
  watch_lines(const pid_t pid, const std::filesystem::path &file, const unsigned int lines)
  {
    Watched w;
    while (w.lines < lines && !w.ended)
      {
        std::this_thread::sleep_for(std::chrono::microseconds(200));
        if (std::filesystem::exists(file))
          w.lines = count_lines(file);
        w.ended = waitpid(pid, &w.status, WNOHANG) == pid;
      }
    return w;
  }
} // namespace archdam::testing
