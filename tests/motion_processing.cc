// Record processing (record_processing.h) against closed forms:
//  1. integration to velocity and displacement: exact for accelerations
//     linear between samples, so a constant and a linear acceleration at
//     irregular times give v and d of the polynomial closed forms to
//     round-off (tolerance 1e-12);
//  2. scaling to a target PGA, time windows and tapers: exact values of a
//     linear function (linear interpolation reproduces it) and of the Hann
//     ramp 0.5 (1 - cos(pi tau / L));
//  3. resampling: onto a finer grid the piecewise-linear record is unchanged
//     (a linear function stays exact); onto a coarser one the anti-alias
//     filter must remove a 40 Hz sine that plain sampling at 50 Hz would
//     fold onto 10 Hz, and keep a 2 Hz sine;
//  4. the zero-phase Butterworth band-pass: the amplitude of a long sine of
//     frequency f after filtering is the gain 1/(1 + (f_h/f)^(2n)) *
//     1/(1 + (f/f_l)^(2n)) and its phase is zero, measured by least squares
//     on the middle of a 400 s record, away from the start-up transients at
//     the ends (the filters' impulse responses last ~n/f_h = 20 s); and
//  5. malformed processing requests, each with its message.

#include <archdam/loads/record_io.h>
#include <archdam/loads/record_processing.h>

#include <cmath>
#include <functional>

#include "archdam_tests.h"

using namespace archdam::loads;
using archdam::testing::check_below;
using archdam::testing::check_relative;
using archdam::testing::log;
using archdam::testing::expect_input_error;

namespace
{
  /// A record of @p f at t_k = k dt, k = 0 ... n.
  AccelerationRecord
  sampled(const std::function<double(double)> &f, const double dt, const unsigned int n)
  {
    std::vector<double> v(n + 1);
    for (unsigned int k = 0; k <= n; ++k)
      v[k] = f(k * dt);
    return uniform_record(v, dt, "test");
  }

  void
  check_integration()
  {
    log() << "1. Integration (irregular times from 0.5 s)" << std::endl;
    AccelerationRecord constant, linear;
    for (unsigned int k = 0; k <= 200; ++k)
      {
        const double t = 0.5 + 0.05 * k + 0.02 * std::sin(2. * k) * (k > 0 && k < 200);
        constant.times.push_back(t);
        constant.values.push_back(2.0);
        linear.times.push_back(t);
        linear.values.push_back(3.0 * (t - 0.5));
      }
    const MotionHistories c = integrate(constant), l = integrate(linear);
    double                err = 0;
    for (std::size_t k = 0; k < c.times.size(); ++k)
      {
        const double s = c.times[k] - 0.5;
        // a = 2: v = 2 s, d = s^2; a = 3 s: v = 1.5 s^2, d = s^3 / 2.
        err = std::max({err, std::abs(c.velocity[k] - 2 * s) / 20.,
                        std::abs(c.displacement[k] - s * s) / 100.,
                        std::abs(l.velocity[k] - 1.5 * s * s) / 150.,
                        std::abs(l.displacement[k] - 0.5 * s * s * s) / 500.});
      }
    check_below("max relative error of v and d for a = 2 and a = 3 (t - t0)", err, 1e-12);
  }

