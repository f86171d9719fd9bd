#include <archdam/output/monitor_histories.h>

#include <cmath>
#include <iomanip>

namespace archdam::output
{
  MonitorHistories::MonitorHistories(const Monitors &monitors, const std::string &directory,
                                     const MPI_Comm comm)
    : HistoryRecorder(directory + "/histories.csv", monitors.column_names(), comm)
    , monitors(monitors)
    , directory(directory)
  {}

  void
  MonitorHistories::record(const StepRecord &s)
  {
    table.append(monitors.evaluate(s.state, s.acceleration));
  }

  void
  MonitorHistories::finish(Summary &summary, const dealii::ConditionalOStream &screen)
  {
    table.write_hdf5(directory + "/histories.h5");
    const auto &rows  = table.rows();
    const auto &names = table.columns();
    if (rows.empty() || names.size() < 2) // the time column alone
      return;
    screen << "Peak values (monitors):" << std::endl;
    for (unsigned int c = 1; c < names.size(); ++c)
      {
        unsigned int best = 0;
        for (unsigned int r = 0; r < rows.size(); ++r)
          if (std::abs(rows[r][c]) > std::abs(rows[best][c]))
            best = r;
        summary.set("peaks/" + names[c] + "/value", rows[best][c]);
        summary.set("peaks/" + names[c] + "/time [s]", rows[best][0]);
        screen << "  peak " << names[c] << " = " << std::setprecision(4) << rows[best][c]
               << " at t = " << rows[best][0] << " s" << std::endl;
      }
  }

} // namespace archdam::output
