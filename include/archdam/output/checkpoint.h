#pragma once

#include <deal.II/base/mpi.h>
#include <deal.II/base/parameter_handler.h>

#include <cstdint>
#include <string>

namespace archdam::output
{
  /// Checkpoints of the dynamic stage (prm section `Checkpoints`).
  struct CheckpointParameters
  {
    /// Every this many steps; 0 = not by steps.
    unsigned int interval = 0;
    /// Every this many seconds of wall time; 0 = not by wall time.
    double wall_interval = 900.;

    void
    add_parameters(dealii::ParameterHandler &prm);
    /// InputError for a negative wall-time interval.
    void
    check() const;
  };

  /// What a checkpoint is of: written by rank 0 as `manifest.txt`.
  struct CheckpointManifest
  {
    unsigned int n_ranks = 0;
    unsigned int step    = 0;
    double       time    = 0.;
    /// Case::fingerprint of the case that wrote it.
    std::string case_fingerprint;
  };

  /**
   * The checkpoint files of a run in `Output/Directory/checkpoint/`: one
   * binary file per rank, `rank_NNNN.bin`, a header (magic, format version,
   * number of ranks, rank, step, payload size, FNV-1a checksum of the
   * payload) and the payload (the state the classes save, base/binary_io.h),
   * and the manifest. A new checkpoint is written into `checkpoint.tmp/`,
   * every file flushed to disk (fsync), the manifest last; then the previous
   * one is renamed to `checkpoint.old/`, the new one to `checkpoint/`, and
   * only then the old one removed: a run killed at any moment leaves a
   * complete checkpoint (`checkpoint/`, or `checkpoint.old/` if it fell
   * between the two renames), and read() finds it.
   */
  class CheckpointFiles
  {
  public:
    CheckpointFiles(const std::string &output_directory, MPI_Comm comm);

    /// Write this rank's @p payload and (rank 0) @p manifest. Collective.
    void
    write(const CheckpointManifest &manifest, const std::string &payload) const;

    /// The manifest of the newest complete checkpoint; InputError if there is
    /// none, if another number of ranks wrote it or if @p case_fingerprint
    /// differs. Collective.
    CheckpointManifest
    read_manifest(const std::string &case_fingerprint) const;

    /// This rank's payload of the newest complete checkpoint, checked against
    /// its header (size, checksum, ranks, step); InputError if damaged.
    std::string
    read_payload(const CheckpointManifest &manifest) const;

    /// The directory of the newest complete checkpoint ("" if none).
    std::string
    newest() const;

  private:
    std::string  directory;
    MPI_Comm     comm;
    unsigned int rank, n_ranks;
  };

  /// FNV-1a 64-bit hash of @p bytes.
  std::uint64_t
  fnv1a(const std::string &bytes);
} // namespace archdam::output
