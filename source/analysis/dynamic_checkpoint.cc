// Checkpoints of the dynamic stage (output/checkpoint.h): what the rest of a
// run needs to continue exactly as if it had not stopped.
#include <archdam/analysis/simulation.h>
#include <archdam/base/binary_io.h>
#include <archdam/base/input_error.h>

#include <sstream>

namespace archdam::analysis
{
  using namespace dealii;

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
  Simulation::read_checkpoint()
  {
    const std::string  payload =
      output::CheckpointFiles(p.output.directory, comm).read_payload(*resume_from);
    std::istringstream in(payload);
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
