#include <archdam/base/binary_io.h>
#include <archdam/base/input_error.h>
#include <archdam/base/on_rank_zero.h>
#include <archdam/output/checkpoint.h>

#include <deal.II/base/utilities.h>

#include <fcntl.h>
#include <unistd.h>

#include <cstring>
#include <filesystem>
#include <fstream>
#include <iomanip>
#include <sstream>

namespace archdam::output
{
  using namespace dealii;
  namespace fs = std::filesystem;

  namespace
  {
    constexpr char          magic[8] = {'A', 'R', 'C', 'H', 'C', 'K', 'P', 'T'};
    // 5: the joints' recorder keeps each pair's peak slip (a checkpoint of
    // version 4 would be read out of step); 6: the stress envelope's points
    // keep their arch capacity and whether the evaluation counts them; 7:
    // the energy balance keeps the last step's increment, whose damping work
    // it adds one step late
    constexpr std::uint32_t format_version = 7;

    struct Header
    {
      char          magic[8];
      std::uint32_t version, n_ranks, rank, step;
      std::uint64_t payload_size, checksum;
    };

    /// Write @p bytes to @p name and flush them to disk.
    void
    write_synced(const std::string &name, const std::string &bytes)
    {
      const int fd = ::open(name.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
      bool      ok = fd >= 0;
      for (std::size_t done = 0; ok && done < bytes.size();)
        {
          const ssize_t n = ::write(fd, bytes.data() + done, bytes.size() - done);
          ok              = n > 0;
          done += ok ? n : 0;
        }
      ok = ok && ::fsync(fd) == 0;
      if (fd >= 0)
        ok = ::close(fd) == 0 && ok;
      if (!ok)
        throw InputError("Checkpoints: cannot write '" + name + "' (" + std::strerror(errno) +
                         "; disk full?).");
    }

    void
    sync_directory(const std::string &name)
    {
      const int fd = ::open(name.c_str(), O_RDONLY | O_DIRECTORY);
      if (fd >= 0)
        {
          ::fsync(fd);
          ::close(fd);
        }
    }

    std::string
    rank_file(const std::string &dir, const unsigned int rank)
    {
      return dir + "/rank_" + Utilities::int_to_string(rank, 4) + ".bin";
    }
  } // namespace

  void
  CheckpointParameters::add_parameters(ParameterHandler &prm)
  {
    prm.add_parameter("Interval (steps)", interval,
                      "Write a checkpoint of the dynamic stage every this many time steps; "
                      "0 = not by steps. `archdam CASE.prm --resume` continues from the "
                      "newest one.",
                      Patterns::Integer(0));
    prm.add_parameter("Wall-time interval (s)", wall_interval,
                      "Write a checkpoint of the dynamic stage when this many seconds of "
                      "wall time have passed since the last one (or the start of the "
                      "stage); 0 = not by wall time.",
                      Patterns::Double());
  }

  void
  CheckpointParameters::check() const
  {
    if (!(wall_interval >= 0.))
      {
        std::ostringstream value;
        value << wall_interval;
        throw InputError("Checkpoints/Wall-time interval (s) = " + value.str() +
                         ": must be 0 (off) or positive.");
      }
  }

  std::uint64_t
  fnv1a(const std::string &bytes)
  {
    std::uint64_t h = 14695981039346656037ull;
    for (const unsigned char c : bytes)
      h = (h ^ c) * 1099511628211ull;
    return h;
  }

  CheckpointFiles::CheckpointFiles(const std::string &output_directory, const MPI_Comm comm)
    : directory(output_directory)
    , comm(comm)
    , rank(Utilities::MPI::this_mpi_process(comm))
    , n_ranks(Utilities::MPI::n_mpi_processes(comm))
  {}

  void
  CheckpointFiles::write(const CheckpointManifest &manifest, const std::string &payload) const
  {
    const std::string current = directory + "/checkpoint", fresh = current + ".tmp",
                      old = current + ".old";
    on_rank_zero(comm, [&] {
      std::error_code ec;
      fs::remove_all(fresh, ec);
      fs::create_directories(fresh, ec);
      if (ec)
        throw InputError("Checkpoints: cannot create '" + fresh + "': " + ec.message() + ".");
    });

    Header header;
    std::memcpy(header.magic, magic, sizeof(magic));
    header.version      = format_version;
    header.n_ranks      = n_ranks;
    header.rank         = rank;
    header.step         = manifest.step;
    header.payload_size = payload.size();
    header.checksum     = fnv1a(payload);
    std::string problem;
    try
      {
        write_synced(rank_file(fresh, rank),
                     std::string(reinterpret_cast<const char *>(&header), sizeof(header)) +
                       payload);
      }
    catch (const InputError &e)
      {
        problem = e.what();
      }
    // every rank's file is on disk before the manifest makes the checkpoint complete
    for (const auto &p : Utilities::MPI::all_gather(comm, problem))
      if (!p.empty())
        throw InputError(p);

    on_rank_zero(comm, [&] {
      std::ostringstream m;
      m << std::setprecision(17) << "format version = " << format_version
        << "\nranks = " << manifest.n_ranks << "\nstep = " << manifest.step
        << "\ntime = " << manifest.time << "\ncase fingerprint = " << manifest.case_fingerprint
        << "\n";
      write_synced(fresh + "/manifest.txt", m.str());
      sync_directory(fresh);
      // The newest complete checkpoint stays until the next one has taken
      // its name: checkpoint/ becomes checkpoint.old/ (an older .old goes
      // first), and a lone checkpoint.old/ stays until fresh is in place.
      std::error_code ec;
      if (fs::exists(current, ec))
        {
          fs::remove_all(old, ec);
          fs::rename(current, old, ec);
        }
      if (!ec)
        fs::rename(fresh, current, ec);
      if (ec)
        throw InputError("Checkpoints: cannot rename '" + fresh + "' to '" + current +
                         "': " + ec.message() + ".");
      sync_directory(directory);
      fs::remove_all(old, ec);
    });
  }

