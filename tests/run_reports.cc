// What a run reports about itself (issue "user holes", items 16, 19, 20, 23),
// each against a reference the run did not produce:
// A. The static resultants on the dam (analysis/static_resultants.h): a box
//    dam of two blocks with a frictional joint standing on a fixed base (no
//    rock meshed), nu = 0, Q2, self-weight: the weight is -rho g L W H e_z
//    (closed form), and the support's force, integrated from the stress on
//    the base, is +rho g L W H e_z: sigma_zz = -rho g (H - z) is exact in Q2
//    for the laterally free column (tests/gravity_column.cc), so the out of
//    balance is round-off (1e-9).
// B. summary.json read with a JSON parser (Boost's): every column of
//    histories.csv (displacement, acceleration in [m/s^2], principal stress)
//    is a key of "peaks" with its value and time, under its full name, and
//    each peak is the largest magnitude of its column in histories.csv; the
//    mesh report's node pairs of the joint (counted on the mesh) equal the
//    node pairs the analysis built.
// C. Warnings in summary.json: a dynamic stage longer than its record (a
//    two-sample record, 0.02 s, a run of 0.05 s), and a generated motion cut
//    while strong (Duration 13 s, Strong motion end 12 s, decay 0.3 1/s:
//    the envelope is exp(-0.3) = 0.74 at the end); a run without either has
//    no warning.
// D. archdam-motion reads a case the way archdam does: `case` of a variant in
//    a subfolder that includes its base one folder up, run from another
//    working directory, finds the base relative to the variant and the
//    record relative to the case file's folder (doc/user-guide.md).

#include <archdam/application/command_line.h>
#include <archdam/application/motion_command.h>

#include <deal.II/base/mpi.h>

#include <boost/property_tree/json_parser.hpp>
#include <boost/property_tree/ptree.hpp>

#include "archdam_tests.h"
#include "case_text.h"
#include "command_line_tests.h"

#include <cmath>
#include <filesystem>
#include <fstream>
#include <sstream>

using archdam::testing::log;
using archdam::testing::write_input;
namespace case_text = archdam::testing::case_text;

namespace
{
  constexpr double L = 2., W = 4., H = 20., E = 25e9, rho = 2500., g = 9.81;

  /// The box column case, with @p more lines after it.
  std::string
  column(const std::string &directory, const std::string &more)
  {
    std::ostringstream s;
    s << "subsection Mesh\n  subsection Box\n    set Length = " << L << "\n    set Width = " << W
      << "\n    set Height = " << H << "\n    set Number of blocks = 2\n    set Cells in x = 1\n"
      << "    set Cells in y = 2\n    set Cells in z = 4\n    set Rock depth = 0\n  end\nend\n"
      << "subsection Finite element\n  set Degree = 2\nend\n"
      << case_text::concrete_under_gravity(E, rho, g)
      << "subsection Contraction joints\n  set Model = frictional contact\nend\n"
      << "subsection Time integration\n  set Time step = 0.01\n  set End time = 0.05\nend\n"
      << "subsection Monitors\n  set Points = top: 1, 1, 20; mid: 1, 3, 10\n"
      << "  set Quantities = displacement, acceleration, principal stress\nend\n"
      << case_text::quiet_output(directory, 0) << more;
    return s.str();
  }

  /// A two-sample record of 0.02 s in x.
  const std::string short_record =
    "subsection Ground motion\n  subsection Component x\n    set File = short.csv\n"
    "    set Format = two-column\n    set Units = m/s^2\n  end\nend\n";

  /// Run archdam on @p file (in-process), quietly; its exit code.
  int
  run(const std::string &file)
  {
    std::string err;
    const int   code = archdam::testing::run_in_process(archdam::run_command_line, "archdam",
                                                      {file}, err);
    if (code != 0)
      log() << "  archdam " << file << ": " << err;
    return code;
  }

  boost::property_tree::ptree
  summary(const std::string &directory)
  {
    boost::property_tree::ptree tree;
    boost::property_tree::read_json(directory + "/summary.json", tree);
    return tree;
  }

  /// The child @p key of @p node, found by comparing keys (property_tree's
  /// own paths would split names at '.').
  const boost::property_tree::ptree *
  child(const boost::property_tree::ptree &node, const std::string &key)
  {
    for (const auto &[k, c] : node)
      if (k == key)
        return &c;
    return nullptr;
  }

  double
  number(const boost::property_tree::ptree &node, const std::vector<std::string> &path)
  {
    const boost::property_tree::ptree *n = &node;
    for (const auto &key : path)
      if (!(n = child(*n, key)))
        return std::nan("");
    return std::stod(n->data());
  }

