#pragma once

// A record suite (doc/user-guide.md, "Record suites"): the same case run under
// several records, one after another, and the statistics of every peak over
// them, as the guidelines read a suite (the mean of seven or more records,
// else the largest).

#include <archdam/loads/design_spectrum.h>
#include <archdam/loads/ground_motion.h>
#include <archdam/parameters/parameters.h>

#include <deal.II/base/mpi.h>

#include <iosfwd>
#include <string>
#include <utility>
#include <vector>

namespace archdam::application
{
  /// One peak over the records of a suite. The standard deviation is the
  /// sample's (n - 1; 0 for one record); the design value is the mean with
  /// seven records or more, else the largest.
  struct SuiteStatistics
  {
    double mean = 0., largest = 0., standard_deviation = 0., mean_plus_sd = 0., design = 0.;
  };

  SuiteStatistics
  suite_statistics(const std::vector<double> &values);

  /// The peaks of a run's summary.json that a suite compares, by their path
  /// in it, as magnitudes: each joint's peak opening and slip, the monitors'
  /// peaks, and per face of the stress envelope the largest major principal
  /// stress, the arch and cantilever DCR and, per DCR level, the longest CID
  /// and the overstressed share of the area.
  std::vector<std::pair<std::string, double>>
  run_peaks(const std::string &summary_file);

  /// The factor Scale to target applies to a record whose motion (scaled
  /// by its own scales) is @p motion: exp of the mean of ln(target(T) /
  /// S_h(T)) over @p n periods spaced evenly in log T from @p period_min to
  /// @p period_max, S_h the geometric mean of the pseudo-accelerations of the
  /// x and y components (the one it has) at @p damping. InputError for a
  /// record without a horizontal component.
  double
  scale_to_target(const loads::GroundMotion     &motion,
                  const loads::TargetSpectrum   &target,
                  double                         damping,
                  double                         period_min,
                  double                         period_max,
                  unsigned int                   n = 40);

  /// What run_record_suite() does: run every record, then write the
  /// statistics; run one record only (as an independent job); or run
  /// nothing and write the statistics from the records' runs already made.
  enum class SuiteRun
  {
    all,
    one_record,
    gather
  };

  /// Run the case @p case_file (with @p overrides; read as @p p) once per
  /// record of p.suite into Output/Directory/NAME, then write suite.csv and
  /// suite.json there. With SuiteRun::one_record only the record named
  /// @p only runs (continued from its checkpoint if @p resume), with the
  /// same scale as in the whole suite, and no statistics are written; with
  /// SuiteRun::gather nothing runs and the statistics come from the records'
  /// folders, each checked to hold a finished run under that record's
  /// motion as the suite scales it. Collective.
  void
  run_record_suite(const std::string              &case_file,
                   const std::vector<std::string> &overrides,
                   const Parameters               &p,
                   MPI_Comm                        comm,
                   std::ostream                   &out,
                   SuiteRun                        run    = SuiteRun::all,
                   const std::string              &only   = "",
                   bool                            resume = false);
} // namespace archdam::application
