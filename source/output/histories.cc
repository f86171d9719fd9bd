#include <archdam/base/binary_io.h>
#include <archdam/base/input_error.h>
#include <archdam/base/on_rank_zero.h>
#include <archdam/output/atomic_file.h>
#include <archdam/output/histories.h>

#include <deal.II/base/hdf5.h>
#include <deal.II/lac/full_matrix.h>

#include <iomanip>
#include <numeric>
#include <sstream>

namespace archdam::output
{
  using namespace dealii;

  HistoryWriter::HistoryWriter(const std::string       &directory,
                               std::vector<std::string> columns,
                               const MPI_Comm           comm)
    : comm(comm)
    , directory(directory)
    , names(std::move(columns))
  {
    on_rank_zero(comm, [&] {
      const std::string file = directory + "/histories.csv";
      csv.open(file);
      if (!csv)
        throw InputError("Output: cannot write '" + file + "'.");
      std::string header;
      for (unsigned int i = 0; i < names.size(); ++i)
        header += (i ? "," : "") + names[i];
      append_line(csv, header + '\n');
    });
  }

  void
  HistoryWriter::append(const std::vector<double> &row)
  {
    table.push_back(row);
    on_rank_zero(comm, [&] {
      std::ostringstream line;
      line << std::setprecision(10);
      for (unsigned int i = 0; i < row.size(); ++i)
        line << (i ? "," : "") << row[i];
      line << '\n';
      append_line(csv, line.str());
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
    std::vector<std::vector<double>> rows;
    binary::read(in, rows);
    if (!rows.empty() && rows.front().size() != names.size())
      throw InputError("Checkpoint: the saved histories have " +
                       std::to_string(rows.front().size()) + " columns, the monitors " +
                       std::to_string(names.size()) + ".");
    AssertThrow(table.empty(), ExcMessage("load() starts a new history"));
    for (const auto &row : rows)
      append(row);
  }

  void
  HistoryWriter::finish()
  {
    if (table.empty())
      return;
    on_rank_zero(comm, [&] {
      FullMatrix<double> data(table.size(), names.size());
      for (unsigned int r = 0; r < table.size(); ++r)
        for (unsigned int c = 0; c < names.size(); ++c)
          data(r, c) = table[r][c];
      const std::string name = directory + "/histories.h5";
      {
        HDF5::File file(temporary_name(name), HDF5::File::FileAccessMode::create);
        auto dataset = file.create_dataset<double>("histories", {table.size(), names.size()});
        dataset.write(data);
        dataset.set_attribute<std::string>(
          "columns", std::accumulate(std::next(names.begin()), names.end(), names.front(),
                                     [](const std::string &a, const std::string &b) {
                                       return a + "," + b;
                                     }));
      }
      commit_temporary(name);
    });
  }
} // namespace archdam::output