  void
  resultants_and_peaks()
  {
    log() << "A. static resultants of a column on a fixed base, self-weight" << std::endl;
    write_input("column.prm", column("column", ""));
    run("column.prm");
    const auto         s      = summary("column");
    const double       weight = rho * g * L * W * H;
    const std::string  key    = "resultants on the dam [N]";
    archdam::testing::check_relative("  weight z [N] against -rho g L W H",
                                     number(s, {"static", key, "weight", "z"}), -weight, 1e-12);
    archdam::testing::check_relative("  support z [N] (stress on the base) against rho g L W H",
                                     number(s, {"static", key, "support", "z"}), weight, 1e-9);
    archdam::testing::check_below("  out of balance", number(s, {"static", key, "out of balance"}),
                                  1e-9);

    log() << "B. summary.json: every monitored quantity under its full name" << std::endl;
    std::ifstream            csv("column/histories.csv");
    std::string              header, line;
    std::getline(csv, header);
    std::vector<std::string> names;
    std::stringstream        h(header);
    for (std::string n; std::getline(h, n, ',');)
      names.push_back(n);
    std::vector<double> largest(names.size(), 0.);
    while (std::getline(csv, line))
      {
        std::stringstream row(line);
        std::string       value;
        for (unsigned int c = 0; std::getline(row, value, ','); ++c)
          if (std::abs(std::stod(value)) > std::abs(largest[c]))
            largest[c] = std::stod(value);
      }
    const auto *peaks   = child(s, "peaks");
    bool        found   = peaks != nullptr, equal = true;
    for (unsigned int c = 1; c < names.size() && peaks; ++c)
      {
        const auto *peak = child(*peaks, names[c]);
        found            = found && peak && child(*peak, "value") && child(*peak, "time [s]");
        if (peak && child(*peak, "value"))
          equal = equal && std::abs(number(*peak, {"value"}) - largest[c]) <=
                             1e-9 * std::abs(largest[c]);
      }
    log() << "  " << names.size() - 1 << " columns in histories.csv, among them "
          << "top.ax [m/s^2]: " << (std::count(names.begin(), names.end(), "top.ax [m/s^2]") ? "yes" : "NO")
          << "\n  each a key of peaks with value and time: " << (found ? "yes" : "NO")
          << "\n  each peak the largest magnitude of its column: " << (equal ? "yes" : "NO")
          << "\n  no warnings: " << (child(s, "warnings") ? "NO" : "yes") << std::endl;
    // One name, one number: the mesh report's node pairs (counted from the
    // mesh at the element degree) are the pairs the analysis built.
    archdam::testing::check_relative("  the mesh report's node pairs of joint 0 against the "
                                     "analysis's",
                                     number(s, {"mesh", "joints", "joint 0", "node pairs"}),
                                     number(s, {"joints", "node pairs"}), 1e-15);
  }

  /// Whether warning @p k of the run in @p directory contains @p text.
  bool
  warns(const std::string &directory, const std::string &text)
  {
    const auto  s        = summary(directory);
    const auto *warnings = child(s, "warnings");
    if (!warnings)
      return false;
    for (const auto &[k, w] : *warnings)
      if (w.data().find(text) != std::string::npos)
        return true;
    return false;
  }

  void
  warnings()
  {
    log() << "C. warnings" << std::endl;
    write_input("short.csv", "0, 0.1\n0.02, 0.2\n");
    write_input("long_run.prm", column("long_run", short_record));
    run("long_run.prm");
    log() << "  a run of 0.05 s on a record of 0.02 s: "
          << (warns("long_run", "past the end of the ground motion at 0.02 s") ? "yes" : "NO")
          << std::endl;
    write_input("cut.prm",
                column("cut", "subsection Ground motion\n  subsection Component x\n"
                              "    set Source = generated\n  end\n  subsection Generated motion\n"
                              "    set Duration = 13\n    set Strong motion end = 12\n"
                              "    set Decay coefficient = 0.3\n  end\nend\n"));
    run("cut.prm");
    log() << "  a generated motion of 13 s whose strong part ends at 12 s: "
          << (warns("cut", "cut while strong") ? "yes" : "NO") << std::endl;
  }

  void
  motion_case_from_elsewhere()
  {
    log() << "D. archdam-motion case: includes and the record relative to each file"
          << std::endl;
    if (dealii::Utilities::MPI::this_mpi_process(MPI_COMM_WORLD) == 0)
      std::filesystem::create_directories("motion_cases/variants");
    MPI_Barrier(MPI_COMM_WORLD);
    write_input("motion_cases/variants/record.csv", "0, 0.1\n0.02, -0.3\n0.04, 0.2\n");
    write_input("motion_cases/base.prm",
                "subsection Ground motion\n  subsection Component x\n    set File = record.csv\n"
                "    set Format = two-column\n    set Units = m/s^2\n  end\nend\n");
    write_input("motion_cases/variants/variant.prm", "include ../base.prm\n");
    std::string err;
    const int   code = archdam::testing::run_in_process(
      archdam::run_motion_command, "archdam-motion",
      {"case", "motion_cases/variants/variant.prm"}, err);
    log() << "  from the test's folder, exit code " << code << (err.empty() ? "" : ": " + err)
          << std::endl;
  }
} // namespace

int
main(int argc, char **argv)
{
  dealii::Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  resultants_and_peaks();
  warnings();
  motion_case_from_elsewhere();
}
