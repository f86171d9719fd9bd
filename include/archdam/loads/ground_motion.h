#pragma once

#include <archdam/base/input_error.h>

#include <deal.II/base/parameter_handler.h>
#include <deal.II/base/tensor.h>

#include <array>
#include <string>
#include <vector>

/**
 * Ground-motion input: readers for recorded accelerograms and the three-
 * component ground acceleration a_g(t) that drives the dynamic stage
 * (numerics.md §6). Components are named by the model axes (architecture.md
 * §3): x stream, y cross-stream, z vertical.
 */
namespace archdam::loads
{
  /**
   * A sampled acceleration history in m/s^2 (SI, architecture.md §3).
   */
  struct AccelerationRecord
  {
    /// The file it came from, as it was given to the reader.
    std::string source;
    /// Sample times in s, strictly increasing; times[0] may be > 0.
    std::vector<double> times;
    /// Accelerations at the sample times, in m/s^2.
    std::vector<double> values;

    /**
     * Piecewise-linear interpolation between samples. Before times.front()
     * and after times.back() the ground is at rest: the value is 0.
     */
    double
    value(const double t) const;

    /// End of the record, times.back(), in s.
    double
    duration() const;

    /// Peak absolute value, max |value|, in m/s^2.
    double
    peak() const;
  };

  /**
   * Read a PEER NGA .AT2 file (accelerations in g, converted with the
   * standard gravity g = 9.80665 m/s^2): 4 header lines, the 4th giving NPTS
   * and DT either as "NPTS=  4000, DT=   .0050 SEC" (NGA, NGA-West2) or as
   * "4000    .0050    NPTS, DT" (the earlier PEER Strong Motion Database),
   * then NPTS values in rows of any width. Sample k is at time k*DT.
   * The values are multiplied by @p scale.
   *
   * Throws InputError naming the file (and line) for every malformed input.
   */
  AccelerationRecord
  read_at2(const std::string &filename, const double scale = 1.0);

  /**
   * Read a two-column text file "time acceleration", columns separated by
   * commas, tabs or blanks; blank lines and lines starting with '#' are
   * skipped. Accelerations are multiplied by @p to_si (the size of the file's
   * unit in m/s^2, e.g. 0.01 for cm/s^2) and by @p scale.
   *
   * Throws InputError naming the file (and line) for every malformed input.
   */
  AccelerationRecord
  read_two_column(const std::string &filename,
                  const double       to_si,
                  const double       scale = 1.0);

  /**
   * The "Ground motion" parameters: one record file per axis.
   */
  struct GroundMotionParameters
  {
    struct Component
    {
      /// Record file; "" means this component is zero.
      std::string file;
      /// auto | AT2 | two-column (auto: .at2/.AT2 extension means AT2,
      /// anything else two-column).
      std::string format = "auto";
      /// g | m/s^2 | cm/s^2 (two-column files only; AT2 files are in g).
      std::string units = "g";
      /// Dimensionless factor applied to the record; negative flips it.
      double scale = 1.0;
    };

    /// Components along x (stream), y (cross-stream), z (vertical).
    std::array<Component, 3> components;

    /**
     * Declare, in the current subsection of @p prm, the subsections
     * "Component x", "Component y", "Component z", each with "File",
     * "Format", "Units" and "Scale factor", bound to the members above.
     */
    void
    add_parameters(dealii::ParameterHandler &prm);
  };

  /**
   * The ground acceleration a_g(t) = (a_x, a_y, a_z) in m/s^2, read from the
   * files named in GroundMotionParameters.
   */
  class GroundMotion
  {
  public:
    /**
     * Read every component that names a file. Relative file names are
     * resolved against @p base_directory (the directory of the prm file);
     * "" means the current working directory.
     */
    GroundMotion(const GroundMotionParameters &p,
                 const std::string            &base_directory);

    /// Ground acceleration at time @p t, components x, y, z, in m/s^2.
    dealii::Tensor<1, 3>
    acceleration(const double t) const;

    /// Whether component @p d (0 = x, 1 = y, 2 = z) was given a record.
    bool
    has_component(const unsigned int d) const;

    /// Whether no component at all was given.
    bool
    empty() const;

    /// End of the longest component in s; 0 if empty().
    double
    duration() const;

    /// The record of component @p d; requires has_component(d).
    const AccelerationRecord &
    record(const unsigned int d) const;

  private:
    /// One record per axis; a component without a file has no samples.
    std::array<AccelerationRecord, 3> records;
  };
} // namespace archdam::loads
