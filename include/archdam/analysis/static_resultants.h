#pragma once

#include <archdam/fe/fe_space.h>
#include <archdam/physics/solid/materials.h>

#include <deal.II/base/tensor.h>

#include <functional>
#include <iosfwd>

namespace archdam::analysis
{
  /**
   * The loads on the dam of the static stage and what holds it, as resultant
   * forces [N] (doc/theory/loading-sequence.md §1): the first check an
   * engineer makes of a model. The dam is a free body loaded by its weight
   * and the water on its wetted face and held by its support, the rock
   * through the faces they share (or the fixed truncation where the dam
   * stands on it, no rock meshed); the joints are inside it and cancel. The
   * support's force is integrated from the recovered stress, int sigma n dA
   * over those faces (n out of the dam), not taken from the loads, so the
   * sum weight + water + support is the model's own out-of-balance: zero for
   * an exact stress, small and falling with the mesh otherwise.
   */
  struct StaticResultants
  {
    dealii::Tensor<1, dim> weight, water, support;

    /// |weight + water + support| / (|weight| + |water|).
    double
    out_of_balance() const;

    /// Lines for the run's log, in MN.
    void
    print(std::ostream &out) const;
  };

  /**
   * The resultants of the dam for the ghosted displacement @p u under the
   * body force @p gravity (m/s^2 on the dam's density) and the water pressure
   * @p pressure(z) on the wetted dam faces (0 without water). Collective.
   */
  StaticResultants
  static_resultants(const fe::FESpace                        &space,
                    const physics::solid::MaterialParameters &materials,
                    const Vector                             &u,
                    const dealii::Tensor<1, dim>             &gravity,
                    const std::function<double(double)>      &pressure);
} // namespace archdam::analysis
