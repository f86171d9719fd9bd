// Baseline correction (record_processing.h) on records known to drift: the
// final ground velocity and displacement before and after, integrated here by
// the test's own loop (trapezoidal velocity, and the exact displacement of an
// acceleration linear between samples, d += h v + h^2 (a0/3 + a1/6), written
// independently of the library's integrate()).
//
//  1. The 1940 El Centro N-S record in its classic "Peknold" digitization:
//     5-decimal values in g, not baseline-corrected; its displacement ends
//     at -2.5 cm, 12 % of its peak.
//  2. The Pacoima Dam record (RSN77, already processed by PEER: it ends at
//     rest) with a constant offset of 0.002 g added, the classic instrument
//     baseline shift. The drift it causes has a closed form, Delta v = c T,
//     Delta d = c T^2 / 2 with c = 0.002 g and T the duration, which the
//     drift before correction must show.
//
// Tolerances. After the correction the end values vanish up to round-off
// (the constraints are imposed on the same exact integration), so |v_end| and
// |d_end| must be below 1e-8 of the peaks. The correction must not change the
// motion itself much: PGA within 1 %; for Pacoima, the corrected record
// against the original one: its acceleration within 2 % of the offset removed
// (the fit removes the offset, a t^2 term in displacement, exactly, and moves
// only the long-period content that the 6th-degree polynomial also
// captures), its 5 %-damped spectrum within 1 % at 0.1 ... 2 s.

#include <archdam/loads/record_io.h>
#include <archdam/loads/record_processing.h>
#include <archdam/loads/response_spectrum.h>

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
  const std::string &data = archdam::testing::ground_motions;
  const double       g    = 9.80665;

  /// @p x in cm with one decimal, without "-0.0" for round-off values.
  double
  cm(const double x)
  {
    const double rounded = std::round(1000 * x) / 10;
    return rounded == 0 ? 0. : rounded;
  }

  void
  print(const std::string &what, const Ends &e)
  {
    log() << std::fixed << std::setprecision(1) << "  " << what << ": end velocity "
          << cm(e.v_end) << " cm/s (peak " << cm(e.v_peak) << "), end displacement "
          << cm(e.d_end) << " cm (peak " << cm(e.d_peak) << ")" << std::defaultfloat << std::endl;
  }

  void
  check_corrected(const AccelerationRecord &before, const AccelerationRecord &after)
  {
    const Ends e = ends(after);
    check_below("  after: |v_end| / peak v", std::abs(e.v_end) / e.v_peak, 1e-8);
    check_below("  after: |d_end| / peak d", std::abs(e.d_end) / e.d_peak, 1e-8);
    check_relative("  after: PGA [g]", after.peak() / g, before.peak() / g, 0.01);
  }
} // namespace

int
main(int argc, char **argv)
{
  dealii::Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);

  log() << "1. El Centro 1940 N-S (Peknold), uncorrected" << std::endl;
  const AccelerationRecord elcentro = read_at2(data + "elCentro_Peknold.AT2");
  const Ends               raw      = ends(elcentro);
  print("before", raw);
  log() << "  before: the displacement drifts, |d_end| > 10 % of its peak: "
        << (std::abs(raw.d_end) > 0.1 * raw.d_peak ? "yes" : "NO") << std::endl;
  const AccelerationRecord corrected = baseline_correction(elcentro);
  print("after", ends(corrected));
  check_corrected(elcentro, corrected);

  log() << "\n2. Pacoima Dam 1971 (RSN77) + 0.002 g offset" << std::endl;
  const AccelerationRecord pacoima = read_at2(data + "RSN77_SFERN_PUL164.AT2");
  AccelerationRecord       shifted = pacoima;
  const double             c       = 0.002 * g;
  for (double &a : shifted.values)
    a += c;
  const double T       = pacoima.times.back();
  const Ends   origin  = ends(pacoima);
  const Ends   drifted = ends(shifted);
  print("original", origin);
  print("with offset", drifted);
  // The offset adds c T to v_end and c T^2/2 to d_end exactly (round-off).
  check_relative("  drift of v_end = c T [m/s]", drifted.v_end - origin.v_end, c * T, 1e-9);
  check_relative("  drift of d_end = c T^2/2 [m]", drifted.d_end - origin.d_end, c * T * T / 2,
                 1e-9);
  const AccelerationRecord fixed = baseline_correction(shifted);
  print("after", ends(fixed));
  check_corrected(pacoima, fixed);

  double worst = 0;
  for (std::size_t k = 0; k < fixed.values.size(); ++k)
    worst = std::max(worst, std::abs(fixed.values[k] - pacoima.values[k]));
  check_below("  max |corrected - original acceleration| / offset", worst / c, 0.02);
  const std::vector<double> periods = {0.1, 0.2, 0.5, 1.0, 2.0};
  const ResponseSpectrum    s0 = response_spectrum(pacoima, periods, 0.05);
  const ResponseSpectrum    s1 = response_spectrum(fixed, periods, 0.05);
  double                    spectral = 0;
  for (std::size_t i = 0; i < periods.size(); ++i)
    spectral = std::max(spectral, std::abs(s1.pseudo_acceleration[i] / s0.pseudo_acceleration[i] - 1));
  check_below("  max relative change of PSA (5 %) at 0.1, 0.2, 0.5, 1, 2 s", spectral, 0.01);
}
