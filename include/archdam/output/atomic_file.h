#pragma once

#include <deal.II/base/mpi.h>

#include <functional>
#include <fstream>
#include <ostream>
#include <string>

namespace archdam::output
{
  /**
   * Result files that a killed run cannot leave half written. A whole file is
   * written to `NAME.tmp` and renamed to NAME (rename is atomic on POSIX file
   * systems): a reader sees the previous complete version or the new one,
   * never a mixture. A history grows by whole lines: each row is formatted
   * first and handed to the file in one write, then flushed, so a run killed
   * at any moment leaves a valid prefix of complete rows.
   *
   * The writers keep no other state than what they have written, so that a
   * restart can reopen a history for appending after its last complete row.
   */

  /// Write @p filename with @p write, atomically. Throws InputError if the
  /// file cannot be written or renamed.
  void
  write_atomically(const std::string &filename, const std::function<void(std::ostream &)> &write);

  /// Rename @p filename.tmp, which a writer without a stream (HDF5) has
  /// completed, to @p filename.
  void
  commit_temporary(const std::string &filename);

  /// The name write_atomically() and commit_temporary() write first.
  inline std::string
  temporary_name(const std::string &filename)
  {
    return filename + ".tmp";
  }

  /// Append @p line (ending in '\n') to @p file, named @p filename, in one
  /// write and flush it.
  void
  append_line(std::ofstream &file, const std::string &filename, const std::string &line);

  /// The message for a file that cannot be written: its name and the
  /// system's reason, from @p error (an errno value, 0 if unknown) or, when
  /// that is 0, from the free space of its folder.
  std::string
  cannot_write(const std::string &filename, int error);

  /// Run @p write, which writes the HDF5 file @p filename of about @p bytes
  /// on the processes of @p comm, with the HDF5 library's own error stack
  /// kept quiet. Room for the file is checked first (a probe write, the
  /// folder's free space): a file that cannot be written, or a failure of
  /// the write, is one InputError, cannot_write()'s message. Collective.
  void
  write_hdf5_file(const std::string &filename, double bytes, MPI_Comm comm,
                  const std::function<void()> &write);
} // namespace archdam::output
