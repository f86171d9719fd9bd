// Verification: the first bending frequency of a slender concrete cantilever,
// measured from a free-vibration run of the whole program
// (analysis::Simulation::run()), against Timoshenko beam theory, on three
// meshes of increasing refinement.
//
// Model. A concrete column 1 m x 1 m in section and 10 m high (box mesh, no
// rock: the base z = 0 is fixed), Q2 elements. Slenderness L/h = 10: slender
// enough that a beam theory describes the 3-D body well, stocky enough that
// shear deformation and rotary inertia matter (Timoshenko is 0.65 % below
// Euler-Bernoulli here), so the reference must be Timoshenko's. Poisson's
// ratio 0: the fully clamped 3-D base then does not stiffen the root by
// preventing the lateral (Poisson) contraction, and the shear coefficient
// k = 5/6 of a rectangle is exact for nu = 0 (Cowper: 10(1+nu)/(12+11nu)).
// No gravity, no damping.
//
// Excitation. A half-sine base acceleration in x of duration ~T1/2 (written
// here as a two-column file in m/s^2 and read through Ground motion/
// Component x), then free vibration. The tip (top centre) displacement ux is
// recorded by a monitor; the period is measured from its zero crossings after
// the pulse (linear interpolation between steps, least-squares line through
// all crossing times over ~5 periods). The average-acceleration rule lengthens
// the period: a mode of frequency w is integrated with frequency W where
// tan(W dt/2) = w dt/2, so the measured W is corrected exactly by
// w = (2/dt) tan(W dt/2) (the correction is ~1e-4 at dt ~ T1/200).
//
// Reference. Timoshenko beam, clamped-free, first root of Huang's (1961)
// frequency equation, with b^2 = rho A w^2 L^4/(E I), r^2 = I/(A L^2),
// s^2 = E I/(k A G L^2):
//   2 + [b^2 (r^2 - s^2)^2 + 2] cosh(b alpha) cos(b beta)
//     - b (r^2 + s^2)/sqrt(1 - b^2 r^2 s^2) sinh(b alpha) sin(b beta) = 0,
//   alpha, beta = (1/sqrt2) sqrt(-/+ (r^2 + s^2) + sqrt((r^2 - s^2)^2 + 4/b^2)).
// The formula is checked here in two ways that do not depend on it:
//  - a second method: shooting on the Timoshenko ODEs (w, psi, Q, M) from the
//    clamped end (RK4), the root of the 2x2 free-end determinant;
//  - for r = s = 0 it must give the Euler-Bernoulli root of
//    1 + cosh(l) cos(l) = 0, l = 1.875104 (Blevins, table 8-1).
// The Euler-Bernoulli value is printed for information.
//
// Tolerance. The FE model is 3-D elasticity, not a beam: the two differ by
// O((h/L)^2) effects beyond what Timoshenko captures (the 3-D clamp prevents
// the shear warping of the root section, the section is not exactly rigid in
// its plane, k = 5/6 holds for the Saint-Venant shear flow away from the
// ends). The whole shear + rotary-inertia correction is 0.65 % here
// ((h/L)^2 = 1 %), and these effects are a small fraction of it. The finest
// mesh is asked to be within 0.2 % of Timoshenko: well above what remains
// (Q2 discretization error of the 3x3x12 mesh ~0.01 % from the convergence
// sequence, a 3-D/Timoshenko difference of a few 1e-5 by extrapolation, and
// ~0.005 % scatter of the zero-crossing measurement from the higher modes
// excited by the pulse, seen by varying pulse, dt and record length), and
// less than a third of the Timoshenko/Euler-Bernoulli gap, so a model without
// shear deformation or rotary inertia, or with a mass or stiffness off by
// 0.4 %, fails. The errors of the three meshes must decrease monotonically
// (measured 0.55 %, 0.049 %, 0.013 %: Q2 discretization error, O(h^4) in the
// frequency, dominates on the coarse meshes), and the finest mesh must be
// closer to Timoshenko than to Euler-Bernoulli.

#include <archdam/analysis/simulation.h>
#include <archdam/parameters/parameters.h>

#include <deal.II/base/mpi.h>

#include <cmath>
#include <fstream>
#include <iomanip>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

#include "archdam_tests.h"
#include "beam_reference.h"

using archdam::testing::check_relative;
using archdam::testing::first_root;
using archdam::testing::log;

namespace
{
  // Material and geometry (SI units).
  constexpr double E      = 22e9;   // Pa
  constexpr double rho    = 2446.5; // kg/m^3
  constexpr double nu     = 0.;
  constexpr double h      = 1.;     // section side, m (x and y)
  constexpr double length = 10.;    // cantilever length = box height (z), m

  const archdam::testing::SquareCantilever beam{E, rho, nu, h, length};

  /// Round to @p digits significant digits (for output that must not depend
  /// on round-off).
  double
  rounded(const double x, const int digits)
  {
    if (x == 0.)
      return 0.;
    const int    exponent = static_cast<int>(std::floor(std::log10(std::abs(x))));
    const double scale    = std::pow(10., digits - 1 - exponent);
    return std::round(x * scale) / scale;
  }

