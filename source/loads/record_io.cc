#include <archdam/base/number_text.h>
#include <archdam/loads/record_io.h>

#include <deal.II/base/exceptions.h>

#include <algorithm>
#include <cctype>
#include <cerrno>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <functional>
#include <optional>
#include <sstream>

namespace archdam::loads
{
  namespace
  {
    /// Start of every error message: the file, and the line if there is one.
    std::string
    where(const std::string &filename, const unsigned int line = 0)
    {
      return "Ground-motion file '" + filename + "'" +
             (line > 0 ? ", line " + std::to_string(line) : std::string()) +
             ": ";
    }

    /// Open @p filename for reading, or throw saying why it cannot be read.
    std::ifstream
    open_record(const std::string &filename)
    {
      namespace fs = std::filesystem;
      std::error_code ignored; // the non-throwing overloads: false on error
      if (!fs::exists(filename, ignored))
        throw InputError(where(filename) + "the file does not exist.");
      if (fs::is_directory(filename, ignored))
        throw InputError(where(filename) + "this is a directory, not a file.");
      std::ifstream in(filename);
      if (!in)
        throw InputError(where(filename) + "the file cannot be read.");
      return in;
    }

    void
    check_not_empty(std::istream &in, const std::string &filename)
    {
      if (in.peek() == std::istream::traits_type::eof())
        throw InputError(where(filename) + "the file is empty.");
    }

    /// After the last getline(): a read error must not pass for the end of
    /// the file, which would silently truncate the record.
    void
    check_read_to_end(const std::istream  &in,
                      const std::string   &filename,
                      const unsigned int   lines_read)
    {
      if (in.bad())
        throw InputError(where(filename) + "reading failed after line " +
                         std::to_string(lines_read) + ".");
    }

    /// The blank-separated words of @p line, after turning every character
    /// of @p separators into a blank (tabs and '\r' are blanks already).
    std::vector<std::string>
    split(std::string line, const std::string &separators = "")
    {
      for (char &c : line)
        if (separators.find(c) != std::string::npos)
          c = ' ';
      std::istringstream       words(line);
      std::vector<std::string> result;
      for (std::string word; words >> word;)
        result.push_back(word);
      return result;
    }

    /// Call @p row with the words and the number of each data line of a
    /// text record read from @p in (words separated by commas or blanks;
    /// blank lines and lines starting with '#' skipped). A line with other
    /// than @p columns words is an InputError naming the line, what the
    /// columns hold (@p what) and @p hint; a read error is one too.
    void
    for_each_data_line(
      std::istream &in, const std::string &filename, const unsigned int columns,
      const std::string &what, const std::string &hint,
      const std::function<void(const std::vector<std::string> &, unsigned int)> &row)
    {
      std::string  line;
      unsigned int line_number = 0;
      while (std::getline(in, line))
        {
          ++line_number;
          const std::vector<std::string> words = split(line, ",");
          if (words.empty() || words[0][0] == '#')
            continue;
          if (words.size() != columns)
            throw InputError(where(filename, line_number) + "expected " +
                             std::to_string(columns) + (columns == 1 ? " column (" : " columns (") +
                             what + "), found " + std::to_string(words.size()) + hint + ".");
          row(words, line_number);
        }
      check_read_to_end(in, filename, line_number);
    }

    /// @p word as a finite real number, if all of it is one. strtod reads the
    /// Fortran E format of .AT2 files (".4981725E-02").
    std::optional<double>
    to_real(const std::string &word)
    {
      char        *end = nullptr;
      const double x   = std::strtod(word.c_str(), &end);
      if (word.empty() || *end != '\0' || !std::isfinite(x))
        return std::nullopt;
      return x;
    }

    /// @p word, which must be a number, read from line @p line of @p filename
    /// and multiplied by @p factor (unit conversion and scale factor); the
    /// product must be a finite number too.
    double
    number(const std::string &word,
           const std::string &filename,
           const unsigned int line,
           const double       factor = 1.)
    {
      const std::optional<double> x = to_real(word);
      if (!x)
        throw InputError(where(filename, line) + "'" + word +
                         "' is not a number.");
      if (!std::isfinite(*x * factor))
        throw InputError(where(filename, line) + "'" + word +
                         "' is out of range once converted to m/s^2.");
      return *x * factor;
    }

    /// @p word as an integer, if all of it is one.
    std::optional<long>
    to_integer(const std::string &word)
    {
      char      *end = nullptr;
      const long n   = std::strtol(word.c_str(), &end, 10);
      if (word.empty() || *end != '\0')
        return std::nullopt;
      return n;
    }

