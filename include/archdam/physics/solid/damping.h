#pragma once

#include <archdam/base/selection.h>

#include <deal.II/base/parameter_handler.h>
#include <deal.II/base/types.h>

#include <string>
#include <utility>

namespace archdam::physics::solid
{
  /// `Damping/Mode` (and `Damping/Rock/Mode`): how a Rayleigh damping is given.
  enum class DampingMode
  {
    damping_ratio,          ///< zeta at two frequencies
    stiffness_proportional, ///< zeta at one frequency, beta K only
    coefficients,           ///< alpha and beta
    same_as_dam             ///< the rock only: the dam's coefficients
  };

  /// The names of DampingMode in the case file: the dam's choices, and with
  /// @p rock also "same as the dam".
  const SelectionNames<DampingMode> &
  damping_mode_names(bool rock);

  /// `Damping/Mass proportional term`: the velocity the dam's alpha M acts
  /// on when the rock has mass and the unknowns are the total motion
  /// (doc/theory/solid.md §4). Elsewhere (massless rock) the unknowns are
  /// relative to the ground and both are the same.
  enum class MassDamping
  {
    relative, ///< v - v_r, v_r the free field's mean over the dam-rock interface
    total     ///< the total velocity v (ArchDam up to 2026-12)
  };

  /// The names of MassDamping in the case file.
  const SelectionNames<MassDamping> &
  mass_damping_names();

  /**
   * One Rayleigh damping D = alpha M + beta K (doc/theory/solid.md §4), with
   * alpha and beta given directly, derived from a damping ratio zeta reached
   * at two frequencies f1, f2: alpha = 2 zeta w1 w2 / (w1 + w2),
   * beta = 2 zeta / (w1 + w2) (Chopra, Dynamics of Structures, eq. 11.4.9),
   * or stiffness proportional with zeta at f1: alpha = 0, beta = 2 zeta / w1.
   */
  struct RayleighDamping
  {
    DampingMode mode             = DampingMode::damping_ratio;
    double      alpha            = 0.;
    double      beta             = 0.;
    double      ratio            = 0.05;
    double      first_frequency  = 1.;
    double      second_frequency = 10.;

    void
    add_parameters(dealii::ParameterHandler &prm, bool rock);

    /// (alpha [1/s], beta [s]); @p section names it in messages. Not for
    /// Mode = same as the dam.
    std::pair<double, double>
    coefficients(const std::string &section) const;
  };

  /**
   * The `Damping` section: the Rayleigh damping of the dam's concrete (its
   * entries), which is also the rock's unless the subsection `Rock` gives
   * the rock its own (doc/theory/solid.md §4). The damping matrix is
   * assembled cell by cell with the coefficients of each cell's material.
   */
  struct DampingParameters : RayleighDamping
  {
    RayleighDamping rock{DampingMode::same_as_dam};
    /// What the dam's mass term acts on (massed rock).
    MassDamping mass_term = MassDamping::relative;

    void
    add_parameters(dealii::ParameterHandler &prm);

    /// Both coefficient pairs can be formed (an input error names the one that cannot).
    void
    check() const;

    /// The dam's (alpha [1/s], beta [s]).
    std::pair<double, double>
    rayleigh_coefficients() const;

    /// The rock's (alpha [1/s], beta [s]).
    std::pair<double, double>
    rock_coefficients() const;

    /// Dam and rock damped alike: D = alpha M + beta K of the whole model.
    bool
    uniform() const;

    /// The coefficients of a solid cell of material @p id.
    std::pair<double, double>
    of(dealii::types::material_id id) const;
  };
} // namespace archdam::physics::solid
