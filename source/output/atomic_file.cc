#include <archdam/base/input_error.h>
#include <archdam/output/atomic_file.h>

#include <cstdio>
#include <sstream>

namespace archdam::output
{
  void
  write_atomically(const std::string &filename, const std::function<void(std::ostream &)> &write)
  {
    // Formatted in memory first: the temporary file is written in one go.
    std::ostringstream text;
    write(text);
    {
      std::ofstream file(temporary_name(filename));
      file << text.str();
      file.flush();
      if (!file)
        throw InputError("Output: cannot write '" + temporary_name(filename) + "'.");
    }
    commit_temporary(filename);
  }

  void
  commit_temporary(const std::string &filename)
  {
    if (std::rename(temporary_name(filename).c_str(), filename.c_str()) != 0)
      throw InputError("Output: cannot rename '" + temporary_name(filename) + "' to '" +
                       filename + "'.");
  }

  void
  append_line(std::ofstream &file, const std::string &line)
  {
    file.write(line.data(), static_cast<std::streamsize>(line.size()));
    file.flush();
    if (!file)
      throw InputError("Output: cannot append to a history file (disk full?).");
  }
} // namespace archdam::output