  struct Measurement
  {
    double       frequency; // Hz, corrected for the period elongation
    unsigned int n_crossings;
  };

  /// Run the whole program on the mesh n x n x 4n of Q2 cells and measure the
  /// first frequency from the tip displacement.
  Measurement
  run_mesh(const unsigned int n, const double dt, const double end_time,
           const double pulse_duration, const std::string &pulse_file)
  {
    std::ostringstream prm;
    prm << "subsection Mesh\n"
        << "  set Source = box\n"
        << "  subsection Box\n"
        << "    set Length = " << h << "\n"
        << "    set Width = " << h << "\n"
        << "    set Height = " << length << "\n"
        << "    set Number of blocks = 1\n"
        << "    set Cells in x = " << n << "\n"
        << "    set Cells in y = " << n << "\n"
        << "    set Cells in z = " << 4 * n << "\n"
        << "    set Rock depth = 0\n"
        << "  end\n"
        << "end\n"
        << "subsection Finite element\n  set Degree = 2\nend\n"
        << "subsection Materials\n  subsection Concrete\n"
        << "    set Young's modulus = " << E << "\n"
        << "    set Poisson's ratio = " << nu << "\n"
        << "    set Density = " << rho << "\n"
        << "  end\nend\n"
        << "subsection Damping\n  set Mode = coefficients\n"
        << "  set Mass proportional coefficient = 0\n"
        << "  set Stiffness proportional coefficient = 0\nend\n"
        << "subsection Time integration\n"
        << "  set Time step = " << std::setprecision(17) << dt << "\n"
        << "  set End time = " << end_time << "\n"
        << "  set Beta1 = 0.5\n  set Beta2 = 0.25\nend\n"
        << "subsection Ground motion\n  subsection Component x\n"
        << "    set File = " << pulse_file << "\n"
        << "    set Format = two-column\n    set Units = m/s^2\n  end\nend\n"
        << "subsection Static loads\n  set Gravity = false\nend\n"
        << "subsection Analysis\n  set Case name = cantilever_frequency\n"
        << "  set Stages = dynamic\nend\n"
        << "subsection Monitors\n  set Points = tip: " << h / 2 << ", " << h / 2 << ", "
        << length << "\n  set Quantities = displacement\nend\n"
        << "subsection Output\n  set Directory = results_cantilever_" << n << "\n"
        << "  set Field output interval = 0\n  set Progress = false\n"
        << "  set Timer summary = false\nend\n";

    const archdam::Parameters    p = archdam::parameters_from_string(prm.str());
    std::ostringstream           screen;
    archdam::analysis::Simulation sim(p, MPI_COMM_WORLD, screen);
    sim.run();

    const auto  &names = sim.recorder<archdam::output::MonitorHistories>()->columns();
    const auto  &rows  = sim.recorder<archdam::output::MonitorHistories>()->rows();
    unsigned int col   = 0;
    for (unsigned int c = 0; c < names.size(); ++c)
      if (names[c] == "tip.ux [m]")
        col = c;
    if (col == 0)
      throw std::runtime_error("no column tip.ux [m]");

    // Zero crossings of ux after the pulse, linearly interpolated.
    std::vector<double> crossings;
    for (unsigned int r = 1; r < rows.size(); ++r)
      {
        const double t0 = rows[r - 1][0], t1 = rows[r][0];
        const double u0 = rows[r - 1][col], u1 = rows[r][col];
        if (t0 > pulse_duration && ((u0 < 0 && u1 >= 0) || (u0 > 0 && u1 <= 0)))
          crossings.push_back(t0 - u0 * (t1 - t0) / (u1 - u0));
      }
    // Least-squares line t_j = t_0 + j T/2 through all crossings.
    const double m = crossings.size();
    double       sj = 0, st = 0, sjj = 0, sjt = 0;
    for (unsigned int j = 0; j < crossings.size(); ++j)
      {
        sj += j;
        st += crossings[j];
        sjj += double(j) * j;
        sjt += j * crossings[j];
      }
    const double half_period = (m * sjt - sj * st) / (m * sjj - sj * sj);
    const double W           = 2. * M_PI / (2. * half_period);
    // Undo the period elongation of the average-acceleration rule.
    const double w = 2. / dt * std::tan(0.5 * W * dt);
    return {w / (2. * M_PI), static_cast<unsigned int>(crossings.size())};
  }
} // namespace

