#pragma once

#include <archdam/base/selection.h>
#include <archdam/base/types.h>
#include <archdam/physics/solid/materials.h>

#include <deal.II/base/parameter_handler.h>

#include <set>
#include <string>

namespace archdam::physics::foundation
{
  /// `Foundation/Model`: whether the rock has inertia.
  enum class Model
  {
    massless, ///< stiffness only, outer boundary fixed, relative formulation
    massed    ///< rock inertia, total motion, plane waves from below
  };

  /// The names of Model in the case file.
  inline const SelectionNames<Model> &
  model_names()
  {
    static const SelectionNames<Model> names{{"massless", Model::massless},
                                             {"massed", Model::massed}};
    return names;
  }

  /// `Foundation/Transmitting boundary`: the outer boundary of the massed
  /// foundation.
  enum class TransmittingBoundary
  {
    mtf,     ///< Liao's multi-transmitting formula (multi_transmitting_boundary.h)
    viscous, ///< Lysmer dashpots (and springs) (viscous_boundary.h)
    fixed    ///< the free-field motion prescribed
  };

  /// The names of TransmittingBoundary in the case file.
  inline const SelectionNames<TransmittingBoundary> &
  transmitting_boundary_names()
  {
    static const SelectionNames<TransmittingBoundary> names{
      {"MTF", TransmittingBoundary::mtf},
      {"viscous", TransmittingBoundary::viscous},
      {"fixed", TransmittingBoundary::fixed}};
    return names;
  }

  /// `Foundation/Free field`: the half-space whose free field the massed
  /// foundation's boundary prescribes (doc/theory/foundation.md §4).
  enum class FreeFieldRock
  {
    damped,  ///< the rock's own Rayleigh damping: the control motion deconvolved
    undamped ///< an undamped half-space (the motion arrives attenuated)
  };

  /// The names of FreeFieldRock in the case file.
  inline const SelectionNames<FreeFieldRock> &
  free_field_rock_names()
  {
    static const SelectionNames<FreeFieldRock> names{
      {"through the damped rock", FreeFieldRock::damped},
      {"undamped", FreeFieldRock::undamped}};
    return names;
  }

  /**
   * The `Foundation` subsection (doc/theory/foundation.md §1).
   *
   * massless: stiffness only, outer boundary (bottom and sides) fixed, the
   * ground acceleration applied uniformly (relative formulation).
   *
   * massed: rock inertia, total-motion formulation, seismic input as
   * vertically propagating plane waves (free_field.h), and on the outer
   * boundary one of
   *  - MTF: Liao's multi-transmitting formula on the scattered motion
   *    (multi_transmitting_boundary.h),
   *  - viscous: Lysmer dashpots (and springs) with equivalent free-field
   *    forces (viscous_boundary.h),
   *  - fixed: the free-field motion prescribed (every outgoing wave reflects).
   */
  struct FoundationParameters
  {
    Model                model                 = Model::massless;
    TransmittingBoundary transmitting_boundary = TransmittingBoundary::mtf;
    unsigned int         mtf_order             = 2;
    /// c_a in m/s; 0 = the rock's wave speed of each component (P for the
    /// component normal to the boundary, S for the tangential ones).
    double artificial_speed = 0.;
    /// Drift stabilization of the MTF as a rate [1/s]: with gamma = rate dt
    /// each j-th term is multiplied by (1 + gamma)^(-j), an artificial decay
    /// of about `rate` per second whatever the step (doc/theory/foundation.md
    /// §6).
    double stabilization_rate = 2.;
    /// R of the viscous-spring boundary in m; 0 = dashpots only.
    double spring_distance = 0.;
    /// The free field's half-space, and the band limit [Hz] of the
    /// deconvolution through the damped rock.
    FreeFieldRock free_field = FreeFieldRock::damped;
    double        band_limit = 20.;

    void
    add_parameters(dealii::ParameterHandler &prm);

    bool
    rock_has_mass() const
    {
      return model == Model::massed;
    }

    /// Whether the outer-boundary displacement is prescribed in the dynamic
    /// stage (massless, or massed with MTF or fixed boundary).
    bool
    prescribes_boundary_motion() const
    {
      return !rock_has_mass() || transmitting_boundary != TransmittingBoundary::viscous;
    }

    /// Boundary ids whose displacement is constrained (fixed in the static
    /// stage; prescribed in the dynamic stage of a massed foundation).
    std::set<dealii::types::boundary_id>
    fixed_boundaries() const;
  };

  /// Shear (S) wave speed sqrt(mu / rho) of a material, m/s.
  double
  shear_wave_speed(const solid::ElasticMaterial &m);

  /// Compression (P) wave speed sqrt((lambda + 2 mu) / rho), m/s.
  double
  pressure_wave_speed(const solid::ElasticMaterial &m);
} // namespace archdam::physics::foundation
