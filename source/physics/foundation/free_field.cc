#include <archdam/loads/record_processing.h>
#include <archdam/physics/foundation/foundation.h>
#include <archdam/physics/foundation/free_field.h>

#include <algorithm>

namespace archdam::physics::foundation
{
  using namespace dealii;

  ControlMotion::ControlMotion(const loads::AccelerationRecord &record)
  {
    const auto h = loads::integrate(record);
    t            = h.times;
    a            = h.acceleration;
    v            = h.velocity;
    d            = h.displacement;
  }

  unsigned int
  ControlMotion::interval(const double time) const
  {
    const auto it = std::upper_bound(t.begin(), t.end(), time);
    return std::min<unsigned int>(it - t.begin() - 1, t.size() - 2);
  }

  // Between samples a is linear (slope j), so over h = t - t_k
  //   a = a_k + j h,  v = v_k + a_k h + j h^2/2,  d = d_k + v_k h + a_k h^2/2 + j h^3/6.
  double
  ControlMotion::acceleration(const double time) const
  {
    if (t.size() < 2 || time < t.front() || time >= t.back())
      return 0.;
    const unsigned int k = interval(time);
    const double       j = (a[k + 1] - a[k]) / (t[k + 1] - t[k]);
    return a[k] + j * (time - t[k]);
  }

  double
  ControlMotion::velocity(const double time) const
  {
    if (t.size() < 2 || time < t.front())
      return 0.;
    if (time >= t.back())
      return v.back();
    const unsigned int k = interval(time);
    const double       j = (a[k + 1] - a[k]) / (t[k + 1] - t[k]);
    const double       h = time - t[k];
    return v[k] + a[k] * h + j * h * h / 2;
  }

  double
  ControlMotion::displacement(const double time) const
  {
    if (t.size() < 2 || time < t.front())
      return 0.;
    if (time >= t.back())
      return d.back() + v.back() * (time - t.back());
    const unsigned int k = interval(time);
    const double       j = (a[k + 1] - a[k]) / (t[k + 1] - t[k]);
    const double       h = time - t[k];
    return d[k] + v[k] * h + a[k] * h * h / 2 + j * h * h * h / 6;
  }

  FreeField::FreeField(const std::array<ControlMotion, dim> &control,
                       const solid::ElasticMaterial         &rock,
                       const double                          z_surface,
                       const double                          z_bottom)
    : control(control)
    , rock(rock)
    , c{{shear_wave_speed(rock), shear_wave_speed(rock), pressure_wave_speed(rock)}}
    , z_s(z_surface)
    , z_b(z_bottom)
  {}

  FreeField
  FreeField::of_ground_motion(const loads::GroundMotion    &motion,
                              const solid::ElasticMaterial &rock,
                              const double                  z_surface,
                              const double                  z_bottom)
  {
    std::array<ControlMotion, dim> control;
    for (unsigned int d = 0; d < dim; ++d)
      if (motion.has_component(d))
        control[d] = ControlMotion(loads::baseline_correction(motion.record(d)));
    return FreeField(control, rock, z_surface, z_bottom);
  }

  // u_ff = 1/2 [u_c(t1) + u_c(t2)], t1,2 = t - T +- s/c (doc/theory/foundation.md §4), and
  // the same for its time derivatives.
  Tensor<1, dim>
  FreeField::incident_plus_reflected(const double z, const double time,
                                     double (ControlMotion::*of)(double) const) const
  {
    Tensor<1, dim> u;
    for (unsigned int d = 0; d < dim; ++d)
      {
        const double t0 = time - delay(d), ds = (z_s - z) / c[d];
        u[d] = 0.5 * ((control[d].*of)(t0 + ds) + (control[d].*of)(t0 - ds));
      }
    return u;
  }

  Tensor<1, dim>
  FreeField::displacement(const double z, const double time) const
  {
    return incident_plus_reflected(z, time, &ControlMotion::displacement);
  }

  Tensor<1, dim>
  FreeField::velocity(const double z, const double time) const
  {
    return incident_plus_reflected(z, time, &ControlMotion::velocity);
  }

  Tensor<1, dim>
  FreeField::acceleration(const double z, const double time) const
  {
    return incident_plus_reflected(z, time, &ControlMotion::acceleration);
  }

  SymmetricTensor<2, dim>
  FreeField::stress(const double z, const double time) const
  {
    // du/dz = 1/(2c) [v_c(t2) - v_c(t1)] (d s/dz = -1).
    Tensor<1, dim> dudz;
    for (unsigned int d = 0; d < dim; ++d)
      {
        const double t0 = time - delay(d), ds = (z_s - z) / c[d];
        dudz[d] = (control[d].velocity(t0 - ds) - control[d].velocity(t0 + ds)) / (2 * c[d]);
      }
    SymmetricTensor<2, dim> eps;
    eps[2][2] = dudz[2];
    eps[0][2] = dudz[0] / 2;
    eps[1][2] = dudz[1] / 2;
    return rock.stress(eps);
  }
} // namespace archdam::physics::foundation
