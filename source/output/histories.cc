#include <archdam/base/input_error.h>
#include <archdam/output/histories.h>

#include <deal.II/base/hdf5.h>
#include <deal.II/lac/full_matrix.h>

#include <iomanip>
#include <numeric>

namespace archdam::output
{
  using namespace dealii;

  HistoryWriter::HistoryWriter(const std::string       &directory,
                               std::vector<std::string> columns,
                               const MPI_Comm           comm)
    : directory(directory)
    , names(std::move(columns))
    , writer(Utilities::MPI::this_mpi_process(comm) == 0)
  {
    if (!writer)
      return;
    const std::string file = directory + "/histories.csv";
    csv.open(file);
    if (!csv)
      throw InputError("Output: cannot write '" + file + "'.");
    for (unsigned int i = 0; i < names.size(); ++i)
      csv << (i ? "," : "") << names[i];
    csv << '\n' << std::setprecision(10);
    csv.flush();
  }

  void
  HistoryWriter::append(const std::vector<double> &row)
  {
    table.push_back(row);
    if (!writer)
      return;
    for (unsigned int i = 0; i < row.size(); ++i)
      csv << (i ? "," : "") << row[i];
    csv << '\n';
    csv.flush();
  }

  void
  HistoryWriter::finish()
  {
    if (!writer || table.empty())
      return;
    FullMatrix<double> data(table.size(), names.size());
    for (unsigned int r = 0; r < table.size(); ++r)
      for (unsigned int c = 0; c < names.size(); ++c)
        data(r, c) = table[r][c];
    HDF5::File    file(directory + "/histories.h5", HDF5::File::FileAccessMode::create);
    auto          dataset = file.create_dataset<double>("histories", {table.size(), names.size()});
    dataset.write(data);
    dataset.set_attribute<std::string>(
      "columns", std::accumulate(std::next(names.begin()), names.end(), names.front(),
                                 [](const std::string &a, const std::string &b) {
                                   return a + "," + b;
                                 }));
  }
} // namespace archdam::output
