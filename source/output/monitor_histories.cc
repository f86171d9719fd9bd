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
    screen << "Peak values (monitors; s1 its largest tension, s3 its largest compression):"
           << std::endl;
    for (unsigned int c = 1; c < names.size(); ++c)
      {
        const Peak         kind = monitors.column_peaks()[c];
        const unsigned int best = peak_row(rows, c, kind);
        summary.set("peaks/" + names[c] + "/value", rows[best][c]);
        summary.set("peaks/" + names[c] + "/time [s]", rows[best][0]);
        screen << "  " << (kind == Peak::largest ? "largest" : kind == Peak::smallest ? "smallest" : "peak")
               << " " << names[c] << " = " << std::setprecision(4) << rows[best][c]
               << " at t = " << rows[best][0] << " s" << std::endl;
      }
  }

  unsigned int
  peak_row(const std::vector<std::vector<double>> &rows, const unsigned int c, const Peak kind)
  {
    const auto value = [&](const unsigned int r) {
      return kind == Peak::magnitude ? std::abs(rows[r][c]) :
             kind == Peak::largest   ? rows[r][c] :
                                       -rows[r][c];
    };
    unsigned int best = 0;
    for (unsigned int r = 1; r < rows.size(); ++r)
      if (value(r) > value(best))
        best = r;
    return best;
  }

} // namespace archdam::output
