#pragma once

#include <archdam/parameters/analysis_parameters.h>
#include <archdam/fe/fe_space.h>
#include <archdam/geometry/mesh.h>
#include <archdam/joints/joint_parameters.h>
#include <archdam/loads/ground_motion.h>
#include <archdam/loads/static_loads.h>
#include <archdam/output/checkpoint.h>
#include <archdam/output/face_evaluation.h>
#include <archdam/output/field_writer.h>
#include <archdam/output/monitors.h>
#include <archdam/physics/foundation/foundation.h>
#include <archdam/physics/reservoir/reservoir_parameters.h>
#include <archdam/physics/solid/damping.h>
#include <archdam/physics/solid/materials.h>
#include <archdam/time/newmark.h>

#include <deal.II/base/parameter_handler.h>

#include <iosfwd>
#include <string>
#include <vector>

namespace archdam
{
  /**
   * All parameters of a case (doc/theory/conventions.md §7). Nothing global lives here:
   * each module declares its own subsection and binds it to its own struct;
   * this only aggregates them.
   */
  struct Parameters
  {
    geometry::MeshParameters                 mesh;
    fe::FiniteElementParameters              finite_element;
    physics::solid::MaterialParameters       materials;
    physics::solid::DampingParameters        damping;
    time::NewmarkParameters                  time_integration;
    physics::foundation::FoundationParameters foundation;
    joints::JointParameters                  joints;
    physics::reservoir::ReservoirParameters  reservoir;
    loads::GroundMotionParameters            ground_motion;
    loads::StaticLoadParameters              static_loads;
    analysis::AnalysisParameters             analysis;
    analysis::ModalParameters                modal;
    analysis::RecordSuiteParameters          suite;
    output::MonitorParameters                monitors;
    output::OutputParameters                 output;
    output::CheckpointParameters             checkpoints;
    output::EvaluationParameters             evaluation;

    /// A hash of every parameter value outside the sections Output and
    /// Checkpoints: a checkpoint continues only the case that wrote it.
    std::string fingerprint;

    /// Directory of the parameter file: relative file names in it are
    /// resolved against it.
    std::string base_directory;

    /// What in the case file looks like a mistake but does not stop the run
    /// (an entry set twice in one section): one sentence each, said before
    /// the run starts.
    std::vector<std::string> warnings;

    void
    add_parameters(dealii::ParameterHandler &prm);
  };

  /**
   * Read a case: the parameter file, then the overrides
   * "Section/Subsection/Name=value" in order. Every problem (missing file,
   * unknown section or parameter, value not matching its pattern, malformed
   * override) is an InputError naming the file, line and parameter.
   */
  Parameters
  read_parameters(const std::string &filename, const std::vector<std::string> &overrides);

  /// Read a case from a string (tests and examples).
  Parameters
  parameters_from_string(const std::string &text);

  /// Every parameter with its default, allowed values and documentation;
  /// format "text" (a commented parameter file), "json", "xml" or "latex".
  void
  print_parameters(std::ostream &out, const std::string &format);
} // namespace archdam
