// Verification (doc/verification.md, "Reservoir"): the hydrodynamic pressure on a
// rigid vertical dam face driven by a harmonic ground acceleration, from the
// project's water operators G, H, Q, S (physics/reservoir), against the
// separation-of-variables series of tests/reservoir_reference.h.
//
// Model. A channel of water H = 50 m deep, truncated L = 3H upstream with the
// Sommerfeld radiation condition, one cell wide between rigid side walls (a
// two-dimensional problem), c = 1440 m/s, rho_w = 1000 kg/m^3, p = 0 on the
// free surface, Q2 pressure. The dam is a fixed slab (every DOF constrained):
// the water sees the face accelerate with the ground. The FE response is the
// steady state of (Q - omega^2 G + i omega H) P = -S iota_x, solved as a real
// 2x2-block symmetric system (tests/harmonic_response.h).
//
// References (all computed here, none from the code under test):
//  - the truncated channel: the same boundary-value problem (Sommerfeld
//    condition at s = L) solved exactly mode by mode; the FE must converge to
//    it under refinement, at every frequency 0 ... 3 omega_1 and every height;
//  - the infinite channel (Chopra's series, doc/theory/reservoir.md §10), the physical
//    reference: below 0.8 omega_1 the truncation at 3H changes the face
//    pressure by about e^{-2 kappa_1 L} (0.35 % at 0.8 omega_1, less below),
//    so the FE must match the infinite series there within 0.5 %; above the first resonance the Sommerfeld
//    condition reflects part of the propagating modes, and the difference
//    between the truncated and infinite references is reported as what it is
//    (a property of the truncation, not of the FE);
//  - the resonance: the infinite channel is unbounded at omega_1 = pi c/(2H);
//    the truncated one peaks near it. The FE peak (golden-section search on
//    |p| at the heel) is compared with the truncated reference's peak: its
//    shift is the finite-mesh shift, below 1e-4 omega_1 on h = H/4 and 1e-5
//    on h = H/8 (finer meshes shift it by less than the search resolves).
//  - an absorbing bottom (alpha_r = 0.5, q = (1 - alpha_r)/(c(1 + alpha_r))):
//    the series with the complex vertical eigenvalues (Fenves & Chopra 1984),
//    found independently by Newton's method.
//  - the coupling S alone: for the interpolated fields u_x = z^2 and p = 1,
//    p^T S u = rho_w int z^2 dA = rho_w W H^3 / 3 exactly (Q2 holds both
//    fields), with matched faces and with a dam mesh twice finer than the
//    water at the face (the coupling integrates on the finer side), and
//    u^T S^T p gives the same.
// Tolerances: the errors are measured relative to the largest |p| over the
// heights at each frequency, maximized over the frequencies; on the finest
// mesh (h = H/16) it must be below 0.1 % against the truncated channel with
// either bottom (measured 1e-4 and 2e-5: Q2 converges as h^4 here), and each
// refinement must reduce the error at least twofold.

#include <archdam/physics/reservoir/fluid_operators.h>

#include <deal.II/base/function.h>
#include <deal.II/numerics/vector_tools.h>

#include "archdam_tests.h"
#include "harmonic_response.h"
#include "reservoir_reference.h"

using namespace archdam;
using namespace archdam::testing;
namespace reservoir = archdam::physics::reservoir;

namespace
{
  const std::vector<double> heights_over_H = {0., 0.25, 0.5, 0.75};

  /// The FE model of the channel with its operators.
  struct Model
  {
    Model(const Channel &ch, const reservoir::ReservoirParameters &rp, unsigned int nx,
          unsigned int nz, unsigned int dam_refinement, bool rigid_dam)
      : tria(MPI_COMM_WORLD)
    {
      make_channel(ch, nx, nz, dam_refinement, tria);
      space = std::make_unique<fe::FESpace>(tria, fe::FiniteElementParameters{});
      space->setup({}, [&](dealii::AffineConstraints<double> &c) {
        if (rigid_dam)
          fix_solid(*space, c);
        reservoir::constrain_free_surface(*space, rp, c);
      });
      pairs                = reservoir::match_interface_faces(*space);
      space->add_couplings = [this](dealii::DynamicSparsityPattern &dsp) {
        reservoir::add_interface_couplings(*space, pairs, dsp);
      };
      reservoir::assemble_fluid_operators(*space, rp, 9.81, pairs, ops);
    }

    dealii::parallel::shared::Triangulation<dim> tria;
    std::unique_ptr<fe::FESpace>                 space;
    std::vector<reservoir::InterfacePair>        pairs;
    reservoir::FluidOperators                    ops;
  };

