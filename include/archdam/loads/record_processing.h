#pragma once

#include <archdam/base/input_error.h>
#include <archdam/loads/acceleration_record.h>

#include <deal.II/base/parameter_handler.h>

#include <string>
#include <vector>

/**
 * What an engineer does to a record before an analysis: cut a time window,
 * resample it to the analysis time step, band-pass filter it, correct its
 * baseline so that velocity and displacement do not drift, scale it to a
 * target PGA; and the exact integration to velocity and displacement.
 *
 * The choices (details at each function):
 *  - the record is piecewise linear between samples (AccelerationRecord), so
 *    integration is exact for it (no quadrature error) and resampling onto a
 *    finer grid changes nothing;
 *  - filtering is acausal (zero phase), as in the PEER NGA processing: the
 *    gain of a Butterworth filter applied forward and backward,
 *    1/(1 + (f_c/f)^(2n)) for the high-pass and 1/(1 + (f/f_c)^(2n)) for the
 *    low-pass (1/2 at each corner), applied in the frequency domain to the
 *    record padded with zeros at both ends (Converse & Brady 1992, USGS OFR
 *    92-296A; Boore & Bommer 2005, Soil Dyn. Earthq. Eng. 25, 93-115);
 *  - the baseline correction subtracts from the acceleration the second
 *    derivative of a polynomial fitted by least squares to the displacement,
 *    as the PEER NGA-West2 processing does (Ancheta et al. 2014, Earthquake
 *    Spectra 30(3), 989-1005; Boore & Bommer 2005), with two equality
 *    constraints added so that the corrected velocity and displacement end
 *    exactly at zero.
 */
namespace archdam::loads
{
  /// Acceleration, velocity and displacement at the record's sample times.
  struct MotionHistories
  {
    std::vector<double> times;
    /// m/s^2
    std::vector<double> acceleration;
    /// m/s
    std::vector<double> velocity;
    /// m
    std::vector<double> displacement;
  };

  /**
   * Velocity and displacement from rest at the first sample, exact for an
   * acceleration linear between samples: over a step of length h
   *   v1 = v0 + h (a0 + a1)/2,   d1 = d0 + h v0 + h^2 (a0/3 + a1/6).
   */
  MotionHistories
  integrate(const AccelerationRecord &record);

  /**
   * The record multiplied by pga / record.peak(), so that its peak |a| is
   * @p pga (m/s^2); the sign of every sample is kept. InputError if the record
   * is zero or pga <= 0.
   */
  AccelerationRecord
  scale_to_pga(const AccelerationRecord &record, const double pga);

  /**
   * The part of the record between @p start and @p end (s; end = 0 means the
   * end of the record), shifted so that it starts at t = 0. An equally spaced
   * record stays equally spaced, sampled at start + k dt (interpolated where
   * start falls between samples); an irregular one keeps its samples inside
   * the window and gets interpolated end points. With @p taper > 0 both ends
   * are multiplied by a half cosine (Hann) ramp of that length, which avoids
   * the jump from rest that filtering would turn into ringing.
   */
  AccelerationRecord
  time_window(const AccelerationRecord &record,
              const double              start,
              const double              end,
              const double              taper = 0.);

  /**
   * The record sampled at t_0 + k @p dt up to its end. Linear interpolation
   * of the piecewise-linear record, which is exact onto a finer grid. Onto a
   * coarser one the record is first low-pass filtered (zero-phase Butterworth
   * of order 8, corner at 0.8 times the new Nyquist frequency 1/(2 dt), gain
   * 0.03 at the Nyquist frequency) so that content the new step cannot carry
   * does not alias into lower frequencies.
   */
  AccelerationRecord
  resample(const AccelerationRecord &record, const double dt);

