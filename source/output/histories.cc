#include <archdam/base/binary_io.h>
#include <archdam/base/input_error.h>
#include <archdam/base/on_rank_zero.h>
#include <archdam/output/atomic_file.h>
#include <archdam/output/histories.h>

#include <deal.II/base/hdf5.h>
#include <deal.II/lac/full_matrix.h>

#include <cerrno>
#include <iomanip>
#include <numeric>
#include <sstream>

namespace archdam::output
{
  using namespace dealii;

  HistoryWriter::HistoryWriter(std::string file, std::vector<std::string> columns,
                               const MPI_Comm comm)
    : comm(comm)
    , file(std::move(file))
    , names(std::move(columns))
  {}

  namespace
  {
    std::string
    csv_line(const std::vector<std::string> &names)
    {
      std::string line;
      for (unsigned int i = 0; i < names.size(); ++i)
        line += (i ? "," : "") + names[i];
      return line + '\n';
    }

    std::string
    csv_line(const std::vector<double> &row)
    {
      std::ostringstream line;
      line << std::setprecision(10);
      for (unsigned int i = 0; i < row.size(); ++i)
        line << (i ? "," : "") << row[i];
      line << '\n';
      return line.str();
    }
  } // namespace

  void
  HistoryWriter::append(const std::vector<double> &row)
  {
    table.push_back(row);
    on_rank_zero(comm, [&] {
      if (csv.is_open())
        append_line(csv, file, csv_line(row));
      else
        {
          errno = 0;
          csv.open(file);
          if (!csv)
            throw InputError(cannot_write(file, errno));
          append_line(csv, file, csv_line(names) + csv_line(row));
        }
    });
  }

  void
  HistoryWriter::save(std::ostream &out) const
  {
    binary::write(out, table);
  }

  void
  HistoryWriter::load(std::istream &in)
  {
    AssertThrow(table.empty(), ExcMessage("load() starts a new history"));
    binary::read(in, table);
    if (!table.empty() && table.front().size() != names.size())
      throw InputError("Checkpoint: the saved rows of '" + file + "' have " +
                       std::to_string(table.front().size()) + " columns, this case " +
                       std::to_string(names.size()) + ".");
  }

  void
  HistoryWriter::rewrite()
  {
    on_rank_zero(comm, [&] {
      csv.close();
      write_atomically(file, [&](std::ostream &out) {
        out << csv_line(names);
        for (const auto &row : table)
          out << csv_line(row);
      });
      errno = 0;
      csv.open(file, std::ios::app);
      if (!csv)
        throw InputError(cannot_write(file, errno));
    });
  }

  void
  HistoryWriter::write_hdf5(const std::string &hdf5_file) const
  {
    if (table.empty())
      return;
    on_rank_zero(comm, [&] {
      FullMatrix<double> data(table.size(), names.size());
      for (unsigned int r = 0; r < table.size(); ++r)
        for (unsigned int c = 0; c < names.size(); ++c)
          data(r, c) = table[r][c];
      write_hdf5_file(temporary_name(hdf5_file), 8. * table.size() * names.size(), MPI_COMM_SELF,
                      [&] {
        HDF5::File h5(temporary_name(hdf5_file), HDF5::File::FileAccessMode::create);
        auto dataset = h5.create_dataset<double>("histories", {table.size(), names.size()});
        dataset.write(data);
        dataset.set_attribute<std::string>(
          "columns", std::accumulate(std::next(names.begin()), names.end(), names.front(),
                                     [](const std::string &a, const std::string &b) {
                                       return a + "," + b;
                                     }));
      });
      commit_temporary(hdf5_file);
    });
  }
} // namespace archdam::output
