#include <archdam/analysis/simulation.h>
#include <archdam/base/input_error.h>
#include <archdam/base/interrupt.h>
#include <archdam/base/run_stopped.h>
#include <archdam/base/wall_time.h>
#include <archdam/time/divergence_check.h>

#include <sys/resource.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <iomanip>
#include <limits>
#include <sstream>

namespace archdam::analysis
{
  using namespace dealii;

  namespace
  {
    std::string
    duration_text(const double seconds)
    {
      const long s = std::lround(seconds);
      std::ostringstream out;
      if (s >= 3600)
        out << s / 3600 << " h ";
      if (s >= 60)
        out << (s / 60) % 60 << " min ";
      out << s % 60 << " s";
      return out.str();
    }
  } // namespace

  /**
   * The energy balance of the dynamic stage (doc/theory/results.md §7) on the
   * operators the integrator steps: the solid's M, K and Rayleigh damping (or
   * the damping matrix assembled per material), or the coupled dam-water
   * system's M, D, K (made with the integrator), the water's operators, and
   * the foundation's boundary.
   */
  std::unique_ptr<EnergyBalance>
  Simulation::make_energy_balance() const
  {
    EnergyBalance::Model operators;
    operators.space     = &model().space();
    operators.mass      = coupled ? &coupled->mass : &model().mass();
    operators.stiffness = coupled ? &coupled->stiffness : &model().stiffness();
    operators.damping   = coupled ? &coupled->damping : model().damping();
    if (operators.damping && integrator)
      {
        operators.damping_products = integrator->single_precision_products();
        if (operators.damping_products)
          operators.integrator = integrator.get();
      }
    operators.rayleigh  = p.damping.rayleigh_coefficients();
    operators.newmark   = p.time_integration;
    operators.fluid     = model().fluid();
    operators.density   = p.reservoir.density;
    operators.dam_damping = model().dam_damping();
    if (model().reference_motion())
      {
        operators.reference       = model().reference_motion();
        operators.reference_loads = &model().reference_loads();
      }
    if (foundation())
      {
        operators.viscous    = foundation()->viscous_boundary();
        operators.prescribed = foundation()->prescribed_dofs();
      }
    else
      operators.influence = &model().influence_loads();
    return std::make_unique<EnergyBalance>(operators);
  }

  std::unique_ptr<time::NewmarkIntegrator>
  Simulation::make_integrator()
  {
    const auto rayleigh = p.damping.rayleigh_coefficients();
    const double dt     = p.time_integration.time_step;
    // The solid's damping (doc/theory/solid.md §4): alpha M + beta K, or the
    // matrix assembled with each material's coefficients.
    const SparseMatrix *D = model().damping();
    if (model().fluid())
      {
        // The coupled dam-water system, symmetric indefinite (paper eq. 3.2).
        coupled = std::make_unique<physics::reservoir::CoupledSystem>();
        physics::reservoir::form_coupled_system(
          *model().fluid(), p.reservoir.density, p.time_integration.beta2, dt, model().mass(),
          model().stiffness(),
          D ? physics::reservoir::MatrixTerms{{1., D}} :
              physics::reservoir::MatrixTerms{{rayleigh.first, &model().mass()},
                                              {rayleigh.second, &model().stiffness()}},
          *coupled);
        // A prescribed outer boundary drives the water too (doc/theory/foundation.md §7).
        if (auto *boundary = foundation() ? foundation()->prescribed_dofs() : nullptr)
          physics::reservoir::form_coupled_columns(model().space(), model().interface_pairs(),
                                                   p.reservoir.density,
                                                   p.time_integration.beta2, dt, *boundary);
        // The coupled system's solid blocks are M, D and K: no matrix held twice.
        built_model->release_solid_matrices();
        return std::make_unique<time::NewmarkIntegrator>(
          p.time_integration, coupled->mass, coupled->damping, coupled->stiffness,
          model().space().constraints, false, foundation() ? foundation()->dashpots() : nullptr,
          condensed_interface());
      }
    if (D)
      return std::make_unique<time::NewmarkIntegrator>(
        p.time_integration, model().mass(), *D, model().stiffness(), model().space().constraints,
        true, foundation() ? foundation()->dashpots() : nullptr, condensed_interface());
    return std::make_unique<time::NewmarkIntegrator>(
      p.time_integration, model().mass(), model().stiffness(), rayleigh,
      model().space().constraints, foundation() ? foundation()->dashpots() : nullptr,
      condensed_interface());
  }

