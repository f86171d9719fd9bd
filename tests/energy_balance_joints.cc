// Contact dissipation in the energy balance (analysis/energy_balance.h;
// doc/verification.md, "Energy balance" and "Contraction joints"): the rigid-block case of
// joint_sliding. A stiff block (1 m cube, rho = 2400 kg/m^3) on a joint over
// a fixed base block, Coulomb friction mu = 0.2 without cohesion, settles
// under its weight, then a rectangular ground pulse A g = 0.5 g for t0 =
// 0.1 s in x (relative formulation) makes it slide, and friction stops it.
//
// References, written here independently of the program:
//  - the joint dissipates mu N times the slip: N = m g the weight, the slip
//    the FE block's (it slides one way only); within 0.5 % (the normal
//    force varies by the block's rocking); the joints' pair forces act as
//    the default step impulse (doc/theory/joints.md §10), here with the
//    Beta1 = 0.6 whose dissipation is checked below;
//  - the rigid block (Newmark 1965): the ground puts in
//    W = m A g (A - mu) g t0^2 / 2 while the block slides during the pulse,
//    and all of it goes into friction once the block is at rest again
//    (mu m g times the permanent slip V^2/(2 g mu)(1 - mu/A), V = A g t0):
//    the input work and the contact dissipation within 2 % (joint_sliding's
//    tolerance on the slip: dt / (2 t0) = 0.5 % at the pulse ends, the
//    first-order Beta1 = 0.6 at the stick/slip transitions);
//  - with Beta1 = 0.6 the scheme dissipates (Beta1 - 1/2) dv^T M dv per step
//    of its own (the discrete energy identity of Newmark's method; the
//    Beta2 - Beta1/2 = 0.0025 term acts on the acceleration jumps only),
//    which for the rigid block, sliding with s'' = -(A - mu) g during the
//    pulse and s'' = mu g until it stops at t0 (A - mu) / mu later, is
//    (Beta1 - 1/2) m dt [((A - mu) g)^2 t0 + (mu g)^2 t0 (A - mu) / mu]:
//    the balance's term `algorithmic` (computed from M and the accelerations
//    of the FE solution) must match it within 5 % (the pulse ends, the
//    block's own vibration), the balance with it close to round-off (1e-8),
//    and without it the gap input - sum must be that same energy.
// The balance measured without the contact term must be open (> 50 %).

#include <archdam/analysis/energy_balance.h>

#include "archdam_tests.h"
#include "joint_tests.h"

using namespace dealii;
using namespace archdam;

