#pragma once

#include <archdam/base/input_error.h>
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
  /**
   * The "Ground motion" parameters: per axis a record file or a generated
   * motion, with optional processing; and the description of the generated
   * motions, shared by the axes.
   */
  struct GroundMotionParameters
  {
    struct Component
    {
      /// file | generated.
      std::string source = "file";
      /// Record file; "" means this component is zero (Source = file).
      std::string file;
      /// auto | AT2 | two-column | single-column (auto: .at2/.AT2 extension
      /// means AT2, anything else two-column).
      std::string format = "auto";
      /// g | m/s^2 | cm/s^2 (text files only; AT2 files are in g).
      std::string units = "g";
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
  };
} // namespace archdam::loads