  void
  Simulation::make_recorders()
  {
    // In the order they finish (the balance's line, then the peaks) and a
    // checkpoint holds them. A new output is one more line here. The energy
    // balance comes first, made with the integrator (run_dynamic_stage()).
    const std::string &directory = p.output.directory;
    recorders.clear();
    recorders.push_back(std::make_unique<output::MonitorHistories>(model().monitors(), directory, comm));
    if (p.reservoir.has_pressure())
      recorders.push_back(std::make_unique<output::PressureRecorder>(
        p.reservoir.pressure_points, p.reservoir.profile_times, model().space(), directory));
    if (model().joint_pairs())
      recorders.push_back(std::make_unique<output::JointOutput>(
        p.joints, *model().joint_pairs(), directory, "dynamic", p.output.field_interval));
    recorders.push_back(
      std::make_unique<output::StressEnvelope>(model().space(), p.materials,
                                               model().temperature(), directory,
                                               p.evaluation, [this](const unsigned int k) {
                                                 return p.joints.law_of(k).tensile_strength;
                                               }));
    recorders.push_back(std::make_unique<output::FieldWriter>(p.output, model().space(), p.materials,
                                                                 model().temperature()));
  }

  output::StepRecord
  Simulation::step_record() const
  {
    return {current,
            joint_solver.get(),
            foundation() ? Tensor<1, dim>() : model().ground_motion().acceleration(current.time),
            step_impulse() && current.step > 0 ? &mean_acceleration : nullptr};
  }

  unsigned int
  Simulation::dynamic_steps() const
  {
    // By default the whole record, as it reaches the free surface.
    const double end = p.time_integration.end_time > 0 ?
                         p.time_integration.end_time :
                         model().ground_motion().duration() + model().ground_motion_delay();
    if (end <= 0)
      throw InputError("Time integration/End time is 0 and there is no ground motion to "
                       "take the duration from.");
    return p.time_integration.n_steps(end);
  }

  void
  Simulation::report_damping_ratios()
  {
    // zeta(omega) = alpha / (2 omega) + beta omega / 2 (doc/theory/solid.md §4)
    const auto [alpha, beta] = p.damping.rayleigh_coefficients();
    const auto zeta          = [alpha = alpha, beta = beta](const double f) {
      const double omega = 2 * M_PI * f;
      return alpha / (2 * omega) + beta * omega / 2;
    };
    screen << "  the dam's damping ratio:" << std::setprecision(3);
    for (const double f : {0.5, 1., 2., 5., 10., 20.})
      screen << "  " << 100 * zeta(f) << " % at " << f << " Hz";
    screen << std::endl;
    if (modes.omega.empty())
      return;
    const double f1 = modes.omega[0] / (2 * M_PI);
    screen << "  at the first mode (" << f1 << " Hz): " << 100 * zeta(f1) << " %" << std::endl;
    summary.set("dynamic/damping ratio at the first mode", zeta(f1));
    const auto &d = p.damping;
    if (d.mode == physics::solid::DampingMode::damping_ratio &&
        (f1 < d.first_frequency || f1 > d.second_frequency) &&
        std::abs(zeta(f1) - d.ratio) > 0.2 * d.ratio)
      {
        std::ostringstream text;
        text << std::setprecision(3) << "the first mode (" << f1 << " Hz, modal stage) lies "
             << "outside Damping/First frequency - Second frequency (" << d.first_frequency
             << " - " << d.second_frequency << " Hz), between which the damping ratio is "
             << 100 * d.ratio << " %: it is damped by " << 100 * zeta(f1)
             << " %. Set the two frequencies about the modes that carry the response "
             << "(doc/theory/solid.md §4).";
        warn(text.str());
      }
  }