    /**
     * NPTS and DT from the 4th line of a PEER .AT2 header. PEER has written
     * it in two ways (both listed in OpenSees' ReadRecord.tcl):
     *   "NPTS=   8773, DT=   .0050 SEC, ..."  NGA, NGA-West2: keyword, value
     *   "  3930 0.00500 NPTS, DT"            the earlier PEER Strong Motion
     *                                        Database: values, then keywords
     */
    std::pair<std::size_t, double>
    read_npts_dt(const std::string &filename, const std::string &line)
    {
      std::string upper = line;
      for (char &c : upper)
        c = static_cast<char>(std::toupper(static_cast<unsigned char>(c)));
      const std::vector<std::string> words = split(upper, ",=");
      const std::size_t              npts_at =
        std::find(words.begin(), words.end(), "NPTS") - words.begin();
      const std::size_t dt_at =
        std::find(words.begin(), words.end(), "DT") - words.begin();

      std::string npts_word, dt_word;
      if (npts_at >= 2 && dt_at == npts_at + 1)
        {
          npts_word = words[npts_at - 2];
          dt_word   = words[npts_at - 1];
        }
      else if (npts_at + 1 < words.size() && dt_at + 1 < words.size())
        {
          npts_word = words[npts_at + 1];
          dt_word   = words[dt_at + 1];
        }

      const std::optional<long>   npts = to_integer(npts_word);
      const std::optional<double> dt   = to_real(dt_word);
      if (!npts || !dt)
        throw InputError(
          where(filename, 4) +
          "the PEER header line does not give NPTS and DT (expected "
          "'NPTS= n, DT= dt SEC' or 'n dt NPTS, DT'), it reads '" +
          line.substr(0, line.find_last_not_of(" \t\r") + 1) + "'.");
      if (*npts < 2)
        throw InputError(where(filename, 4) + "NPTS = " + npts_word +
                         ", but a record needs at least 2 samples.");
      if (*dt <= 0)
        throw InputError(where(filename, 4) + "DT = " + dt_word +
                         " s, but the time step must be positive.");
      return {static_cast<std::size_t>(*npts), *dt};
    }

  } // namespace



  AccelerationRecord
  read_at2(const std::string &filename, const double scale)
  {
    std::ifstream in = open_record(filename);
    return read_at2(in, filename, scale);
  }



  AccelerationRecord
  read_at2(std::istream &in, const std::string &filename, const double scale)
  {
    check_not_empty(in, filename);

    // PEER header: title; event, date, station, component; units; NPTS, DT.
    std::string  line;
    unsigned int line_number = 0;
    while (line_number < 4 && std::getline(in, line))
      ++line_number;
    check_read_to_end(in, filename, line_number);
    if (line_number < 4)
      throw InputError(where(filename) + "the file ends after " +
                       std::to_string(line_number) +
                       " line(s), inside the 4-line PEER header.");
    const auto [npts, dt] = read_npts_dt(filename, line);

    AccelerationRecord record;
    record.source = filename;
    while (std::getline(in, line))
      {
        ++line_number;
        for (const std::string &word : split(line))
          record.values.push_back(
            number(word, filename, line_number, standard_gravity * scale));
      }
    check_read_to_end(in, filename, line_number);
    if (record.values.size() != npts)
      throw InputError(
        where(filename) + "the header gives NPTS = " + std::to_string(npts) +
        ", but " + std::to_string(record.values.size()) + " values follow it.");

    // PEER samples are equally spaced, the first one at t = 0.
    record.times.resize(npts);
    for (std::size_t k = 0; k < npts; ++k)
      record.times[k] = k * dt;
    return record;
  }



  AccelerationRecord
  read_two_column(const std::string &filename,
                  const double       to_si,
                  const double       scale)
  {
    std::ifstream in = open_record(filename);
    return read_two_column(in, filename, to_si, scale);
  }



  AccelerationRecord
  read_two_column(std::istream      &in,
                  const std::string &filename,
                  const double       to_si,
                  const double       scale)
  {
    Assert(to_si > 0, dealii::ExcMessage("The unit factor must be positive."));
    check_not_empty(in, filename);

    AccelerationRecord record;
    record.source = filename;
    for_each_data_line(in, filename, 2, "time, acceleration", "",
                       [&](const std::vector<std::string> &words, const unsigned int line_number) {
                         const double t = number(words[0], filename, line_number);
                         const double a = number(words[1], filename, line_number, to_si * scale);
                         if (!record.times.empty() && t <= record.times.back())
                           throw InputError(where(filename, line_number) + "time " + words[0] +
                                            " s is not later than the time on the previous "
                                            "data line; times must increase strictly.");
                         record.times.push_back(t);
                         record.values.push_back(a);
                       });
    if (record.times.size() < 2)
      throw InputError(where(filename) + "found " +
                       std::to_string(record.times.size()) +
                       " sample(s), but a record needs at least 2.");
    return record;
  }



