#include <archdam/analysis/analysis_parameters.h>

#include <deal.II/base/utilities.h>

namespace archdam::analysis
{
  using namespace dealii;

  void
  AnalysisParameters::add_parameters(ParameterHandler &prm)
  {
    prm.add_parameter("Case name", case_name,
                      "Name of the case in the summary; empty = the parameter "
                      "file's name without extension.",
                      Patterns::Anything());
    prm.add_parameter("Stages", stages,
                      "Stages to run, in this order: static (gravity), modal "
                      "(natural frequencies and mode shapes, see Modal analysis), "
                      "dynamic (ground motion, starting from the static state).",
                      Patterns::MultipleSelection("static|modal|dynamic"));
  }

  bool
  AnalysisParameters::runs(const std::string &stage) const
  {
    for (const auto &s : Utilities::split_string_list(stages, ','))
      if (s == stage)
        return true;
    return false;
  }
} // namespace archdam::analysis