  void
  Simulation::check_dynamic_steps()
  {
    const double       dt  = p.time_integration.time_step;
    const double       end = dynamic_steps() * dt;
    std::ostringstream text;
    text << std::setprecision(6);
    // The stage ends at the step nearest to End time (doc/theory/time-integration.md §8).
    const double requested = p.time_integration.end_time;
    if (requested > 0 && std::abs(end - requested) > 1e-6 * dt)
      {
        text << "End time = " << requested << " s is not a whole number of time steps of " << dt
             << " s: the dynamic stage ends at the nearest step, t = " << end
             << " s (Time integration/End time).";
        warn(text.str());
      }
    if (model().ground_motion().empty())
      return;
    // The ground motion enters only at the steps: a step longer than a record
    // has nothing to sample, one coarser than its sampling interval skips
    // samples (doc/theory/time-integration.md §8).
    for (unsigned int d = 0; d < 3; ++d)
      if (model().ground_motion().has_component(d))
        {
          const auto &times    = model().ground_motion().record(d).times;
          double      interval = std::numeric_limits<double>::max();
          for (unsigned int k = 1; k < times.size(); ++k)
            interval = std::min(interval, times[k] - times[k - 1]);
          text.str("");
          const double length = times.empty() ? 0. : times.back() - times.front();
          if (dt >= length)
            {
              text << "Time integration: Time step = " << dt << " s is not shorter than the ground "
                   << "motion in " << "xyz"[d] << " (" << length << " s): no step would sample it. "
                   << "Use a step of at most its sampling interval (" << interval
                   << " s) and about 20 steps per period of the highest frequency of interest "
                   << "(doc/theory/time-integration.md §8).";
              throw InputError(text.str());
            }
          if (dt > interval * (1. + 1e-9))
            {
              text << "Time step = " << dt << " s is coarser than the sampling interval of the ground "
                   << "motion in " << "xyz"[d] << " (" << interval << " s): the motion is taken only at "
                   << "the steps and the samples between them are skipped. Use a step of at most the "
                   << "sampling interval, and about 20 steps per period of the highest frequency of "
                   << "interest (doc/theory/time-integration.md §8).";
              warn(text.str());
            }
        }
    text.str("");
    const double motion_end = model().ground_motion().duration() + model().ground_motion_delay();
    if (end > motion_end + 0.5 * p.time_integration.time_step)
      {
        text << "the dynamic stage runs to t = " << end << " s, past the end of the ground "
             << "motion at " << motion_end << " s";
        if (model().ground_motion_delay() > 0.)
          text << " (its record's end, plus " << model().ground_motion_delay()
               << " s for the wave to reach the free surface)";
        text << ": from there on the ground is at rest and the dam vibrates freely (Time "
                "integration/End time).";
        warn(text.str());
      }
    // A generated motion ends at rest whatever its envelope; cut while the
    // envelope is still high, its last seconds are forced down by the
    // end-at-rest correction instead of decaying (doc/ground-motion.md).
    for (unsigned int d = 0; d < 3; ++d)
      if (model().ground_motion().generation_report(d))
        {
          const auto   s         = p.ground_motion.generated.settings(d, "");
          const double intensity = s.envelope(s.duration);
          if (intensity > 0.1)
            {
              text.str("");
              text << "the generated motion in " << "xyz"[d] << " ends at Duration = "
                   << s.duration << " s with its intensity envelope still at " << intensity
                   << " of the strong part (Strong motion end = " << s.envelope.strong_end
                   << " s, Decay coefficient = " << s.envelope.decay
                   << " 1/s): it is cut while strong; a Duration of at least "
                   << s.envelope.strong_end + std::log(10.) / std::max(s.envelope.decay, 1e-12)
                   << " s lets it decay to 0.1 (Ground motion/Generated motion).";
              warn(text.str());
            }
        }
  }

