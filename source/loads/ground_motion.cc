#include <archdam/loads/ground_motion.h>

#include <deal.II/base/exceptions.h>

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <optional>
#include <sstream>

namespace archdam::loads
{
  namespace
  {
    /// Standard gravity (3rd CGPM, 1901), the "g" of PEER .AT2 files.
    constexpr double standard_gravity = 9.80665;

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
      if (in.peek() == std::ifstream::traits_type::eof())
        throw InputError(where(filename) + "the file is empty.");
      return in;
    }

    /// After the last getline(): a read error must not pass for the end of
    /// the file, which would silently truncate the record.
    void
    check_read_to_end(const std::ifstream &in,
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

    /// @p word, which must be a number, read from line @p line of @p filename.
    double
    number(const std::string &word,
           const std::string &filename,
           const unsigned int line)
    {
      const std::optional<double> x = to_real(word);
      if (!x)
        throw InputError(where(filename, line) + "'" + word +
                         "' is not a number.");
      return *x;
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

    /// Size in m/s^2 of the acceleration unit @p units.
    double
    unit_in_si(const std::string &units, const std::string &context)
    {
      if (units == "g")
        return standard_gravity;
      if (units == "m/s^2")
        return 1.;
      if (units == "cm/s^2")
        return 0.01;
      throw InputError(context + "unit '" + units +
                       "' not recognized (use g, m/s^2 or cm/s^2).");
    }

    /// Whether @p filename ends in .at2 in any letter case.
    bool
    has_at2_extension(const std::string &filename)
    {
      std::string extension =
        std::filesystem::path(filename).extension().string();
      for (char &c : extension)
        c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
      return extension == ".at2";
    }
  } // namespace



  double
  AccelerationRecord::value(const double t) const
  {
    Assert(times.size() >= 2 && values.size() == times.size(),
           dealii::ExcMessage("An acceleration record needs at least two "
                              "samples, one value per time."));
    // The ground is at rest before and after the record.
    if (t < times.front() || t > times.back())
      return 0.;
    // k: the first sample after t, searched among times[1 .. n-1] so that
    // t == times.back() falls in the last interval.
    const std::size_t k =
      std::upper_bound(times.begin() + 1, times.end() - 1, t) - times.begin();
    const double w = (t - times[k - 1]) / (times[k] - times[k - 1]);
    // This form returns the samples exactly at w = 0 and w = 1.
    return (1. - w) * values[k - 1] + w * values[k];
  }



  double
  AccelerationRecord::duration() const
  {
    Assert(!times.empty(), dealii::ExcMessage("The record has no samples."));
    return times.back();
  }



  double
  AccelerationRecord::peak() const
  {
    double peak = 0.;
    for (const double a : values)
      peak = std::max(peak, std::abs(a));
    return peak;
  }



  AccelerationRecord
  read_at2(const std::string &filename, const double scale)
  {
    std::ifstream in = open_record(filename);

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
          record.values.push_back(number(word, filename, line_number) *
                                  standard_gravity * scale);
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
    Assert(to_si > 0, dealii::ExcMessage("The unit factor must be positive."));
    std::ifstream in = open_record(filename);

    AccelerationRecord record;
    record.source = filename;
    std::string  line;
    unsigned int line_number = 0;
    while (std::getline(in, line))
      {
        ++line_number;
        const std::vector<std::string> words = split(line, ",");
        if (words.empty() || words[0][0] == '#')
          continue;
        if (words.size() != 2)
          throw InputError(where(filename, line_number) +
                           "expected 2 columns (time, acceleration), found " +
                           std::to_string(words.size()) + ".");
        const double t = number(words[0], filename, line_number);
        const double a = number(words[1], filename, line_number);
        if (!record.times.empty() && t <= record.times.back())
          throw InputError(where(filename, line_number) + "time " + words[0] +
                           " s is not later than the time on the previous "
                           "data line; times must increase strictly.");
        record.times.push_back(t);
        record.values.push_back(a * to_si * scale);
      }
    check_read_to_end(in, filename, line_number);
    if (record.times.size() < 2)
      throw InputError(where(filename) + "found " +
                       std::to_string(record.times.size()) +
                       " sample(s), but a record needs at least 2.");
    return record;
  }



  void
  GroundMotionParameters::add_parameters(dealii::ParameterHandler &prm)
  {
    const std::array<std::string, 3> axis      = {{"x", "y", "z"}};
    const std::array<std::string, 3> direction = {
      {"stream (x)", "cross-stream (y)", "vertical (z)"}};
    for (unsigned int d = 0; d < 3; ++d)
      {
        Component &c = components[d];
        prm.enter_subsection("Component " + axis[d]);
        prm.add_parameter(
          "File",
          c.file,
          "Acceleration record in the " + direction[d] +
            " direction; empty means no ground motion in this direction; "
            "a relative path starts at the folder of this parameter file.",
          dealii::Patterns::FileName(dealii::Patterns::FileName::input));
        prm.add_parameter(
          "Format",
          c.format,
          "File format: AT2 (PEER, in g), two-column (time and acceleration "
          "on each line) or auto (AT2 if the name ends in .AT2).",
          dealii::Patterns::Selection("auto|AT2|two-column"));
        prm.add_parameter(
          "Units",
          c.units,
          "Unit of the accelerations in a two-column file; AT2 files are "
          "always in g.",
          dealii::Patterns::Selection("g|m/s^2|cm/s^2"));
        prm.add_parameter(
          "Scale factor",
          c.scale,
          "Factor applied to the record (dimensionless); a negative value "
          "reverses its direction.",
          dealii::Patterns::Double());
        prm.leave_subsection();
      }
  }



  GroundMotion::GroundMotion(const GroundMotionParameters &p,
                             const std::string            &base_directory)
  {
    namespace fs = std::filesystem;
    for (unsigned int d = 0; d < 3; ++d)
      {
        const GroundMotionParameters::Component &c = p.components[d];
        if (c.file.empty())
          continue;

        const std::string filename =
          (base_directory.empty() || fs::path(c.file).is_absolute()) ?
            c.file :
            (fs::path(base_directory) / c.file).string();
        const std::string context = "Ground motion, Component " +
                                    std::string(1, "xyz"[d]) + ", file '" +
                                    filename + "': ";

        bool at2 = false;
        if (c.format == "auto")
          at2 = has_at2_extension(filename);
        else if (c.format == "AT2")
          at2 = true;
        else if (c.format != "two-column")
          throw InputError(context + "format '" + c.format +
                           "' not recognized (use auto, AT2 or two-column).");

        if (at2)
          {
            // Say so rather than ignore a unit the user believes applies.
            if (c.units != "g")
              throw InputError(context + "Units = " + c.units +
                               ", but AT2 files are always in g.");
            records[d] = read_at2(filename, c.scale);
          }
        else
          records[d] =
            read_two_column(filename, unit_in_si(c.units, context), c.scale);
      }
  }



  dealii::Tensor<1, 3>
  GroundMotion::acceleration(const double t) const
  {
    dealii::Tensor<1, 3> a;
    for (unsigned int d = 0; d < 3; ++d)
      if (has_component(d))
        a[d] = records[d].value(t);
    return a;
  }



  bool
  GroundMotion::has_component(const unsigned int d) const
  {
    AssertIndexRange(d, 3);
    return !records[d].times.empty();
  }



  bool
  GroundMotion::empty() const
  {
    return !has_component(0) && !has_component(1) && !has_component(2);
  }



  double
  GroundMotion::duration() const
  {
    double duration = 0.;
    for (unsigned int d = 0; d < 3; ++d)
      if (has_component(d))
        duration = std::max(duration, records[d].duration());
    return duration;
  }



  const AccelerationRecord &
  GroundMotion::record(const unsigned int d) const
  {
    Assert(has_component(d),
           dealii::ExcMessage("This ground-motion component has no record."));
    return records[d];
  }
} // namespace archdam::loads
