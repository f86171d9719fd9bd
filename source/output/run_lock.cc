#include <archdam/base/input_error.h>
#include <archdam/base/on_rank_zero.h>
#include <archdam/output/run_lock.h>

#include <fcntl.h>
#include <sys/file.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>
#include <ctime>
#include <filesystem>
#include <string>

namespace archdam::output
{
  RunLock::RunLock(const std::string &directory, const std::string &case_name, const MPI_Comm comm)
  {
    on_rank_zero(comm, [&] {
      std::error_code ec;
      std::filesystem::create_directories(directory, ec);
      if (ec)
        throw InputError("Output/Directory: cannot create '" + directory + "': " + ec.message() +
                         ".");
      const std::string name = directory + "/.archdam.lock";
      fd                     = ::open(name.c_str(), O_RDWR | O_CREAT | O_CLOEXEC, 0644);
      if (fd < 0)
        throw InputError("Output/Directory: cannot create '" + name + "': " +
                         std::strerror(errno) + ".");
      if (::flock(fd, LOCK_EX | LOCK_NB) != 0)
        {
          char          text[512] = {};
          const ssize_t n         = ::pread(fd, text, sizeof text - 1, 0);
          ::close(fd);
          fd = -1;
          std::string holder = n > 0 ? std::string(text, n) : "another run";
          while (!holder.empty() && holder.back() == '\n')
            holder.pop_back();
          throw InputError("Output/Directory '" + directory + "' is in use by " + holder +
                           "; two runs in one directory would mix their results: wait "
                           "for it to end, or choose another Output/Directory.");
        }
      char host[256] = "unknown host";
      ::gethostname(host, sizeof host - 1);
      const std::time_t now = std::time(nullptr);
      char              started[32];
      std::strftime(started, sizeof started, "%Y-%m-%d %H:%M:%S", std::localtime(&now));
      const std::string holder = "the run of case '" + case_name + "' (process " +
                                 std::to_string(::getpid()) + " on " + host + ", started " +
                                 started + ")\n";
      if (::ftruncate(fd, 0) != 0 ||
          ::pwrite(fd, holder.data(), holder.size(), 0) != static_cast<ssize_t>(holder.size()))
        throw InputError("Output/Directory: cannot write '" + name + "': " +
                         std::strerror(errno) + ".");
    });
  }

  RunLock::~RunLock()
  {
    if (fd >= 0)
      ::close(fd);
  }
} // namespace archdam::output
