#pragma once

#include <deal.II/base/parameter_handler.h>

#include <array>
#include <string>
#include <vector>

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
    /// Points nearer than this to the dam's contact with the rock [m] are
    /// left out (the contact's stresses are singular and grow with the
    /// mesh's refinement).
    double base_band = 0.;
    /// The arch stress of points nearer than this to a contraction joint's
    /// line on the face [m] is measured against the joint's own tensile
    /// strength (Contraction joints/Tensile strength), not the concrete's.
    double joint_band = 0.;
    /// The limits of a linear analysis the verdict reads (with
    /// allowed_cid > 0): the largest DCR, the performance curve's CID at
    /// DCR 1 [s], falling linearly to 0 at allowed_dcr, and the largest
    /// share of a face's area above DCR 1.
    double allowed_dcr                = 2.;
    double allowed_cid                = 0.;
    double allowed_overstressed_share = 0.;

    void
    add_parameters(dealii::ParameterHandler &prm);

    /// InputError for a tensile strength or a level not above zero, or
    /// levels not increasing, when evaluate is set; for a performance curve
    /// without an area limit, or an allowed DCR not above 1.
    void
    check() const;

    /// Whether the verdict is asked for.
    bool
    judges() const
    {
      return evaluate && allowed_cid > 0.;
    }
  };

  /// What the verdict reads of one stress on one face: its largest DCR,
  /// its longest CID above each of the levels, and the share of the face's
  /// area whose largest DCR exceeds 1.
  struct FaceDemand
  {
    double                            largest_dcr = 0.;
    std::array<double, n_dcr_levels> longest_cid{};
    double                            share_above_one = 0.;
  };

  /// The limits of @p e that @p d exceeds, one sentence each (none: the
  /// linear analysis is acceptable for this stress and face): the largest
  /// DCR against allowed_dcr; at each level L in [1, allowed_dcr] the
  /// longest CID against the performance curve allowed_cid (allowed_dcr -
  /// L) / (allowed_dcr - 1); the share above DCR 1 against
  /// allowed_overstressed_share (doc/theory/results.md §3).
  std::vector<std::string>
  exceeded_limits(const FaceDemand &d, const EvaluationParameters &e);

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