  AccelerationRecord
  read_single_column(const std::string &filename,
                     const double       dt,
                     const double       to_si,
                     const double       scale)
  {
    std::ifstream in = open_record(filename);
    return read_single_column(in, filename, dt, to_si, scale);
  }



  AccelerationRecord
  read_single_column(std::istream      &in,
                     const std::string &filename,
                     const double       dt,
                     const double       to_si,
                     const double       scale)
  {
    Assert(to_si > 0, dealii::ExcMessage("The unit factor must be positive."));
    if (!(dt > 0) || !std::isfinite(dt))
      throw InputError(where(filename) + "the time step of a single-column "
                       "file must be positive, it is " +
                       number_text(dt) + " s.");
    check_not_empty(in, filename);

    std::vector<double> values;
    for_each_data_line(in, filename, 1, "acceleration",
                       "; a file of time-acceleration pairs needs Format = two-column",
                       [&](const std::vector<std::string> &words, const unsigned int line_number) {
                         values.push_back(
                           number(words[0], filename, line_number, to_si * scale));
                       });
    if (values.size() < 2)
      throw InputError(where(filename) + "found " +
                       std::to_string(values.size()) +
                       " sample(s), but a record needs at least 2.");
    return uniform_record(values, dt, filename);
  }



  double
  unit_in_si(const RecordUnits units)
  {
    switch (units)
      {
        case RecordUnits::g:
          return standard_gravity;
        case RecordUnits::m_per_s2:
          return 1.;
        case RecordUnits::cm_per_s2:
          return 0.01;
      }
    Assert(false, dealii::ExcInternalError());
    return 0.;
  }



  RecordUnits
  record_units(const std::string &name, const std::string &context)
  {
    if (const auto units = selection_value(name, record_units_names()))
      return *units;
    throw InputError(context + "unit '" + name + "' not recognized (use " +
                     selection_choices(record_units_names()) + ").");
  }



  std::ofstream
  open_for_writing(const std::string &filename)
  {
    std::ofstream out(filename);
    if (out)
      return out;
    const int         error  = errno;
    const std::string folder = std::filesystem::path(filename).parent_path().string();
    std::error_code   ec;
    if (!folder.empty() && !std::filesystem::is_directory(folder, ec))
      throw InputError("Cannot write '" + filename + "': its folder '" + folder +
                       "' does not exist.");
    throw InputError("Cannot write '" + filename + "': " + std::strerror(error) + ".");
  }

  void
  write_at2(const std::string        &filename,
            const AccelerationRecord &record,
            const std::string        &title,
            const std::string        &description)
  {
    double dt = 0.;
    if (!record.is_uniform(&dt))
      throw InputError("Cannot write '" + filename +
                       "': an AT2 file needs equally spaced samples; resample "
                       "the record first.");
    if (std::abs(record.times.front()) > 1e-9 * dt)
      throw InputError("Cannot write '" + filename +
                       "': an AT2 record starts at t = 0, this one at t = " +
                       number_text(record.times.front()) +
                       " s; cut a time window first.");
    std::ofstream out = open_for_writing(filename);

    // One header line each, without line breaks that would shift the 4th.
    const auto one_line = [](std::string s) {
      for (char &c : s)
        if (c == '\n' || c == '\r')
          c = ' ';
      return s;
    };
    char npts_dt[100];
    std::snprintf(npts_dt,
                  sizeof(npts_dt),
                  "NPTS=%8zu, DT=%14.10g SEC",
                  record.values.size(),
                  dt);
    out << one_line(title) << "\n"
        << one_line(description) << "\n"
        << "ACCELERATION TIME SERIES IN UNITS OF G\n"
        << npts_dt << "\n";
    char value[32];
    for (std::size_t k = 0; k < record.values.size(); ++k)
      {
        std::snprintf(value,
                      sizeof(value),
                      "%16.7E",
                      record.values[k] / standard_gravity);
        out << value << ((k % 5 == 4 || k + 1 == record.values.size()) ? "\n" : "");
      }
    if (!out)
      throw InputError("Writing '" + filename + "' failed.");
  }



  void
  write_two_column(const std::string        &filename,
                   const AccelerationRecord &record,
                   const std::string        &description)
  {
    std::ofstream out = open_for_writing(filename);
    out << "# " << description << "\n"
        << "# time [s], acceleration [m/s^2]\n";
    char line[64];
    for (std::size_t k = 0; k < record.values.size(); ++k)
      {
        std::snprintf(line,
                      sizeof(line),
                      "%.10g, %.10g\n",
                      record.times[k],
                      record.values[k]);
        out << line;
      }
    if (!out)
      throw InputError("Writing '" + filename + "' failed.");
  }
} // namespace archdam::loads