int
main(int argc, char **argv)
{
  dealii::Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  try
    {
      log() << std::setprecision(6);

      // ---------------------------------------------------------------------
      // References.
      const double r2 = beam.r2();
      const double s2 = beam.s2();

      // Euler-Bernoulli: first root of 1 + cosh(l) cos(l) = 0.
      const double l_eb =
        first_root([](const double l) { return 1. + std::cosh(l) * std::cos(l); }, 1., 3.);
      check_relative("Euler-Bernoulli root of 1 + cosh(l) cos(l) = 0", l_eb, 1.875104, 1e-6, 7);
      const double w_eb = beam.euler_bernoulli_omega(l_eb);
      log() << "Euler-Bernoulli first frequency (information): " << std::setprecision(5)
            << w_eb / (2 * M_PI) << " Hz" << std::endl;

      // Huang's equation with r = s = 0 must reduce to Euler-Bernoulli.
      const double w_huang_eb = first_root(
        [](const double w) { return beam.huang(w, 0., 0.); }, 0.5 * w_eb, 1.5 * w_eb);
      check_relative("Huang's equation with r = s = 0: l = sqrt(b)",
                     std::sqrt(std::sqrt(rho * beam.area() * w_huang_eb * w_huang_eb *
                                         std::pow(length, 4) / (E * beam.inertia()))),
                     l_eb, 1e-10, 7);

      // Timoshenko: Huang's equation against shooting on the ODEs.
      const double w_huang = first_root(
        [&](const double w) { return beam.huang(w, r2, s2); }, 0.5 * w_eb, 1.5 * w_eb);
      const double w_shoot =
        first_root([](const double w) { return beam.shooting(w); }, 0.5 * w_eb, 1.5 * w_eb, 100);
      check_relative("Timoshenko first frequency [Hz], Huang's equation vs shooting",
                     w_huang / (2 * M_PI), w_shoot / (2 * M_PI), 1e-8, 6);
      const double f_ref = w_huang / (2 * M_PI);
      log() << "Timoshenko / Euler-Bernoulli = " << std::setprecision(4) << w_huang / w_eb
            << " (r^2 = " << std::setprecision(3) << r2 << ", s^2 = " << s2 << ")"
            << std::endl;

      // ---------------------------------------------------------------------
      // The run: dt ~ T1/200, pulse ~ T1/2, about 5 free periods after it.
      const double T1             = 1. / f_ref;
      const double dt             = 0.001;
      const double pulse_duration = 0.1;
      const double end_time       = 1.2;
      log() << "T1 = " << std::setprecision(4) << T1 << " s, dt = T1/"
            << std::lround(T1 / dt) << ", pulse " << pulse_duration << " s = "
            << std::setprecision(2) << pulse_duration / T1 << " T1, end time "
            << std::setprecision(3) << end_time / T1 << " T1" << std::endl;
      const double x = 0.5 * 2 * M_PI * dt / T1;
      log() << "average-acceleration period elongation at this dt (corrected for): "
            << std::setprecision(2) << 100. * (x / std::atan(x) - 1.) << " %" << std::endl;

      // Half-sine pulse, amplitude 1 m/s^2, finely sampled, zero afterwards.
      const std::string pulse_file = "cantilever_pulse.txt";
      if (dealii::Utilities::MPI::this_mpi_process(MPI_COMM_WORLD) == 0)
        {
          std::ofstream out(pulse_file);
          out << "# time [s]  acceleration [m/s^2]: half-sine base pulse\n"
              << std::setprecision(17);
          const unsigned int n = 1000;
          for (unsigned int i = 0; i <= n; ++i)
            {
              const double t = pulse_duration * i / n;
              out << t << " " << (i == n ? 0. : std::sin(M_PI * t / pulse_duration)) << "\n";
            }
        }
      MPI_Barrier(MPI_COMM_WORLD);

      // ---------------------------------------------------------------------
      // Mesh convergence.
      std::vector<double> errors;
      double              f_finest = 0.;
      for (const unsigned int n : {1u, 2u, 3u})
        {
          const Measurement m = run_mesh(n, dt, end_time, pulse_duration, pulse_file);
          const double      e = std::abs(m.frequency - f_ref) / f_ref;
          errors.push_back(e);
          f_finest = m.frequency;
          log() << "Q2 mesh " << n << "x" << n << "x" << 4 * n << ": " << m.n_crossings
                << " zero crossings, f1 = " << std::setprecision(4) << m.frequency
                << " Hz, error against Timoshenko " << rounded(100. * e, 2) << " %"
                << std::endl;
        }
      bool decreasing = true;
      for (unsigned int i = 1; i < errors.size(); ++i)
        decreasing = decreasing && errors[i] < errors[i - 1];
      log() << "error decreases with refinement: " << (decreasing ? "yes" : "NO") << std::endl;
      check_relative("finest mesh f1 [Hz] against Timoshenko", f_finest, f_ref, 2e-3, 4);
      const double f_eb = w_eb / (2 * M_PI);
      log() << "finest mesh closer to Timoshenko than to Euler-Bernoulli: "
            << (std::abs(f_finest - f_ref) < std::abs(f_finest - f_eb) ? "yes" : "NO")
            << std::endl;
    }
  catch (const std::exception &e)
    {
      std::cerr << "Exception: " << e.what() << std::endl;
      return 1;
    }
  return 0;
}
