#include <archdam/analysis/simulation.h>
#include <archdam/base/input_error.h>
#include <archdam/base/wall_time.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <sstream>
#include <iomanip>

namespace archdam::analysis
{
  using namespace dealii;

  namespace
  {
    /// Contraction joints/On non-convergence: stop with the message, or go on
    /// (the caller flags the step). @p advice: a remedy named before the
    /// general ones.
    void
    check_convergence(const joints::JointParameters &p, const joints::JointSolver &solver,
                      const joints::ContactStep &step, const std::string &when,
                      const std::string &advice = "")
    {
      if (!step.converged && p.on_non_convergence == joints::OnNonConvergence::stop)
        throw InputError("Contraction joints: " + when + ", " + solver.describe(step) + ". " +
                         advice + "Set 'On non-convergence = continue' to go on and flag such "
                         "steps, or adjust Maximum iterations or the tolerances.");
    }
  } // namespace

  std::vector<types::global_dof_index>
  Simulation::condensed_interface() const
  {
    if (model().joint_pairs() && p.joints.solver == joints::Solver::mixed &&
        p.joints.mixed_solves == joints::MixedSolves::condensed_on_the_pairs)
      return model().joint_pairs()->interface();
    return {};
  }

  /**
   * Static stage with the joints in frictional contact (doc/theory/loading-sequence.md
   * §1, doc/theory/joints.md §8, first line). Grouting = after self-weight:
   * the self-weight on the independent cantilevers (K u_g = F_g, no pair
   * forces), the joints grouted at u_g; then the mixed method with K in place
   * of Kbar for the whole static load from the grouted, closed joints, which
   * see only the displacement since grouting (the hydrostatic load's).
   * Grouting = before self-weight: that second solve alone, the weight
   * carried through the closed joints too.
   */
  void
  Simulation::solve_static_with_joints(const SparseMatrix             &stiffness,
                                       const time::FactorizedOperator &stiffness_factor,
                                       const Vector                   &rhs)
  {
    // K alone couples every pair of a joint, and neighbouring joints
    // strongly, so that joint by joint would need many sweeps
    // (doc/theory/joints.md §12): the one solve takes all pairs at once.
    joints::JointParameters static_joints = p.joints;
    static_joints.contact_problem         = joints::ContactProblem::all_pairs_at_once;
    joint_solver =
      joints::make_joint_solver(static_joints, *model().joint_pairs(), 1., stiffness, stiffness_factor);
    if (p.joints.grouting == joints::Grouting::after_self_weight)
      {
        solve_ungrouted_self_weight(stiffness_factor, u_static);
        joint_solver->grout(u_static);
      }
    const auto step = joint_solver->solve(rhs, joint_solver->unloaded(), u_static);
    if (!step.converged)
      non_converged_times.push_back(0.);
    check_convergence(p.joints, *joint_solver, step, "static stage",
                      "The one solve's active set can cycle on meshes with many cells over "
                      "the height: 'Static solution = dynamic relaxation' brings the static "
                      "load on in a damped transient instead (doc/theory/loading-sequence.md "
                      "§1). ");
    joint_solver->accept();
    finish_static_joints(step.iterations);
  }

  void
  Simulation::solve_ungrouted_self_weight(const time::FactorizedOperator &stiffness_factor,
                                          Vector                         &u)
  {
    Vector weight = model().self_weight();
    model().space().constraints.set_zero(weight);
    stiffness_factor.solve(u, weight);
    // What the blocks do on their own: a block that cannot stand without
    // its neighbours shows here (doc/theory/loading-sequence.md §1).
    const double max_u = u.linfty_norm();
    screen << "  the self-weight on the independent cantilevers (max |u_i| = "
           << std::setprecision(4) << max_u << " m), then the joints grouted" << std::endl;
    summary.set("static/ungrouted cantilevers under self-weight: max nodal displacement "
                "component [m]",
                max_u);
    // Whether they stand apart: the normal relative displacement of every
    // pair, negative where two blocks would overlap.
    Vector distributed = u;
    model().space().constraints.distribute(distributed);
    std::vector<double> w;
    model().joint_pairs()->relative_displacement(distributed, w);
    unsigned int closest = 0;
    for (unsigned int q = 0; q < model().joint_pairs()->size(); ++q)
      if (w[dim * q] < w[dim * closest])
        closest = q;
    if (model().joint_pairs()->size() > 0)
      {
        const auto &pair = (*model().joint_pairs())[closest];
        screen << "  the smallest normal relative displacement of a pair: " << std::setprecision(3)
               << w[dim * closest] << " m (joint " << pair.joint << " at " << pair.position
               << "; negative: the blocks would overlap)" << std::endl;
        const std::string key = "static/ungrouted cantilevers under self-weight: smallest "
                                "normal relative displacement of a pair [m]/";
        summary.set(key + "value", w[dim * closest]);
        summary.set(key + "joint", pair.joint);
        for (unsigned int d = 0; d < dim; ++d)
          summary.set(key + std::string(1, "xyz"[d]) + " [m]", pair.position[d]);
      }
  }

