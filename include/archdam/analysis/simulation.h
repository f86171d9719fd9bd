#pragma once

#include <archdam/analysis/energy_balance.h>
#include <archdam/analysis/modal_analysis.h>
#include <archdam/analysis/model.h>
#include <archdam/joints/joint_solver.h>
#include <archdam/output/checkpoint.h>
#include <archdam/output/field_writer.h>
#include <archdam/output/joint_output.h>
#include <archdam/output/monitor_histories.h>
#include <archdam/output/pressure_recorder.h>
#include <archdam/output/stress_envelope.h>
#include <archdam/physics/reservoir/coupled_system.h>
#include <archdam/physics/solid/stress.h>
#include <archdam/time/newmark.h>

#include <deal.II/base/conditional_ostream.h>
#include <deal.II/base/timer.h>

#include <memory>

namespace archdam::analysis
{
  /**
   * One case from start to end (doc/theory/conventions.md §1): the model is built once
   * (model.h: mesh, DOFs, M, K, loads), then the stages drive it in order,
   * static (gravity; static_stage.cc), modal (natural modes; modal_stage.cc)
   * and dynamic (ground motion from the static state; dynamic_stage.cc), each
   * writing its results; summary.json is written at the end. What the stages
   * leave (the state, the modes, the joints, the records) is read here, what
   * the model is made of through model().
   */
  class Simulation
  {
  public:
    Simulation(const Parameters &p, MPI_Comm comm, std::ostream &screen);

    /// Build the model and run every stage the parameters ask for; with
    /// @p resume, continue the dynamic stage from the newest checkpoint in
    /// Output/Directory instead (the static and modal stages are not
    /// repeated: their results are in the checkpoint).
    void
    run(bool resume = false);

    /// Build the model only: mesh, DOFs, M, K and loads (run() does it first).
    const Model &
    setup_model();

    /// `archdam CASE.prm --mesh-only`: build the model mesh, print its report,
    /// write it to Output/Directory as mesh.vtu and mesh_boundary.vtu
    /// (output/mesh_writer.h) with summary.json, and stop.
    void
    run_mesh_only();
    /// `archdam CASE.prm --free-field-check`: the case's rock alone as a
    /// column (physics/foundation/site_column.h) under the case's motion,
    /// against the control motion at the free surface and the free field at
    /// the dam's base; histories and spectra as CSV in the output directory
    /// (doc/theory/foundation.md §4). InputError on massless rock or without
    /// a ground motion.
    void
    run_free_field_check();

    /// The model the stages run on (setup_model() or run() built it).
    const Model &
    model() const
    {
      return *built_model;
    }

    // What the stages leave behind, for tests and benchmarks.
    const time::NewmarkState &
    state() const
    {
      return current;
    }
    const Vector &
    static_displacement() const
    {
      return u_static;
    }
    /// The recorder of type @p R of the dynamic stage (output::MonitorHistories,
    /// output::PressureRecorder, output::JointOutput, EnergyBalance, ...), or
    /// null if the case has none; its records are those of the last run.
    template <typename R>
    const R *
    recorder() const
    {
      for (const auto &r : recorders)
        if (const auto *found = dynamic_cast<const R *>(r.get()))
          return found;
      return nullptr;
    }
    /// The natural modes of the modal stage (empty before it ran).
    const NaturalModes &
    natural_modes() const
    {
      return modes;
    }
    /// Wall times and call counts of the stages.
    const dealii::TimerOutput &
    timers() const
    {
      return timer;
    }
    /// The joints in frictional contact (null for glued joints): their state
    /// after the last stage.
    const joints::JointSolver *
    joint_state() const
    {
      return joint_solver.get();
    }
    /// The dynamic stage's integrator with its factorized effective matrix,
    /// as that stage makes it (the coupled system with water, which then
    /// replaces the model's M and K: they are released); for benchmarks of
    /// the factorization.
    std::unique_ptr<time::NewmarkIntegrator>
    make_integrator();

