// A block sliding on a joint under base acceleration (doc/verification.md,
// joints; doc/theory/joints.md §2): a stiff block (1 m cube) on a rigid base block
// (all its outer faces fixed: it moves with the ground), the horizontal joint
// between them carrying the weight, then the ground acceleration a_g(t) in x
// (relative formulation, load -a_g M iota_x), mixed method with Kbar.
// The yield acceleration is N g with N = mu + c A / (m g) (cohesion kept at
// its intact value here: Residual cohesion = Cohesion).
// References, written here independently of the program:
//  - rectangular pulse A g for t0 (Newmark 1965): permanent slip
//    V^2 / (2 g N) (1 - N / A), V = A g t0;
//  - harmonic input A g sin(2 pi t / T): the rigid-block equation
//    s'' = -a_g - N g sign(s') while sliding, s' = 0 while |a_g| <= N g,
//    integrated event by event with exact sub-steps of 1e-6 s.
// Both schemes of the pair forces in time (Contraction joints/Contact in
// time, doc/theory/joints.md §10) run every reference: the step impulse (the
// default) with the average acceleration rule, with its dissipative closure
// (the default) and with the velocities closure (§11), and the trapezoidal
// forces with Beta1 = 0.6. The block settles under its weight for 0.05 s first (it
// has no support but the joint, so there is no static stage here), the
// weight rising smoothly over 0.04 s so as not to set the stiff block
// ringing (its own period is about 1 ms, and Beta1 = 1/2 does not damp it).
// Pulse tolerance 2 %: the elastic block (E = 1e11 Pa) deforms by ~1e-7 m,
// the time step 1 ms resolves the pulse ends to dt / (2 t0) = 0.5 %, and
// Beta1 = 0.6 is first order in dt on the two stick/slip transitions.
// The mixed and monolithic solvers are compared with the trapezoidal forces
// (the monolithic reference has no other).

#include <archdam/time/newmark.h>

#include "archdam_tests.h"
#include "joint_tests.h"

using namespace dealii;
using namespace archdam;

namespace
{
  constexpr double g      = 9.81;
  constexpr double settle = 0.05; // s
  constexpr double ramp   = 0.04; // s: the weight's smooth rise

  /// A contact solver and how its pair forces act in time, each with the
  /// Newmark rule it is used with (doc/user-guide.md, "Contraction joints"):
  /// the step impulse with the average acceleration rule, the trapezoidal
  /// forces with Beta1 = 0.6 (which also damps the block's bouncing while it
  /// settles).
  struct Scheme
  {
    std::string           name;
    joints::Solver        solver;
    joints::ContactInTime contact;
    joints::Closure       closure = joints::Closure::dissipative;
  };
  const Scheme step_impulse{"step impulse, dissipative closure, Beta1 = 0.5",
                            joints::Solver::mixed, joints::ContactInTime::step_impulse};
  const Scheme velocities{"step impulse, velocities closure, Beta1 = 0.5", joints::Solver::mixed,
                          joints::ContactInTime::step_impulse, joints::Closure::velocities};
  const Scheme trapezoidal{"trapezoidal, Beta1 = 0.6", joints::Solver::mixed,
                           joints::ContactInTime::trapezoidal};

