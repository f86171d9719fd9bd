#pragma once

#include <archdam/joints/joint_solver.h>
#include <archdam/output/histories.h>
#include <archdam/output/summary.h>

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
   *  - in the summary, the peak opening of each joint with time and place.
   */
  class JointOutput
  {
  public:
    JointOutput(const joints::JointParameters &p, const joints::NodePairs &pairs, const std::string &directory,
                const std::string &stage);

    /// One row of histories, and the running envelopes.
    void
    record(double time, const joints::JointSolver &joints);
    /// One VTU of the pair fields at @p time.
    void
    write_fields(double time, const joints::JointSolver &joints);
    /// Envelope files and the per-joint peaks into @p summary.
    void
    finish(output::Summary &summary) const;

    const std::vector<std::string> &
    columns() const
    {
      return histories->columns();
    }
    const std::vector<std::vector<double>> &
    rows() const
    {
      return histories->rows();
    }

    /// The rows, peaks and field records so far, for a checkpoint
    /// (output/checkpoint.h).
    void
    save(std::ostream &out) const;
    /// Continue after a checkpoint; rewrite_history() then writes the joint
    /// histories file anew with its rows.
    void
    load(std::istream &in);
    void
    rewrite_history()
    {
      histories->rewrite();
    }

  private:
    const joints::NodePairs                 &pairs;
    const std::string                directory, stage;
    const bool                       writer;
    std::vector<unsigned int>        monitored;
    /// Opening and slip of the monitored pairs.
    std::unique_ptr<output::HistoryWriter> histories;
    std::vector<double>              peak_opening, peak_time;
    std::vector<std::pair<double, std::string>> pvd_records;
  };
} // namespace archdam::output
