#include <archdam/base/input_error.h>
#include <archdam/base/number_text.h>
#include <archdam/loads/response_spectrum.h>

#include <deal.II/base/exceptions.h>

#include <algorithm>
#include <cmath>
#include <sstream>
#include <string>

namespace archdam::loads
{
  namespace
  {
    /**
     * One step of length h of the Nigam-Jennings recurrence (BSSA 1969,
     * eq. 23-26, written for the load -a_g):
     *   [u1]   [a11 a12] [u0]   [b11 b12] [a_g0]
     *   [v1] = [a21 a22] [v0] + [b21 b22] [a_g1]
     * exact for a_g linear over the step, 0 <= zeta < 1.
     */
    struct NigamJenningsStep
    {
      double a11, a12, a21, a22, b11, b12, b21, b22;

      NigamJenningsStep(const double omega, const double zeta, const double h)
      {
        const double s1  = std::sqrt(1. - zeta * zeta);
        const double wd  = omega * s1;
        const double E   = std::exp(-zeta * omega * h);
        const double S   = std::sin(wd * h);
        const double C   = std::cos(wd * h);
        const double w2  = omega * omega;
        const double w3h = w2 * omega * h;

        a11 = E * (zeta / s1 * S + C);
        a12 = E * S / wd;
        a21 = -omega / s1 * E * S;
        a22 = E * (C - zeta / s1 * S);

        const double p = (2. * zeta * zeta - 1.) / (w2 * h);
        const double q = 2. * zeta / w3h;
        b11 = E * ((p + zeta / omega) * S / wd + (q + 1. / w2) * C) - q;
        b12 = -E * (p * S / wd + q * C) - 1. / w2 + q;
        b21 = E * ((p + zeta / omega) * (C - zeta / s1 * S) -
                   (q + 1. / w2) * (wd * S + zeta * omega * C)) +
              1. / (w2 * h);
        b22 = -E * (p * (C - zeta / s1 * S) - q * (wd * S + zeta * omega * C)) -
              1. / (w2 * h);
      }

      void
      advance(double &u, double &v, const double ag0, const double ag1) const
      {
        const double u1 = a11 * u + a12 * v + b11 * ag0 + b12 * ag1;
        const double v1 = a21 * u + a22 * v + b21 * ag0 + b22 * ag1;
        u               = u1;
        v               = v1;
      }
    };

    void
    check_oscillator(const double period, const double damping)
    {
      if (!(period > 0) || !std::isfinite(period))
        throw InputError("Response spectrum: the period must be positive, "
                         "it is " +
                         number_text(period) + " s.");
      if (!(damping >= 0 && damping < 1))
        throw InputError("Response spectrum: the damping ratio must be at "
                         "least 0 and below 1, it is " +
                         number_text(damping) + ".");
    }

    void
    check_record(const AccelerationRecord &record)
    {
      if (record.times.size() < 2 || record.values.size() != record.times.size())
        throw InputError("Response spectrum: the record '" + record.source +
                         "' needs at least 2 samples.");
    }

    /**
     * Largest |u| on the cubic Hermite interpolant of (u0, v0), (u1, v1) over
     * a sub-step of length h in which the velocity changes sign. With
     * s = tau/h, h du/dtau = A s^2 + B s + C (from the derivatives of the
     * Hermite basis functions); its root in (0, 1) is the extremum.
     */
    double
    hermite_extremum(const double u0,
                     const double v0,
                     const double u1,
                     const double v1,
                     const double h)
    {
      const double A = 6. * (u0 - u1) + 3. * h * (v0 + v1);
      const double B = 6. * (u1 - u0) - h * (4. * v0 + 2. * v1);
      const double C = h * v0;
      // A root in (0, 1) exists: the quadratic is h v0 at s = 0 and h v1 at
      // s = 1, of opposite signs. Bisection would do; this is the stable
      // quadratic formula, checked against the bracket.
      double s = 0.5;
      if (std::abs(A) < 1e-14 * (std::abs(B) + std::abs(C)))
        s = -C / B;
      else
        {
          const double disc = std::max(0., B * B - 4. * A * C);
          const double qq   = -0.5 * (B + std::copysign(std::sqrt(disc), B));
          const double r1   = qq / A;
          const double r2   = (qq != 0.) ? C / qq : r1;
          s                 = (r1 >= 0. && r1 <= 1.) ? r1 : r2;
        }
      s              = std::clamp(s, 0., 1.);
      const double s2 = s * s, s3 = s2 * s;
      const double u  = (2. * s3 - 3. * s2 + 1.) * u0 +
                       (s3 - 2. * s2 + s) * h * v0 + (-2. * s3 + 3. * s2) * u1 +
                       (s3 - s2) * h * v1;
      return std::abs(u);
    }