  /**
   * Dynamic stage (doc/theory/time-integration.md §2 and doc/theory/loading-sequence.md §3): the generalized Newmark
   * scheme from the static state at rest, under F(t) = F_static - M iota a_g(t),
   * recording the monitors and the stress envelope on the dam faces every
   * step and the fields every few steps.
   */
  void
  Simulation::run_dynamic_stage()
  {
    const double       dt      = p.time_integration.time_step;
    const unsigned int n_steps = dynamic_steps();

    const auto rayleigh = p.damping.rayleigh_coefficients();
    screen << "Dynamic stage: factorizing the effective matrix (" << model().space().dof_handler.n_dofs()
           << " DOFs)" << std::endl;
    {
      TimerOutput::Scope t(timer, "dynamic: factorization");
      integrator = make_integrator();
    }
    screen << "  factors: " << std::setprecision(4) << integrator->effective_factor().factor_entries()
           << " entries" << std::endl;
    if (model().joint_pairs())
      start_dynamic_joints(*integrator);
    // The steps need Kbar's factor, not Kbar (unless the joints' solver
    // refactorizes it): a matrix the size of K less to hold.
    if (!joint_solver || !joint_solver->uses_matrix())
      integrator->release_effective_matrix();
    // With the effective load's products in single precision the integrator
    // copies M and D now, Kbar's memory given back (doc/performance.md §11);
    // the energy balance takes D v from the copy and the boundary's rows it
    // needs from the columns, and then the coupled D goes, and the columns
    // are copied and go: one matrix copied beside its original at a time.
    integrator->hold_in_single_precision(nullptr);
    recorders.insert(recorders.begin(), make_energy_balance());
    if (integrator->single_precision_products())
      {
        if (coupled)
          coupled->damping.clear();
        if (auto *boundary = foundation() ? foundation()->prescribed_dofs() : nullptr)
          {
            integrator->hold_in_single_precision(boundary);
            for (SparseMatrix *A : {&boundary->mass_columns, &boundary->stiffness_columns,
                                    &boundary->damping_columns})
              A->clear();
          }
      }
    screen << "Dynamic stage: " << n_steps << " steps of " << dt << " s to t = "
           << n_steps * dt << " s (Rayleigh alpha = " << rayleigh.first
           << " 1/s, beta = " << rayleigh.second << " s";
    if (!p.damping.uniform())
      screen << "; rock: alpha = " << p.damping.rock_coefficients().first
             << " 1/s, beta = " << p.damping.rock_coefficients().second << " s";
    screen << ")" << std::endl;
    report_damping_ratios();

    if (foundation())
      foundation()->start(current.u);
    if (resume_from) // the records so far come with the checkpoint
      read_checkpoint();
    else
      {
        current.time = 0.;
        current.step = 0;
        current.v    = 0.;
        current.a    = 0.;
        for (const auto &r : recorders)
          r->start(step_record());
      }

    Vector     load;
    model().space().reinit(load);
    const auto start       = std::chrono::steady_clock::now();
    const auto elapsed     = [&] { return seconds_since(start); };
    double       last_report = 0.;
    const double report_every = 10.; // seconds of wall time between progress lines
    const time::DivergenceCheck divergence(model().space());
    double                      last_checkpoint = 0.;
    std::string                 step_before; // the last good step, for the divergence stop

    const unsigned int       first_step = resume_from ? resume_from->step + 1 : 1;
    const interrupt::Armed   interruptible;
    for (unsigned int n = first_step; n <= n_steps; ++n)
      {
        {
          TimerOutput::Scope t(timer, "dynamic: last good step kept");
          std::ostringstream out;
          save_step_state(out);
          step_before = out.str();
        }
        {
          TimerOutput::Scope t(timer, "dynamic: steps");
          external_load(n * dt, load);
          if (step_impulse())
            v_before = current.v;
          joints::ContactStep contact;
          time::NewmarkIntegrator::StepSolver solve;
          if (joint_solver)
            solve = [&, joint_step = joints::contact_step_solver(*integrator, *joint_solver,
                                                                 contact)](const Vector &rhs,
                                                                           Vector       &da) {
              step_solve.start();
              joint_step(rhs, da);
              step_solve.stop();
            };
          if (foundation())
            foundation()->advance(*integrator, load, current, solve);
          else
            integrator->advance(load, current, solve);
          if (joint_solver)
            {
              check_contact_step(contact, n * dt);
              joint_solver->correct_position(*integrator, current);
            }
          if (step_impulse())
            {
              mean_acceleration = current.v;
              mean_acceleration -= v_before;
              mean_acceleration /= dt;
            }
          current.time = n * dt; // no drift from repeated additions
        }
        try
          {
            divergence.check(current, n);
          }
        catch (const RunStopped &stop)
          {
            // A checkpoint of the last good step, without the one that failed;
            // if it cannot be written (a full disk), the stop is still reported.
            std::istringstream before(step_before);
            load_step_state(before);
            std::string checkpoint_problem;
            try
              {
                write_checkpoint();
              }
            catch (const InputError &e)
              {
                checkpoint_problem = e.what();
              }
            // The results up to the last good step stay: the histories end
            // with it, the summary says why and when the run stopped.
            finish_dynamic_stage(elapsed(), n - first_step);
            summary.set("stopped/reason", stop.what());
            summary.set("stopped/step", stop.step);
            summary.set("stopped/time [s]", stop.time);
            summary.set("stopped/last complete time [s]", (n - 1) * dt);
            if (!checkpoint_problem.empty())
              summary.set("stopped/checkpoint not written", checkpoint_problem);
            write_summary();
            throw;
          }
        // after the check: a stopped run's records end with its last good step
        const auto record = step_record();
        for (const auto &r : recorders)
          {
            TimerOutput::Scope t(timer, "dynamic: " + r->name());
            r->record(record);
          }

        // Checkpoints by steps or wall time (rank 0's clock decides for all).
        const auto &every = p.checkpoints;
        bool        due   = n < n_steps && every.interval > 0 && n % every.interval == 0;
        if (n < n_steps && every.wall_interval > 0)
          due = Utilities::MPI::broadcast(
            comm, due || elapsed() - last_checkpoint >= every.wall_interval, 0);
        if (due)
          {
            write_checkpoint();
            last_checkpoint = elapsed();
            screen << "  checkpoint after step " << n << " (t = " << current.time << " s)"
                   << std::endl;
          }

        if (p.output.progress && (elapsed() - last_report > report_every || n == n_steps))
          {
            last_report = elapsed();
            screen << "  step " << n << "/" << n_steps << "  t = " << std::setprecision(4)
                   << current.time << " s  (" << 100 * n / n_steps << " %)  ETA "
                   << duration_text(last_report / (n + 1 - first_step) * (n_steps - n));
            if (joint_solver)
              screen << "  contact iterations <= " << reported_contact_iterations;
            screen << std::endl;
            reported_contact_iterations = 0;
          }

        // Ctrl-C or SIGTERM (base/interrupt.h): every rank stops after the
        // same step, with its results and a checkpoint of it.
        if (n < n_steps && Utilities::MPI::max(int(interrupt::requested()), comm) > 0)
          {
            write_checkpoint();
            finish_dynamic_stage(elapsed(), n + 1 - first_step);
            std::ostringstream text;
            text << "interrupted after step " << n << " of " << n_steps << " (t = " << current.time
                 << " s): the results up to it are in '" << p.output.directory
                 << "', with a checkpoint of it; the same command with --resume continues the run.";
            summary.set("stopped/reason", text.str());
            summary.set("stopped/step", n);
            summary.set("stopped/time [s]", current.time);
            summary.set("stopped/last complete time [s]", current.time);
            write_summary();
            throw RunStopped(text.str(), current.time, n);
          }
      }
    finish_dynamic_stage(elapsed(), n_steps + 1 - first_step);
  }

