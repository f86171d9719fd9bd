#pragma once

#include <archdam/base/input_error.h>
#include <archdam/base/selection.h>
#include <archdam/loads/acceleration_record.h>
#include <archdam/loads/design_spectrum.h>

#include <deal.II/base/parameter_handler.h>

#include <string>
#include <vector>

/**
 * Artificial spectrum-compatible ground motions, after SIMQKE (Gasparini &
 * Vanmarcke 1976, "SIMQKE: a program for artificial motion generation", MIT
 * report R76-4):
 *
 *  1. a stationary Gaussian process s(t) as a sum of cosines at the
 *     frequencies f_j = j df with amplitudes A_j shaped by the target
 *     spectrum and independent phases phi_j uniform in [0, 2 pi) (the
 *     spectral representation of Shinozuka & Deodatis 1991, Appl. Mech. Rev.
 *     44(4), 191-204; the sum is Gaussian by the central limit theorem),
 *     evaluated by one inverse FFT, and brought to the right overall level;
 *  2. the motion a(t) = I(t) s(t), with the intensity envelope I(t)
 *     (Jennings, Housner & Tsai 1968, "Simulated earthquake motions", EERL
 *     Caltech): (t/t_1)^2 while it rises, 1 in the strong part up to t_2,
 *     exp(-c (t - t_2)) in the decay. Every later step keeps this form, so
 *     the motion starts at rest and follows the envelope exactly;
 *  3. every iteration, the motion is finished: with match_pga, the
 *     half-waves whose peak exceeds the target PGA are scaled down to it (in
 *     s, so that later iterations keep it; the target's S_a at T = 0 is the
 *     PGA, which spectrum matching alone leaves 10-40 % too high for the
 *     NB 35047 shape); then I(t) (c_0 + c_1 t) is subtracted with c_0, c_1
 *     such that the ground velocity and displacement end at zero; then a
 *     global factor close to 1 makes the PGA exact;
 *  4. iterated in the frequency domain: the response spectrum of the
 *     finished motion is computed at the control periods
 *     (response_spectrum.h); the Fourier transform of I s is multiplied by
 *     R - 1, R = target / computed interpolated in log f, and the result
 *     delta is added to s: the motion becomes I s + I delta, which is the
 *     frequency-domain correction of the motion in its strong part and the
 *     same correction tapered by the envelope in the rise and decay (a plain
 *     correction of the motion would spread energy there). Until every
 *     control period is within the tolerance or the iterations run out; the
 *     best iteration (smallest largest error) is kept. The iterations, and
 *     the PGA step that lowers the strong part's peaks, move some energy
 *     from the strong part into the decay: over 30 realizations of the
 *     NB 35047 arch-dam case the RMS on the decay was 1.0 to 1.9 times that
 *     of I s with s stationary (doc/ground-motion.md).
 *
 * The phases come from std::mt19937 seeded by std::seed_seq{seed, stream},
 * both fully specified by the C++ standard, turned into uniform numbers in
 * [0, 1) by our own 53-bit transform (two draws, as genrand_res53 of
 * Matsumoto & Nishimura) rather than by std::uniform_real_distribution or
 * std::normal_distribution, whose algorithms differ between standard
 * libraries. The random numbers are therefore identical on every platform;
 * the motion is identical for the same seed on the same platform and differs
 * across platforms only by the round-off of cos, sin and exp in libm. Each
 * stream (0, 1, 2 for the components x, y, z) draws from its own sequence, so
 * the components are statistically independent.
 */
namespace archdam::loads
{
  /// The intensity envelope I(t) (see the namespace documentation).
  struct IntensityEnvelope
  {
    /// End of the rise t_1, s.
    double rise_end = 2.;
    /// End of the strong part t_2, s.
    double strong_end = 12.;
    /// Decay coefficient c, 1/s.
    double decay = 0.3;

    /// I(t) in [0, 1].
    double
    operator()(const double t) const;
  };

