#include <archdam/base/input_error.h>
#include <archdam/output/atomic_file.h>

#include <hdf5.h>

#include <fcntl.h>
#include <unistd.h>

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <sstream>
#include <vector>

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

  namespace
  {
    /// Close what a failed HDF5 write left open (deal.II's parallel HDF5
    /// writer holds its file and datasets in plain handles): left open, the
    /// HDF5 library would flush them at exit, after MPI has ended, and crash.
    void
    close_hdf5_objects()
    {
      const ssize_t n = H5Fget_obj_count(H5F_OBJ_ALL, H5F_OBJ_ALL);
      if (n <= 0)
        return;
      std::vector<hid_t> ids(n);
      H5Fget_obj_ids(H5F_OBJ_ALL, H5F_OBJ_DATASET | H5F_OBJ_GROUP | H5F_OBJ_DATATYPE |
                                    H5F_OBJ_ATTR,
                     n, ids.data());
      for (const hid_t id : ids)
        if (id > 0 && H5Oclose(id) < 0)
          H5Aclose(id);
      ids.assign(n, 0);
      H5Fget_obj_ids(H5F_OBJ_ALL, H5F_OBJ_FILE, n, ids.data());
      for (const hid_t id : ids)
        if (id > 0)
          H5Fclose(id);
    }

    /// Standard error sent to /dev/null while it lives: the HDF5 and MPI-IO
    /// layers print their own diagnostics of a failed write there, which the
    /// one message of write_hdf5_file() replaces.
    class QuietStandardError
    {
    public:
      QuietStandardError()
        : saved(::dup(STDERR_FILENO))
      {
        std::fflush(stderr);
        const int null = ::open("/dev/null", O_WRONLY);
        if (null >= 0)
          {
            ::dup2(null, STDERR_FILENO);
            ::close(null);
          }
      }
      ~QuietStandardError()
      {
        std::fflush(stderr);
        if (saved >= 0)
          {
            ::dup2(saved, STDERR_FILENO);
            ::close(saved);
          }
      }

    private:
      const int saved;
    };
  } // namespace

  void
  write_hdf5_file(const std::string &filename, const std::function<void()> &write)
  {
    H5Eset_auto2(H5E_DEFAULT, nullptr, nullptr);
    int error = 0;
    {
      const QuietStandardError quiet;
      errno = 0;
      try
        {
          write();
          return;
        }
      catch (const std::exception &)
        {
          error = errno;
          close_hdf5_objects();
        }
    }
    throw InputError(cannot_write(filename, error));
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
