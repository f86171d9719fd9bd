// Verification (doc/verification.md, "Reservoir"): a transient ground motion in
// the time domain against the frequency-domain solution, and the effect of
// the upstream truncation (radiation condition).
//
// Model. The channel of reservoir_rigid_dam (H = 50 m, c = 1440 m/s, rigid
// fixed dam, Q2, h = H/8), bottom reflection coefficient alpha_r = 0.5. The
// coupled dam-water system of the paper's eq. 3.2 (coupled_system.h) is
// integrated by the generalized Newmark scheme with the general damping
// matrix, its symmetric indefinite effective matrix factorized once as
// LDL^T. Ground motion: a_g(t) = sin^2(pi t / t_d), t_d = 0.1 s (most of its
// energy below 3 omega_1), in x; dt = 2 ms, 1 s.
//
// Reference. The average-acceleration rule is the trapezoidal rule, which
// maps a linear system exactly through the bilinear transform: the discrete
// response to the sampled input a_n is
//   p_n = IDFT[ P(Omega_k) DFT(a)_k ],  Omega_k = (2/dt) tan(omega_k dt / 2),
// with P(omega) the exact frequency response of the channel (the series with
// the complex eigenvalues of the absorbing bottom, reservoir_reference.h),
// P(-omega) = conj P(omega), on a record padded to 16 s (the response has
// decayed long before: no wrap-around). Frequencies above 10 omega_1, where
// the input spectrum is below 1e-6 of its peak, are left out. So the
// comparison measures the spatial discretization only: the face pressure at
// the heel and at mid-height must match within 0.1 % of the peak pressure
// (the frequency-domain error of this mesh, reservoir_rigid_dam, is 0.2 % at
// worst near the resonance and far less where the input has its energy).
//
// Truncation. The same run with the reservoir truncated at 2H and at 4H
// (Sommerfeld condition): the face pressure histories must differ by less
// than 5 % of the peak; each is also compared with the infinite channel
// (the reference synthesized with L = infinity), printed.

#include <archdam/loads/fft.h>
#include <archdam/physics/reservoir/coupled_system.h>
#include <archdam/physics/solid/solid_operators.h>
#include <archdam/time/newmark.h>

#include "archdam_tests.h"
#include "reservoir_reference.h"

using namespace archdam;
using namespace archdam::testing;
namespace reservoir = archdam::physics::reservoir;

namespace
{
  const double dt = 0.002, t_d = 0.1, duration = 1.0;
  const std::vector<double> z_over_H = {0., 0.5};

  double
  ground_acceleration(const double t)
  {
    return t < t_d ? std::pow(std::sin(M_PI * t / t_d), 2) : 0.;
  }

  /// Face pressure histories (one per height) of the coupled FE model.
  std::vector<std::vector<double>>
  fe_histories(const Channel &ch, const unsigned int nz)
  {
    dealii::parallel::shared::Triangulation<dim> tria(MPI_COMM_WORLD);
    make_channel(ch, static_cast<unsigned int>(std::lround(ch.L / ch.H * nz)), nz, 0, tria);
    reservoir::ReservoirParameters rp;
    rp.model       = reservoir::Model::compressible;
    rp.density     = ch.rho;
    rp.sound_speed = ch.c;
    rp.reflection  = 0.5;
    fe::FESpace space(tria, fe::FiniteElementParameters{});
    space.setup({}, [&](dealii::AffineConstraints<double> &c) {
      fix_solid(space, c);
      reservoir::constrain_free_surface(space, rp, c);
    });
    const auto pairs    = reservoir::match_interface_faces(space);
    space.add_couplings = [&](dealii::DynamicSparsityPattern &dsp) {
      reservoir::add_interface_couplings(space, pairs, dsp);
    };
    SparseMatrix M, K;
    physics::solid::assemble_mass_and_stiffness(space, physics::solid::MaterialParameters{},
                                                physics::solid::InertiaOf::dam, M, K);
    reservoir::FluidOperators ops;
    reservoir::assemble_fluid_operators(space, rp, 9.81, pairs, ops);

    time::NewmarkParameters np;
    np.time_step = dt;
    reservoir::CoupledSystem sys;
    reservoir::form_coupled_system(ops, rp.density, np.beta2, dt, M, K, {{0., &M}, {0., &K}}, sys);
    time::NewmarkIntegrator newmark(np, sys.mass, sys.damping, sys.stiffness, space.constraints,
                                    false);
    time::NewmarkState s;
    for (Vector *v : {&s.u, &s.v, &s.a})
      space.reinit(*v);
    Vector load, ghosted;
    space.reinit(load);
    space.reinit_ghosted(ghosted);
    std::vector<std::vector<double>> p(z_over_H.size());
    const unsigned int               n_steps = std::lround(duration / dt);
    for (unsigned int n = 1; n <= n_steps; ++n)
      {
        load = sys.fluid_influence[0];
        load *= -ground_acceleration(n * dt);
        newmark.advance(load, s);
        ghosted = s.u;
        for (unsigned int i = 0; i < z_over_H.size(); ++i)
          p[i].push_back(
            point_value(space, ghosted, dealii::Point<dim>(0, ch.W / 2, z_over_H[i] * ch.H), dim));
      }
    return p;
  }

