#include <archdam/parameters/analysis_parameters.h>

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

  void
  ModalParameters::add_parameters(ParameterHandler &prm)
  {
    prm.add_parameter("Number of modes", n_modes,
                      "How many of the lowest natural modes the modal stage computes.",
                      Patterns::Integer(1, 1000));
    prm.add_parameter("Tolerance", tolerance,
                      "Relative tolerance of the eigensolver on each eigenpair.",
                      Patterns::Double(1e-15, 1e-3));
    prm.add_parameter("Write mode shapes", write_mode_shapes,
                      "Write the mode shapes to modes.vtu (one displacement field per "
                      "mode) in the output directory.",
                      Patterns::Bool());
  }
} // namespace archdam::analysis
