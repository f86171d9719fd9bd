#pragma once

#include <archdam/base/types.h>
#include <archdam/loads/acceleration_record.h>
#include <archdam/loads/ground_motion.h>
#include <archdam/physics/solid/materials.h>

#include <deal.II/base/symmetric_tensor.h>
#include <deal.II/base/tensor.h>

#include <array>
#include <vector>

namespace archdam::physics::foundation
{
  /**
   * One component of the motion of the control point on the free surface:
   * the acceleration is linear between the samples of its record (as
   * everywhere in ArchDam, acceleration_record.h), velocity and displacement
   * are its exact integrals (loads::integrate), so the three are consistent at
   * every time. At rest before the record; after it the acceleration is zero.
   * A default-constructed motion is zero.
   */
  class ControlMotion
  {
  public:
    ControlMotion() = default;
    explicit ControlMotion(const loads::AccelerationRecord &record);

    double
    acceleration(double t) const;
    double
    velocity(double t) const;
    double
    displacement(double t) const;

  private:
    /// Index k of the sample interval [t_k, t_k+1) holding t; requires
    /// t_0 <= t < t_end.
    unsigned int
    interval(double t) const;

    std::vector<double> t, a, v, d;
  };

  /**
   * The free field of a homogeneous half-space for vertically propagating
   * plane waves (doc/theory/foundation.md §4): SV waves for the horizontal components
   * (speed c_s), P waves for the vertical one (speed c_p). With the free
   * surface at z_s, the model bottom at z_b and the depth s = z_s - z,
   *   u_ff(z, t) = 1/2 [u_c(t - T + s/c) + u_c(t - T - s/c)],  T = (z_s - z_b)/c,
   * the incident wave u_in(t - (z - z_b)/c) plus its reflection from the free
   * surface, with u_in = u_c/2 delayed by T: at t = 0 the incident front is at
   * the bottom and the model is at rest, and the free surface moves as the
   * control point, u_ff(z_s, t) = u_c(t - T) (the motion arrives T later).
   */
  class FreeField
  {
  public:
    FreeField(const std::array<ControlMotion, dim> &control,
              const solid::ElasticMaterial         &rock,
              double                                z_surface,
              double                                z_bottom);

    /// The free field of the ground motion (each component baseline
    /// corrected, loads::baseline_correction) on @p rock.
    static FreeField
    of_ground_motion(const loads::GroundMotion    &motion,
                     const solid::ElasticMaterial &rock,
                     double                        z_surface,
                     double                        z_bottom);

    dealii::Tensor<1, dim>
    displacement(double z, double t) const;
    dealii::Tensor<1, dim>
    velocity(double z, double t) const;
    dealii::Tensor<1, dim>
    acceleration(double z, double t) const;
    /// sigma = lambda tr(eps) I + 2 mu eps with the strains of u_ff(z):
    /// eps_zz = du_z/dz, eps_xz = du_x/dz / 2, eps_yz = du_y/dz / 2.
    dealii::SymmetricTensor<2, dim>
    stress(double z, double t) const;

    /// Wave speed of component @p d (c_s for x and y, c_p for z).
    double
    speed(unsigned int d) const
    {
      return c[d];
    }
    /// Travel time T of component @p d from the bottom to the surface.
    double
    delay(unsigned int d) const
    {
      return (z_s - z_b) / c[d];
    }

  private:
    /// 1/2 [q(t1) + q(t2)] for q = the control motion's displacement,
    /// velocity or acceleration (@p of).
    dealii::Tensor<1, dim>
    incident_plus_reflected(double z, double t, double (ControlMotion::*of)(double) const) const;

    std::array<ControlMotion, dim> control;
    solid::ElasticMaterial         rock;
    std::array<double, dim>        c;
    double                         z_s, z_b;
  };
} // namespace archdam::physics::foundation
