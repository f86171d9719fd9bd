#pragma once

#include <archdam/fe/fe_space.h>
#include <archdam/physics/solid/materials.h>
#include <archdam/physics/solid/thermal.h>

#include <deal.II/base/point.h>
#include <deal.II/base/tensor.h>

#include <functional>
#include <iosfwd>

namespace archdam::analysis
{
  /**
   * The loads on the dam of the static stage and what holds it, as resultant
   * forces [N] and moments [N m] (doc/theory/loading-sequence.md §1): the
   * first check an engineer makes of a model. The dam is a free body loaded
   * by its weight and the water on its wetted face and held by its support,
   * the rock through the faces they share (or the fixed truncation where the
   * dam stands on it, no rock meshed); the joints are inside it and cancel.
   *
   * The support's force is computed twice:
   *  - the reactions, as commercial codes report them: the residual of the
   *    dam's own equations, r = int B^T sigma dV - f (f its weight and its
   *    water), summed over the nodes on the support. Every other node is in
   *    equilibrium to the solver's precision, so the reactions balance the
   *    loads to round-off (a direct solve) or to the relaxation's tolerance:
   *    their out of balance is the static solution's equilibrium error;
   *  - int sigma n dA over the support's faces, from the stress at the
   *    faces' quadrature points: zero out of balance only for an exact
   *    stress, so its out of balance measures the stress's discretization
   *    error, which falls with the mesh.
   * Moments are taken about the centroid of the support's faces.
   */
  struct StaticResultants
  {
    dealii::Tensor<1, dim> weight, water, reaction, support_stress;
    dealii::Tensor<1, dim> weight_moment, water_moment, reaction_moment;
    dealii::Point<dim>     centroid;

    /// |weight + water + reaction| / (|weight| + |water|).
    double
    out_of_balance() const;
    /// |weight + water + support_stress| / (|weight| + |water|).
    double
    stress_out_of_balance() const;

    /// Above this the reactions' out of balance is warned about: far above
    /// the round-off of a direct solve (1e-12) and a hundred times the
    /// dynamic relaxation's default tolerance.
    static constexpr double warning_threshold = 1e-4;

    /// Lines for the run's log, in MN and MN m.
    void
    print(std::ostream &out) const;
  };

  /**
   * The resultants of the dam for the ghosted displacement @p u under the
   * body force @p gravity (m/s^2 on the dam's density) and the water pressure
   * @p pressure(z) on the wetted dam faces (0 without water), the stress
   * C (eps - alpha dT I) with the dam's temperature change @p temperature
   * (whose load is self-equilibrated: it adds no resultant). Collective.
   */
  StaticResultants
  static_resultants(const fe::FESpace                        &space,
                    const physics::solid::MaterialParameters &materials,
                    const physics::solid::TemperatureField   &temperature,
                    const Vector                             &u,
                    const dealii::Tensor<1, dim>             &gravity,
                    const std::function<double(double)>      &pressure);
} // namespace archdam::analysis
