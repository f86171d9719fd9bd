#pragma once

#include <deal.II/base/parameter_handler.h>

#include <array>

namespace archdam::output
{
  /// The number of demand-capacity levels a face point keeps a cumulative
  /// duration for.
  constexpr unsigned int n_dcr_levels = 3;

  /**
   * The `Evaluation` section: the demand-capacity evaluation of the dam's
   * faces as USACE EM 1110-2-6053 reads a linear time-history analysis
   * (doc/theory/results.md §3): the demand-capacity ratio DCR = stress /
   * tensile strength of the arch and the cantilever stress (tension
   * positive), and the cumulative inelastic duration CID, the time a
   * point's DCR stays above each of three levels; and the largest
   * compression against the compressive strength.
   */
  struct EvaluationParameters
  {
    bool                              evaluate             = false;
    double                            tensile_strength     = 0.;
    /// 0: no compression check.
    double                            compressive_strength = 0.;
    std::array<double, n_dcr_levels> levels{{1., 1.5, 2.}};

    void
    add_parameters(dealii::ParameterHandler &prm);

    /// InputError for a tensile strength or a level not above zero, or
    /// levels not increasing, when evaluate is set.
    void
    check() const;
  };

  /// One point's demand over the stage for one stress: its largest DCR and,
  /// per level, the cumulative time its DCR exceeded the level.
  struct Exceedance
  {
    double                            largest_dcr = 0.;
    std::array<double, n_dcr_levels> duration{};

    /// The DCR @p dcr held over a step of length @p dt that ends with it
    /// (rectangle rule: a duration is exact to one step).
    void
    add(double dcr, double dt, const std::array<double, n_dcr_levels> &levels);
  };
} // namespace archdam::output
