#include <archdam/base/number_text.h>
#include <archdam/loads/artificial_motion.h>
#include <archdam/loads/fft.h>
#include <archdam/loads/record_io.h>
#include <archdam/loads/record_processing.h>
#include <archdam/loads/response_spectrum.h>

#include <deal.II/base/exceptions.h>

#include <algorithm>
#include <cmath>
#include <complex>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <limits>
#include <random>
#include <sstream>

namespace archdam::loads
{
  namespace
  {
    /**
     * A uniform number in [0, 1) with 53 random bits from two 32-bit draws
     * of std::mt19937 (genrand_res53 of Matsumoto & Nishimura's reference
     * code): exact integer arithmetic and one exact division by 2^53, so the
     * result is the same on every platform.
     */
    double
    uniform_53(std::mt19937 &generator)
    {
      const std::uint64_t a = generator() >> 5; // 27 bits
      const std::uint64_t b = generator() >> 6; // 26 bits
      return static_cast<double>(a * 67108864ULL + b) / 9007199254740992.;
    }

    void
    check_settings(const GenerationSettings &s)
    {
      const auto fail = [](const std::string &message) {
        throw InputError("Generated motion: " + message);
      };
      if (!(s.time_step > 0) || !std::isfinite(s.time_step))
        fail("Time step must be positive, it is " + number_text(s.time_step) + " s.");
      if (!(s.duration >= 10 * s.time_step) || !std::isfinite(s.duration))
        fail("Duration (" + number_text(s.duration) +
             " s) must be at least 10 time steps (" + number_text(10 * s.time_step) +
             " s).");
      const IntensityEnvelope &e = s.envelope;
      if (!(e.rise_end >= 0) || !(e.strong_end >= e.rise_end) ||
          !(e.strong_end <= s.duration))
        fail("the envelope needs 0 <= Rise time <= Strong motion end <= "
             "Duration, it has " +
             number_text(e.rise_end) + " s, " + number_text(e.strong_end) + " s, " +
             number_text(s.duration) + " s.");
      if (!(e.decay >= 0) || !std::isfinite(e.decay))
        fail("Decay coefficient must be at least 0, it is " + number_text(e.decay) +
             " 1/s.");
      if (!(s.damping >= 0 && s.damping < 1))
        fail("Damping ratio must be at least 0 and below 1, it is " +
             number_text(s.damping) + ".");
      if (!(s.period_min >= 3 * s.time_step))
        fail("the shortest matched period (" + number_text(s.period_min) +
             " s) must be at least 3 time steps (" + number_text(3 * s.time_step) +
             " s): shorter periods are above the frequencies the time step "
             "can carry.");
      if (!(s.period_max > s.period_min) || !(s.period_max <= s.duration / 2))
        fail("the longest matched period (" + number_text(s.period_max) +
             " s) must be longer than the shortest (" + number_text(s.period_min) +
             " s) and at most half the duration (" + number_text(s.duration / 2) +
             " s).");
      if (s.n_periods < 2)
        fail("at least 2 matched periods are needed.");
      if (!(s.tolerance > 0))
        fail("the matching tolerance must be positive.");
    }

    /// "0.7" or "2/3" as a positive number; InputError otherwise.
    double
    parse_factor(const std::string &text, const std::string &context)
    {
      const auto slash = text.find('/');
      const auto read  = [](const std::string &word, double &x) {
        const auto  b = word.find_first_not_of(" \t");
        const auto  e = word.find_last_not_of(" \t");
        const std::string w = (b == std::string::npos) ? "" : word.substr(b, e - b + 1);
        char       *end = nullptr;
        x               = std::strtod(w.c_str(), &end);
        return !w.empty() && *end == '\0' && std::isfinite(x);
      };
      double num = 0., den = 1.;
      const bool ok = (slash == std::string::npos) ?
                        read(text, num) :
                        read(text.substr(0, slash), num) && read(text.substr(slash + 1), den);
      if (!ok || !(num > 0) || !(den > 0))
        throw InputError(context + "Vertical factor '" + text +
                         "' is not a positive number or fraction (such as 2/3).");
      return num / den;
    }

