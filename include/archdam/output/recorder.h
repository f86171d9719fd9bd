#pragma once

#include <archdam/output/summary.h>
#include <archdam/time/newmark.h>

#include <deal.II/base/conditional_ostream.h>
#include <deal.II/base/tensor.h>

#include <iosfwd>
#include <string>

namespace archdam::joints
{
  class JointSolver;
}

namespace archdam::output
{
  /// What a recorder sees of a state of a stage.
  struct StepRecord
  {
    /// u, v, a, the time and the step number (0: the stage's initial state).
    const time::NewmarkState &state;
    /// The joints' forces and state (null without frictional joints).
    const joints::JointSolver *joints = nullptr;
    /// The ground acceleration of the relative formulation at this time
    /// (zero with a massed foundation, whose input enters at its boundary).
    dealii::Tensor<1, dim> ground_acceleration;
    /// The acceleration the outputs show when it is not state.a: with the
    /// joints' step impulse, the step's mean acceleration (v_{n+1} - v_n) / dt
    /// (doc/theory/joints.md §10: state.a carries the load's oscillation).
    const Vector *acceleration = nullptr;

    /// The acceleration the outputs show.
    const Vector &
    shown_acceleration() const
    {
      return acceleration ? *acceleration : state.a;
    }
  };

  /**
   * One result of a stage that follows the state step by step: histories,
   * envelopes, fields, the energy balance (doc/theory/results.md). The
   * dynamic stage keeps one list of recorders and calls each in the same
   * way; the checkpoint saves and loads the same list in its order. A new
   * output implements this interface in its own file and is added where the
   * stage lists its recorders.
   */
  class Recorder
  {
  public:
    virtual ~Recorder() = default;

    /// A short name ("monitors", "energy balance"): the stage's timer for
    /// this recorder is "dynamic: NAME".
    virtual std::string
    name() const = 0;

    /// The stage's initial state (step 0). Not called on a resume: the
    /// checkpoint brings the records up to its step.
    virtual void
    start(const StepRecord &s)
    {
      record(s);
    }

    /// The state after a step.
    virtual void
    record(const StepRecord &s) = 0;

    /// The stage has ended, or stopped after its last good step: complete
    /// the files, put the peaks into @p summary, say what the user should
    /// see on @p screen.
    virtual void
    finish(Summary &summary, const dealii::ConditionalOStream &screen) = 0;

    /// The records so far, for a checkpoint (output/checkpoint.h).
    virtual void
    save(std::ostream &out) const = 0;
    virtual void
    load(std::istream &in) = 0;

    /// A resume has read the whole checkpoint: write the files anew from the
    /// records (cut back to the checkpoint's step).
    virtual void
    resumed()
    {}
  };
} // namespace archdam::output