  /// The FE slip history: x component of w = u2 - u1, mean over the pairs,
  /// every time step, with the chosen scheme.
  std::vector<double>
  fe_block(const Scheme &scheme, const std::function<double(double)> &ag,
           const double mu, const double c, const double end, const double dt,
           const bool condensed = false)
  {
    const double rho = 2400.;
    // base block 0 fixed on all its outer faces (rigid, moving with the
    // ground), block 1 of 1 m^3 on top of it
    testing::BlockModel m(2, 2, Point<dim>(1., 1., 2.), 1, 1, 1e11, 0.2, rho, {0});
    archdam::Vector gravity, iota_x;
    physics::solid::assemble_inertia_load(*m.space, m.materials, physics::solid::InertiaOf::dam,
                                          -g * Point<dim>::unit_vector(2), gravity);
    physics::solid::assemble_inertia_load(*m.space, m.materials, physics::solid::InertiaOf::dam,
                                          Point<dim>::unit_vector(0), iota_x);
    joints::JointParameters jp;
    jp.model                    = joints::Model::frictional_contact;
    jp.solver                   = scheme.solver;
    jp.contact_in_time          = scheme.contact;
    jp.closure                  = scheme.closure;
    jp.law.friction_coefficient = mu;
    jp.law.cohesion = jp.law.residual_cohesion = c;

    // The block rests on the joint alone (no support of its own: K is
    // singular, Kbar is not), so its weight is applied at t = 0 and left to
    // settle (Beta1 = 0.6 damps the bouncing) before the ground moves at
    // t = settle.
    time::NewmarkState s;
    m.space->reinit(s.u);
    const time::NewmarkParameters np = testing::newmark_for(scheme.contact, dt);
    // condensed: Kbar factorized with the pair DOFs last (Contraction
    // joints/Mixed method solves = condensed on the pairs), else plainly
    // (the predictor and corrector).
    time::NewmarkIntegrator newmark(np, m.M, m.K, {0., 0.}, m.space->constraints, nullptr,
                                    condensed ? m.pairs->interface() :
                                                std::vector<types::global_dof_index>());
    auto solver = joints::make_joint_solver(jp, *m.pairs, newmark.displacement_factor(),
                                            newmark.effective(), newmark.effective_factor());
    m.space->reinit(s.v);
    m.space->reinit(s.a);
    archdam::Vector load;
    m.space->reinit(load);
    double     slip_at_rest = 0.;
    const auto slip         = [&] {
      double sum = 0.;
      for (unsigned int i = 0; i < m.pairs->size(); ++i)
        for (unsigned int k = 0; k < dim; ++k)
          sum += solver->w[dim * i + k] * (*m.pairs)[i].frame[k][0];
      return sum / m.pairs->size();
    };
    std::vector<double> out;
    const unsigned int  n_settle = std::lround(settle / dt), n = std::lround(end / dt);
    for (unsigned int k = 1; k <= n_settle + n; ++k)
      {
        load = gravity;
        if (k * dt < ramp)
          load *= 0.5 * (1 - std::cos(M_PI * k * dt / ramp));
        if (k > n_settle)
          load.add(-ag((k - n_settle) * dt), iota_x);
        const auto step = joints::advance_with_contact(newmark, *solver, load, s);
        AssertThrow(step.converged, ExcMessage("t = " + std::to_string(k * dt) + ": " + solver->describe(step)));
        if (k == n_settle)
          slip_at_rest = slip();
        if (k >= n_settle)
          out.push_back(slip() - slip_at_rest);
      }
    return out;
  }

  double
  peak(const std::vector<double> &v)
  {
    double p = 0.;
    for (const double x : v)
      p = std::max(p, std::abs(x));
    return p;
  }
} // namespace