    /**
     * Largest |u(t)|, t >= 0, of the damped free vibration from (u0, v0):
     * u' = e^{-zeta omega t} (v0 cos wd t - (omega^2 u0 + zeta omega v0)/wd
     * sin wd t) vanishes first at wd t1 = pi/2 - phi (mod pi),
     * phi = atan2(omega^2 u0 + zeta omega v0, wd v0); later extrema are
     * smaller by e^{-zeta omega pi / wd} each.
     */
    double
    free_vibration_peak(const double u0,
                        const double v0,
                        const double omega,
                        const double zeta)
    {
      const double wd = omega * std::sqrt(1. - zeta * zeta);
      const double p  = wd * v0;
      const double q  = omega * omega * u0 + zeta * omega * v0;
      if (p == 0. && q == 0.)
        return std::abs(u0);
      double theta = 0.5 * M_PI - std::atan2(q, p);
      theta        = std::fmod(theta, M_PI);
      if (theta <= 0.)
        theta += M_PI;
      const double t = theta / wd;
      const double u =
        std::exp(-zeta * omega * t) *
        (u0 * std::cos(wd * t) + (v0 + zeta * omega * u0) / wd * std::sin(wd * t));
      return std::max(std::abs(u0), std::abs(u));
    }
  } // namespace



  double
  peak_oscillator_displacement(const AccelerationRecord &record,
                               const double              period,
                               const double              damping,
                               const bool                include_free_vibration)
  {
    check_oscillator(period, damping);
    check_record(record);
    const double omega  = 2. * M_PI / period;
    const double h_max  = period / 20.;
    const auto  &t      = record.times;
    const auto  &ag     = record.values;
    double       dt     = 0.;
    const bool   steady = record.is_uniform(&dt);

    // Coefficients for the current sub-step length, recomputed only when it
    // changes (every step of an irregular record, once for a uniform one).
    double            h_cached = -1.;
    NigamJenningsStep step(omega, damping, dt > 0 ? dt : 1.);

    double u = 0., v = 0., peak = 0.;
    for (std::size_t k = 0; k + 1 < t.size(); ++k)
      {
        const double       interval = steady ? dt : t[k + 1] - t[k];
        const unsigned int m =
          std::max(1u, static_cast<unsigned int>(std::ceil(interval / h_max)));
        const double h = interval / m;
        if (std::abs(h - h_cached) > 1e-12 * h)
          {
            step     = NigamJenningsStep(omega, damping, h);
            h_cached = h;
          }
        for (unsigned int j = 0; j < m; ++j)
          {
            // a_g at the sub-step ends, on the record's linear segment.
            const double a0 = ag[k] + (ag[k + 1] - ag[k]) * j / m;
            const double a1 = ag[k] + (ag[k + 1] - ag[k]) * (j + 1) / m;
            const double u0 = u, v0 = v;
            step.advance(u, v, a0, a1);
            peak = std::max(peak, std::abs(u));
            if ((v0 > 0.) != (v > 0.) && v0 != 0.)
              peak = std::max(peak, hermite_extremum(u0, v0, u, v, h));
          }
      }
    if (include_free_vibration)
      {
        // The record ends at its last sample; the ground is at rest after it
        // (AccelerationRecord::value), but a_g jumps from its last value to 0
        // there only if that value is not 0. The jump is a step load on the
        // free oscillator: u'' + ... = 0 from (u, v) is the motion after it.
        peak = std::max(peak, free_vibration_peak(u, v, omega, damping));
      }
    return peak;
  }



  ResponseSpectrum
  response_spectrum(const AccelerationRecord  &record,
                    const std::vector<double> &periods,
                    const double               damping,
                    const bool                 include_free_vibration)
  {
    ResponseSpectrum spectrum;
    spectrum.damping = damping;
    spectrum.periods = periods;
    for (const double T : periods)
      {
        const double sd = peak_oscillator_displacement(record,
                                                       T,
                                                       damping,
                                                       include_free_vibration);
        const double omega = 2. * M_PI / T;
        spectrum.displacement.push_back(sd);
        spectrum.pseudo_velocity.push_back(omega * sd);
        spectrum.pseudo_acceleration.push_back(omega * omega * sd);
      }
    return spectrum;
  }



  void
  oscillator_response(const AccelerationRecord &record,
                      const double              period,
                      const double              damping,
                      std::vector<double>      &displacement,
                      std::vector<double>      &velocity)
  {
    check_oscillator(period, damping);
    check_record(record);
    const double omega = 2. * M_PI / period;
    const auto  &t     = record.times;
    const auto  &ag    = record.values;
    displacement.assign(t.size(), 0.);
    velocity.assign(t.size(), 0.);
    double u = 0., v = 0.;
    for (std::size_t k = 0; k + 1 < t.size(); ++k)
      {
        const NigamJenningsStep step(omega, damping, t[k + 1] - t[k]);
        step.advance(u, v, ag[k], ag[k + 1]);
        displacement[k + 1] = u;
        velocity[k + 1]     = v;
      }
  }



  std::vector<double>
  log_spaced_periods(const double t_min, const double t_max, const unsigned int n)
  {
    Assert(t_min > 0 && t_max >= t_min && n > 0,
           dealii::ExcMessage("Need 0 < t_min <= t_max and n > 0."));
    std::vector<double> periods(n);
    for (unsigned int i = 0; i < n; ++i)
      periods[i] =
        (n == 1) ? t_min : t_min * std::pow(t_max / t_min, double(i) / (n - 1));
    return periods;
  }
} // namespace archdam::loads
