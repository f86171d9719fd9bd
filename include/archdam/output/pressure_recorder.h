#pragma once

#include <archdam/fe/fe_space.h>
#include <archdam/output/histories.h>
#include <archdam/output/monitors.h>
#include <archdam/output/recorder.h>
#include <archdam/time/newmark.h>

#include <iosfwd>
#include <string>
#include <vector>

namespace archdam::output
{
  /**
   * The hydrodynamic pressure at named points in the water (doc/theory/results.md §4):
   * its history every step (`pressure_histories.csv`, rank 0 writes) and, on
   * finish(), the profile over the points at the chosen times with the
   * envelope (`pressure_profile.csv`: name, x, y, z, p at each time, max,
   * min). The FE weights of each point are computed once; an evaluation
   * gathers the few DOF values involved from their owners (one all-reduce).
   */
  class PressureRecorder : public HistoryRecorder
  {
  public:
    /// Throws InputError if a point lies in no water cell.
    PressureRecorder(const std::string &points, const std::string &profile_times,
                     const fe::FESpace &space, const std::string &directory);

    /// Pressure at each point for the nodal vector @p state.u.
    std::vector<double>
    evaluate(const Vector &u) const;

    std::string
    name() const override
    {
      return "pressure";
    }

    /// Evaluate and append a row at the step's time.
    void
    record(const StepRecord &s) override;

    /// Write the profile CSV.
    void
    finish(Summary &summary, const dealii::ConditionalOStream &screen) override;

  private:
    struct Weights
    {
      std::vector<dealii::types::global_dof_index> dofs;
      std::vector<double>                          value;
    };
    const fe::FESpace                &space;
    std::vector<MonitorPoint>         points;
    std::vector<double>               times;
    std::vector<Weights>              weights;
    std::string                       directory;
  };
} // namespace archdam::output
