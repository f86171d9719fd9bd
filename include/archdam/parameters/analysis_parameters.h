#pragma once

// The settings of the stages themselves (the sections `Analysis` and `Modal
// analysis`): in the parameters module, below the analysis that runs them
// (doc/theory/conventions.md §2).

#include <deal.II/base/parameter_handler.h>

#include <array>
#include <string>
#include <vector>

namespace archdam::analysis
{
  /// The `Analysis` subsection: what the run does.
  struct AnalysisParameters
  {
    std::string case_name;
    std::string stages = "static, dynamic";

    void
    add_parameters(dealii::ParameterHandler &prm);

    bool
    runs(const std::string &stage) const;
  };

  /// The `Modal analysis` subsection (doc/theory/loading-sequence.md §2).
  struct ModalParameters
  {
    unsigned int n_modes          = 10;
    double       tolerance        = 1e-10;
    bool         write_mode_shapes = true;

    void
    add_parameters(dealii::ParameterHandler &prm);
  };

  /// One record of a suite: its name and, per direction (x, y, z), the
  /// record file and its scale factor; an empty file: no motion in that
  /// direction.
  struct SuiteRecord
  {
    std::string                name;
    std::array<std::string, 3> file;
    std::array<double, 3>      scale = {{1., 1., 1.}};
  };

  /// The `Record suite` subsection (doc/user-guide.md, "Record suites"): the
  /// same case run under several records, one after another.
  struct RecordSuiteParameters
  {
    std::string records;
    /// Scale each record to the target spectrum (Ground motion/Generated
    /// motion) over [period_min, period_max].
    bool   scale_to_target = false;
    double period_min      = 0.1;
    double period_max      = 1.;

    void
    add_parameters(dealii::ParameterHandler &prm);

    /// The records, parsed from `Records` ("NAME: x = FILE * SCALE, y = ...;
    /// NAME: ..."); empty without a suite. Throws InputError naming the
    /// record and what is wrong with it.
    std::vector<SuiteRecord>
    parse() const;

    /// InputError for a period range that is not 0 < min < max.
    void
    check() const;
  };
} // namespace archdam::analysis
