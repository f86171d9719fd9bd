// Response spectrum (Nigam-Jennings recurrence, response_spectrum.h) against
// the closed-form response of a damped oscillator to a harmonic ground
// acceleration a_g = A sin(Omega t), from rest (Chopra, Dynamics of Structures,
// eq. 3.2.1-3.2.4):
//   u(t)  = C sin(Omega t) + D cos(Omega t)
//           + exp(-zeta w t) (E1 cos(wd t) + E2 sin(wd t)),
//   C     = (p0/w^2) (1 - r^2) / Q,  D = (p0/w^2) (-2 zeta r) / Q,
//   Q     = (1 - r^2)^2 + (2 zeta r)^2,  p0 = -A,  r = Omega / w,
//   E1    = -D,  E2 = (zeta w E1 - C Omega) / wd          (u(0) = u'(0) = 0),
// and its steady-state amplitude u0 = (A/w^2) / sqrt(Q).
//
// The record samples the sine at 400 points per forcing period and is linear
// between them. That piecewise-linear input differs from the sine: over each
// interval its mean is smaller by the factor 1 - (Omega h)^2/12 = 1 - 2.1e-5,
// and the rest of the difference is at the sampling frequency, far above the
// oscillator. So the recurrence, exact for the piecewise-linear input, must
// agree with the closed form for the sine to about 2e-5 of the amplitude; the
// tolerance is 1e-4.

#include <archdam/loads/response_spectrum.h>

#include <cmath>
#include <vector>

#include "archdam_tests.h"

using namespace archdam::loads;
using archdam::testing::check_below;
using archdam::testing::check_relative;
using archdam::testing::log;

namespace
{
  struct Harmonic
  {
    double A, Omega, w, zeta;

    double
    Q() const
    {
      const double r = Omega / w;
      return (1 - r * r) * (1 - r * r) + (2 * zeta * r) * (2 * zeta * r);
    }

    double
    amplitude() const
    {
      return A / (w * w) / std::sqrt(Q());
    }

    /// The closed-form u(t) from rest.
    double
    u(const double t) const
    {
      const double r  = Omega / w;
      const double p0 = -A;
      const double C  = p0 / (w * w) * (1 - r * r) / Q();
      const double D  = p0 / (w * w) * (-2 * zeta * r) / Q();
      const double wd = w * std::sqrt(1 - zeta * zeta);
      const double E1 = -D;
      const double E2 = (zeta * w * E1 - C * Omega) / wd;
      return C * std::sin(Omega * t) + D * std::cos(Omega * t) +
             std::exp(-zeta * w * t) * (E1 * std::cos(wd * t) + E2 * std::sin(wd * t));
    }
  };
} // namespace

int
main(int argc, char **argv)
{
  dealii::Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);

  const double period = 1.0, w = 2 * M_PI / period, A = 1.5;
  for (const double zeta : {0.02, 0.05, 0.2})
    for (const double r : {0.5, 1.0, 2.0})
      {
        const Harmonic h{A, r * w, w, zeta};
        // Long enough for the transient to decay to exp(-14) < 1e-6 of its
        // start, then 5 more forcing periods; whole forcing periods.
        const double       T_force  = 2 * M_PI / h.Omega;
        const unsigned int n_cycles = static_cast<unsigned int>(
          std::ceil((14. / (zeta * w)) / T_force)) + 5;
        const unsigned int  per_cycle = 400;
        const double        dt        = T_force / per_cycle;
        const unsigned int  n         = n_cycles * per_cycle;
        AccelerationRecord  record;
        for (unsigned int k = 0; k <= n; ++k)
          {
            record.times.push_back(k * dt);
            record.values.push_back(A * std::sin(h.Omega * k * dt));
          }
        log() << "zeta = " << zeta << ", Omega/w = " << r << " (" << n_cycles
              << " forcing periods)" << std::endl;

        // 1. Every state of the recurrence against the closed form.
        std::vector<double> u, v;
        oscillator_response(record, period, zeta, u, v);
        double worst = 0.;
        for (unsigned int k = 0; k <= n; ++k)
          worst = std::max(worst, std::abs(u[k] - h.u(k * dt)));
        check_below("  max |u - u_exact| / u0 over all samples", worst / h.amplitude(), 1e-4);

        // 2. The steady-state amplitude: the last 5 forcing periods, where the
        // transient is below 1e-6. Sampling 400 points per period misses the
        // crest by at most 1 - cos(pi/400) = 3e-5.
        double late_peak = 0.;
        for (unsigned int k = n - 5 * per_cycle; k <= n; ++k)
          late_peak = std::max(late_peak, std::abs(u[k]));
        check_relative("  steady amplitude max|u| [mm]", 1e3 * late_peak, 1e3 * h.amplitude(), 1e-4);

        // 3. The spectral displacement (peak over the record, no free
        // vibration after it) against the maximum of the closed form on a grid
        // 10 times finer than the samples (crest missed by < 1e-6 there).
        double exact_peak = 0.;
        for (unsigned int k = 0; k <= 10 * n; ++k)
          exact_peak = std::max(exact_peak, std::abs(h.u(0.1 * k * dt)));
        const double sd = peak_oscillator_displacement(record, period, zeta, false);
        check_relative("  SD = max|u| over the record [mm]", 1e3 * sd, 1e3 * exact_peak, 1e-4);

        // 4. At resonance the response grows monotonically to the steady
        // amplitude (A/w^2)/(2 zeta), so PSA = w^2 SD -> A/(2 zeta).
        if (r == 1.0)
          {
            const ResponseSpectrum s = response_spectrum(record, {period}, zeta, false);
            check_relative("  PSA at resonance = A/(2 zeta) [m/s^2]", s.pseudo_acceleration[0],
                           A / (2 * zeta), 1e-4);
            check_relative("  PSV at resonance = A/(2 zeta w) [m/s]", s.pseudo_velocity[0],
                           A / (2 * zeta * w), 1e-4);
          }
      }
}
