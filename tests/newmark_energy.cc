// Energy of the generalized Newmark scheme (doc/theory/time-integration.md §7) on an elastic
// body (doc/verification.md, time integration: for an undamped linear elastic
// body the total energy stays constant to round-off with the average
// acceleration rule).
//
// The reference is the discrete energy identity of the average acceleration
// rule, derived independently of the code: with u_{n+1} - u_n = dt vbar and
// M abar + D vbar + K ubar = 0 (the equation averaged over n, n+1),
//   E_{n+1} - E_n = -dt vbar^T D vbar,  E = 1/2 v^T M v + 1/2 u^T K u,
// so E is constant without damping, and with Rayleigh damping every step
// dissipates exactly dt vbar^T D vbar. With Beta1 > 1/2 the scheme must lose
// energy (numerical dissipation).

#include <archdam/analysis/simulation.h>
#include <archdam/physics/solid/solid_operators.h>

#include "archdam_tests.h"
#include "case_text.h"
#include "foundation_tests.h"

using namespace dealii;
using namespace archdam;

int
main(int argc, char **argv)
{
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  std::ostringstream               quiet;
  const Parameters                 p = parameters_from_string(
    testing::case_text::tall_box_on_fixed_base + testing::case_text::no_gravity);
  analysis::Simulation             sim(p, MPI_COMM_WORLD, quiet);
  sim.setup_model();
  const auto &M = sim.model().mass();
  const auto &K = sim.model().stiffness();

  // Initial state: the static deflection under a lateral (x) body force,
  // released at t = 0 with a consistent acceleration a0 = -M^-1 K u0.
  archdam::Vector f, u0, a0, tmp;
  physics::solid::assemble_inertia_load(sim.model().space(), p.materials, physics::solid::InertiaOf::dam,
                                        Point<dim>::unit_vector(0), f);
  for (archdam::Vector *v : {&u0, &a0, &tmp})
    sim.model().space().reinit(*v);
  time::FactorizedOperator solver;
  solver.factorize(K, true);
  solver.solve(u0, f);
  sim.model().space().constraints.distribute(u0); // the glued joint's side 2 follows side 1
  K.vmult(tmp, u0);
  tmp *= -1.;
  sim.model().space().constraints.set_zero(tmp);
  time::FactorizedOperator mass_solver;
  mass_solver.factorize(M, true);
  mass_solver.solve(a0, tmp);
  sim.model().space().constraints.distribute(a0);

  const double T1_estimate = 0.05; // s, the order of the first period here
  const double dt          = T1_estimate / 40;

  struct Case
  {
    std::string name;
    double      beta1;
    double      alpha, beta; // Rayleigh
  };
  for (const Case &c : {Case{"undamped, Beta1 = 0.5", 0.5, 0., 0.},
                        Case{"Rayleigh damped, Beta1 = 0.5", 0.5, 2., 1e-4},
                        Case{"undamped, Beta1 = 0.6 (numerical damping)", 0.6, 0., 0.}})
    {
      time::NewmarkParameters tp;
      tp.time_step = dt;
      tp.beta1     = c.beta1;
      tp.beta2     = 0.25 * (c.beta1 + 0.5) * (c.beta1 + 0.5);
      time::NewmarkIntegrator newmark(tp, M, K, {c.alpha, c.beta}, sim.model().space().constraints);

      time::NewmarkState s;
      archdam::Vector    zero, vbar;
      for (archdam::Vector *v : {&s.v, &zero, &vbar})
        sim.model().space().reinit(*v);
      s.u = u0;
      s.a = a0;

      const double E0       = testing::elastic_energy(M, K, sim.model().space().constraints, s);
      double       E        = E0;
      double       worst    = 0.; // largest violation of the identity, relative to E0
      bool         monotone = true;
      for (unsigned int n = 0; n < 200; ++n)
        {
          vbar = s.v;
          newmark.advance(zero, s);
          vbar += s.v;
          vbar *= 0.5;
          sim.model().space().constraints.set_zero(vbar); // as in elastic_energy()
          // dissipation dt vbar^T (alpha M + beta K) vbar
          M.vmult(tmp, vbar);
          double dissipated = c.alpha * (tmp * vbar);
          K.vmult(tmp, vbar);
          dissipated = dt * (dissipated + c.beta * (tmp * vbar));

          const double E_next = testing::elastic_energy(M, K, sim.model().space().constraints, s);
          monotone            = monotone && E_next < E;
          if (c.beta1 == 0.5)
            worst = std::max(worst, std::abs(E_next - E + dissipated) / E0);
          E = E_next;
        }
      testing::log() << c.name << ": E(200 dt) / E(0) = " << std::setprecision(3) << E / E0
                     << std::endl;
      if (c.beta1 == 0.5)
        // Each step's direct solve leaves a relative residual ~1e-14 times the
        // condition number of Kbar (~1e3 here): 1e-10 over 200 steps is
        // round-off, while any first- or second-order defect would be >1e-4.
        testing::check_below("  |E_{n+1} - E_n + dt vbar^T D vbar| / E0, max over steps",
                             worst, 1e-10);
      else
        {
          testing::log() << "  energy decreases every step: " << (monotone ? "yes" : "NO")
                         << std::endl;
          testing::check_below("  E(200 dt) / E(0)", E / E0, 0.99);
        }
    }
}