  void
  Simulation::finish_dynamic_stage(const double wall_time, const unsigned int n_run)
  {
    for (const auto &r : recorders)
      r->finish(summary, screen);

    const double dt       = p.time_integration.time_step;
    const auto   rayleigh = p.damping.rayleigh_coefficients();
    summary.set("dynamic/time step [s]", dt);
    summary.set("dynamic/steps", current.step);
    summary.set("dynamic/end time [s]", current.time);
    summary.set("dynamic/beta1", p.time_integration.beta1);
    summary.set("dynamic/beta2", p.time_integration.beta2);
    summary.set("dynamic/rayleigh alpha [s^-1]", rayleigh.first);
    summary.set("dynamic/rayleigh beta [s]", rayleigh.second);
    if (!p.damping.uniform())
      {
        summary.set("dynamic/rock rayleigh alpha [s^-1]", p.damping.rock_coefficients().first);
        summary.set("dynamic/rock rayleigh beta [s]", p.damping.rock_coefficients().second);
      }
    const double steps_run = std::max(n_run, 1u); // steps of this run (a resume: since it)
    summary.set("dynamic/wall time per step [s]", wall_time / steps_run);
    if (foundation())
      summary.set("dynamic/foundation boundary update per step [s]",
                  foundation()->boundary_update_time() / steps_run);
    if (joint_solver)
      {
        summary.set("dynamic/contact iterations per step/average",
                    static_cast<double>(contact_iterations) / std::max(current.step, 1u));
        summary.set("dynamic/contact iterations per step/maximum", max_contact_iterations);
        if (auto mixed = dynamic_cast<const joints::MixedJointSolver *>(joint_solver.get()))
          {
            summary.set("dynamic/time to build the flexibility matrix [s]", mixed->build_time);
            summary.set("dynamic/contact problem/factorizations", mixed->factorizations);
            summary.set("dynamic/contact problem/updated solves", mixed->updated_solves);
            if (p.joints.contact_problem == joints::ContactProblem::joint_by_joint)
              summary.set("dynamic/contact problem/handed over", mixed->handed_over);
          }
        if (p.joints.corrects_positions())
          {
            summary.set("dynamic/joints/steps with a position correction",
                        joint_solver->corrections);
            summary.set("dynamic/joints/largest position correction [m]",
                        joint_solver->largest_correction);
            summary.set("dynamic/time per step [s]/position correction",
                        joint_solver->correction_time / steps_run);
          }
      }
    summarize_step_costs(steps_run);
    summarize_memory();
  }