  std::vector<complex>
  fe_face_pressure(const Model &m, const Channel &ch, const double omega)
  {
    Vector pr, pi, gr, gi;
    harmonic_pressure(*m.space, m.ops, omega, 0, pr, pi);
    m.space->reinit_ghosted(gr);
    m.space->reinit_ghosted(gi);
    gr = pr;
    gi = pi;
    std::vector<complex> p;
    for (const double z : heights_over_H)
      {
        const dealii::Point<dim> x(0., ch.W / 2, z * ch.H);
        p.emplace_back(point_value(*m.space, gr, x, dim), point_value(*m.space, gi, x, dim));
      }
    return p;
  }

  std::vector<double>
  heights(const Channel &ch)
  {
    std::vector<double> z;
    for (const double h : heights_over_H)
      z.push_back(h * ch.H);
    return z;
  }

  /// max_z |a - b| / max_z |b|
  double
  relative_error(const std::vector<complex> &a, const std::vector<complex> &b)
  {
    double err = 0., scale = 0.;
    for (unsigned int i = 0; i < a.size(); ++i)
      {
        err   = std::max(err, std::abs(a[i] - b[i]));
        scale = std::max(scale, std::abs(b[i]));
      }
    return err / scale;
  }

  /// Maximum of f on [a, b] by golden-section search.
  template <typename F>
  double
  argmax(const F &f, double a, double b)
  {
    const double r = (std::sqrt(5.) - 1.) / 2.;
    double       c = b - r * (b - a), d = a + r * (b - a);
    double       fc = f(c), fd = f(d);
    while (b - a > 1e-7 * (a + b))
      if (fc > fd)
        {
          b  = d;
          d  = c;
          fd = fc;
          c  = b - r * (b - a);
          fc = f(c);
        }
      else
        {
          a  = c;
          c  = d;
          fc = fd;
          d  = a + r * (b - a);
          fd = f(d);
        }
    return (a + b) / 2;
  }

  void
  check_coupling(const Channel &ch)
  {
    log() << "Coupling S: p^T S u for u_x = z^2, p = 1 (reference rho_w W H^3/3)" << std::endl;
    reservoir::ReservoirParameters rp;
    rp.model        = reservoir::Model::compressible;
    // gravity waves: no constraint on p, so that p = 1 everywhere
    rp.free_surface = reservoir::FreeSurface::gravity_waves;
    for (const unsigned int refinement : {0u, 1u})
      {
        const Model m(ch, rp, 6, 2, refinement, false);
        class Field : public dealii::Function<dim>
        {
        public:
          Field()
            : dealii::Function<dim>(dim + 1)
          {}
          double
          value(const dealii::Point<dim> &x, const unsigned int c) const override
          {
            return c == 0 ? x[2] * x[2] : c == dim ? 1. : 0.;
          }
        } field;
        Vector v, Sv;
        m.space->reinit(v);
        m.space->reinit(Sv);
        dealii::VectorTools::interpolate(m.space->dof_handler, field, v);
        const double reference = ch.rho * ch.W * std::pow(ch.H, 3) / 3;
        m.ops.S.vmult(Sv, v);
        check_relative(std::string(refinement ? "  dam mesh finer than the water" :
                                                "  matched faces") + ": p^T S u",
                       v * Sv, reference, 1e-10, 10);
        m.ops.S_transpose.vmult(Sv, v);
        check_relative("    u^T S^T p", v * Sv, reference, 1e-10, 10);
      }
  }
} // namespace