  private:
    void
    create_output_directory();
    void
    run_static_stage();
    void
    run_modal_stage();
    void
    run_dynamic_stage();
    /// The static stage's loads on the dam against the force of the rock
    /// (static_resultants.h), on screen and in summary.json.
    void
    report_static_resultants();
    /// summary.json, and the peaks on screen.
    void
    write_summary();
    /// The output directory and the result files in it, on screen.
    void
    say_where_results_are();
    /// Say @p text on screen as a warning and keep it for summary.json
    /// (warnings/...): what does not stop the run but may make its results
    /// other than the user expects.
    void
    warn(const std::string &text);
    /// The dynamic stage's number of steps (InputError without an end).
    unsigned int
    dynamic_steps() const;
    /// Checks of the dynamic stage's steps against End time and the ground
    /// motion, before any stage runs: warnings for an End time that is no
    /// whole number of steps, a step coarser than a record's sampling, a run
    /// past the end of its record, a generated motion cut while still
    /// strong; InputError for a step not shorter than a record.
    void
    check_dynamic_steps();
    /// Warnings for values that are allowed but unlikely for a dam (a
    /// modulus or density in other units, a Westergaard water level other
    /// than the reservoir mesh's), before any stage runs.
    void
    check_plausibility();
    /// The damping ratio that the dam's Rayleigh coefficients give at a few
    /// frequencies and at the modal stage's first mode, on screen and in
    /// summary.json; a warning when that mode lies outside the frequencies
    /// at which the damping ratio was set and is damped otherwise.
    void
    report_damping_ratios();
    /// InputError when the static state is no state of a dam (a largest
    /// displacement above 1 % of the model's size).
    void
    check_static_state(double max_u) const;
    template <typename R>
    R *
    own_recorder()
    {
      return const_cast<R *>(std::as_const(*this).recorder<R>());
    }

    // Contraction joints/Model = frictional contact (joint_stages.cc).
    /// The pairs' DOFs when the stages' factorizations are condensed on them
    /// (Mixed method solves = condensed on the pairs), else empty.
    std::vector<dealii::types::global_dof_index>
    condensed_interface() const;
    /// K u = F_static with the joints in contact (the mixed method with K).
    void
    solve_static_with_joints(const SparseMatrix             &stiffness,
                             const time::FactorizedOperator &stiffness_factor,
                             const Vector                   &rhs);
    /// The same by dynamic relaxation: the load ramped in a damped transient
    /// with the mass M until at rest (Static solution = dynamic relaxation).
    void
    relax_static_with_joints(const SparseMatrix &stiffness, const Vector &rhs);
    /// Grouting = after self-weight: u = K^-1 F_g on the independent
    /// cantilevers, reported; the caller grouts the joints at u.
    void
    solve_ungrouted_self_weight(const time::FactorizedOperator &stiffness_factor, Vector &u);
    /// The static contact state's summary and output (joint_static_*.csv).
    void
    finish_static_joints(unsigned int iterations);
    /// The dynamic stage's joint solver with Kbar, from the static state.
    void
    start_dynamic_joints(const time::NewmarkIntegrator &newmark);
    /// Count the contact iterations of the step ending at @p t and stop
    /// (or flag the step) if it did not converge.
    void
    check_contact_step(const joints::ContactStep &step, double t);
    // Checkpoints of the dynamic stage (dynamic_checkpoint.cc).
    /// The state a step changes before the divergence check: u, v, a, the
    /// joints' committed state, the boundary's histories, contact counts.
    void
    save_step_state(std::ostream &out) const;
    void
    load_step_state(std::istream &in);
    /// The one list of what a checkpoint holds, read or written in the
    /// same order: the step state (@p a.values() for plain values,
    /// a.records() for objects with save()/load()), then the records.
    template <typename Self, typename Archive>
    static void
    visit_step_state(Self &self, Archive &a);
    template <typename Self, typename Archive>
    static void
    visit_records(Self &self, Archive &a);
    /// Everything the rest of the run needs (step state, histories,
    /// envelopes, energy sums, summary, field records) to
    /// Output/Directory/checkpoint (output/checkpoint.h).
    void
    write_checkpoint();
    /// Read and check the checkpoint resume_from names (files, checksums,
    /// partition) into resume_payload, before any result file is reopened:
    /// a resume that fails leaves the earlier results as they were.
    void
    check_checkpoint();
    /// Continue from resume_payload.
    void
    read_checkpoint();
    /// Set by run(true): the checkpoint the dynamic stage continues from.
    std::unique_ptr<output::CheckpointManifest> resume_from;
    std::string                                 resume_payload;

