// Response spectrum (Nigam-Jennings recurrence with sub-steps, Hermite peaks
// and the free vibration after the record, response_spectrum.h) against an
// independent time integration: the classical 4th-order Runge-Kutta scheme on
//   u'' + 2 zeta w u' + w^2 u = -a_g(t),
// with a_g linear between the record's samples, steps aligned with the
// samples (so that the input is smooth inside every step) and at most T/2000
// long, continued with a_g = 0 for 2 periods after the record (the free
// vibration peaks within half a period and then decays). Its peak |u| over the
// steps is a reference accurate to about 1e-6: RK4's error is of order
// (w h)^4/120 ~ 1e-13 per step, ~1e-8 over 10^5 steps, and the crest is
// missed by at most 1 - cos(pi/2000) = 1.2e-6.
//
// The recurrence's own errors: none from the integration (exact for the
// piecewise-linear input) beyond round-off, and the Hermite location of the
// peaks within sub-steps of at most T/20, O((w h)^4/384) = 2.5e-5 at most.
// The tolerance is 1e-4.
//
// Inputs: the 1940 El Centro record (elCentro_Peknold.AT2, dt = 0.02 s, so
// periods down to 0.05 s use several sub-steps per sample), and the first
// 6 s of the Pacoima Dam record (RSN77, dt = 0.01 s) resampled at irregular
// times (the recurrence's path for irregular records). Periods 0.05 ... 10 s,
// damping ratios 0, 2 %, 5 %, 20 %.

#include <archdam/loads/record_io.h>
#include <archdam/loads/response_spectrum.h>

#include <cmath>
#include <string>
#include <vector>

#include "archdam_tests.h"
#include "motion_reference.h"

using namespace archdam::loads;
using archdam::testing::log;

namespace
{
  const std::string &data = archdam::testing::ground_motions;

  double
  rk4_peak(const AccelerationRecord &r, const double T, const double zeta)
  {
    return archdam::testing::rk4_peak(r, T, zeta, 2000);
  }

  void
  compare(const AccelerationRecord &r, const std::string &name)
  {
    log() << name << std::endl;
    const std::vector<double> periods = {0.05, 0.2, 0.5, 1.0, 2.0, 5.0, 10.0};
    for (const double zeta : {0.0, 0.02, 0.05, 0.2})
      {
        const ResponseSpectrum s = response_spectrum(r, periods, zeta);
        double                 worst = 0;
        for (std::size_t i = 0; i < periods.size(); ++i)
          {
            const double reference = rk4_peak(r, periods[i], zeta);
            worst = std::max(worst, std::abs(s.displacement[i] - reference) / reference);
            // PSA = w^2 SD, PSV = w SD (definitions), checked against the
            // reference too.
            const double w = 2 * M_PI / periods[i];
            worst = std::max(worst, std::abs(s.pseudo_acceleration[i] - w * w * reference) /
                                      (w * w * reference));
            worst = std::max(worst,
                             std::abs(s.pseudo_velocity[i] - w * reference) / (w * reference));
          }
        archdam::testing::check_below("  zeta = " + std::to_string(zeta).substr(0, 4) +
                                        ": max relative difference of SD, PSV, PSA at "
                                        "T = 0.05, 0.2, 0.5, 1, 2, 5, 10 s",
                                      worst, 1e-4);
      }
  }
} // namespace

int
main(int argc, char **argv)
{
  dealii::Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);

  compare(read_at2(data + "elCentro_Peknold.AT2"), "El Centro 1940 (dt = 0.02 s)");

  // Irregular times: Pacoima's first 6 s at t_k + 0.004 sin(k) (interpolated).
  const AccelerationRecord pacoima = read_at2(data + "RSN77_SFERN_PUL164.AT2");
  AccelerationRecord       irregular;
  for (unsigned int k = 0; k <= 600; ++k)
    {
      const double t = 0.01 * k + (k > 0 && k < 600 ? 0.004 * std::sin(1. * k) : 0.);
      irregular.times.push_back(t);
      irregular.values.push_back(pacoima.value(t));
    }
  compare(irregular, "Pacoima Dam 1971, first 6 s at irregular times");
}
