#pragma once

#include <archdam/base/input_error.h>
#include <archdam/base/selection.h>
#include <archdam/loads/acceleration_record.h>
#include <archdam/loads/artificial_motion.h>
#include <archdam/loads/record_io.h>
#include <archdam/loads/record_processing.h>

#include <deal.II/base/parameter_handler.h>
#include <deal.II/base/tensor.h>

#include <array>
#include <string>
#include <vector>

/**
 * Ground-motion input: the three-component ground acceleration a_g(t) that
 * drives the dynamic stage (doc/theory/loading-sequence.md §3-§4), each component a recorded
 * accelerogram (record_io.h) or an artificial spectrum-compatible motion
 * (artificial_motion.h), optionally processed (record_processing.h).
 * Components are named by the model axes (doc/theory/conventions.md §3): x stream,
 * y cross-stream, z vertical.
 */
namespace archdam::loads
{
  /// `Source` of a ground-motion component: where its acceleration comes from.
  enum class MotionSource
  {
    file,     ///< the record named by File
    generated ///< an artificial motion (artificial_motion.h)
  };

  /// The names of MotionSource in the case file.
  inline const SelectionNames<MotionSource> &
  motion_source_names()
  {
    static const SelectionNames<MotionSource> names{{"file", MotionSource::file},
                                                    {"generated", MotionSource::generated}};
    return names;
  }

  /// `Format` of a ground-motion component's record file (archdam-motion
  /// --format).
  enum class RecordFormat
  {
    automatic,    ///< AT2 if the name ends in .AT2 (any case), else two-column
    at2,          ///< PEER .AT2 (read_at2)
    two_column,   ///< time and acceleration (read_two_column)
    single_column ///< one acceleration a line, spaced by Time step (read_single_column)
  };

  /// The names of RecordFormat in the case file and on the command line.
  inline const SelectionNames<RecordFormat> &
  record_format_names()
  {
    static const SelectionNames<RecordFormat> names{
      {"auto", RecordFormat::automatic},
      {"AT2", RecordFormat::at2},
      {"two-column", RecordFormat::two_column},
      {"single-column", RecordFormat::single_column}};
    return names;
  }

  /**
   * The format named @p name ("auto", "AT2", "two-column" or
   * "single-column"), for text that no parameter pattern has checked
   * (archdam-motion --format); InputError starting with @p context for any
   * other text.
   */
  RecordFormat
  record_format(const std::string &name, const std::string &context);

  /// "Ground motion, Component x, file 'NAME': ", the start of the messages
  /// about the record file @p filename of component @p d (0 = x, 1 = y,
  /// 2 = z).
  std::string
  record_file_context(const unsigned int d, const std::string &filename);

  /**
   * The "Ground motion" parameters: per axis a record file or a generated
   * motion, with optional processing; and the description of the generated
   * motions, shared by the axes.
   */
  struct GroundMotionParameters
  {
    struct Component
    {
      MotionSource source = MotionSource::file;
      /// Record file; "" means this component is zero (Source = file).
      std::string file;
      RecordFormat format = RecordFormat::automatic;
      /// Text files only; AT2 files are in g.
      RecordUnits units = RecordUnits::g;
      /// Sample spacing of a single-column file, s.
      double time_step = 0.;
      /// Dimensionless factor applied to the record; negative flips it.
      double scale = 1.0;
      /// Optional processing, after the scale factor.
      ProcessingParameters processing;
    };

    /// Components along x (stream), y (cross-stream), z (vertical).
    std::array<Component, 3> components;

    /// What a component with Source = generated is.
    ArtificialMotionParameters generated;

    /// The largest peak ground acceleration a component may have, in g, as
    /// read, scaled and processed: above it the record is refused as a
    /// units error (cm/s^2 read as g is 981 times too strong); 0 = no limit.
    double largest_pga = 5.;

    /**
     * Declare, in the current subsection of @p prm, the subsections
     * "Component x", "Component y", "Component z", each with "Source",
     * "File", "Format", "Units", "Time step", "Scale factor" and a
     * subsection "Processing" (ProcessingParameters), and the subsection
     * "Generated motion" (ArtificialMotionParameters), bound to the members
     * above.
     */
    void
    add_parameters(dealii::ParameterHandler &prm);
  };

  /**
   * The ground acceleration a_g(t) = (a_x, a_y, a_z) in m/s^2, read from the
   * files named in GroundMotionParameters or generated, then scaled and
   * processed.
   */
  class GroundMotion
  {
  public:
    /**
     * Read every component that names a file and generate every component
     * with Source = generated; then apply the scale factor and the
     * processing. Relative file names are looked for in @p base_directory
     * (the directory of the prm file; "" means the current working
     * directory), then in the data folder (find_input_file(),
     * base/data_files.h). InputError for every problem, naming the
     * component.
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

    /// The processing applied to component @p d after reading or
    /// generating it, in words (ProcessingParameters::description()); the
    /// same whatever the foundation model.
    const std::string &
    processing(const unsigned int d) const;

    /// How well generated component @p d matches its target; nullptr if it
    /// is not generated.
    const GenerationReport *
    generation_report(const unsigned int d) const;

  private:
    /// One record per axis; a component without a file has no samples.
    std::array<AccelerationRecord, 3> records;
    /// Matching reports of the generated components.
    std::array<GenerationReport, 3> reports;
    std::array<bool, 3>             generated = {{false, false, false}};
    std::array<std::string, 3>      processing_applied;
  };
} // namespace archdam::loads
