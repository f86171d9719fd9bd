// Helpers shared by ArchDam's tests. Every verification test compares with a
// reference computed independently inside the test (closed form, series, a
// second method) and prints a verdict with the stated tolerance; the .output
// file then records the verdicts, never raw numbers produced by the code alone.
#pragma once

#include <archdam/base/input_error.h>

#include <deal.II/base/exceptions.h>
#include <deal.II/base/mpi.h>

#include <algorithm>
#include <cmath>
#include <fstream>
#include <functional>
#include <iomanip>
#include <iostream>
#include <regex>
#include <sstream>
#include <string>
#include <vector>

namespace archdam::testing
{
  /// The recorded motions shipped with the repository.
  inline const std::string ground_motions = SOURCE_DIR "/../data/ground_motions/";

  /// Only rank 0 prints; the others write to a sink.
  inline std::ostream &
  log()
  {
    static std::ostringstream sink;
    if (dealii::Utilities::MPI::this_mpi_process(MPI_COMM_WORLD) == 0)
      return std::cout;
    sink.str("");
    return sink;
  }

  /// The verdict printed for a check: "yes" or "NO".
  inline std::string
  yes(const bool ok)
  {
    return ok ? "yes" : "NO";
  }

  /**
   * Print "what: value (reference ref), relative error below tol: yes|NO".
   * Values are printed with @p digits significant digits so that round-off
   * (serial against MPI runs) does not change the text; the verdict is what
   * matters.
   */
  inline bool
  check_relative(const std::string &what, const double value, const double reference,
                 const double tol, const unsigned int digits = 4)
  {
    const double err = std::abs(value - reference) / std::abs(reference);
    const bool   ok  = err < tol;
    log() << what << ": " << std::setprecision(digits) << value << " (reference "
          << reference << "), relative error below " << tol << ": " << (ok ? "yes" : "NO")
          << std::endl;
    return ok;
  }

  /// Print "what: below tol: yes|NO" for an error measure, without its value.
  inline bool
  check_below(const std::string &what, const double value, const double tol)
  {
    const bool ok = value < tol;
    log() << what << " below " << tol << ": " << (ok ? "yes" : "NO") << std::endl;
    return ok;
  }

  /// Run @p run, which must throw an InputError, and print @p what with the
  /// verdict and the message.
  inline void
  check_input_error(const std::string &what, const std::function<void()> &run)
  {
    try
      {
        run();
        log() << "* " << what << "\n  accepted: NO (an InputError was expected)" << std::endl;
      }
    catch (const InputError &e)
      {
        log() << "* " << what << "\n  InputError: yes\n  " << e.what() << std::endl;
      }
    catch (const std::exception &e)
      {
        log() << "* " << what << "\n  another exception: NO\n  " << e.what() << std::endl;
      }
  }

  /// The message of the InputError that @p run throws, "" when it throws none
  /// (for tests that look for words in the message).
  inline std::string
  input_error_message(const std::function<void()> &run)
  {
    try
      {
        run();
      }
    catch (const InputError &e)
      {
        return e.what();
      }
    return "";
  }

  /// Print @p what and then the message of the InputError that @p run must
  /// throw ("  InputError: ..."), or what happened instead.
  inline void
  expect_input_error(const std::string &what, const std::function<void()> &run)
  {
    log() << what << std::endl;
    try
      {
        run();
        log() << "  NO EXCEPTION" << std::endl;
      }
    catch (const InputError &e)
      {
        log() << "  InputError: " << e.what() << std::endl;
      }
    catch (const std::exception &e)
      {
        log() << "  WRONG EXCEPTION: " << e.what() << std::endl;
      }
  }

  /// The index of the column @p name among @p names (a history's header).
  inline std::size_t
  column(const std::vector<std::string> &names, const std::string &name)
  {
    const std::size_t c = std::find(names.begin(), names.end(), name) - names.begin();
    AssertThrow(c < names.size(), dealii::ExcMessage("column '" + name + "' missing"));
    return c;
  }

  /// The first number stored under @p key in a summary.json (read on rank 0,
  /// the same on every rank); -1 if the file or the key is missing.
  inline double
  summary_number(const std::string &file, const std::string &key)
  {
    double value = -1.;
    if (dealii::Utilities::MPI::this_mpi_process(MPI_COMM_WORLD) == 0)
      {
        std::ifstream     in(file);
        std::stringstream text;
        text << in.rdbuf();
        const std::string s = text.str();
        std::smatch       m;
        if (std::regex_search(s, m, std::regex("\"" + key + "\": *\"?([-+0-9.eE]+)")))
          value = std::stod(m[1]);
      }
    return dealii::Utilities::MPI::broadcast(MPI_COMM_WORLD, value, 0);
  }
} // namespace archdam::testing
