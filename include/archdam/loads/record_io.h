#pragma once

#include <archdam/base/input_error.h>
#include <archdam/base/selection.h>
#include <archdam/loads/acceleration_record.h>

#include <istream>
#include <fstream>
#include <string>

/**
 * Reading and writing acceleration records: PEER .AT2, two-column text
 * (time, acceleration) and single-column text (acceleration at a given time
 * step). Every reader throws InputError naming the file (and line) for every
 * malformed input.
 */
namespace archdam::loads
{
  /// Standard gravity (3rd CGPM, 1901), the "g" of PEER .AT2 files and of
  /// every acceleration given in g in ArchDam.
  constexpr double standard_gravity = 9.80665;

  /// The unit of the accelerations in a text record (`Units` of a
  /// ground-motion component, ground_motion.h; archdam-motion --units).
  enum class RecordUnits
  {
    g,        ///< standard gravity (standard_gravity)
    m_per_s2, ///< m/s^2
    cm_per_s2 ///< cm/s^2
  };

  /// The names of RecordUnits in the case file and on the command line.
  inline const SelectionNames<RecordUnits> &
  record_units_names()
  {
    static const SelectionNames<RecordUnits> names{{"g", RecordUnits::g},
                                                   {"m/s^2", RecordUnits::m_per_s2},
                                                   {"cm/s^2", RecordUnits::cm_per_s2}};
    return names;
  }

  /**
   * Read a PEER NGA .AT2 file (accelerations in g, converted with the
   * standard gravity g = 9.80665 m/s^2): 4 header lines, the 4th giving NPTS
   * and DT either as "NPTS=  4000, DT=   .0050 SEC" (NGA, NGA-West2) or as
   * "4000    .0050    NPTS, DT" (the earlier PEER Strong Motion Database),
   * then NPTS values in rows of any width. Sample k is at time k*DT.
   * The values are multiplied by @p scale.
   */
  AccelerationRecord
  read_at2(const std::string &filename, const double scale = 1.0);
  /// The same from a stream; @p filename names it in messages.
  AccelerationRecord
  read_at2(std::istream &in, const std::string &filename, const double scale = 1.0);

  /**
   * Read a two-column text file "time acceleration", columns separated by
   * commas, tabs or blanks; blank lines and lines starting with '#' are
   * skipped. Accelerations are multiplied by @p to_si (the size of the file's
   * unit in m/s^2, e.g. 0.01 for cm/s^2) and by @p scale.
   */
  AccelerationRecord
  read_two_column(const std::string &filename,
                  const double       to_si,
                  const double       scale = 1.0);
  /// The same from a stream; @p filename names it in messages.
  AccelerationRecord
  read_two_column(std::istream      &in,
                  const std::string &filename,
                  const double       to_si,
                  const double       scale = 1.0);

  /**
   * Read a single-column text file: one acceleration per line, sample k at
   * time k * @p dt; blank lines and lines starting with '#' are skipped.
   * Accelerations are multiplied by @p to_si and by @p scale. A line with more
   * than one number is an error (it is probably a two-column file).
   */
  AccelerationRecord
  read_single_column(const std::string &filename,
                     const double       dt,
                     const double       to_si,
                     const double       scale = 1.0);
  /// The same from a stream; @p filename names it in messages.
  AccelerationRecord
  read_single_column(std::istream      &in,
                     const std::string &filename,
                     const double       dt,
                     const double       to_si,
                     const double       scale = 1.0);

  /// Size in m/s^2 of the acceleration unit @p units.
  double
  unit_in_si(const RecordUnits units);

  /**
   * The unit named @p name ("g", "m/s^2" or "cm/s^2"), for text that no
   * parameter pattern has checked (archdam-motion --units); InputError
   * starting with @p context for any other text.
   */
  RecordUnits
  record_units(const std::string &name, const std::string &context);

  /// @p filename opened for writing, or InputError saying why it cannot be
  /// (its folder does not exist, or the system's reason).
  std::ofstream
  open_for_writing(const std::string &filename);

  /**
   * Write @p record as a PEER .AT2 file (in g, NPTS and DT on line 4 in the
   * NGA form, 5 values per line in E format with 7 decimals, which read_at2
   * and other PEER readers accept). @p title and @p description fill the
   * first two header lines. The record must be uniformly sampled from t = 0
   * (InputError otherwise: resample it or cut a window first).
   */
  void
  write_at2(const std::string        &filename,
            const AccelerationRecord &record,
            const std::string        &title,
            const std::string        &description);

  /**
   * Write @p record as a two-column CSV file "time [s], acceleration
   * [m/s^2]" after a '#' comment header: read_two_column() (Units m/s^2)
   * reads it back, with 10 significant digits.
   */
  void
  write_two_column(const std::string        &filename,
                   const AccelerationRecord &record,
                   const std::string        &description);
} // namespace archdam::loads
