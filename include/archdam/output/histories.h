#pragma once

#include <deal.II/base/mpi.h>

#include <fstream>
#include <string>
#include <vector>

namespace archdam::output
{
  /**
   * Time histories of the monitored quantities. Rank 0 appends one CSV row per
   * step to `histories.csv` in one write and flushes it, so a killed run
   * leaves a valid prefix of complete rows (output/atomic_file.h); at the end
   * the whole table goes to `histories.h5` (written whole, then renamed) as
   * the dataset
   * "histories" (rows = steps) with the column names as the attribute
   * "columns". Every row is also kept in memory for peaks and tests.
   */
  class HistoryWriter
  {
  public:
    HistoryWriter(const std::string &directory, std::vector<std::string> columns,
                  MPI_Comm comm);

    void
    append(const std::vector<double> &row);

    /// Write the HDF5 copy.
    void
    finish();

    const std::vector<std::string> &
    columns() const
    {
      return names;
    }
    const std::vector<std::vector<double>> &
    rows() const
    {
      return table;
    }

    /// The rows so far, for a checkpoint (output/checkpoint.h).
    void
    save(std::ostream &out) const;
    /// Continue after the rows of a checkpoint: histories.csv is written
    /// anew with them (a killed run may have appended rows after the
    /// checkpoint), then append() goes on.
    void
    load(std::istream &in);

  private:
    MPI_Comm                         comm;
    std::string                      directory;
    std::vector<std::string>         names;
    std::ofstream                    csv;
    std::vector<std::vector<double>> table;
  };
} // namespace archdam::output
