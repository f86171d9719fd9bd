#include <archdam/base/input_error.h>
#include <archdam/output/face_evaluation.h>

#include <deal.II/base/utilities.h>

#include <algorithm>
#include <iomanip>
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
    prm.add_parameter("Excluded band at the base", base_band,
                      "Face points nearer than this to the dam's contact with the rock [m] are "
                      "left out of the DCR, the CID, the areas and the verdict (the contact's "
                      "stresses are singular: they grow with the mesh's refinement); 0 = none.",
                      Patterns::Double(0.));
    prm.add_parameter("Joint band width", joint_band,
                      "The arch stress of face points nearer than this to a contraction "
                      "joint's line [m] is measured against that joint's own tensile strength "
                      "(Contraction joints/Tensile strength, Per joint), not the concrete's; "
                      "0 = none.",
                      Patterns::Double(0.));
    prm.add_parameter("Allowed DCR", allowed_dcr,
                      "The verdict's largest DCR of a linear analysis (EM 1110-2-6053: 2).",
                      Patterns::Double(0.));
    prm.add_parameter("Allowed CID at DCR 1", allowed_cid,
                      "The performance curve of the verdict: the CID allowed at DCR 1 [s], "
                      "falling linearly to 0 at the Allowed DCR; 0 = no verdict.",
                      Patterns::Double(0.));
    prm.add_parameter("Allowed overstressed share", allowed_overstressed_share,
                      "The verdict's largest share of a face's area whose DCR exceeds 1 (a "
                      "fraction, 0 to 1); needed with a performance curve.",
                      Patterns::Double(0., 1.));
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
    if (allowed_cid > 0.)
      {
        if (!(allowed_dcr > 1.))
          {
            std::ostringstream text;
            text << "Evaluation: the Allowed DCR must be above 1 for the performance curve (it "
                    "falls from Allowed CID at DCR 1 to 0 there), got "
                 << allowed_dcr << ".";
            throw InputError(text.str());
          }
        if (!(allowed_overstressed_share > 0.))
          throw InputError("Evaluation: Allowed CID at DCR 1 asks for the verdict, which also "
                           "needs the Allowed overstressed share (a fraction of a face's area "
                           "above 0).");
      }
  }

  std::vector<std::string>
  exceeded_limits(const FaceDemand &d, const EvaluationParameters &e)
  {
    std::vector<std::string> beyond;
    const auto               text = [](const auto &...parts) {
      std::ostringstream out;
      out << std::setprecision(3);
      (out << ... << parts);
      return out.str();
    };
    if (d.largest_dcr > e.allowed_dcr)
      beyond.push_back(text("largest DCR ", d.largest_dcr, " above ", e.allowed_dcr));
    for (unsigned int i = 0; i < n_dcr_levels; ++i)
      if (e.levels[i] >= 1. && e.levels[i] <= e.allowed_dcr)
        {
          const double allowed =
            e.allowed_cid * (e.allowed_dcr - e.levels[i]) / (e.allowed_dcr - 1.);
          if (d.longest_cid[i] > allowed)
            beyond.push_back(text("CID above DCR ", e.levels[i], " ", d.longest_cid[i],
                                  " s against the curve's ", allowed, " s"));
        }
    if (d.share_above_one > e.allowed_overstressed_share)
      beyond.push_back(text("overstressed share ", d.share_above_one, " of the face above ",
                            e.allowed_overstressed_share));
    return beyond;
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