    /// Linear interpolation of y(x) at @p x, x ascending, constant beyond.
    double
    interpolate(const std::vector<double> &xs,
                const std::vector<double> &ys,
                const double               x)
    {
      if (x <= xs.front())
        return ys.front();
      if (x >= xs.back())
        return ys.back();
      const std::size_t k =
        std::upper_bound(xs.begin(), xs.end(), x) - xs.begin();
      const double w = (x - xs[k - 1]) / (xs[k] - xs[k - 1]);
      return (1. - w) * ys[k - 1] + w * ys[k];
    }

    /**
     * Bring the peaks of @p a above @p pga down to it without a global scale
     * (which would move the whole spectrum): every half-wave (run of samples
     * of one sign) whose peak exceeds pga is multiplied by pga / its peak,
     * which keeps its shape and its zero crossings. The same samples of
     * @p s (the stationary process, a = I s) are scaled alike.
     */
    void
    adjust_peak(std::vector<double> &a, std::vector<double> &s, const double pga)
    {
      for (std::size_t k = 0; k < a.size();)
        {
          std::size_t end  = k;
          double      peak = 0.;
          for (; end < a.size() && (a[end] > 0.) == (a[k] > 0.); ++end)
            peak = std::max(peak, std::abs(a[end]));
          if (peak > pga)
            for (std::size_t i = k; i < end; ++i)
              {
                a[i] *= pga / peak;
                s[i] *= pga / peak;
              }
          k = end;
        }
    }

    /**
     * Make the ground velocity and displacement end at zero, and remove the
     * slow drift of the displacement, with a correction that follows the
     * envelope: subtract I(t) (c_0 + c_1 tau + c_2 tau^2 + c_3 tau^3),
     * tau = t / duration, fitted by least squares to the displacement under
     * the constraints that the corrected velocity and displacement end at
     * zero (subtract_fitted_baseline(), record_processing.h). Unlike a plain
     * polynomial it keeps the motion at rest where the envelope is 0 (a(0) =
     * 0); unlike the two-term correction that only fixes the ends, it also
     * removes the slow displacement humps a few cycles of very long period
     * leave in a 20 s motion.
     */
    void
    end_at_rest(AccelerationRecord &motion, const std::vector<double> &envelope)
    {
      const std::size_t                n = motion.values.size();
      const double                     L = motion.times.back() - motion.times.front();
      std::vector<std::vector<double>> basis(4, std::vector<double>(n));
      for (std::size_t k = 0; k < n; ++k)
        {
          const double tau = (motion.times[k] - motion.times.front()) / L;
          for (unsigned int j = 0; j < 4; ++j)
            basis[j][k] = envelope[k] * std::pow(tau, int(j));
        }
      motion = subtract_fitted_baseline(motion, basis);
    }
  } // namespace



  double
  IntensityEnvelope::operator()(const double t) const
  {
    if (t < 0.)
      return 0.;
    if (t < rise_end)
      return (t / rise_end) * (t / rise_end);
    if (t <= strong_end)
      return 1.;
    return std::exp(-decay * (t - strong_end));
  }



