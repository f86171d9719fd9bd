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

  namespace
  {
    /// Writes a checkpoint's items (Simulation::visit_step_state()).
    struct Saver
    {
      std::ostream &out;
      template <typename... T>
      void
      values(const T &...v)
      {
        binary::write_all(out, v...);
      }
      template <typename T>
      void
      records(const T &r)
      {
        r.save(out);
      }
    };

    /// Reads them back, in the same order.
    struct Loader
    {
      std::istream &in;
      template <typename... T>
      void
      values(T &...v)
      {
        binary::read_all(in, v...);
      }
      template <typename T>
      void
      records(T &r)
      {
        r.load(in);
      }
    };
  } // namespace

  template <typename Self, typename Archive>
  void
  Simulation::visit_step_state(Self &self, Archive &a)
  {
    a.values(self.current.time, self.current.step, self.current.u, self.current.v,
             self.current.a, self.contact_iterations, self.max_contact_iterations,
             self.non_converged_times);
    if (self.joint_solver)
      a.records(*self.joint_solver);
    if (self.foundation())
      a.records(*self.foundation());
  }

  template <typename Self, typename Archive>
  void
  Simulation::visit_records(Self &self, Archive &a)
  {
    // The records so far (their files are written anew from them once a
    // resume has read everything), then the summary (static and modal
    // results included).
    for (const auto &r : self.recorders)
      a.records(*r);
    a.records(self.summary);
  }

  void
  Simulation::save_step_state(std::ostream &out) const
  {
    Saver saver{out};
    visit_step_state(*this, saver);
  }

  void
  Simulation::load_step_state(std::istream &in)
  {
    Loader loader{in};
    visit_step_state(*this, loader);
  }

  void
  Simulation::write_checkpoint()
  {
    TimerOutput::Scope t(timer, "dynamic: checkpoints");
    if (joint_solver) // a resumed run starts its contact factorization here too
      joint_solver->forget_factorization();
    std::ostringstream out;
    binary::write(out, partition_signature(model().space()));
    save_step_state(out);
    Saver saver{out};
    visit_records(*this, saver);

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
    if (Utilities::MPI::logical_or(partition != partition_signature(model().space()), comm))
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
    Loader loader{in};
    visit_records(*this, loader);
    if (current.step != resume_from->step || in.peek() != std::char_traits<char>::eof())
      throw InputError("Checkpoint: the saved state does not match this case (step " +
                       std::to_string(current.step) + ", expected " +
                       std::to_string(resume_from->step) + ", or data left over).");
    // Only now, with the whole checkpoint read, are the history files cut
    // back to its rows: a resume refused above leaves them as they were.
    for (const auto &r : recorders)
      r->resumed();
  }
} // namespace archdam::analysis
