// The NB 35047-2015 design spectrum and the user table (design_spectrum.h)
// against values worked out by hand from the standard's definition:
//   beta = 1 + 10 (beta_max - 1) T   (T <= 0.1 s), beta_max up to T_g,
//   beta_max (T_g/T)^0.6 beyond, never below 0.2 beta_max.
// The reference numbers below are typed in (decimal expansions computed
// once, outside the code), so they do not come from the code under test; the
// only error is round-off, hence the tolerance 1e-12.
// Then the malformed inputs, each with its message.

#include <archdam/loads/design_spectrum.h>
#include <archdam/loads/record_io.h>

#include "archdam_tests.h"

using namespace archdam::loads;
using archdam::testing::check_relative;
using archdam::testing::log;
using archdam::testing::expect_input_error;

int
main(int argc, char **argv)
{
  dealii::Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  const double g = 9.80665;

  log() << "NB 35047-2015, arch dam (beta_max 2.50), T_g = 0.40 s, PGA 0.3 g" << std::endl;
  const TargetSpectrum arch = TargetSpectrum::nb35047(0.3 * g, 0.4, 2.5);
  const double         tol  = 1e-12;
  // Rising branch: beta(0) = 1, beta(0.05) = 1 + 10 * 1.5 * 0.05 = 1.75,
  // beta(0.1) = 1 + 10 * 1.5 * 0.1 = 2.5.
  check_relative("beta(0)", arch.amplification(0.), 1.0, tol);
  check_relative("beta(0.05 s)", arch.amplification(0.05), 1.75, tol);
  check_relative("beta(0.1 s)", arch.amplification(0.1), 2.5, tol);
  // Plateau.
  check_relative("beta(0.25 s)", arch.amplification(0.25), 2.5, tol);
  check_relative("beta(T_g = 0.4 s)", arch.amplification(0.4), 2.5, tol);
  // Descent: 2.5 (0.4/0.8)^0.6 = 2.5 * 2^-0.6 = 2.5 * 0.6597539553864471;
  // 2.5 (0.4/0.6)^0.6 = 1.9601317042077895; 2.5 (0.4/3)^0.6 = 0.7462824878234051;
  // 2.5 (0.4/2)^0.6 = 2.5 * 0.3807307877431757.
  check_relative("beta(0.6 s)", arch.amplification(0.6), 1.9601317042077895, tol);
  check_relative("beta(0.8 s)", arch.amplification(0.8), 2.5 * 0.6597539553864471, tol);
  check_relative("beta(2 s)", arch.amplification(2.0), 2.5 * 0.3807307877431757, tol);
  check_relative("beta(3 s)", arch.amplification(3.0), 0.7462824878234051, tol);
  // Floor 0.2 * 2.5 = 0.5, reached at T = 0.4 * 5^(1/0.6) = 5.848035476425733 s.
  check_relative("beta(5.8 s), just above the floor", arch.amplification(5.8),
                 2.5 * std::pow(0.4 / 5.8, 0.6), tol);
  check_relative("beta(5.9 s) = floor 0.5", arch.amplification(5.9), 0.5, tol);
  check_relative("beta(10 s) = floor 0.5", arch.amplification(10.), 0.5, tol);
  // S_a = PGA beta, in m/s^2: 0.3 g * 2.5 on the plateau.
  check_relative("S_a(0.3 s) [m/s^2]", arch.acceleration(0.3), 0.75 * g, tol);
  check_relative("PGA [m/s^2]", arch.pga(), 0.3 * g, tol);
  check_relative("S_a of the spectrum scaled by 2/3 at 0.3 s [m/s^2]",
                 arch.scaled(2. / 3.).acceleration(0.3), 0.5 * g, tol);
  log() << "description: " << arch.description() << std::endl;

  log() << "\nGravity dam (beta_max 2.00), T_g = 0.20 s" << std::endl;
  const TargetSpectrum gravity = TargetSpectrum::nb35047(0.1 * g, 0.2, 2.0);
  // 1 + 10 * 1.0 * 0.07 = 1.7; 2.0 (0.2/0.4)^0.6 = 2 * 0.6597539553864471;
  // floor 0.4 from T = 0.2 * 5^(1/0.6) = 2.924 s.
  check_relative("beta(0.07 s)", gravity.amplification(0.07), 1.7, tol);
  check_relative("beta(0.15 s)", gravity.amplification(0.15), 2.0, tol);
  check_relative("beta(0.4 s)", gravity.amplification(0.4), 2 * 0.6597539553864471, tol);
  check_relative("beta(4 s) = floor 0.4", gravity.amplification(4.0), 0.4, tol);

  log() << "\nUser table \"0: 1; 0.1: 2.5; 0.5: 2.5; 2: 1; 4: 0.5\", PGA 0.2 g" << std::endl;
  const TargetSpectrum table = TargetSpectrum::table(
    0.2 * g, parse_spectrum_table("0: 1; 0.1: 2.5; 0.5 : 2.5 ;2:1; 4: 0.5", "test: "));
  // Linear between points: at 0.05 s the mean of 1 and 2.5; at 1.25 s the
  // mean of 2.5 and 1; at 3 s the mean of 1 and 0.5; constant beyond 4 s.
  check_relative("beta(0.05 s)", table.amplification(0.05), 1.75, tol);
  check_relative("beta(0.3 s)", table.amplification(0.3), 2.5, tol);
  check_relative("beta(1.25 s)", table.amplification(1.25), 1.75, tol);
  check_relative("beta(2 s), a table point", table.amplification(2.0), 1.0, tol);
  check_relative("beta(3 s)", table.amplification(3.0), 0.75, tol);
  check_relative("beta(8 s), beyond the last point", table.amplification(8.0), 0.5, tol);
  check_relative("S_a(0.3 s) [m/s^2]", table.acceleration(0.3), 0.5 * g, tol);
  log() << "description: " << table.description() << std::endl;

  log() << "\nMalformed input" << std::endl;
  expect_input_error("T_g below the end of the rising branch",
               [&] { TargetSpectrum::nb35047(0.3 * g, 0.05, 2.5); });
  expect_input_error("PGA zero", [&] { TargetSpectrum::nb35047(0., 0.4, 2.5); });
  expect_input_error("beta_max below 1", [&] { TargetSpectrum::nb35047(0.3 * g, 0.4, 0.8); });
  expect_input_error("table entry without a colon",
               [&] { parse_spectrum_table("0: 1; 0.1 2.5", "Spectrum table: "); });
  expect_input_error("table entry with text",
               [&] { parse_spectrum_table("0: 1; 0.1: high", "Spectrum table: "); });
  expect_input_error("table with one point", [&] {
    TargetSpectrum::table(g, parse_spectrum_table("0: 1", ""));
  });
  expect_input_error("table periods not increasing", [&] {
    TargetSpectrum::table(g, parse_spectrum_table("0: 1; 0.5: 2; 0.5: 2.2", ""));
  });
  expect_input_error("table with a negative period", [&] {
    TargetSpectrum::table(g, parse_spectrum_table("-0.1: 1; 0.5: 2", ""));
  });
  expect_input_error("table with beta = 0", [&] {
    TargetSpectrum::table(g, parse_spectrum_table("0: 1; 0.5: 0", ""));
  });
}
