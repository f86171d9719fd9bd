// Artificial spectrum-compatible motions (artificial_motion.h) for an arch
// dam: NB 35047-2015 target with PGA 0.3 g, T_g 0.4 s, beta_max 2.5, 20 s,
// three components generated through the analysis' own path (the "Ground
// motion" parameters with Source = generated, GroundMotion).
//
// The match is judged with a response spectrum computed here, independently
// of the library's (which drives the iterations): 4th-order Runge-Kutta on
// u'' + 2 zeta w u' + w^2 u = -a_g, a_g linear between samples, steps of at
// most T/200 aligned with the samples, continued 2 periods after the record;
// its peak is accurate to ~1e-4 (crest missed by at most 1 - cos(pi/200)),
// far below the +-10 % band. Requirement (issue "ground-motion", must show
// 2): within +-10 % of the target at >= 90 % of 100 periods equally spaced
// in log T from 0.04 s to 4 s; the vertical component against 2/3 of the
// target.
//
// Also: the PGA is the target's (the generator brings it there, tolerance
// round-off 1e-9); the ground velocity and displacement end at rest (the
// test's own exact integration, 1e-8 of their peaks); the same seed gives
// the same motion bit for bit (two generations compared), another seed a
// different one that matches as well; the components are statistically
// independent: for independent zero-mean processes the sample correlation
// coefficient is 0 with a standard deviation of about 1/sqrt(N_eff), N_eff ~
// 2 x bandwidth (~10 Hz) x strong duration (~10 s) = 200, i.e. 0.07, so
// |rho| < 0.25 (3.5 standard deviations); and the intensity follows the
// envelope (details below). Only verdicts and rounded fractions are printed,
// no raw random values.

#include <archdam/loads/ground_motion.h>

#include <deal.II/base/parameter_handler.h>

#include <cmath>
#include <iomanip>

#include "archdam_tests.h"
#include "motion_reference.h"

using namespace archdam::loads;
using archdam::testing::check_below;
using archdam::testing::check_relative;
using archdam::testing::log;

using archdam::testing::ends;
using archdam::testing::Ends;

namespace
{
  const double g = 9.80665;

  double
  rk4_peak(const AccelerationRecord &r, const double T, const double zeta)
  {
    return archdam::testing::rk4_peak(r, T, zeta, 200);
  }

  /// NB 35047-2015 for T_g = 0.4 s, beta_max = 2.5, written out here.
  double
  target_beta(const double T)
  {
    const double beta = T <= 0.1 ? 1 + 15 * T : T <= 0.4 ? 2.5 : 2.5 * std::pow(0.4 / T, 0.6);
    return std::max(beta, 0.5);
  }

  void
  check_spectrum(const AccelerationRecord &r, const double pga, const std::string &name)
  {
    unsigned int within = 0, n = 100;
    double       worst  = 0;
    for (unsigned int i = 0; i < n; ++i)
      {
        const double T   = 0.04 * std::pow(100., i / (n - 1.));
        const double psa = std::pow(2 * M_PI / T, 2) * rk4_peak(r, T, 0.05);
        const double e   = std::abs(psa / (pga * target_beta(T)) - 1);
        within += e <= 0.1;
        worst = std::max(worst, e);
      }
    log() << name << ": fraction of the 100 periods in 0.04 ... 4 s within +-10 % of the target: "
          << std::fixed << std::setprecision(2) << double(within) / n << std::defaultfloat
          << ", at least 0.90: " << (within >= 90 ? "yes" : "NO") << std::endl;
    check_below(name + ": largest deviation from the target", worst, 0.2);
  }

  double
  correlation(const AccelerationRecord &a, const AccelerationRecord &b)
  {
    double ab = 0, aa = 0, bb = 0;
    for (std::size_t k = 0; k < a.values.size(); ++k)
      {
        ab += a.values[k] * b.values[k];
        aa += a.values[k] * a.values[k];
        bb += b.values[k] * b.values[k];
      }
    return ab / std::sqrt(aa * bb);
  }

  /// Time at which int_0^t a^2 reaches @p fraction of its total.
  double
  husid_time(const AccelerationRecord &r, const double fraction)
  {
    double total = 0;
    for (const double a : r.values)
      total += a * a;
    double sum = 0;
    for (std::size_t k = 0; k < r.values.size(); ++k)
      {
        sum += r.values[k] * r.values[k];
        if (sum >= fraction * total)
          return r.times[k];
      }
    return r.times.back();
  }

  GroundMotionParameters
  parameters(const unsigned int seed)
  {
    GroundMotionParameters   p;
    dealii::ParameterHandler prm;
    prm.enter_subsection("Ground motion");
    p.add_parameters(prm);
    prm.leave_subsection();
    prm.parse_input_from_string("subsection Ground motion\n"
                                "  subsection Component x\n"
                                "    set Source = generated\n"
                                "  end\n"
                                "  subsection Component y\n"
                                "    set Source = generated\n"
                                "  end\n"
                                "  subsection Component z\n"
                                "    set Source = generated\n"
                                "  end\n"
                                "  subsection Generated motion\n"
                                "    set Target spectrum = NB 35047\n"
                                "    set Peak ground acceleration = 0.3\n"
                                "    set Characteristic period = 0.4\n"
                                "    set Maximum amplification = 2.5\n"
                                "    set Duration = 20\n"
                                "    set Seed = " +
                                std::to_string(seed) +
                                "\n"
                                "  end\n"
                                "end\n");
    return p;
  }
} // namespace

