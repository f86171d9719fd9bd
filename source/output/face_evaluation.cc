#include <archdam/base/input_error.h>
#include <archdam/output/face_evaluation.h>

#include <deal.II/base/utilities.h>

#include <algorithm>
#include <sstream>

namespace archdam::output
{
  using namespace dealii;

  void
  EvaluationParameters::add_parameters(ParameterHandler &prm)
  {
    prm.add_parameter("Evaluate", evaluate,
                      "Evaluate the arch and cantilever stresses of the dam's faces as demand-"
                      "capacity ratios DCR = stress / Tensile strength, with the cumulative "
                      "inelastic duration above each DCR level (USACE EM 1110-2-6053; "
                      "doc/theory/results.md §3).");
    prm.add_parameter("Tensile strength", tensile_strength,
                      "The concrete's tensile strength [Pa] the DCR is measured against (the "
                      "dynamic one for the dynamic stage); must be positive with Evaluate = "
                      "true.",
                      Patterns::Double(0.));
    prm.add_parameter("Compressive strength", compressive_strength,
                      "The concrete's compressive strength [Pa]: the largest arch and cantilever "
                      "compression is reported as a ratio to it; 0 = no compression check.",
                      Patterns::Double(0.));
    prm.add_parameter("DCR levels", levels,
                      "Three increasing DCR levels at which the cumulative inelastic duration "
                      "is kept (EM 1110-2-6053 uses 1, 1.5 and 2 for a linear analysis).");
  }

  void
  EvaluationParameters::check() const
  {
    if (!evaluate)
      return;
    if (!(tensile_strength > 0.))
      {
        std::ostringstream text;
        text << "Evaluation: Tensile strength must be positive with Evaluate = true (it is the "
                "capacity of the demand-capacity ratio), got "
             << tensile_strength << " Pa.";
        throw InputError(text.str());
      }
    for (unsigned int i = 0; i < n_dcr_levels; ++i)
      if (!(levels[i] > 0.) || (i > 0 && !(levels[i] > levels[i - 1])))
        {
          std::ostringstream text;
          text << "Evaluation: the DCR levels must be positive and increasing, got "
               << levels[0] << ", " << levels[1] << ", " << levels[2] << ".";
          throw InputError(text.str());
        }
  }

  void
  Exceedance::add(const double dcr, const double dt, const std::array<double, n_dcr_levels> &levels)
  {
    largest_dcr = std::max(largest_dcr, dcr);
    for (unsigned int i = 0; i < n_dcr_levels; ++i)
      if (dcr > levels[i])
        duration[i] += dt;
  }
} // namespace archdam::output
