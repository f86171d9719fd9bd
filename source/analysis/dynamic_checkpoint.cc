// Checkpoints of the dynamic stage (output/checkpoint.h): what the rest of a
// run needs to continue exactly as if it had not stopped.
#include <archdam/analysis/simulation.h>
#include <archdam/base/binary_io.h>
#include <archdam/base/input_error.h>

#include <sstream>

namespace archdam::analysis
{
  using namespace dealii;

  namespace
  {
    /// Which cells and DOFs this rank owns: a checkpoint continues only on
    /// the same partition (each rank reads back its own part).
    std::uint64_t
    partition_signature(const fe::FESpace &space)
    {
      std::ostringstream owned;
      for (const auto &cell : space.dof_handler.active_cell_iterators())
        if (cell->is_locally_owned())
          binary::write(owned, cell->active_cell_index());
      for (auto range = space.locally_owned.begin_intervals();
           range != space.locally_owned.end_intervals(); ++range)
        binary::write_all(owned, *range->begin(), range->last());
      return output::fnv1a(owned.str());
    }
  } // namespace

  void
  Simulation::save_step_state(std::ostream &out) const
  {
    binary::write_all(out, current.time, current.step, current.u, current.v, current.a,
                      contact_iterations, max_contact_iterations, non_converged_times);
    if (joint_solver)
      joint_solver->save(out);
    if (massed_foundation)
      massed_foundation->save_state(out);
  }

  void
  Simulation::load_step_state(std::istream &in)
  {
    binary::read_all(in, current.time, current.step, current.u, current.v, current.a,
                     contact_iterations, max_contact_iterations, non_converged_times);
    if (joint_solver)
      joint_solver->load(in);
    if (massed_foundation)
      massed_foundation->load_state(in);
  }

  void
  Simulation::write_checkpoint()
  {
    TimerOutput::Scope t(timer, "dynamic: checkpoints");
    std::ostringstream out;
    binary::write(out, partition_signature(*fe_space));
    save_step_state(out);
    // The records so far: monitor, pressure and joint histories (their
    // files are written anew from them on resume), envelopes, the energy
    // sums, the summary (static and modal results included), field records.
    binary::write_all(out, peak_stress.value, peak_stress.where, peak_stress_time);
    history->save(out);
    if (pressure)
      pressure->save(out);
    if (joint_output)
      joint_output->save(out);
    stress_envelope->save(out);
    energy->save(out);
    fields->save(out);
    summary.save(out);

    output::CheckpointManifest manifest;
    manifest.n_ranks          = Utilities::MPI::n_mpi_processes(comm);
    manifest.step             = current.step;
    manifest.time             = current.time;
    manifest.case_fingerprint = p.fingerprint;
    output::CheckpointFiles(p.output.directory, comm).write(manifest, out.str());
  }

  void
  Simulation::check_checkpoint()
  {
    resume_payload = output::CheckpointFiles(p.output.directory, comm).read_payload(*resume_from);
    std::istringstream in(resume_payload);
    std::uint64_t      partition = 0;
    binary::read(in, partition);
    if (Utilities::MPI::logical_or(partition != partition_signature(*fe_space), comm))
      throw InputError("--resume: the model is divided among the MPI processes differently "
                       "from the run that wrote the checkpoint (another partition of the "
                       "mesh); each process can only continue its own part.");
  }

  void
  Simulation::read_checkpoint()
  {
    std::istringstream in(resume_payload);
    std::uint64_t      partition = 0;
    binary::read(in, partition); // checked by check_checkpoint()
    load_step_state(in);
    binary::read_all(in, peak_stress.value, peak_stress.where, peak_stress_time);
    history->load(in);
    if (pressure)
      pressure->load(in);
    if (joint_output)
      joint_output->load(in);
    stress_envelope->load(in);
    energy->load(in);
    fields->load(in);
    summary.load(in);
    if (current.step != resume_from->step || in.peek() != std::char_traits<char>::eof())
      throw InputError("Checkpoint: the saved state does not match this case (step " +
                       std::to_string(current.step) + ", expected " +
                       std::to_string(resume_from->step) + ", or data left over).");
  }
} // namespace archdam::analysis
