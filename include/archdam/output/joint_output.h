#pragma once

#include <archdam/joints/joint_solver.h>
#include <archdam/output/histories.h>
#include <archdam/output/recorder.h>

#include <memory>
#include <string>
#include <vector>

namespace archdam::output
{
  /**
   * What the joints leave behind (doc/theory/results.md §2), written by rank 0 into the
   * output directory:
   *  - joints_<stage>.pvd with joints_<stage>_NNNN.vtu: every node pair as a
   *    point with its joint, opening (gap, m), slip (m), normal and shear
   *    stress (Pa, compression negative) and state (0 separation, 1 stick,
   *    2 slip);
   *  - joint_histories_<stage>.csv: opening and slip of the pair nearest to
   *    each of `Contraction joints/Monitor points`, every recorded time;
   *  - joint_envelopes_<stage>.csv: for each joint and height z the largest
   *    opening over time; joint_crest_<stage>.csv: for each joint the largest
   *    opening at its crest (its highest pairs), where and when;
   *  - in the summary, the peak opening of each joint with time and place,
   *    and the largest penetration of a closed pair (the closure error of the
   *    step impulse, doc/theory/joints.md §10) with its joint and time.
   */
  class JointOutput : public HistoryRecorder
  {
  public:
    /// The pair fields are written at the stage's start and every
    /// @p field_interval steps (never with 0).
    JointOutput(const joints::JointParameters &p, const joints::NodePairs &pairs,
                const std::string &directory, const std::string &stage,
                unsigned int field_interval);

    std::string
    name() const override
    {
      return "joint histories";
    }
    /// One row of histories, the running envelopes, and the pair fields at
    /// the field output steps.
    void
    start(const StepRecord &s) override;
    void
    record(const StepRecord &s) override;
    /// Envelope files and the per-joint peaks into @p summary.
    void
    finish(Summary &summary, const dealii::ConditionalOStream &screen) override;

    /// The rows, peaks and field records so far, for a checkpoint
    /// (output/checkpoint.h).
    void
    save(std::ostream &out) const override;
    void
    load(std::istream &in) override;

    /// The largest penetration (-gap) of any pair recorded so far [m], 0 if none.
    double
    largest_penetration() const
    {
      return deepest;
    }

  private:
    /// One row of histories and the running envelopes at @p time.
    void
    add_row(double time, const joints::JointSolver &joints);
    /// One VTU of the pair fields at @p time.
    void
    write_fields(double time, const joints::JointSolver &joints);

    const joints::NodePairs                 &pairs;
    const std::string                directory, stage;
    const bool                       writer;
    const unsigned int               field_interval;
    std::vector<unsigned int>        monitored;
    std::vector<double>              peak_opening, peak_time;
    /// The largest slip of each pair so far (its tangential relative
    /// displacement since grouting) and when [m, s].
    std::vector<double>              peak_slip, peak_slip_time;
    /// The largest penetration (-gap) of any pair so far, its pair and time.
    double                           deepest = 0., deepest_time = 0.;
    unsigned int                     deepest_pair = 0;
    std::vector<std::pair<double, std::string>> pvd_records;
  };
} // namespace archdam::output
