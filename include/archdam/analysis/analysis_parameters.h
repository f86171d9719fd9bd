#pragma once

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
} // namespace archdam::analysis
