#pragma once

#include <archdam/base/types.h>
#include <archdam/physics/foundation/free_field.h>

#include <deal.II/base/tensor.h>
#include <deal.II/grid/tria.h>

#include <vector>

namespace archdam::physics::foundation
{
  /**
   * The reference motion of the dam's mass-proportional damping on massed
   * rock (doc/theory/solid.md §4): the free field's mean over the dam-rock
   * interface, v_r(t) = (1/A) int_interface v_ff(z, t) dA, and its
   * displacement. The dam moving rigidly with it is not damped. The free
   * field depends on z alone, so the interface is kept as the heights of
   * its quadrature points with their area weights.
   */
  class ReferenceMotion
  {
  public:
    /// The faces between dam and rock cells of @p mesh (every cell: the
    /// triangulation is shared), with a 3 x 3 Gauss rule. InputError if
    /// the dam does not touch the rock.
    ReferenceMotion(const FreeField &free_field, const dealii::Triangulation<dim> &mesh);

    dealii::Tensor<1, dim>
    velocity(double t) const;
    dealii::Tensor<1, dim>
    displacement(double t) const;

    /// The interface's area [m^2] and its lowest and highest points [m].
    double area = 0., z_low = 0., z_high = 0.;

  private:
    dealii::Tensor<1, dim>
    mean(double t, dealii::Tensor<1, dim> (FreeField::*of)(double, double) const) const;

    const FreeField &free_field;
    /// (z, area weight / area), one per distinct height.
    std::vector<std::pair<double, double>> points;
  };
} // namespace archdam::physics::foundation
