#pragma once

// The settings of the stages themselves (the sections `Analysis` and `Modal
// analysis`): in the parameters module, below the analysis that runs them
// (doc/theory/conventions.md §2).

#include <deal.II/base/parameter_handler.h>

#include <string>

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
} // namespace archdam::analysis