  /// The discrete response p_1 ... p_n of the trapezoidal rule (see above).
  std::vector<std::vector<double>>
  reference_histories(const Channel &ch, const double L)
  {
    const double       record = 16.;
    const unsigned int N      = loads::next_power_of_two(std::lround(record / dt));
    std::vector<complex> a(N, 0.);
    for (unsigned int n = 0; n < N; ++n)
      a[n] = ground_acceleration(n * dt);
    loads::fft(a);
    const double omega1 = M_PI * ch.c / (2 * ch.H);
    std::vector<double> z;
    for (const double h : z_over_H)
      z.push_back(h * ch.H);
    std::vector<std::vector<complex>> P(z.size(), std::vector<complex>(N, 0.));
    for (unsigned int k = 1; k < N / 2; ++k)
      {
        const double omega = 2 * M_PI * k / (N * dt);
        const double Omega = 2 / dt * std::tan(omega * dt / 2);
        if (Omega > 10 * omega1)
          break;
        const auto response = face_pressure(ch, Omega, z, L, 2000);
        for (unsigned int i = 0; i < z.size(); ++i)
          {
            P[i][k]     = response[i] * a[k];
            P[i][N - k] = std::conj(P[i][k]);
          }
      }
    // omega = 0: the incompressible static limit
    const auto response0 = face_pressure(ch, 0., z, L, 2000);
    std::vector<std::vector<double>> p(z.size());
    for (unsigned int i = 0; i < z.size(); ++i)
      {
        P[i][0] = response0[i] * a[0];
        loads::fft(P[i], true);
        for (unsigned int n = 1; n <= std::lround(duration / dt); ++n)
          p[i].push_back(P[i][n].real());
      }
    return p;
  }

  /// max |a - b| / max |b| over all heights and steps
  double
  difference(const std::vector<std::vector<double>> &a, const std::vector<std::vector<double>> &b)
  {
    double err = 0., peak = 0.;
    for (unsigned int i = 0; i < a.size(); ++i)
      for (unsigned int n = 0; n < a[i].size(); ++n)
        {
          err  = std::max(err, std::abs(a[i][n] - b[i][n]));
          peak = std::max(peak, std::abs(b[i][n]));
        }
    return err / peak;
  }
} // namespace

int
main(int argc, char **argv)
{
  dealii::Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  Channel ch;
  ch.q    = (1 - 0.5) / (ch.c * (1 + 0.5));
  bool ok = true;

  ch.L             = 3 * ch.H;
  const auto fe    = fe_histories(ch, 8);
  const auto ref   = reference_histories(ch, ch.L);
  double     peak  = 0.;
  for (const double v : ref[0])
    peak = std::max(peak, std::abs(v));
  log() << "Truncation at 3H, h = H/8: peak heel pressure " << std::setprecision(3)
        << peak / (ch.rho * ch.H) << " rho_w H (per m/s^2 of peak ground acceleration)"
        << std::endl;
  log() << "  time domain vs frequency-domain synthesis: largest difference "
        << std::setprecision(2) << difference(fe, ref) << " of the peak" << std::endl;
  ok &= check_below("  time domain vs frequency-domain synthesis, relative to the peak",
                    difference(fe, ref), 1e-3);

  ch.L           = 2 * ch.H;
  const auto fe2 = fe_histories(ch, 8);
  ch.L           = 4 * ch.H;
  const auto fe4 = fe_histories(ch, 8);
  const auto inf = reference_histories(ch, 0.);
  log() << "Truncation at 2H vs 4H: difference of the face pressure histories "
        << std::setprecision(2) << difference(fe2, fe4) << " of the peak" << std::endl;
  ok &= check_below("  truncation 2H vs 4H, relative to the peak", difference(fe2, fe4), 5e-2);
  log() << "  vs the infinite channel: 2H " << difference(fe2, inf) << ", 3H "
        << difference(fe, inf) << ", 4H " << difference(fe4, inf) << std::endl;
  log() << (ok ? "OK" : "FAILED") << std::endl;
}
