#pragma once

#include <archdam/base/selection.h>

#include <deal.II/base/mpi.h>

#include <string>
#include <vector>

namespace archdam::output
{
  /// `Output/Earlier results`: what a new run does with the results of an
  /// earlier run in its output directory.
  enum class EarlierResults
  {
    replace, ///< remove them before the run writes anything
    keep,    ///< leave them (files the new run does not write stay)
    refuse   ///< stop, naming them
  };

  /// The names of EarlierResults in the case file.
  inline const SelectionNames<EarlierResults> &
  earlier_results_names()
  {
    static const SelectionNames<EarlierResults> names{{"replace", EarlierResults::replace},
                                                      {"keep", EarlierResults::keep},
                                                      {"refuse", EarlierResults::refuse}};
    return names;
  }

  /// The entries of @p directory that an ArchDam run writes (the summary,
  /// histories, joint and stress tables, field and mesh files, checkpoints),
  /// by name, sorted; nothing else in the directory is ever listed.
  std::vector<std::string>
  earlier_results(const std::string &directory);

  /**
   * Before a new run (not a resumed one) writes into @p directory: with
   * replace, remove the entries earlier_results() lists, so that ParaView
   * and a reader of the tables see this run alone; with refuse, throw
   * InputError naming them if there are any; with keep, nothing. Rank 0
   * acts for all ranks. Collective.
   */
  void
  handle_earlier_results(const std::string &directory, EarlierResults policy, MPI_Comm comm);
} // namespace archdam::output
