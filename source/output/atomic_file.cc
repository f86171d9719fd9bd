#include <archdam/base/input_error.h>
#include <archdam/output/atomic_file.h>

#include <hdf5.h>

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <sstream>

namespace archdam::output
{
  std::string
  cannot_write(const std::string &filename, const int error)
  {
    // A file system that is full may report the failure late (at close) or
    // through a library that loses errno: its free space tells.
    std::error_code ec;
    const auto      folder = std::filesystem::path(filename).parent_path();
    const auto      space  = std::filesystem::space(folder.empty() ? "." : folder, ec);
    const std::string reason = (!ec && space.available < 4096) ? std::strerror(ENOSPC) :
                               error != 0                       ? std::strerror(error) :
                                                                  "the system gave no reason";
    return "Output: cannot write '" + filename + "': " + reason + ".";
  }

  void
  write_atomically(const std::string &filename, const std::function<void(std::ostream &)> &write)
  {
    // Formatted in memory first: the temporary file is written in one go.
    std::ostringstream text;
    write(text);
    {
      errno = 0;
      std::ofstream file(temporary_name(filename));
      file << text.str();
      file.flush();
      if (!file)
        throw InputError(cannot_write(temporary_name(filename), errno));
    }
    commit_temporary(filename);
  }

  void
  write_hdf5_file(const std::string &filename, const std::function<void()> &write)
  {
    H5Eset_auto2(H5E_DEFAULT, nullptr, nullptr);
    errno = 0;
    try
      {
        write();
      }
    catch (const std::exception &)
      {
        throw InputError(cannot_write(filename, errno));
      }
  }

  void
  commit_temporary(const std::string &filename)
  {
    if (std::rename(temporary_name(filename).c_str(), filename.c_str()) != 0)
      throw InputError("Output: cannot rename '" + temporary_name(filename) + "' to '" +
                       filename + "': " + std::strerror(errno) + ".");
  }

  void
  append_line(std::ofstream &file, const std::string &filename, const std::string &line)
  {
    errno = 0;
    file.write(line.data(), static_cast<std::streamsize>(line.size()));
    file.flush();
    if (!file)
      throw InputError(cannot_write(filename, errno));
  }
} // namespace archdam::output