  std::string
  CheckpointFiles::newest() const
  {
    for (const std::string &dir : {directory + "/checkpoint", directory + "/checkpoint.old"})
      if (fs::exists(dir + "/manifest.txt"))
        return dir;
    return "";
  }

  CheckpointManifest
  CheckpointFiles::read_manifest(const std::string &case_fingerprint) const
  {
    CheckpointManifest manifest;
    on_rank_zero(comm, [&] {
      const std::string dir = newest();
      if (dir.empty())
        throw InputError("--resume: there is no checkpoint in '" + directory +
                         "/checkpoint' (a run writes checkpoints when Checkpoints/Interval "
                         "(steps) or Wall-time interval (s) is set, during its dynamic "
                         "stage).");
      std::ifstream in(dir + "/manifest.txt");
      unsigned int  version = 0;
      for (std::string line; std::getline(in, line);)
        {
          const auto eq = line.find(" = ");
          if (eq == std::string::npos)
            continue;
          const std::string key = line.substr(0, eq), value = line.substr(eq + 3);
          try
            {
              if (key == "format version")
                version = std::stoul(value);
              else if (key == "ranks")
                manifest.n_ranks = std::stoul(value);
              else if (key == "step")
                manifest.step = std::stoul(value);
              else if (key == "time")
                manifest.time = std::stod(value);
              else if (key == "case fingerprint")
                manifest.case_fingerprint = value;
            }
          catch (const std::exception &)
            {
              throw InputError("--resume: '" + dir + "/manifest.txt' is damaged (" + key + ").");
            }
        }
      if (version != format_version || manifest.n_ranks == 0)
        throw InputError("--resume: '" + dir + "/manifest.txt' is damaged or of another "
                         "format version (" + std::to_string(version) + ", expected " +
                         std::to_string(format_version) + ").");
      if (manifest.n_ranks != n_ranks)
        throw InputError("--resume: the checkpoint in '" + dir + "' was written by " +
                         std::to_string(manifest.n_ranks) + " MPI processes, this run has " +
                         std::to_string(n_ranks) + "; resume with mpirun -np " +
                         std::to_string(manifest.n_ranks) + ".");
      if (manifest.case_fingerprint != case_fingerprint)
        throw InputError("--resume: the case differs from the one that wrote the checkpoint "
                         "in '" + dir + "' (every parameter outside the sections Output and "
                         "Checkpoints must stay the same to continue a run).");
    });
    manifest.n_ranks          = Utilities::MPI::broadcast(comm, manifest.n_ranks, 0);
    manifest.step             = Utilities::MPI::broadcast(comm, manifest.step, 0);
    manifest.time             = Utilities::MPI::broadcast(comm, manifest.time, 0);
    manifest.case_fingerprint = Utilities::MPI::broadcast(comm, manifest.case_fingerprint, 0);
    return manifest;
  }

  std::string
  CheckpointFiles::read_payload(const CheckpointManifest &manifest) const
  {
    std::string problem, payload;
    const std::string dir  = Utilities::MPI::broadcast(comm, newest(), 0);
    const std::string name = rank_file(dir, rank);
    {
      std::ifstream in(name, std::ios::binary);
      const std::string bytes((std::istreambuf_iterator<char>(in)),
                              std::istreambuf_iterator<char>());
      Header header;
      if (!in.is_open())
        problem = "is missing";
      else if (bytes.size() < sizeof(Header))
        problem = "is truncated (shorter than its header)";
      else
        {
          std::memcpy(&header, bytes.data(), sizeof(Header));
          payload = bytes.substr(sizeof(Header));
          if (std::memcmp(header.magic, magic, sizeof(magic)) != 0 ||
              header.version != format_version)
            problem = "is not a checkpoint file of this format version";
          else if (payload.size() != header.payload_size)
            problem = "is truncated or extended (its size does not match its header)";
          else if (fnv1a(payload) != header.checksum)
            problem = "is damaged (checksum mismatch)";
          else if (header.n_ranks != manifest.n_ranks || header.rank != rank ||
                   header.step != manifest.step)
            problem = "belongs to another checkpoint (ranks, rank or step differ from the "
                      "manifest)";
        }
    }
    if (!problem.empty())
      problem = "--resume: the checkpoint file '" + name + "' " + problem + ".";
    for (const auto &p : Utilities::MPI::all_gather(comm, problem))
      if (!p.empty())
        throw InputError(p);
    return payload;
  }
} // namespace archdam::output