  /**
   * Zero-phase Butterworth band-pass (see the namespace documentation):
   * high-pass corner @p high_pass (Hz, 0 = none), low-pass corner
   * @p low_pass (Hz, 0 = none, else below the Nyquist frequency), order
   * @p order of each pass (1 ... 10). The record must be equally spaced. It
   * is padded with zeros at both ends by 1.5 order / high_pass seconds each
   * (Converse & Brady 1992), transformed, multiplied by the gain, transformed
   * back, and the pads are cut off again; cutting them leaves small offsets in
   * velocity and displacement, which baseline_correction() removes.
   */
  AccelerationRecord
  bandpass_filter(const AccelerationRecord &record,
                  const double              high_pass,
                  const double              low_pass,
                  const unsigned int        order = 4);

  /**
   * Baseline correction: with d(t) the displacement (integrate()) and
   * tau = (t - t_0)/(t_end - t_0), fit p(tau) = sum_{k=2..degree} c_k tau^k
   * to d by least squares (trapezoidal weights, equal for equally spaced
   * samples) under the constraints that the corrected velocity
   * and displacement are zero at the end, and subtract p'' from the
   * acceleration. The terms from k = 2 keep the initial velocity and
   * displacement at zero. The correction acceleration is integrated by the
   * same exact rule as the record, so the constraints hold to round-off.
   * @p degree from 3 to 10 (6 as in the NGA-West2 processing).
   */
  AccelerationRecord
  baseline_correction(const AccelerationRecord &record,
                      const unsigned int        degree = 6);

  /**
   * The machinery of baseline_correction() for any correction shapes: with
   * @p basis the accelerations b_k at the record's samples (at least 2),
   * subtract sum_k c_k b_k, where the c_k minimize the least-squares
   * difference between the displacement of the record and that of
   * sum_k c_k b_k (both by integrate()), under the constraints that the
   * corrected velocity and displacement end at zero (hold to round-off).
   * With 2 functions the constraints alone fix the c_k.
   */
  AccelerationRecord
  subtract_fitted_baseline(const AccelerationRecord               &record,
                           const std::vector<std::vector<double>> &basis);

  /**
   * Optional processing of a ground-motion component, applied in this order:
   * time window, resampling, band-pass filter, baseline correction, scaling
   * to a target PGA. Every entry's default leaves the record unchanged.
   */
  struct ProcessingParameters
  {
    /// Window start, s.
    double start_time = 0.;
    /// Window end, s; 0 = the end of the record.
    double end_time = 0.;
    /// Length of the cosine ramps at both ends of the window, s; 0 = none.
    double taper = 0.;
    /// New time step, s; 0 = keep the record's samples.
    double time_step = 0.;
    /// High-pass corner, Hz; 0 = none.
    double high_pass = 0.;
    /// Low-pass corner, Hz; 0 = none.
    double low_pass = 0.;
    /// Order of each Butterworth pass.
    unsigned int filter_order = 4;
    /// Whether to correct the baseline.
    bool baseline = false;
    /// Degree of the baseline polynomial.
    unsigned int baseline_degree = 6;
    /// Target peak ground acceleration in g; 0 = keep the record's.
    double target_pga = 0.;

    /// Whether any entry asks for a change.
    bool
    any() const;

    /// What process() applies, in its order, in words ("none" if nothing):
    /// for the run's log and summary.json.
    std::string
    description() const;

    /**
     * Declare, in the current subsection of @p prm, the entries "Start time",
     * "End time", "Taper length", "Resample time step", "High-pass corner",
     * "Low-pass corner", "Filter order", "Baseline correction", "Baseline
     * polynomial degree", "Target PGA", bound to the members above.
     */
    void
    add_parameters(dealii::ParameterHandler &prm);
  };

  /**
   * Apply @p p to @p record in the documented order. InputError starting with
   * @p context for inconsistent entries (window outside the record, corners
   * above the Nyquist frequency or in the wrong order, filtering an irregular
   * record without resampling, ...).
   */
  AccelerationRecord
  process(const AccelerationRecord   &record,
          const ProcessingParameters &p,
          const std::string          &context);
} // namespace archdam::loads
