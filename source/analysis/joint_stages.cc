#include <archdam/analysis/simulation.h>
#include <archdam/base/input_error.h>

#include <algorithm>
#include <iomanip>

namespace archdam::analysis
{
  using namespace dealii;

  namespace
  {
    /// Contraction joints/On non-convergence: stop with the message, or go on
    /// (the caller flags the step).
    void
    check_convergence(const joints::JointParameters &p, const joints::JointSolver &solver,
                      const joints::ContactStep &step, const std::string &when)
    {
      if (!step.converged && p.on_non_convergence == joints::OnNonConvergence::stop)
        throw InputError("Contraction joints: " + when + ", " + solver.describe(step) +
                         ". Set 'On non-convergence = continue' to go on and flag such "
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
    joint_solver =
      joints::make_joint_solver(p.joints, *model().joint_pairs(), 1., stiffness, stiffness_factor);
    if (p.joints.grouting == joints::Grouting::after_self_weight)
      {
        Vector weight = model().self_weight();
        model().space().constraints.set_zero(weight);
        stiffness_factor.solve(u_static, weight);
        joint_solver->grout(u_static);
        // What the blocks do on their own: a block that cannot stand without
        // its neighbours shows here (doc/theory/loading-sequence.md §1).
        const double max_u = u_static.linfty_norm();
        screen << "  the self-weight on the independent cantilevers (max |u_i| = "
               << std::setprecision(4) << max_u << " m), then the joints grouted" << std::endl;
        summary.set("static/ungrouted cantilevers under self-weight: max nodal displacement "
                    "component [m]",
                    max_u);
      }
    const auto step = joint_solver->solve(rhs, joint_solver->unloaded(), u_static);
    if (!step.converged)
      non_converged_times.push_back(0.);
    check_convergence(p.joints, *joint_solver, step, "static stage");
    joint_solver->accept();
    summary.set("static/contact iterations", step.iterations);
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