int
main(int argc, char **argv)
{
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  auto                            &log = testing::log();
  const double                     dt  = 1e-3;

  // Rectangular pulse, friction alone and friction with cohesion.
  const double A = 0.5, t0 = 0.1, mu = 0.2, m = 2400., area = 1.;
  const auto   pulse = [&](const double t) { return t > 0 && t <= t0 + 1e-12 ? A * g : 0.; };
  for (const Scheme &scheme : {step_impulse, velocities, trapezoidal})
    for (const double c : {0., 0.1 * m * g / area})
      {
        const double N    = mu + c * area / (m * g);
        const double V    = A * g * t0;
        const double ref  = V * V / (2 * g * N) * (1 - N / A);
        const auto   slip = fe_block(scheme, pulse, mu, c, 0.4, dt);
        log << scheme.name << ", rectangular pulse A = " << A << ", t0 = " << t0
            << " s, N = " << N << ":" << std::endl;
        testing::check_relative("  permanent slip [m] (Newmark 1965)", -slip.back(), ref, 0.02);
      }

  // Harmonic input: event-driven rigid-block reference at two time steps,
  // the error as max |slip - reference| / peak slip.
  //  - Step impulse, Beta1 = 1/2, velocities closure: below 0.6 % at both
  //    steps (measured 0.47 % and 0.39 %, and 0.31 % at dt / 4: it falls
  //    slowly, the stick/slip transitions inside a step leave a residual of
  //    their own).
  //  - Step impulse, Beta1 = 1/2, dissipative closure (the default): below
  //    1 % at both steps (measured 0.78 % and 0.72 %): where the block
  //    turns inside a step, the step's one force lies against its net
  //    increment or holds its position, and the block leaves the turn with
  //    an error of its velocity; first order on average, the error depends
  //    on where the turn falls in the step, so 1 % holds at these two
  //    steps, not at every step (doc/theory/joints.md §11;
  //    scripts/one-mass-closures.py: 0.84 % and 0.70 % at these steps, up
  //    to 1.8 % at steps of 1 to 1.5 ms).
  //  - Trapezoidal forces, Beta1 = 0.6: first order, the error (Beta1 - 1/2)
  //    dt times the jumps of the acceleration at the stick/slip transitions:
  //    halving dt must halve the error (ratio >= 1.7 checked; first order
  //    gives 2), and at dt / 2 the error must be below 1.5 % of the peak slip.
  const double T  = 0.5, Ah = 0.4;
  const auto   harmonic = [&](const double t) { return Ah * g * std::sin(2 * M_PI * t / T); };
  for (const Scheme &scheme : {step_impulse, velocities, trapezoidal})
    {
      log << scheme.name << ", harmonic input A = " << Ah << ", T = " << T << " s, N = " << mu
          << ":" << std::endl;
      const bool          impulse = scheme.contact == joints::ContactInTime::step_impulse;
      std::vector<double> error;
      for (const double step : {dt, dt / 2})
        {
          const auto ref   = testing::rigid_block([&](const double t) { return -harmonic(t); },
                                                mu * g, 1.0, step);
          const auto mixed = fe_block(scheme, harmonic, mu, 0., 1.0, step);
          double     err   = 0.;
          for (unsigned int k = 0; k < ref.size(); ++k)
            err = std::max(err, std::abs(mixed[k] - ref[k]));
          error.push_back(err / peak(ref));
          if (step == dt)
            testing::check_relative("  peak |slip| [m] (event-driven rigid block, dt = 1 ms)",
                                    peak(mixed), peak(ref), 0.02);
          if (impulse)
            testing::check_below("  max |slip - reference| / peak slip at dt = " +
                                   std::string(step == dt ? "1" : "0.5") + " ms",
                                 error.back(),
                                 scheme.closure == joints::Closure::velocities ? 0.006 : 0.01);
        }
      if (!impulse)
        {
          testing::check_below("  max |slip - reference| / peak slip at dt = 0.5 ms", error[1],
                               0.015);
          log << "  error ratio dt / (dt / 2) at least 1.7 (first order): "
              << (error[0] / error[1] >= 1.7 ? "yes" : "NO") << std::endl;
        }
    }

  // Mixed method against the monolithic reference (the friction pulse: the
  // block slides and comes to rest): both enforce the same law, the
  // monolithic one with penalty springs of 1e8 times the largest diagonal
  // entry of Kbar, so they agree to ~1e-8 of the displacements; 1e-6 of the
  // peak slip leaves room for the contact tolerances.
  const auto monolithic  = fe_block(Scheme{"monolithic", joints::Solver::monolithic, joints::ContactInTime::trapezoidal}, pulse, mu, 0., 0.4, dt);
  const auto mixed_pulse = fe_block(trapezoidal, pulse, mu, 0., 0.4, dt);
  double     diff        = 0.;
  for (unsigned int k = 0; k < monolithic.size(); ++k)
    diff = std::max(diff, std::abs(mixed_pulse[k] - monolithic[k]));
  log << "rectangular pulse, mixed and monolithic solvers:" << std::endl;
  testing::check_below("  max |mixed - monolithic| / peak slip", diff / peak(mixed_pulse), 1e-6);

  // The mixed method condensed on the pairs (one back-substitution per step)
  // against the predictor and corrector: the same contact problem, so the
  // same slip to the contact tolerances.
  const auto condensed = fe_block(trapezoidal, pulse, mu, 0., 0.4, dt, true);
  diff                 = 0.;
  for (unsigned int k = 0; k < condensed.size(); ++k)
    diff = std::max(diff, std::abs(condensed[k] - mixed_pulse[k]));
  log << "rectangular pulse, mixed method condensed on the pairs and predictor-corrector:"
      << std::endl;
  testing::check_below("  max |condensed - predictor-corrector| / peak slip",
                       diff / peak(mixed_pulse), 1e-9);
}