  void
  check_scale_and_window()
  {
    log() << "\n2. Scaling, time window, taper" << std::endl;
    const auto         line = [](double t) { return 2.0 + 3.0 * t; };
    AccelerationRecord r    = sampled(line, 0.01, 1000); // 0 ... 10 s
    r.values[300]           = -40.;                      // the peak, negative
    const AccelerationRecord s = scale_to_pga(r, 5.0);
    check_relative("peak after scaling to 5 m/s^2", s.peak(), 5.0, 1e-14);
    check_relative("sample 300 keeps its sign: -5 m/s^2", s.values[300], -5.0, 1e-14);
    check_relative("sample 700 scaled by 5/40", s.values[700], line(7.0) * 5. / 40., 1e-13);

    // Window from 2.505 s (between samples) to 6 s: sampled at 2.505 + k dt,
    // shifted to start at 0; values of the linear function there.
    const AccelerationRecord line_record = sampled(line, 0.01, 1000);
    const AccelerationRecord w = time_window(line_record, 2.505, 6.0);
    double                   dt = 0, err = 0;
    for (std::size_t k = 0; k < w.times.size(); ++k)
      err = std::max(err, std::abs(w.values[k] - line(2.505 + w.times[k])));
    log() << "window: " << w.times.size() << " samples, equally spaced: "
          << (w.is_uniform(&dt) && std::abs(dt - 0.01) < 1e-12 ? "yes" : "NO")
          << ", starts at 0: " << (w.times.front() == 0. ? "yes" : "NO") << std::endl;
    check_below("max |window - (2 + 3 (t + 2.505))|", err, 1e-12);

    // Taper of 0.5 s on a window from 1 s to 9 s: zero at both ends, half
    // at 0.25 s from each end (0.5 (1 - cos(pi/2)) = 0.5), untouched inside.
    const AccelerationRecord ones = sampled([](double) { return 1.0; }, 0.01, 1000);
    const AccelerationRecord tw   = time_window(ones, 1.0, 9.0, 0.5);
    const std::size_t        n    = tw.values.size();
    check_below("taper: |first| + |last| sample", std::abs(tw.values[0]) + std::abs(tw.values[n - 1]),
                1e-12);
    check_relative("taper at 0.25 s", tw.values[25], 0.5, 1e-12);
    check_relative("taper at 0.25 s before the end", tw.values[n - 26], 0.5, 1e-12);
    check_relative("taper at 0.1 s: 0.5 (1 - cos(pi/5))", tw.values[10],
                   0.5 * (1 - std::cos(M_PI / 5)), 1e-12);
    check_relative("inside: 1", tw.values[n / 2], 1.0, 1e-14);
  }

  void
  check_resampling()
  {
    log() << "\n3. Resampling" << std::endl;
    const auto               line = [](double t) { return 2.0 + 3.0 * t; };
    const AccelerationRecord fine = resample(sampled(line, 0.02, 500), 0.005);
    double                   err = 0, dt = 0;
    for (std::size_t k = 0; k < fine.times.size(); ++k)
      err = std::max(err, std::abs(fine.values[k] - line(fine.times[k])));
    log() << "0.02 s -> 0.005 s: " << fine.times.size() << " samples (expected 2001), uniform: "
          << (fine.is_uniform(&dt) && std::abs(dt - 0.005) < 1e-12 ? "yes" : "NO") << std::endl;
    check_below("finer grid: max |a - (2 + 3 t)|", err, 1e-12);

    // 2 Hz + 40 Hz, dt = 0.005 s (Nyquist 100 Hz), 20 s, resampled to
    // 0.02 s (Nyquist 25 Hz). The anti-alias filter (corner 20 Hz, order 8)
    // passes 2 Hz with gain 1 - 1e-16 and 40 Hz with 1/(1 + 2^16) = 1.5e-5;
    // the 40 Hz sine starts and stops abruptly, so its filtered transient
    // is confined near the ends: compare on 2 ... 18 s.
    const auto two = [](double t) { return std::sin(2 * M_PI * 2 * t); };
    const auto mix = [&](double t) { return two(t) + std::sin(2 * M_PI * 40 * t + 0.3); };
    const AccelerationRecord source = sampled(mix, 0.005, 4000);
    const AccelerationRecord coarse = resample(source, 0.02);
    double                   filtered = 0, plain = 0;
    for (std::size_t k = 0; k < coarse.times.size(); ++k)
      {
        const double t = coarse.times[k];
        if (t < 2 || t > 18)
          continue;
        filtered = std::max(filtered, std::abs(coarse.values[k] - two(t)));
        plain    = std::max(plain, std::abs(source.value(t) - two(t)));
      }
    log() << "0.005 s -> 0.02 s: " << coarse.times.size() << " samples (expected 1001)" << std::endl;
    check_below("anti-aliased: max |a - sin(2 pi 2 t)| on 2 ... 18 s (amplitude 1)", filtered,
                2e-3);
    log() << "plain sampling would leave the folded 40 Hz sine, error > 0.5: "
          << (plain > 0.5 ? "yes" : "NO") << std::endl;
  }