  AccelerationRecord
  generate_artificial_motion(const GenerationSettings &s,
                             GenerationReport         *report)
  {
    check_settings(s);
    const double      dt = s.time_step;
    const std::size_t n  = static_cast<std::size_t>(std::lround(s.duration / dt)) + 1;
    // A transform at least 4 times longer than the motion: frequency spacing
    // df = 1/(m dt) <= 1/(4 duration), fine enough that the half-power band
    // 2 zeta f of the longest matched oscillator holds several frequencies,
    // and zero padding of 3 durations that takes up what the corrections
    // spread beyond the ends of the motion instead of wrapping it around.
    const std::size_t m      = next_power_of_two(4 * n);
    const std::size_t n_freq = m / 2;
    const double      df     = 1. / (m * dt);

    // Control periods and the target there; log f ascending for the
    // interpolation of the correction.
    const std::vector<double> periods =
      log_spaced_periods(s.period_min, s.period_max, s.n_periods);
    const std::size_t   n_c = periods.size();
    std::vector<double> target(n_c), log_f(n_c);
    for (std::size_t c = 0; c < n_c; ++c)
      {
        target[c] = s.target.acceleration(periods[c]);
        log_f[c]  = std::log(1. / periods[n_c - 1 - c]);
      }

    // 1. The stationary process. Starting amplitudes from the asymptotic
    // relation between a response spectrum and a power spectral density
    // (Vanmarcke 1976): G(omega) = 4 zeta S_a(omega)^2 / (pi omega r^2) with
    // the peak factor r = 2.5, and A_j = sqrt(2 G(omega_j) d omega); only the
    // shape matters, the level is set below. Below 0.5/period_max the motion
    // has no content (a cosine ramp up to 0.8/period_max), so that it carries
    // no long-period displacement the target does not ask for.
    std::seed_seq seeds{s.seed, s.stream};
    std::mt19937  generator(seeds);
    const double  f_zero = 0.5 / s.period_max, f_full = 0.8 / s.period_max;
    std::vector<std::complex<double>> x(m, 0.);
    for (std::size_t j = 1; j < n_freq; ++j)
      {
        const double phase = 2. * M_PI * uniform_53(generator);
        const double f     = j * df;
        const double omega = 2. * M_PI * f;
        const double sa    = s.target.acceleration(1. / f);
        const double G     = 4. * s.damping * sa * sa / (M_PI * omega * 2.5 * 2.5);
        double       ramp  = 1.;
        if (f <= f_zero)
          ramp = 0.;
        else if (f < f_full)
          ramp = 0.5 * (1. - std::cos(M_PI * (f - f_zero) / (f_full - f_zero)));
        x[j] = std::polar(ramp * std::sqrt(2. * G * 2. * M_PI * df), phase);
      }
    // sum_j A_j cos(omega_j t_k + phi_j) = Re(m * inverse FFT) at t_k = k dt.
    fft(x, true);
    std::vector<double> stationary(n);
    for (std::size_t k = 0; k < n; ++k)
      stationary[k] = x[k].real() * static_cast<double>(m);

    // 2. The envelope: the motion is a = I s. Every later step keeps this
    // form (s changes, I does not), so the motion follows the envelope
    // exactly and starts at rest.
    std::vector<double> envelope(n);
    for (std::size_t k = 0; k < n; ++k)
      envelope[k] = s.envelope(k * dt);
    const auto enveloped = [&]() {
      std::vector<double> a(n);
      for (std::size_t k = 0; k < n; ++k)
        a[k] = envelope[k] * stationary[k];
      return a;
    };

    char source[200];
    std::snprintf(source,
                  sizeof(source),
                  "generated: %s, seed %u, component %c, %.4g s",
                  s.target.description().c_str(),
                  s.seed,
                  "xyz"[std::min(s.stream, 2u)],
                  s.duration);

    // The level: s scaled by the geometric mean of target / spectrum, so that
    // the iterations start from the right level and only correct the shape.
    {
      const ResponseSpectrum start =
        response_spectrum(uniform_record(enveloped(), dt, source), periods, s.damping);
      double log_mean = 0.;
      for (std::size_t c = 0; c < n_c; ++c)
        log_mean += std::log(target[c] / start.pseudo_acceleration[c]) / n_c;
      for (double &v : stationary)
        v *= std::exp(log_mean);
    }

    AccelerationRecord best;
    GenerationReport   best_report;
    best_report.max_error = std::numeric_limits<double>::infinity();
    for (unsigned int iteration = 0;; ++iteration)
      {
        // 3. The motion of this iteration: peak, rest at the end, exact PGA.
        // Half-waves above the PGA are scaled down in s as well, so that
        // later iterations keep them. The end correction moves the peak a
        // little; a global scale then makes the PGA exact and keeps the zero
        // end velocity and displacement.
        std::vector<double> a = enveloped();
        if (s.match_pga)
          adjust_peak(a, stationary, s.target.pga());
        AccelerationRecord motion = uniform_record(a, dt, source);
        end_at_rest(motion, envelope);
        if (s.match_pga)
          motion = scale_to_pga(motion, s.target.pga());

        const ResponseSpectrum spectrum =
          response_spectrum(motion, periods, s.damping);
        GenerationReport r;
        r.iterations = iteration;
        r.periods    = periods;
        r.spectrum   = spectrum.pseudo_acceleration;
        r.target     = target;
        unsigned int within = 0;
        for (std::size_t c = 0; c < n_c; ++c)
          {
            const double e = std::abs(r.spectrum[c] / target[c] - 1.);
            r.max_error    = std::max(r.max_error, e);
            within += (e <= 0.1);
          }
        r.fraction_within_10_percent = double(within) / n_c;
        if (r.max_error < best_report.max_error)
          {
            best        = motion;
            best_report = r;
          }
        if (r.max_error <= s.tolerance || iteration == s.max_iterations)
          break;

        // 4. Correction in the frequency domain. The Fourier transform of
        // the motion I s (zero-padded to m samples, which takes up what the
        // correction spreads beyond its ends) is multiplied by R(f) - 1, with
        // R = target / computed interpolated in log f (constant beyond the
        // control periods); the result delta is the change the motion asks
        // for, and s + delta the new stationary part, so that the motion
        // becomes I s + I delta: the correction of a motion of the strong
        // part (I = 1), tapered like the motion where the envelope is below
        // 1, so that no energy leaks into the rise and the decay.
        std::vector<double> log_ratio(n_c);
        for (std::size_t c = 0; c < n_c; ++c)
          log_ratio[c] = std::log(target[n_c - 1 - c] / r.spectrum[n_c - 1 - c]);
        std::fill(x.begin(), x.end(), 0.);
        const std::vector<double> current = enveloped();
        for (std::size_t k = 0; k < n; ++k)
          x[k] = current[k];
        fft(x);
        x[0] = 0.;
        for (std::size_t j = 1; j < m; ++j)
          {
            // Bins j and m - j hold the same frequency: the gain is real and
            // even, so delta is real (a zero-phase correction).
            const double f = std::min(j, m - j) * df;
            x[j] *= std::exp(interpolate(log_f, log_ratio, std::log(f))) - 1.;
          }
        fft(x, true);
        for (std::size_t k = 0; k < n; ++k)
          stationary[k] += x[k].real();
      }

    if (report != nullptr)
      *report = best_report;
    return best;
  }