  /**
   * Static stage with the joints by dynamic relaxation (doc/theory/loading-sequence.md
   * §1, "How the static contact problem is solved"):
   *   M a + alpha M v + K u + B^T f = F_0 + lambda(t) (F - F_0),
   * alpha = 4 pi Frequency, lambda rising from 0 to 1 over the loading time,
   * stepped with the Newmark scheme (Beta1 = 3/4) as a dynamic step (one
   * factorization of Kbar = (1 + alpha beta1 dt) M + beta2 dt^2 K, the
   * contact problem on the pairs), from the grouted state at rest (u = 0, or
   * u_g with F_0 = F_g after self-weight) until
   * |F - K u - B^T f| <= Tolerance |F| (the absolute value without a load).
   */
  void
  Simulation::relax_static_with_joints(const SparseMatrix &stiffness, const Vector &rhs)
  {
    const auto            &r = p.joints.relaxation;
    // The trapezoidal forces hold the closed pairs' positions, so the state
    // at rest satisfies the law (the step impulse holds their velocities, and
    // a pair may rest closed at a small gap); Beta1 = 3/4 dissipates what
    // they put in when pairs open, and damps the high modes.
    joints::JointParameters relaxation_joints = p.joints;
    relaxation_joints.contact_in_time         = joints::ContactInTime::trapezoidal;
    // its long step (10 ms) couples the joints more than the dynamic
    // stage's, and the sweeps would not pay (doc/theory/joints.md §12)
    relaxation_joints.contact_problem = joints::ContactProblem::all_pairs_at_once;
    time::NewmarkParameters scheme;
    scheme.time_step   = r.time_step;
    scheme.beta1       = 0.75;
    scheme.beta2       = 0.390625; // (beta1 + 1/2)^2 / 4
    // Its factor in the dynamic stage's precision (doc/performance.md §8):
    // the out-of-balance force that ends the relaxation is computed with K
    // itself, so a single-precision factor changes the path to rest, not
    // what the state at rest satisfies. (Block low rank is left to the
    // dynamic stage: on the case's mesh it raised this stage's peak memory.)
    scheme.factor_precision = p.time_integration.factor_precision;
    const double alpha = 4. * numbers::PI * r.frequency;

    time::NewmarkState s;
    for (Vector *x : {&s.u, &s.v, &s.a})
      model().space().reinit(*x);
    Vector start_load, load, residual;
    model().space().reinit(start_load);
    model().space().reinit(load);
    model().space().reinit(residual);
    if (p.joints.grouting == joints::Grouting::after_self_weight)
      {
        time::FactorizedOperator stiffness_factor;
        stiffness_factor.factorize(stiffness, true);
        solve_ungrouted_self_weight(stiffness_factor, s.u);
        start_load = model().self_weight();
        model().space().constraints.set_zero(start_load);
      }
    time::NewmarkIntegrator relaxation(scheme, model().mass(), stiffness, {alpha, 0.},
                                       model().space().constraints, nullptr,
                                       condensed_interface());
    joint_solver = joints::make_joint_solver(relaxation_joints, *model().joint_pairs(),
                                             relaxation.displacement_factor(),
                                             relaxation.effective(), relaxation.effective_factor());
    joint_solver->grout(s.u);
    if (!joint_solver->uses_matrix())
      relaxation.release_effective_matrix();
    screen << "  dynamic relaxation: steps of " << r.time_step << " s, damping critical at "
           << r.frequency << " Hz, the load ramped over " << r.loading_time << " s" << std::endl;

    const double scale       = rhs.linfty_norm();
    const auto   start       = std::chrono::steady_clock::now();
    double       last_report = 0.;
    unsigned int iterations = 0, most_iterations = 0;
    double       out_of_balance = 1.;
    unsigned int n              = 0;
    while (true)
      {
        if (n == r.max_steps)
          {
            std::ostringstream text;
            text << "Static stage: the dynamic relaxation has not come to rest in " << n
                 << " steps (t = " << n * r.time_step << " s): the out-of-balance force is "
                 << out_of_balance << " of the largest load, Tolerance = " << r.tolerance
                 << ". Raise Contraction joints/Dynamic relaxation/Maximum steps, or set "
                 << "its Frequency near the dam's first natural frequency.";
            throw InputError(text.str());
          }
        ++n;
        const double t      = n * r.time_step;
        const double lambda = t >= r.loading_time ? 1. : 0.5 * (1. - std::cos(numbers::PI * t / r.loading_time));
        load.equ(1. - lambda, start_load);
        load.add(lambda, rhs);
        const auto step = joints::advance_with_contact(relaxation, *joint_solver, load, s);
        iterations += step.iterations;
        most_iterations = std::max(most_iterations, step.iterations);
        if (!step.converged)
          non_converged_times.push_back(0.);
        check_convergence(p.joints, *joint_solver, step,
                          "static stage, dynamic relaxation step " + std::to_string(n));
        // F - K u - B^T f with the forces the law holds.
        stiffness.vmult(residual, s.u);
        residual.sadd(-1., 1., rhs);
        model().joint_pairs()->add_transpose(joint_solver->force, -1., residual);
        model().space().constraints.set_zero(residual);
        out_of_balance = residual.linfty_norm() / (scale > 0. ? scale : 1.);
        const bool   done = t >= r.loading_time && out_of_balance <= r.tolerance;
        const double wall = seconds_since(start);
        if (p.output.progress && (wall - last_report > 10. || done))
          {
            last_report = wall;
            screen << "  relaxation step " << n << "  t = " << std::setprecision(4) << t
                   << " s  load " << std::setprecision(3) << lambda << "  out of balance "
                   << out_of_balance << "  contact iterations <= " << most_iterations
                   << std::endl;
          }
        if (done)
          break;
      }
    u_static = s.u;
    summary.set("static/dynamic relaxation/steps", n);
    summary.set("static/dynamic relaxation/out-of-balance force relative to the largest load",
                out_of_balance);
    summary.set("static/dynamic relaxation/largest contact iterations in a step", most_iterations);
    finish_static_joints(iterations);
  }