  void
  Simulation::summarize_memory()
  {
    // The matrices as PETSc stores them, 8 bytes of value and one column
    // index per entry (doc/performance.md §9), summed over the processes.
    const auto megabytes = [](std::initializer_list<const SparseMatrix *> matrices) {
      double bytes = 0.;
      for (const SparseMatrix *A : matrices)
        bytes += A->n_nonzero_elements() * (sizeof(PetscScalar) + sizeof(PetscInt)) +
                 A->m() * sizeof(PetscInt);
      return 1e-6 * bytes;
    };
    const std::string s = "dynamic/memory [MB]/";
    if (model().mass().m() > 0)
      summary.set(s + "solid M and K", megabytes({&model().mass(), &model().stiffness()}));
    if (const SparseMatrix *D = model().damping())
      summary.set(s + "solid D", megabytes({D}));
    if (const auto *water = model().fluid())
      summary.set(s + "water G, H, Q, S, S^T",
                  megabytes({&water->G, &water->H, &water->Q, &water->S, &water->S_transpose}));
    if (coupled)
      summary.set(s + (coupled->damping.m() > 0 ? "coupled M, D, K" : "coupled M, K"),
                  megabytes({&coupled->mass, &coupled->damping, &coupled->stiffness}));
    if (integrator && integrator->single_precision_products())
      summary.set(s + "effective load's products in single precision",
                  1e-6 * Utilities::MPI::sum(static_cast<double>(integrator->single_precision_memory()),
                                             comm));
    if (integrator && integrator->effective().m() > 0)
      summary.set(s + "effective matrix", megabytes({&integrator->effective()}));
    if (const auto *boundary = foundation() ? foundation()->prescribed_dofs() : nullptr;
        boundary && boundary->mass_columns.m() > 0)
      summary.set(s + "outer boundary columns",
                  megabytes({&boundary->mass_columns, &boundary->stiffness_columns,
                             &boundary->damping_columns}));
    if (const auto *condensed = integrator ? integrator->effective_factor().condensed() : nullptr)
      summary.set(s + "factorization", 1e-6 * condensed->statistics().memory);
    if (auto mixed = dynamic_cast<const joints::MixedJointSolver *>(joint_solver.get()))
      summary.set(s + "contact problem", 1e-6 * static_cast<double>(mixed->memory()));
    // The largest process's peak, and the sum of the processes' peaks.
    rusage usage;
    getrusage(RUSAGE_SELF, &usage);
    const double peak = 1e-3 * usage.ru_maxrss; // kB
    summary.set(s + "peak resident, largest process", Utilities::MPI::max(peak, comm));
    summary.set(s + "peak resident, all processes", Utilities::MPI::sum(peak, comm));
  }

  void
  Simulation::summarize_step_costs(const double steps_run)
  {
    // Where a step's time goes (doc/performance.md §7): the factorization's
    // size, and per step the parts of the solve, the recorders, the rest.
    const auto *condensed = integrator ? integrator->effective_factor().condensed() : nullptr;
    if (!condensed)
      return;
    const std::string s     = "dynamic/factorization/";
    const auto       &stats = condensed->statistics();
    summary.set(s + "factor entries", stats.entries);
    summary.set(s + "operations", stats.operations);
    summary.set(s + "memory [MB]", 1e-6 * stats.memory);
    const auto  times = condensed->solve_times();
    const auto  wall  = timer.get_summary_data(TimerOutput::total_wall_time);
    const auto  per_step = [&](const std::string &section) {
      const auto it = wall.find(section);
      return it == wall.end() ? 0. : it->second / steps_run;
    };
    const std::string t = "dynamic/time per step [s]/";
    summary.set(t + "forward elimination", times.elimination / steps_run);
    summary.set(t + "backward substitution", times.substitution / steps_run);
    if (joint_solver)
      summary.set(t + "contact problem",
                  (step_solve.wall_time() - times.elimination - times.substitution) /
                    steps_run);
    double recorded = 0.;
    for (const auto &r : recorders)
      recorded += per_step("dynamic: " + r->name());
    summary.set(t + "energy balance", per_step("dynamic: energy balance"));
    summary.set(t + "other recorders", recorded - per_step("dynamic: energy balance"));
    summary.set(t + "last good step kept", per_step("dynamic: last good step kept"));
    summary.set(t + "step", per_step("dynamic: steps"));
  }
} // namespace archdam::analysis