  /// Everything the generator needs for one component.
  struct GenerationSettings
  {
    /// Target 5 %-damped (or @p damping) acceleration spectrum.
    TargetSpectrum target = TargetSpectrum::nb35047(0.1 * 9.80665, 0.4);
    /// Duration of the motion, s.
    double duration = 20.;
    /// Time step of the motion, s.
    double time_step = 0.01;
    IntensityEnvelope envelope;
    /// Seed of the random phases.
    unsigned int seed = 1;
    /// Independent stream: 0, 1, 2 for the components x, y, z.
    unsigned int stream = 0;
    /// Damping ratio of the spectrum that is matched.
    double damping = 0.05;
    /// Control periods: n_periods from period_min to period_max (log).
    double       period_min = 0.04;
    double       period_max = 4.;
    unsigned int n_periods  = 100;
    /// Stop when every control period is within this relative error.
    double tolerance = 0.05;
    /// At most this many corrections.
    unsigned int max_iterations = 100;
    /// Whether the peak of the motion is brought to the target's PGA.
    bool match_pga = true;
  };

  /// How well the generated motion matches its target.
  struct GenerationReport
  {
    /// Corrections applied before the kept motion.
    unsigned int iterations = 0;
    /// Control periods and the motion's spectrum there (m/s^2).
    std::vector<double> periods;
    std::vector<double> spectrum;
    std::vector<double> target;
    /// Largest |spectrum/target - 1| over the control periods.
    double max_error = 0.;
    /// Fraction of control periods with |spectrum/target - 1| <= 0.1.
    double fraction_within_10_percent = 0.;
  };

  /**
   * Generate one spectrum-compatible acceleration record (see the namespace
   * documentation), sampled at k time_step up to the duration. InputError for
   * inconsistent settings (non-positive duration or step, envelope times
   * outside the motion, control periods the step cannot resolve, ...).
   */
  AccelerationRecord
  generate_artificial_motion(const GenerationSettings &settings,
                             GenerationReport         *report = nullptr);

  /// `Target spectrum` of the generated motion.
  enum class TargetSpectrumKind
  {
    nb35047, ///< the design spectrum of NB 35047-2015 (TargetSpectrum::nb35047)
    table    ///< Spectrum table times the PGA (TargetSpectrum::table)
  };

  /// The names of TargetSpectrumKind in the case file.
  inline const SelectionNames<TargetSpectrumKind> &
  target_spectrum_names()
  {
    static const SelectionNames<TargetSpectrumKind> names{
      {"NB 35047", TargetSpectrumKind::nb35047}, {"table", TargetSpectrumKind::table}};
    return names;
  }

  /**
   * The "Generated motion" parameters of the analysis: the target spectrum
   * (NB 35047-2015 or a table), the duration, time step and envelope, the seed
   * and the matching. Component x, y and z use the streams 0, 1, 2 (independent
   * motions); the vertical one matches the target scaled by the vertical
   * factor (NB 35047: 2/3 of the horizontal).
   */
  struct ArtificialMotionParameters
  {
    TargetSpectrumKind spectrum = TargetSpectrumKind::nb35047;
    /// Horizontal design peak ground acceleration, g.
    double pga = 0.1;
    /// Characteristic period T_g, s.
    double characteristic_period = 0.4;
    /// Plateau beta_max (2.50 for arch dams).
    double beta_max = 2.5;
    /// "T: beta; ..." points for spectrum = table.
    std::string table;
    double      duration  = 20.;
    double      time_step = 0.01;
    IntensityEnvelope envelope;
    unsigned int      seed = 1;
    double            damping = 0.05;
    /// Factor of the vertical target: a number or a fraction ("2/3").
    std::string       vertical_factor = "2/3";
    double            period_min = 0.04;
    double            period_max = 4.;
    double            tolerance = 0.05;
    unsigned int      max_iterations = 100;
    bool              match_pga = true;

    /// Declare the entries in the current subsection of @p prm.
    void
    add_parameters(dealii::ParameterHandler &prm);

    /// The horizontal target spectrum; InputError starting with @p context.
    TargetSpectrum
    target(const std::string &context) const;

    /// The settings of component @p d (0 = x, 1 = y, 2 = z).
    GenerationSettings
    settings(const unsigned int d, const std::string &context) const;
  };
} // namespace archdam::loads