    /// The dynamic stage's recorders (dynamic_stage.cc), made with the
    /// model; the energy balance is made with the integrator, whose
    /// operators it uses.
    void
    make_recorders();
    std::unique_ptr<EnergyBalance>
    make_energy_balance() const;
    /// The current state as the recorders see it.
    output::StepRecord
    step_record() const;
    /// Whether the joints' pair forces act as one impulse per step: the
    /// outputs then show the step's mean acceleration (doc/theory/joints.md
    /// §10).
    bool
    step_impulse() const
    {
      return joint_solver && p.joints.contact_in_time == joints::ContactInTime::step_impulse;
    }
    /// Finish the recorders and put the stage's settings and costs into the
    /// summary: at the end, or after the last good step of a stopped run
    /// (@p n_run steps in @p wall_time seconds).
    void
    finish_dynamic_stage(double wall_time, unsigned int n_run);
    /// The factorization's size and the time per step of its parts into the
    /// summary (dynamic/factorization, dynamic/time per step).
    void
    summarize_step_costs(double steps_run);
    /// What the dynamic stage holds, part by part, and the peak resident
    /// memory, into the summary (dynamic/memory [MB]).
    void
    summarize_memory();
    /// Node pairs, solver and the steps whose contact problem did not
    /// converge, into the summary.
    void
    summarize_joints();

    /// The massed foundation's outer boundary, whose histories the
    /// dynamic stage advances, else null.
    physics::foundation::MassedFoundation *
    foundation() const
    {
      return built_model->foundation();
    }

    /// F(t) = F_static - sum_d a_g,d(t) M iota_d (relative formulation), and
    /// in the fluid rows of the coupled system -sum_d a_g,d(t) Phi S iota_d;
    /// F_static only if the static stage runs. With a massed foundation
    /// (total motion) the ground motion enters at the boundary instead.
    void
    external_load(double t, Vector &load) const;

    const Parameters                        &p;
    MPI_Comm                                 comm;
    dealii::ConditionalOStream               screen;
    dealii::TimerOutput                      timer;
    std::unique_ptr<Model>                   built_model;
    Vector                                   u_static;
    std::unique_ptr<physics::reservoir::CoupledSystem>           coupled;
    time::NewmarkState                       current;
    /// With the joints' step impulse: v at the start of the step and the
    /// step's mean acceleration, which the outputs show (output::StepRecord).
    Vector                                   v_before, mean_acceleration;
    NaturalModes                             modes;
    /// The dynamic stage's results (make_recorders()).
    std::vector<std::unique_ptr<output::Recorder>> recorders;
    output::Summary                          summary;
    std::unique_ptr<joints::JointSolver>     joint_solver;
    /// The dynamic stage's integrator (make_integrator()).
    std::unique_ptr<time::NewmarkIntegrator> integrator;
    /// Wall time of the steps' solves with the joints (the forward
    /// elimination, the contact problem, the backward substitution).
    dealii::Timer                            step_solve;
    /// Contact iterations per dynamic step: sum, maximum; flagged steps.
    unsigned long                            contact_iterations = 0;
    unsigned int                             max_contact_iterations = 0;
    /// The largest contact iteration count since the last progress line.
    unsigned int                             reported_contact_iterations = 0;
    std::vector<double>                      non_converged_times;
  };
} // namespace archdam::analysis