  void
  ArtificialMotionParameters::add_parameters(dealii::ParameterHandler &prm)
  {
    using dealii::Patterns::Anything;
    using dealii::Patterns::Double;
    using dealii::Patterns::Integer;
    add_selection(prm,
                  "Target spectrum",
                  spectrum,
                  target_spectrum_names(),
                  "Target response spectrum (at Damping ratio): "
                  "NB 35047 (the design spectrum of NB 35047-2015, from "
                  "Peak ground acceleration, Characteristic period and "
                  "Maximum amplification) or table (Spectrum table times "
                  "the Peak ground acceleration).");
    prm.add_parameter("Peak ground acceleration",
                      pga,
                      "Horizontal design peak ground acceleration, g (the "
                      "target spectrum at T = 0); the vertical component "
                      "gets Vertical factor times it.",
                      Double(0));
    prm.add_parameter("Characteristic period",
                      characteristic_period,
                      "Characteristic period T_g of the site, s: the end of "
                      "the plateau of the NB 35047 spectrum.",
                      Double(0));
    prm.add_parameter("Maximum amplification",
                      beta_max,
                      "Plateau beta_max of the NB 35047 spectrum: 2.50 for "
                      "arch dams, 2.00 for gravity dams, 2.25 otherwise.",
                      Double(1));
    prm.add_parameter("Spectrum table",
                      table,
                      "For Target spectrum = table: points \"T: beta; T: "
                      "beta; ...\" (T in s, beta = S_a / PGA), linear between "
                      "them, constant beyond the first and last.",
                      Anything());
    prm.add_parameter("Duration",
                      duration,
                      "Duration of the generated motion, s.",
                      Double(0));
    prm.add_parameter("Time step",
                      time_step,
                      "Time step of the generated motion, s.",
                      Double(0));
    prm.add_parameter("Rise time",
                      envelope.rise_end,
                      "Intensity envelope: end of the rise (t/t1)^2, s.",
                      Double(0));
    prm.add_parameter("Strong motion end",
                      envelope.strong_end,
                      "Intensity envelope: end of the strong part (intensity "
                      "1), s; the decay exp(-c (t - t2)) follows.",
                      Double(0));
    prm.add_parameter("Decay coefficient",
                      envelope.decay,
                      "Intensity envelope: decay coefficient c, 1/s.",
                      Double(0));
    prm.add_parameter("Seed",
                      seed,
                      "Seed of the random phases: the same seed gives the same "
                      "motion; components x, y and z are independent.",
                      Integer(0));
    prm.add_parameter("Damping ratio",
                      damping,
                      "Damping ratio of the response spectrum that is matched "
                      "to the target (NB 35047: 0.05).",
                      Double(0, 0.99));
    prm.add_parameter("Vertical factor",
                      vertical_factor,
                      "The vertical component (z) matches the target scaled "
                      "by this factor, a number or a fraction (NB 35047: "
                      "2/3).",
                      Anything());
    prm.add_parameter("Shortest matched period",
                      period_min,
                      "Shortest period at which the spectrum is matched, s "
                      "(100 periods equally spaced in log T up to the "
                      "longest).",
                      Double(0));
    prm.add_parameter("Longest matched period",
                      period_max,
                      "Longest period at which the spectrum is matched, s (at "
                      "most half the duration).",
                      Double(0));
    prm.add_parameter("Matching tolerance",
                      tolerance,
                      "The iterations stop when the spectrum is within this "
                      "relative error of the target at every matched period.",
                      Double(0));
    prm.add_parameter("Maximum iterations",
                      max_iterations,
                      "At most this many corrections of the Fourier "
                      "transform; the best iteration is kept.",
                      Integer(0, 1000));
    prm.add_parameter("Match PGA",
                      match_pga,
                      "Bring the peak acceleration of the motion to the "
                      "target's PGA (S_a at T = 0) by scaling the half-waves "
                      "that exceed it, at every iteration.",
                      dealii::Patterns::Bool());
  }



