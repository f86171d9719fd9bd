#pragma once

#include <archdam/loads/acceleration_record.h>

#include <vector>

/**
 * Elastic response spectra of a ground motion.
 *
 * The single-degree-of-freedom oscillator of natural period T = 2 pi / omega
 * and damping ratio zeta, at rest when the record starts, is driven by the
 * ground acceleration a_g(t):
 *
 *   u'' + 2 zeta omega u' + omega^2 u = -a_g(t)          (u relative to ground)
 *
 * Between samples a_g is linear (AccelerationRecord), and for a linear load the
 * state (u, u') at the end of a step is an exact linear function of the state
 * at its start and of the two end values of a_g (Nigam & Jennings 1969,
 * "Calculation of response spectra from strong-motion earthquake records",
 * BSSA 59(2), 909-922): the recurrence has no time-discretisation error at
 * all, for any period and step.
 *
 * Peaks between the computed states: every step longer than T/20 is split
 * into equal sub-steps (still exact, the load is linear in each), and where the
 * velocity changes sign inside a sub-step the extremum is located on the cubic
 * Hermite interpolant of (u, u') at its two ends, whose error is
 * O((omega h)^4) ~ 2.5e-5 |u| at h = T/20. After the record the oscillator
 * keeps vibrating freely; with include_free_vibration the first extremum of
 * that free vibration (the largest, the later ones decay) counts as well.
 *
 * Spectral values: SD = max |u|, PSV = omega SD, PSA = omega^2 SD.
 */
namespace archdam::loads
{
  /// Spectra of one motion at one damping ratio, in SI units.
  struct ResponseSpectrum
  {
    /// Damping ratio zeta (0.05 = 5 %).
    double damping = 0.05;
    /// Periods T in s.
    std::vector<double> periods;
    /// SD(T) = max |u|, in m.
    std::vector<double> displacement;
    /// PSV(T) = omega SD, in m/s.
    std::vector<double> pseudo_velocity;
    /// PSA(T) = omega^2 SD, in m/s^2.
    std::vector<double> pseudo_acceleration;
  };

  /**
   * Peak |u| of the oscillator of period @p period (s, > 0) and damping ratio
   * @p damping (0 <= zeta < 1) under @p record, from rest at the first sample.
   * Throws InputError for a period or damping outside these ranges.
   */
  double
  peak_oscillator_displacement(const AccelerationRecord &record,
                               const double              period,
                               const double              damping,
                               const bool include_free_vibration = true);

  /**
   * Response spectra of @p record at @p periods (each > 0) and damping ratio
   * @p damping (0 <= zeta < 1).
   */
  ResponseSpectrum
  response_spectrum(const AccelerationRecord  &record,
                    const std::vector<double> &periods,
                    const double               damping,
                    const bool                 include_free_vibration = true);

  /**
   * The oscillator's relative displacement u and velocity u' at the record's
   * sample times (the states of the Nigam-Jennings recurrence, without
   * sub-steps), starting from rest.
   */
  void
  oscillator_response(const AccelerationRecord &record,
                      const double              period,
                      const double              damping,
                      std::vector<double>      &displacement,
                      std::vector<double>      &velocity);

  /// @p n periods from @p t_min to @p t_max (both > 0), equally spaced in
  /// log T; n = 1 gives {t_min}.
  std::vector<double>
  log_spaced_periods(const double t_min, const double t_max, const unsigned int n);
} // namespace archdam::loads
