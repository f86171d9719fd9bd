#include <archdam/base/input_error.h>
#include <archdam/output/atomic_file.h>

#include <deal.II/base/mpi.h>

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

    /// 0 if @p bytes can be written to @p filename (a write of its first
    /// bytes succeeds and its folder has room for all of them), else the
    /// errno that says why not.
    int
    room_for(const std::string &filename, const double bytes)
    {
      errno        = 0;
      const int fd = ::open(filename.c_str(), O_WRONLY | O_CREAT | O_TRUNC | O_CLOEXEC, 0644);
      if (fd < 0)
        return errno;
      const char probe[4096] = {};
      const bool written     = ::write(fd, probe, sizeof probe) == ssize_t(sizeof probe) &&
                           ::fsync(fd) == 0;
      const int  error = written ? 0 : (errno != 0 ? errno : ENOSPC);
      ::close(fd);
      if (error != 0)
        return error;
      std::error_code ec;
      const auto      folder = std::filesystem::path(filename).parent_path();
      const auto      space  = std::filesystem::space(folder.empty() ? "." : folder, ec);
      return (!ec && double(space.available) < 1.05 * bytes + 65536) ? ENOSPC : 0;
    }
  } // namespace

  void
  write_hdf5_file(const std::string &filename, const double bytes, const MPI_Comm comm,
                  const std::function<void()> &write)
  {
    // The HDF5 library cannot be left safely after a write that failed half
    // way (a file whose flush fails stays open and crashes the library when
    // it ends), so the room is checked first, by rank 0 for all.
    int error = dealii::Utilities::MPI::this_mpi_process(comm) == 0 ? room_for(filename, bytes) : 0;
    error     = dealii::Utilities::MPI::broadcast(comm, error, 0);
    if (error != 0)
      throw InputError(cannot_write(filename, error));
    H5Eset_auto2(H5E_DEFAULT, nullptr, nullptr);
    const QuietStandardError quiet;
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