int
main(int argc, char **argv)
{
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  constexpr double g = 9.81, rho = 2400., m = rho, mu = 0.2, A = 0.5, t0 = 0.1, dt = 1e-3;
  const double     settle = 0.05, end = 0.4;

  testing::BlockModel model(2, 2, Point<dim>(1., 1., 2.), 1, 1, 1e11, 0.2, rho, {0});
  archdam::Vector     gravity;
  std::array<archdam::Vector, dim> iota;
  physics::solid::assemble_inertia_load(*model.space, model.materials,
                                        physics::solid::InertiaOf::dam,
                                        -g * Point<dim>::unit_vector(2), gravity);
  for (unsigned int d = 0; d < dim; ++d)
    physics::solid::assemble_inertia_load(*model.space, model.materials,
                                          physics::solid::InertiaOf::dam,
                                          Point<dim>::unit_vector(d), iota[d]);
  joints::JointParameters jp;
  jp.model                    = joints::Model::frictional_contact;
  jp.law.friction_coefficient = mu;
  jp.law.cohesion = jp.law.residual_cohesion = 0.;

  time::NewmarkParameters np;
  np.time_step = dt;
  np.beta1     = 0.6; // damps the block's bouncing while it settles
  np.beta2     = 0.3025;
  time::NewmarkIntegrator newmark(np, model.M, model.K, {0., 0.}, model.space->constraints);
  auto solver = joints::make_joint_solver(jp, *model.pairs, newmark.displacement_factor(),
                                          newmark.effective(), newmark.effective_factor());
  time::NewmarkState s;
  archdam::Vector    load;
  for (archdam::Vector *v : {&s.u, &s.v, &s.a, &load})
    model.space->reinit(*v);

  analysis::EnergyBalance::Model em;
  em.space     = model.space.get();
  em.mass      = &model.M;
  em.stiffness = &model.K;
  em.newmark   = np;
  em.influence = &iota;
  analysis::EnergyBalance balance(em);

  const auto slip = [&] { // mean x component of w over the pairs
    double sum = 0.;
    for (unsigned int i = 0; i < model.pairs->size(); ++i)
      for (unsigned int k = 0; k < dim; ++k)
        sum += solver->w[dim * i + k] * (*model.pairs)[i].frame[k][0];
    return sum / model.pairs->size();
  };
  // The same steps with the pair system's base factorized and its update
  // columns computed anew at every step (JointSolver::forget_factorization(),
  // as after a checkpoint): the columns kept over the run must give the same
  // forces, to the round-off of the solves carried through the steps (1e-8
  // of the largest force; measured 1.1e-9 over the 90 steps). The update
  // itself is checked against a direct LU of the same systems in
  // tests/pair_system.
  time::NewmarkIntegrator fresh_newmark(np, model.M, model.K, {0., 0.}, model.space->constraints);
  auto fresh = joints::make_joint_solver(jp, *model.pairs, fresh_newmark.displacement_factor(),
                                         fresh_newmark.effective(),
                                         fresh_newmark.effective_factor());
  time::NewmarkState fresh_state;
  for (archdam::Vector *v : {&fresh_state.u, &fresh_state.v, &fresh_state.a})
    model.space->reinit(*v);
  double largest_force = 0., largest_difference = 0.;

  const unsigned int n_settle = std::lround(settle / dt), n = std::lround(end / dt);
  double             slip_at_rest = 0.;
  for (unsigned int k = 1; k <= n_settle + n; ++k)
    {
      const double t  = (k - double(n_settle)) * dt;
      const double ag = k > n_settle && t <= t0 + 1e-12 ? A * g : 0.;
      load            = gravity;
      load.add(-ag, iota[0]);
      const auto step = joints::advance_with_contact(newmark, *solver, load, s);
      AssertThrow(step.converged, ExcMessage(solver->describe(step)));
      fresh->forget_factorization();
      joints::advance_with_contact(fresh_newmark, *fresh, load, fresh_state);
      for (unsigned int j = 0; j < solver->force.size(); ++j)
        {
          largest_force      = std::max(largest_force, std::abs(solver->force[j]));
          largest_difference = std::max(largest_difference,
                                        std::abs(solver->force[j] - fresh->force[j]));
        }
      if (k == n_settle)
        {
          // The settled block is the static state of the balance.
          balance.start(s, solver.get());
          slip_at_rest = slip();
        }
      else if (k > n_settle)
        {
          Tensor<1, dim> ground;
          ground[0] = ag;
          balance.add_step(s, ground, solver.get());
        }
    }

  const auto *updated = dynamic_cast<const joints::MixedJointSolver *>(solver.get());
  AssertThrow(updated, ExcMessage("the mixed solver was expected"));
  testing::log() << "pair forces with the pair system's kept LU and columns ("
                 << (updated->updated_solves > 0 ? "some" : "no")
                 << " solves updated) against both built anew at every step: ";
  testing::check_below("largest difference / largest force",
                       largest_difference / largest_force, 1e-8);
  const auto   e          = balance.terms();
  const double fe_slip    = std::abs(slip() - slip_at_rest);
  const double V          = A * g * t0;
  const double rigid_slip = V * V / (2 * g * mu) * (1 - mu / A);
  const double rigid_work = m * A * g * (A - mu) * g * t0 * t0 / 2;
  auto        &log        = testing::log();
  log << "block sliding under a rectangular pulse, A = " << A << ", t0 = " << t0
      << " s, mu = " << mu << std::endl;
  testing::check_relative("  contact dissipation [J] against mu m g x FE slip", e.contact,
                          mu * m * g * fe_slip, 5e-3);
  testing::check_relative("  contact dissipation [J] against the rigid block (mu m g x slip)",
                          e.contact, mu * m * g * rigid_slip, 0.02);
  testing::check_relative("  input work [J] against the rigid block", e.input, rigid_work, 0.02);
  const double t_stop = t0 * (A - mu) / mu;
  const double numerical =
    (np.beta1 - 0.5) * m * dt *
    (std::pow((A - mu) * g, 2) * t0 + std::pow(mu * g, 2) * t_stop);
  testing::check_relative("  algorithmic dissipation [J] against the scheme's dissipation",
                          e.algorithmic, numerical, 0.05);
  testing::check_below("  balance error with the algorithmic term (round-off)",
                       e.balance_error(), 1e-8);
  auto no_algorithmic        = e;
  no_algorithmic.algorithmic = 0.;
  testing::check_relative("  without it, the gap input - sum [J] against the same",
                          no_algorithmic.input - no_algorithmic.sum(), numerical, 0.05);
  auto without = e;
  without.contact = 0.;
  log << "  balance without the contact term open by more than 50 %: "
      << (without.balance_error() > 0.5 ? "yes" : "NO") << std::endl;
  if (std::getenv("ENERGY_BALANCE_NUMBERS")) // the terms, for the verification report
    std::cerr << "balance error " << e.balance_error() << " kinetic " << e.kinetic << " strain "
            << e.strain << " contact " << e.contact << " input " << e.input << std::endl;
}