  void
  Simulation::finish_static_joints(const unsigned int iterations)
  {
    summary.set("static/contact iterations", iterations);
    if (auto mixed = dynamic_cast<const joints::MixedJointSolver *>(joint_solver.get()))
      summary.set("static/time to build the flexibility matrix [s]", mixed->build_time);

    // The static stage's one state, its pair fields always written.
    output::JointOutput static_output(p.joints, *model().joint_pairs(), p.output.directory, "static", 1);
    static_output.start(step_record());
    static_output.finish(summary, screen);
  }

  void
  Simulation::start_dynamic_joints(const time::NewmarkIntegrator &newmark)
  {
    auto solver = joints::make_joint_solver(p.joints, *model().joint_pairs(), newmark.displacement_factor(),
                                            newmark.effective(), newmark.effective_factor());
    if (joint_solver) // the static state: forces, relative displacements, damage
      solver->set_state(*joint_solver);
    joint_solver = std::move(solver);
  }

  void
  Simulation::check_contact_step(const joints::ContactStep &step, const double t)
  {
    contact_iterations += step.iterations;
    max_contact_iterations = std::max(max_contact_iterations, step.iterations);
    reported_contact_iterations = std::max(reported_contact_iterations, step.iterations);
    if (!step.converged)
      non_converged_times.push_back(t);
    check_convergence(p.joints, *joint_solver, step, "t = " + std::to_string(t) + " s");
  }

  void
  Simulation::summarize_joints()
  {
    summary.set("joints/node pairs", model().joint_pairs()->size());
    summary.set("joints/solver", selection_name(p.joints.solver, joints::solver_names()));
    summary.set("joints/steps not converged", non_converged_times.size());
    for (unsigned int k = 0; k < std::min<std::size_t>(non_converged_times.size(), 20); ++k)
      summary.set("joints/steps not converged at [s]/" + std::to_string(k),
                  non_converged_times[k]);
  }
} // namespace archdam::analysis