int
main(int argc, char **argv)
{
  dealii::Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  Channel ch;
  const double omega1 = M_PI * ch.c / (2 * ch.H);
  const auto   z      = heights(ch);

  check_coupling(ch);

  reservoir::ReservoirParameters rp;
  rp.model       = reservoir::Model::compressible;
  rp.density     = ch.rho;
  rp.sound_speed = ch.c;

  std::vector<double> omegas;
  for (unsigned int k = 0; k < 24; ++k)
    omegas.push_back(0.125 * (k + 0.5) * omega1);

  log() << "Rigid bottom, truncation at " << ch.L / ch.H << " H, omega = 0.0625 ... "
        << omegas.back() / omega1 << " omega_1 (24 frequencies)" << std::endl;
  std::vector<double> errors;
  double              peak_reference = 0.;
  {
    const auto abs_ref = [&](const double w) { return std::abs(face_pressure(ch, w, {0.}, ch.L)[0]); };
    peak_reference = argmax(abs_ref, 0.9 * omega1, 1.1 * omega1);
    log() << "  truncated reference: peak at " << std::setprecision(4) << peak_reference / omega1
          << " omega_1 (the infinite channel's resonance is at 1 omega_1)" << std::endl;
  }
  bool ok = true;
  for (const unsigned int n : {4u, 8u, 16u})
    {
      const Model m(ch, rp, 3 * n, n, 0, true);
      double      err = 0., amp_err = 0., phase_err = 0., err_infinite_low = 0.,
             truncation_effect = 0.;
      for (const double w : omegas)
        {
          const auto fe  = fe_face_pressure(m, ch, w);
          const auto ref = face_pressure(ch, w, z, ch.L);
          err            = std::max(err, relative_error(fe, ref));
          for (unsigned int i = 0; i < z.size(); ++i)
            {
              amp_err   = std::max(amp_err, std::abs(std::abs(fe[i]) / std::abs(ref[i]) - 1));
              phase_err = std::max(phase_err, std::abs(std::arg(fe[i] / ref[i])) * 180 / M_PI);
            }
          const auto inf = face_pressure(ch, w, z, 0.);
          if (w < 0.8 * omega1)
            err_infinite_low = std::max(err_infinite_low, relative_error(fe, inf));
          if (w > 1.2 * omega1)
            truncation_effect = std::max(truncation_effect, relative_error(ref, inf));
        }
      errors.push_back(err);
      log() << "  mesh h = H/" << n << " (" << m.space->dof_handler.n_dofs() << " DOFs):" << std::endl
            << std::setprecision(2) << "    vs the truncated channel: error " << err
            << ", amplitude " << amp_err << ", phase " << phase_err << " deg" << std::endl
            << "    vs the infinite channel below 0.8 omega_1: error " << err_infinite_low
            << std::endl;
      if (n < 16) // the finest mesh's shift is below what the search resolves
        {
          const auto abs_fe = [&](const double w) {
            return std::abs(fe_face_pressure(m, ch, w)[0]);
          };
          const double shift =
            (argmax(abs_fe, 0.9 * omega1, 1.1 * omega1) - peak_reference) / omega1;
          log() << "    peak near omega_1: finite-mesh shift " << std::setprecision(1) << shift
                << " omega_1" << std::endl;
          ok &= check_below("    |shift|", std::abs(shift), n == 4 ? 1e-4 : 1e-5);
        }
      if (n == 16)
        {
          ok &= check_below("    finest mesh: error vs the truncated channel", err, 1e-3);
          ok &= check_below("    finest mesh: error vs the infinite channel below 0.8 omega_1",
                            err_infinite_low, 5e-3);
          log() << "    truncation at 3H with the Sommerfeld condition vs the infinite "
                   "channel above 1.2 omega_1: "
                << std::setprecision(2) << truncation_effect << std::endl;
        }
    }
  for (unsigned int i = 1; i < errors.size(); ++i)
    {
      ok &= check_below("  error ratio of mesh " + std::to_string(i + 1) + " to mesh " +
                          std::to_string(i),
                        errors[i] / errors[i - 1], 0.5);
    }

  // Absorbing bottom.
  rp.reflection = 0.5;
  ch.q          = rp.bottom_absorption();
  log() << "Absorbing bottom, alpha_r = 0.5, omega = 0.075 ... 2.9 omega_1 (20 frequencies)"
        << std::endl;
  std::vector<double> absorbing_errors;
  for (const unsigned int n : {4u, 8u, 16u})
    {
      const Model m(ch, rp, 3 * n, n, 0, true);
      double      err = 0.;
      for (unsigned int k = 0; k < 20; ++k)
        {
          const double w = 0.15 * (k + 0.5) * omega1;
          err            = std::max(err, relative_error(fe_face_pressure(m, ch, w),
                                                        face_pressure(ch, w, z, ch.L)));
        }
      absorbing_errors.push_back(err);
      log() << "  mesh h = H/" << n << ": error vs the series with complex eigenvalues "
            << std::setprecision(2) << err << std::endl;
    }
  ok &= check_below("  finest mesh: error", absorbing_errors.back(), 1e-3);
  for (unsigned int i = 1; i < absorbing_errors.size(); ++i)
    ok &= check_below("  error ratio of mesh " + std::to_string(i + 1) + " to mesh " +
                        std::to_string(i),
                      absorbing_errors[i] / absorbing_errors[i - 1], 0.5);
  log() << (ok ? "OK" : "FAILED") << std::endl;
}
