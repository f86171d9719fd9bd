// Generalized Newmark scheme (doc/theory/time-integration.md §6) on a small FE cantilever, against
// the exact solution of the semi-discrete system M u'' + K u = 0, obtained
// independently by modal superposition from a dense generalized eigensolver
// (LAPACK): u(t) = sum_i phi_i (q_i cos w_i t + p_i / w_i sin w_i t).
//
// Shows (doc/verification.md, time integration):
// 1. with Beta1 = 1/2, Beta2 = 1/4 the error at a fixed time falls by 4 when
//    dt halves (second order);
// 2. the period elongation of the average acceleration rule matches its known
//    formula T_num / T = (w dt / 2) / atan(w dt / 2);
// 3. with Beta1 = 0.6 (numerical damping) the scheme is only first order;
// 4. Rayleigh damping derived from a damping ratio zeta at two frequencies
//    (doc/theory/solid.md §4) gives each of those modes the decay of zeta: the modal
//    damping ratio of M u'' + (alpha M + beta K) u' + K u = 0 is
//    alpha / (2 w) + beta w / 2, measured here by the logarithmic decrement.

#include <archdam/analysis/simulation.h>
#include <archdam/physics/solid/damping.h>

#include <deal.II/lac/lapack_full_matrix.h>

#include "archdam_tests.h"

using namespace dealii;
using namespace archdam;

namespace
{
  const char *model = R"(
subsection Mesh
  subsection Box
    set Length = 1
    set Width = 1
    set Height = 4
    set Rock depth = 0
    set Cells in x = 1
    set Cells in y = 1
    set Cells in z = 4
  end
end
subsection Finite element
  set Degree = 1
end
subsection Damping
  set Mode = coefficients
end
subsection Static loads
  set Gravity = false
end
)";

  struct Modes
  {
    std::vector<unsigned int>           free; // unconstrained DOFs
    std::vector<double>                 omega;
    std::vector<dealii::Vector<double>> phi;  // M-orthonormal, on free DOFs
    LAPACKFullMatrix<double>            M;
  };

  Modes
  compute_modes(const analysis::Simulation &sim)
  {
    Modes m;
    for (unsigned int i = 0; i < sim.model().space().dof_handler.n_dofs(); ++i)
      if (!sim.model().space().constraints.is_constrained(i))
        m.free.push_back(i);
    const unsigned int       n = m.free.size();
    LAPACKFullMatrix<double> K(n, n);
    m.M.reinit(n, n);
    for (unsigned int i = 0; i < n; ++i)
      for (unsigned int j = 0; j < n; ++j)
        {
          K(i, j)   = sim.model().stiffness().el(m.free[i], m.free[j]);
          m.M(i, j) = sim.model().mass().el(m.free[i], m.free[j]);
        }
    LAPACKFullMatrix<double> B = m.M;
    m.phi.resize(n, dealii::Vector<double>(n));
    K.compute_generalized_eigenvalues_symmetric(B, m.phi);
    for (unsigned int i = 0; i < n; ++i)
      m.omega.push_back(std::sqrt(K.eigenvalue(i).real()));
    // LAPACK returns them in ascending order.
    return m;
  }

  /// Integrate from t = 0 to t_end with n steps; return the final free-DOF
  /// displacement and, if asked, the history of one modal coordinate.
  dealii::Vector<double>
  integrate(const analysis::Simulation &sim, const Modes &m, const dealii::Vector<double> &u0,
            const dealii::Vector<double> &v0, const dealii::Vector<double> &a0,
            const double t_end, const unsigned int n, const double beta1,
            std::vector<double>            *modal_history = nullptr,
            const unsigned int              mode          = 0,
            const std::pair<double, double> rayleigh      = {0., 0.})
  {
    time::NewmarkParameters tp;
    tp.time_step = t_end / n;
    tp.beta1     = beta1;
    tp.beta2     = 0.25 * (beta1 + 0.5) * (beta1 + 0.5);
    time::NewmarkIntegrator newmark(tp, sim.model().mass(), sim.model().stiffness(), rayleigh,
                                    sim.model().space().constraints);
    time::NewmarkState s;
    archdam::Vector    zero;
    for (archdam::Vector *v : {&s.u, &s.v, &s.a, &zero})
      sim.model().space().reinit(*v);
    for (unsigned int i = 0; i < m.free.size(); ++i)
      {
        s.u(m.free[i]) = u0(i);
        s.v(m.free[i]) = v0(i);
        s.a(m.free[i]) = a0(i);
      }
    for (archdam::Vector *v : {&s.u, &s.v, &s.a})
      v->compress(VectorOperation::insert);

    dealii::Vector<double> u(m.free.size()), Mphi(m.free.size());
    m.M.vmult(Mphi, m.phi[mode]);
    for (unsigned int k = 0; k <= n; ++k)
      {
        if (k > 0)
          newmark.advance(zero, s);
        for (unsigned int i = 0; i < m.free.size(); ++i)
          u(i) = s.u(m.free[i]);
        if (modal_history)
          modal_history->push_back(Mphi * u);
      }
    return u;
  }
} // namespace