  TargetSpectrum
  ArtificialMotionParameters::target(const std::string &context) const
  {
    try
      {
        if (spectrum == TargetSpectrumKind::table)
          {
            if (table.find_first_not_of(" \t") == std::string::npos)
              throw InputError("Target spectrum = table, but Spectrum table "
                               "is empty.");
            return TargetSpectrum::table(pga * standard_gravity,
                                         parse_spectrum_table(table, ""));
          }
        return TargetSpectrum::nb35047(pga * standard_gravity,
                                       characteristic_period,
                                       beta_max);
      }
    catch (const InputError &e)
      {
        throw InputError(context + e.what());
      }
  }



  GenerationSettings
  ArtificialMotionParameters::settings(const unsigned int d,
                                       const std::string &context) const
  {
    GenerationSettings s;
    s.target = target(context);
    if (d == 2)
      s.target = s.target.scaled(parse_factor(vertical_factor, context));
    s.duration       = duration;
    s.time_step      = time_step;
    s.envelope       = envelope;
    s.seed           = seed;
    s.stream         = d;
    s.damping        = damping;
    s.period_min     = period_min;
    s.period_max     = period_max;
    s.tolerance      = tolerance;
    s.max_iterations = max_iterations;
    s.match_pga      = match_pga;
    return s;
  }
} // namespace archdam::loads