int
main(int argc, char **argv)
{
  dealii::Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);

  log() << "Arch dam: NB 35047-2015, PGA 0.3 g, T_g 0.4 s, beta_max 2.5, 20 s, seed 7"
        << std::endl;
  const GroundMotion motion(parameters(7), "");
  const GroundMotion again(parameters(7), "");
  const GroundMotion other(parameters(8), "");

  const std::array<std::string, 3> name = {{"x", "y", "z"}};
  for (unsigned int d = 0; d < 3; ++d)
    {
      const AccelerationRecord &r   = motion.record(d);
      const double              pga = (d == 2 ? 0.2 : 0.3) * g;
      log() << "\nComponent " << name[d] << (d == 2 ? " (target times 2/3)" : "") << std::endl;
      log() << "  " << r.times.size() << " samples from 0 s to " << r.times.back() << " s"
            << std::endl;
      check_spectrum(r, pga, "  spectrum");
      // Vertical factor "2/3" (the default) is parsed as 2/3 exactly.
      check_relative("  PGA [g]", r.peak() / g, pga / g, 1e-9);
      const Ends e = ends(r);
      check_below("  |v_end| / peak v", std::abs(e.v_end) / e.v_peak, 1e-8);
      check_below("  |d_end| / peak d", std::abs(e.d_end) / e.d_peak, 1e-8);
      log() << "  same seed, second generation identical bit for bit: "
            << (again.record(d).values == r.values && again.record(d).times == r.times ? "yes" :
                                                                                        "NO")
            << std::endl;
    }

  log() << "\nComponents statistically independent" << std::endl;
  check_below("  |rho(x, y)|", std::abs(correlation(motion.record(0), motion.record(1))), 0.25);
  check_below("  |rho(x, z)|", std::abs(correlation(motion.record(0), motion.record(2))), 0.25);
  check_below("  |rho(y, z)|", std::abs(correlation(motion.record(1), motion.record(2))), 0.25);

  // The envelope I = (t/2)^2 up to 2 s, 1 up to 12 s, exp(-0.3 (t - 12))
  // after. The motion is I times a stationary Gaussian process s, so
  //  - it starts at rest: a(0) = 0 (I(0) = 0);
  //  - its RMS on the rise 0 ... 2 s and on the decay 14 ... 20 s, relative to
  //    sigma, its RMS on the strong part 2 ... 12 s, is that of I: the square
  //    root of the mean of I^2, sqrt((2/5)/2) = 0.4472 on the rise and
  //    sqrt((e^-1.2 - e^-4.8)/(0.6 x 6)) = 0.2853 on the decay. A realization
  //    scatters by ~1/sqrt(2 x 5 Hz x window) ~ 20 %; on top of that the
  //    iterations lower the strong part's peaks (PGA) and tend to move some
  //    energy out of the strong part (up to 1.9 times the decay's RMS over 30
  //    realizations, doc/ground-motion.md): within a factor 2, which a motion
  //    without the envelope (1/0.2853 = 3.5 on the decay) would not meet;
  //  - the 5 % point of the cumulative energy int a^2 dt (Husid) is that of
  //    int I^2 dt: 2/5 on the rise, 10 on the strong part,
  //    (1 - e^-4.8)/0.6 = 1.6518 on the decay, 12.0518 in all, 5 % = 0.6026
  //    reached at 2 + 0.2026 = 2.20 s; the energy of a realization on the
  //    first ~2 s fluctuates by ~20 %, i.e. 0.12 in energy or 0.12 s in time
  //    (I^2 = 1 there): tolerance 0.6 s.
  log() << "\nIntensity follows the envelope" << std::endl;
  for (unsigned int d = 0; d < 3; ++d)
    {
      const AccelerationRecord &r = motion.record(d);
      double       strong = 0, rise = 0, decay = 0;
      unsigned int n_strong = 0, n_rise = 0, n_decay = 0;
      for (std::size_t k = 0; k < r.times.size(); ++k)
        {
          const double t = r.times[k], a2 = r.values[k] * r.values[k];
          if (t >= 2 && t <= 12)
            strong += a2, ++n_strong;
          if (t < 2)
            rise += a2, ++n_rise;
          if (t >= 14)
            decay += a2, ++n_decay;
        }
      const double sigma        = std::sqrt(strong / n_strong);
      const double rise_ratio   = std::sqrt(rise / n_rise) / sigma / 0.4472;
      const double decay_ratio  = std::sqrt(decay / n_decay) / sigma / 0.2853;
      log() << "  " << name[d] << ": a(0) = 0: " << (r.values[0] == 0. ? "yes" : "NO") << std::endl;
      log() << "  " << name[d] << ": RMS on 0 ... 2 s / (0.4472 sigma) within 1/2 ... 2: "
            << (rise_ratio > 0.5 && rise_ratio < 2 ? "yes" : "NO") << std::endl;
      log() << "  " << name[d] << ": RMS on 14 ... 20 s / (0.2853 sigma) within 1/2 ... 2: "
            << (decay_ratio > 0.5 && decay_ratio < 2 ? "yes" : "NO") << std::endl;
      check_below("  " + name[d] + ": |t_5 - 2.20 s| [s]", std::abs(husid_time(r, 0.05) - 2.20), 0.6);
    }

  log() << "\nSeed 8" << std::endl;
  double difference = 0;
  for (std::size_t k = 0; k < other.record(0).values.size(); ++k)
    difference = std::max(difference, std::abs(other.record(0).values[k] - motion.record(0).values[k]));
  log() << "  another motion: max |a_8 - a_7| > 0.1 g: " << (difference > 0.1 * g ? "yes" : "NO")
        << std::endl;
  check_spectrum(other.record(0), 0.3 * g, "  x spectrum");
}
