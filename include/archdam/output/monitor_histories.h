#pragma once

#include <archdam/output/histories.h>
#include <archdam/output/monitors.h>

namespace archdam::output
{
  /**
   * The monitor points' histories (doc/theory/results.md §1): one row of
   * `histories.csv` a step, `histories.h5` at the end, and every column's
   * peak (largest magnitude, with its time) in the summary and on screen.
   */
  class MonitorHistories : public HistoryRecorder
  {
  public:
    MonitorHistories(const Monitors &monitors, const std::string &directory, MPI_Comm comm);

    std::string
    name() const override
    {
      return "monitors";
    }
    void
    record(const StepRecord &s) override;
    void
    finish(Summary &summary, const dealii::ConditionalOStream &screen) override;

  private:
    const Monitors &monitors;
    std::string     directory;
  };
} // namespace archdam::output