  void
  check_filter()
  {
    log() << "\n4. Zero-phase Butterworth band-pass 0.2 ... 10 Hz, order 4" << std::endl;
    const double f_h = 0.2, f_l = 10, dt = 0.01;
    const int    order = 4;
    for (const double f : {0.1, 0.2, 0.5, 1.0, 5.0, 10.0, 20.0})
      {
        const AccelerationRecord r =
          sampled([f](double t) { return std::sin(2 * M_PI * f * t); }, dt, 40000);
        const AccelerationRecord b = bandpass_filter(r, f_h, f_l, order);
        // Least squares fit a sin + b cos on 100 ... 300 s (a whole number of
        // periods of every f here): a = (2/N) sum y sin, b = (2/N) sum y cos.
        double s = 0, c = 0;
        int    N = 0;
        for (unsigned int k = 10000; k < 30000; ++k)
          {
            const double t = k * dt;
            s += b.values[k] * std::sin(2 * M_PI * f * t);
            c += b.values[k] * std::cos(2 * M_PI * f * t);
            ++N;
          }
        const double gain = 1 / (1 + std::pow(f_h / f, 2 * order)) / (1 + std::pow(f / f_l, 2 * order));
        log() << "f = " << f << " Hz:" << std::endl;
        check_below("  |amplitude - gain| (gain " + std::to_string(gain).substr(0, 7) + ")",
                    std::abs(2 * s / N - gain), 1e-3);
        check_below("  |out-of-phase part| (zero phase)", std::abs(2 * c / N), 1e-3);
      }
  }

  void
  check_errors()
  {
    log() << "\n5. Malformed requests" << std::endl;
    const AccelerationRecord r = sampled([](double t) { return std::sin(t); }, 0.01, 1000);
    AccelerationRecord       irregular = r;
    irregular.times[5] += 0.003;
    ProcessingParameters p;
    const std::string    context = "Ground motion, Component x, file 'a.AT2': processing: ";
    expect_input_error("window ends after the record", [&] {
      p.end_time = 12;
      process(r, p, context);
    });
    expect_input_error("window ends before it starts", [&] {
      p.start_time = 5, p.end_time = 4;
      process(r, p, context);
    });
    expect_input_error("taper longer than half the window", [&] {
      p            = ProcessingParameters();
      p.start_time = 1, p.end_time = 3, p.taper = 1.5;
      process(r, p, context);
    });
    expect_input_error("filter on an irregular record", [&] {
      p           = ProcessingParameters();
      p.high_pass = 0.1;
      process(irregular, p, context);
    });
    expect_input_error("low-pass corner above the Nyquist frequency", [&] {
      p          = ProcessingParameters();
      p.low_pass = 60;
      process(r, p, context);
    });
    expect_input_error("high-pass corner above the low-pass corner", [&] {
      p           = ProcessingParameters();
      p.high_pass = 5, p.low_pass = 2;
      process(r, p, context);
    });
    expect_input_error("resampling step longer than the record", [&] {
      p           = ProcessingParameters();
      p.time_step = 20;
      process(r, p, context);
    });
    expect_input_error("target PGA for a record of zeros", [&] {
      p            = ProcessingParameters();
      p.target_pga = 0.3;
      process(sampled([](double) { return 0.; }, 0.01, 10), p, context);
    });
    expect_input_error("baseline polynomial of degree 2", [] { baseline_correction(
      sampled([](double t) { return t; }, 0.01, 100), 2); });
  }
} // namespace

int
main(int argc, char **argv)
{
  dealii::Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  check_integration();
  check_scale_and_window();
  check_resampling();
  check_filter();
  check_errors();
}