int
main(int argc, char **argv)
{
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  std::ostringstream               quiet;
  const Parameters                 p = parameters_from_string(model);
  analysis::Simulation             sim(p, MPI_COMM_WORLD, quiet);
  sim.setup_model();
  const Modes        m  = compute_modes(sim);
  const unsigned int n  = m.free.size();
  const double       T1 = 2 * M_PI / m.omega[0];
  testing::log() << "free DOFs: " << n << ", first period T1 = " << std::setprecision(4) << T1
                 << " s" << std::endl;

  // 1. Convergence: u0 and v0 in the three lowest modes (so that the finest
  //    steps are in the asymptotic range for all of them).
  dealii::Vector<double> u0(n), v0(n), a0(n);
  const double           q[3] = {1e-3, -5e-4, 2e-4}, pv[3] = {0., 3e-3, -1e-3};
  for (unsigned int i = 0; i < 3; ++i)
    {
      u0.add(q[i], m.phi[i]);
      v0.add(pv[i], m.phi[i]);
      a0.add(-m.omega[i] * m.omega[i] * q[i], m.phi[i]); // a0 = -M^-1 K u0
    }
  // At t = 2.25 T1 no mode sits near a zero of sin(w t), where the leading
  // (phase) error term would vanish and hide the order.
  const double           t_end = 2.25 * T1;
  dealii::Vector<double> exact(n);
  for (unsigned int i = 0; i < 3; ++i)
    exact.add(q[i] * std::cos(m.omega[i] * t_end) +
                pv[i] / m.omega[i] * std::sin(m.omega[i] * t_end),
              m.phi[i]);

  for (const double beta1 : {0.5, 0.6})
    {
      testing::log() << "Beta1 = " << beta1 << ":" << std::endl;
      std::vector<double> errors;
      for (const unsigned int steps : {400u, 800u, 1600u, 3200u})
        {
          dealii::Vector<double> e = integrate(sim, m, u0, v0, a0, t_end, steps, beta1);
          e -= exact;
          errors.push_back(e.linfty_norm() / u0.linfty_norm());
        }
      for (unsigned int k = 1; k < errors.size(); ++k)
        {
          const double ratio = errors[k - 1] / errors[k];
          // Second order gives 4, first order 2; the finest steps have
          // w3 dt < 0.05, where the next term of the error is below 1 %, so
          // +-5 % separates the orders safely. Two digits: the third
          // (2.01 or 2.02 with Beta1 = 0.6) depends on the machine's round-off.
          const double expected = beta1 == 0.5 ? 4. : 2.;
          testing::check_relative("  error ratio dt/dt/2, step " + std::to_string(k), ratio,
                                  expected, 0.05, 2);
        }
    }

  // 2. Period elongation: start in mode 1 exactly with 20 steps per period;
  //    measure the period from the zero crossings of the modal coordinate over
  //    ten periods (linear interpolation between steps).
  {
    const unsigned int     steps_per_period = 20, periods = 10;
    dealii::Vector<double> u1 = m.phi[0], v1(n), a1 = m.phi[0];
    a1 *= -m.omega[0] * m.omega[0];
    std::vector<double> q1;
    const double        dt = T1 / steps_per_period;
    integrate(sim, m, u1, v1, a1, periods * T1, steps_per_period * periods, 0.5, &q1);
    std::vector<double> crossings;
    for (unsigned int k = 1; k < q1.size(); ++k)
      if (q1[k - 1] > 0 && q1[k] <= 0)
        crossings.push_back(dt * (k - 1 + q1[k - 1] / (q1[k - 1] - q1[k])));
    const double T_num = (crossings.back() - crossings.front()) / (crossings.size() - 1);
    const double Omega = m.omega[0] * dt;
    const double T_formula = T1 * (Omega / 2) / std::atan(Omega / 2);
    testing::log() << "period elongation with w dt = " << std::setprecision(3) << Omega
                   << ":" << std::endl;
    // The interpolation between samples is exact to O(Omega^3) at a zero crossing
    // (the curvature vanishes there), i.e. ~1e-4 of dt; averaged over ten
    // periods this is ~1e-6 of T, far below the elongation (~8e-3 of T).
    testing::check_relative("  T_num / T - 1", T_num / T1 - 1, T_formula / T1 - 1, 0.01, 3);
  }

  // 4. Rayleigh damping with zeta = 5 % at f1 and f3 (modes 1 and 3; mode 2
  //    is mode 1 turned by 90 degrees). Start in one mode, measure the
  //    logarithmic decrement over five periods from the interpolated peaks.
  {
    physics::solid::DampingParameters dp;
    dp.ratio            = 0.05;
    dp.first_frequency  = m.omega[0] / (2 * M_PI);
    dp.second_frequency = m.omega[2] / (2 * M_PI);
    const auto rayleigh = dp.rayleigh_coefficients();
    testing::log() << "Rayleigh damping, zeta = 0.05 at modes 1 and 3:" << std::endl;
    for (const unsigned int mode : {0u, 2u})
      {
        const double           T = 2 * M_PI / m.omega[mode];
        const unsigned int     steps_per_period = 100, periods = 5;
        dealii::Vector<double> u1 = m.phi[mode], v1(n), a1 = m.phi[mode];
        a1 *= -m.omega[mode] * m.omega[mode];
        std::vector<double> q;
        integrate(sim, m, u1, v1, a1, periods * T, steps_per_period * periods, 0.5, &q, mode,
                  rayleigh);
        // Peaks by parabolic interpolation through the three samples around
        // each local maximum (relative error ~ (2 pi / 100)^4, negligible).
        std::vector<double> peaks;
        for (unsigned int k = 1; k + 1 < q.size(); ++k)
          if (q[k] > q[k - 1] && q[k] >= q[k + 1])
            peaks.push_back(q[k] + (q[k + 1] - q[k - 1]) * (q[k + 1] - q[k - 1]) /
                                     (8 * (2 * q[k] - q[k - 1] - q[k + 1])));
        const double delta = std::log(q[0] / peaks.back()) / peaks.size();
        const double zeta  = delta / std::sqrt(4 * M_PI * M_PI + delta * delta);
        // The average acceleration rule changes the decay and the period by
        // O((w dt)^2 / 12) ~ 3e-4 relative at 100 steps per period: 1 % is a
        // safe margin that still catches any wrong coefficient.
        testing::check_relative("  measured zeta of mode " + std::to_string(mode + 1), zeta,
                                0.05, 0.01, 3);
      }
  }
}
