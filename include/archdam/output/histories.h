#pragma once

#include <archdam/output/recorder.h>

#include <deal.II/base/mpi.h>

#include <fstream>
#include <string>
#include <utility>
#include <vector>

namespace archdam::output
{
  /**
   * A table of time histories with its CSV file: the monitors'
   * (`histories.csv`), the joints' and the water pressure's. Rank 0 creates
   * the file with its header at the first row (so that a run stopped before
   * it, or a failed --resume, leaves an earlier file alone), appends every
   * row in one write and flushes it, so a killed run leaves a valid prefix of
   * complete rows (output/atomic_file.h). Every row is also kept in memory
   * for peaks, envelopes, checkpoints and tests. Collective calls.
   */
  class HistoryWriter
  {
  public:
    HistoryWriter(std::string file, std::vector<std::string> columns, MPI_Comm comm);

    void
    append(const std::vector<double> &row);

    /// The whole table as the HDF5 dataset "histories" (rows = steps) with
    /// the column names as its attribute "columns", written whole, then
    /// renamed.
    void
    write_hdf5(const std::string &hdf5_file) const;

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
    /// The rows of a checkpoint, in memory only: the file is left as it is
    /// until rewrite(), once the whole checkpoint has been read.
    void
    load(std::istream &in);
    /// The file anew with the rows in memory (a killed run may have
    /// appended rows after its checkpoint), written whole and renamed; then
    /// append() goes on.
    void
    rewrite();

  private:
    MPI_Comm                         comm;
    std::string                      file;
    std::vector<std::string>         names;
    std::ofstream                    csv;
    std::vector<std::vector<double>> table;
  };

  /// A recorder whose records are one table of histories: the checkpoint
  /// saves and loads the table, a resume writes its file anew.
  class HistoryRecorder : public Recorder
  {
  public:
    const std::vector<std::string> &
    columns() const
    {
      return table.columns();
    }
    const std::vector<std::vector<double>> &
    rows() const
    {
      return table.rows();
    }

    void
    save(std::ostream &out) const override
    {
      table.save(out);
    }
    void
    load(std::istream &in) override
    {
      table.load(in);
    }
    void
    resumed() override
    {
      table.rewrite();
    }

  protected:
    HistoryRecorder(std::string file, std::vector<std::string> columns, MPI_Comm comm)
      : table(std::move(file), std::move(columns), comm)
    {}

    HistoryWriter table;
  };
} // namespace archdam::output
