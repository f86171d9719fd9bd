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

  /// The rock's damping as the free field sees it (doc/theory/foundation.md
  /// §4): Rayleigh coefficients alpha [1/s] and beta [s], and the band limit
  /// [Hz] above which the deconvolution leaves the damping out.
  struct FreeFieldDamping
  {
    double alpha = 0., beta = 0.;
    double band_limit = 20.;

    /// Whether the free field is that of an undamped half-space.
    bool
    none() const
    {
      return alpha == 0. && beta == 0.;
    }
  };

  /**
   * The free field of a homogeneous half-space for vertically propagating
   * plane waves (doc/theory/foundation.md §4): SV waves for the horizontal components
   * (speed c_s), P waves for the vertical one (speed c_p), the control point
   * on the free surface at z_s, the model bottom at z_b, the depth
   * s = z_s - z.
   *
   * Undamped rock: the incident wave plus its reflection from the free surface,
   *   u_ff(z, t) = 1/2 [u_c(t - T + s/c) + u_c(t - T - s/c)],  T = (z_s - z_b)/c,
   * with u_in = u_c/2 delayed by T: at t = 0 the incident front is at the
   * bottom and the model is at rest, and the free surface moves as the
   * control point, u_ff(z_s, t) = u_c(t - T) (the motion arrives T later).
   *
   * Rock damped as alpha M + beta K (deconvolved, §4): for exp(i w t) the
   * field of the damped half-space whose free surface moves as u_c is
   *   u_ff(s, w) = u_c(w) cos(k s),  k^2 = rho (w^2 - i w alpha) / (G (1 + i w beta))
   * (G the shear or the P-wave modulus), evaluated by the FFT of the control
   * acceleration on levels of depth (an eighth of the shortest wave apart:
   * of the record's Nyquist frequency or of four times the band limit) and cubic
   * Lagrange interpolation between them; the levels' histories are delayed by
   * T rounded up to whole samples, with a margin for the damped waves'
   * precursors, so that the free surface moves as the control point's
   * samples exactly. Above the band limit the damping is left out of k (a
   * cosine taper to twice the limit): there the deconvolution would
   * amplify by about exp(w^2 beta s / (2 c)), and those frequencies reach
   * the surface damped as with the undamped free field.
   */
  class FreeField
  {
  public:
    /// The undamped free field of the motions @p control (today's
    /// d'Alembert form).
    FreeField(const std::array<ControlMotion, dim> &control,
              const solid::ElasticMaterial         &rock,
              double                                z_surface,
              double                                z_bottom);

    /// The free field of the records @p control (an empty record: that
    /// component at rest) in the rock damped by @p damping. InputError if a
    /// record's samples are not equally spaced while the rock is damped.
    FreeField(const std::array<loads::AccelerationRecord, dim> &control,
              const solid::ElasticMaterial                     &rock,
              const FreeFieldDamping                           &damping,
              double                                            z_surface,
              double                                            z_bottom);

    /// The free field of the ground motion, its records as the case
    /// processes them (`Ground motion/Component */Processing`, the same for
    /// every foundation model), in @p rock damped by @p damping.
    static FreeField
    of_ground_motion(const loads::GroundMotion    &motion,
                     const solid::ElasticMaterial &rock,
                     const FreeFieldDamping       &damping,
                     double                        z_surface,
                     double                        z_bottom);

    dealii::Tensor<1, dim>
    displacement(double z, double t) const;
    dealii::Tensor<1, dim>
    velocity(double z, double t) const;
    dealii::Tensor<1, dim>
    acceleration(double z, double t) const;
    /// sigma = lambda tr(eps) I + 2 mu eps with the strains of u_ff(z):
    /// eps_zz = du_z/dz, eps_xz = du_x/dz / 2, eps_yz = du_y/dz / 2; in
    /// damped rock plus beta times the same of the velocity (the rock's
    /// strain-rate stress).
    dealii::SymmetricTensor<2, dim>
    stress(double z, double t) const;

    /// Wave speed of component @p d (c_s for x and y, c_p for z).
    double
    speed(unsigned int d) const
    {
      return c[d];
    }
    /// Time of component @p d from the start of the stage to the control
    /// point's first motion at the surface: the travel time from the bottom
    /// (rounded up to the record's samples, with the precursors' margin, in
    /// damped rock).
    double
    delay(unsigned int d) const
    {
      return T[d];
    }
    /// The free surface's and the model bottom's elevations [m].
    double
    surface() const
    {
      return z_s;
    }
    double
    bottom() const
    {
      return z_b;
    }
    /// Whether the free field is deconvolved through damped rock.
    bool
    damped() const
    {
      return !damping.none();
    }

  private:
    /// q = displacement, velocity or acceleration (@p of) of component @p d
    /// at depth s = z_s - @p z (and, with @p slope, its derivative in z).
    double
    value(unsigned int d, double z, double t, double (ControlMotion::*of)(double) const,
          bool slope = false) const;
    dealii::Tensor<1, dim>
    field(double z, double t, double (ControlMotion::*of)(double) const) const;
    /// The stress of the field (@p of: displacement or velocity).
    dealii::SymmetricTensor<2, dim>
    hooke(double z, double t, double (ControlMotion::*of)(double) const) const;

    /// Undamped: the control motions.
    std::array<ControlMotion, dim> control;
    /// Damped: per component the histories at the depths j h[d].
    std::array<std::vector<ControlMotion>, dim> levels;
    std::array<double, dim>                     h{};
    solid::ElasticMaterial                      rock;
    FreeFieldDamping                            damping;
    std::array<double, dim>                     c, T;
    double                                      z_s, z_b;
  };
} // namespace archdam::physics::foundation
