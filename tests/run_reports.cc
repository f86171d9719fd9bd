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
//    each peak is its column's in histories.csv as doc/theory/results.md §1
//    defines it (s1 the largest value, s3 the smallest, any other the
//    largest magnitude; on a hand-made history too, whose largest tension is
//    smaller than its largest compression: "user holes, second round",
//    item 4); the
//    mesh report's node pairs of the joint (counted on the mesh) equal the
//    node pairs the analysis built.
// C. Warnings in summary.json: a dynamic stage longer than its record (a
//    two-sample record, 0.02 s, a run of 0.05 s), a generated motion cut
//    while strong (Duration 13 s, Strong motion end 12 s, decay 0.3 1/s:
//    the envelope is exp(-0.3) = 0.74 at the end), an End time that is no
//    whole number of steps (0.043 s at 0.01 s ends at 0.04 s), a step coarser
//    than the record's sampling (0.01 s on 0.005 s), a concrete density of
//    24000 kg/m^3 (a unit weight), a modulus of 5e8 Pa (below any
//    concrete's 1 GPa), g = 12 m/s^2, a Westergaard water level of 20 m
//    beside a reservoir mesh up to 25 m, and a first mode outside the
//    frequencies of the damping ratio, whose damping ratio summary.json
//    gives; a run
//    without any has no warning.
// D. archdam-motion reads a case the way archdam does: `case` of a variant in
//    a subfolder that includes its base one folder up, run from another
//    working directory, finds the base relative to the variant and the
//    record relative to the case file's folder (doc/user-guide.md).
// E. An output directory used before ("user holes, second round", item
//    6): by default a new run removes the earlier run's files (a joints
//    record it does not write) and keeps the user's; with keep they stay;
//    with refuse the run stops, naming them, and writes nothing.

#include <archdam/application/command_line.h>
#include <archdam/application/motion_command.h>
#include <archdam/output/monitors.h>
#include <archdam/output/summary.h>

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
namespace output    = archdam::output;

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
    // The peak as doc/theory/results.md §1 defines it: s1 its largest value
    // (tension), s3 its smallest (compression), any other its value of
    // largest magnitude.
    const auto ends_with = [](const std::string &n, const std::string &tail) {
      return n.size() >= tail.size() && n.compare(n.size() - tail.size(), tail.size(), tail) == 0;
    };
    const auto score = [&](const unsigned int c, const double v) {
      return ends_with(names[c], ".s1 [Pa]") ? v : ends_with(names[c], ".s3 [Pa]") ? -v : std::abs(v);
    };
    std::vector<double> largest(names.size(), std::nan(""));
    while (std::getline(csv, line))
      {
        std::stringstream row(line);
        std::string       value;
        for (unsigned int c = 0; std::getline(row, value, ','); ++c)
          if (std::isnan(largest[c]) || score(c, std::stod(value)) > score(c, largest[c]))
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
          << "\n  each peak its column's (s1 largest, s3 smallest, else largest magnitude): "
          << (equal ? "yes" : "NO")
          << "\n  no warnings: " << (child(s, "warnings") ? "NO" : "yes") << std::endl;
    // A history whose largest tension is smaller than its largest
    // compression (the values of a run where s1's value of largest
    // magnitude was -7.272e4 Pa while it reached +6.88e4 Pa): s1's peak is
    // the tension, s3's the compression, a displacement's the magnitude.
    const std::vector<std::vector<double>> history{
      {0., 0., 1278., 1.}, {0.1, -7.272e4, -500., -2.}, {0.2, 6.88e4, 900., 1.5}, {0.3, 1e3, 0., 0.}};
    log() << "  a history with s1 = 0, -7.272e4, 6.88e4, 1e3 Pa: largest tension at row 2: "
          << archdam::testing::yes(output::peak_row(history, 1, output::Peak::largest) == 2)
          << "\n  s3 = 1278, -500, 900, 0 Pa: largest compression at row 1: "
          << archdam::testing::yes(output::peak_row(history, 2, output::Peak::smallest) == 1)
          << "\n  u = 1, -2, 1.5, 0 m: largest magnitude at row 1: "
          << archdam::testing::yes(output::peak_row(history, 3, output::Peak::magnitude) == 1)
          << std::endl;
    // Every string is escaped for JSON ("user holes, second round", item
    // 12): a case name with quotes, a backslash and non-ASCII letters (the
    // case file's reader reads a tab in a value as a blank) read back by the
    // parser from a run's summary.json; and a string with a tab, a carriage
    // return and another control character written by the summary itself.
    const std::string name = "tab\there \"quoted\" back\\slash Staumauer \xC3\x84\xC3\x96";
    write_input("names.prm", column("names", "subsection Analysis\n  set Case name = " + name +
                                                "\nend\n"));
    run("names.prm");
    const auto read_back = [](const std::string &directory, const std::string &key) {
      try
        {
          return summary(directory).get<std::string>(key);
        }
      catch (const std::exception &e)
        {
          return std::string("(does not parse: ") + e.what() + ")";
        }
    };
    std::string as_read = name;
    as_read[3]          = ' ';
    log() << "  a case name with quotes, a backslash and non-ASCII letters read back from "
             "summary.json: "
          << archdam::testing::yes(read_back("names", "case") == as_read) << std::endl;
    const std::string controls = "a\tb\rc\x01d\ne \"f\" g\\h \xC3\x84";
    if (dealii::Utilities::MPI::this_mpi_process(MPI_COMM_WORLD) == 0)
      {
        std::filesystem::create_directories("controls");
        output::Summary direct;
        direct.set("text", controls);
        direct.write("controls/summary.json");
      }
    MPI_Barrier(MPI_COMM_WORLD);
    log() << "  a string with a tab, a carriage return, U+0001, a line end, quotes, a backslash "
             "and a non-ASCII letter read back: "
          << archdam::testing::yes(read_back("controls", "text") == controls) << std::endl;
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
    // Run the case @p text as NAME.prm into NAME/ and say whether its
    // summary warns with @p expected.
    const auto check = [](const std::string &name, const std::string &text,
                          const std::string &label, const std::string &expected) {
      write_input(name + ".prm", text);
      run(name + ".prm");
      log() << "  " << label << ": " << archdam::testing::yes(warns(name, expected)) << std::endl;
    };
    write_input("short.csv", "0, 0.1\n0.02, 0.2\n");
    check("long_run", column("long_run", short_record), "a run of 0.05 s on a record of 0.02 s",
          "past the end of the ground motion at 0.02 s");
    // What the model is shaken by ("user holes, second round", item 1): the
    // record a = 0.1, 0.2 m/s^2 at t = 0, 0.02 s, linear between, from rest:
    // PGA 0.2 m/s^2 at 0.02 s, PGV = h (a0 + a1) / 2, PGD = h^2 (a0 / 3 + a1 / 6).
    {
      const auto   s = summary("long_run");
      const double h = 0.02, a0 = 0.1, a1 = 0.2;
      for (const auto &[name, value] :
           std::vector<std::pair<std::string, double>>{{"PGA [m/s^2]", a1},
                                                       {"PGA [g]", a1 / 9.80665},
                                                       {"PGA time [s]", h},
                                                       {"PGV [m/s]", h * (a0 + a1) / 2},
                                                       {"PGD [m]", h * h * (a0 / 3 + a1 / 6)},
                                                       {"duration [s]", h}})
        archdam::testing::check_relative("  summary.json: ground motion, x, " + name,
                                         number(s, {"ground motion", "x", name}), value,
                                         1e-10); // written with 12 digits
    }
    check("cut",
          column("cut", "subsection Ground motion\n  subsection Component x\n"
                        "    set Source = generated\n  end\n  subsection Generated motion\n"
                        "    set Duration = 13\n    set Strong motion end = 12\n"
                        "    set Decay coefficient = 0.3\n  end\nend\n"),
          "a generated motion of 13 s whose strong part ends at 12 s", "cut while strong");
    // End time 0.043 s with steps of 0.01 s: the stage ends at 0.04 s, and
    // says so ("user holes, second round", item 7).
    std::string odd_end = column("odd_end", short_record);
    odd_end.replace(odd_end.find("End time = 0.05"), 15, "End time = 0.043");
    check("odd_end", odd_end, "End time 0.043 s with steps of 0.01 s, ending at 0.04 s",
          "not a whole number of time steps of 0.01 s: the dynamic stage ends at the nearest "
          "step, t = 0.04 s");
    // A record sampled every 5 ms under steps of 10 ms (item 2).
    std::ostringstream fine;
    for (unsigned int k = 0; k <= 10; ++k)
      fine << 0.005 * k << ", " << 0.1 * (k % 3) << "\n";
    write_input("fine.csv", fine.str());
    std::string coarse = column("coarse", short_record);
    coarse.replace(coarse.find("short.csv"), 9, "fine.csv");
    check("coarse", coarse, "steps of 0.01 s on a record sampled every 0.005 s",
          "coarser than the sampling interval of the ground motion in x (0.005 s)");
    // Values the parameters allow but no dam has (item 16): a unit weight of
    // 24 kN/m^3 given as the density, a modulus below any concrete's.
    const auto concrete = [](const std::string &entry) {
      return "subsection Materials\n  subsection Concrete\n    set " + entry + "\n  end\nend\n";
    };
    check("unit_weight", column("unit_weight", short_record) + concrete("Density = 24000"),
          "a concrete density of 24000 kg/m^3", "is it a unit weight in N/m^3?");
    check("soft", column("soft", short_record) + concrete("Young's modulus = 5e8"),
          "a concrete modulus of 5e8 Pa", "is it in kPa or MPa?");
    check("heavy", column("heavy", short_record) +
                     "subsection Static loads\n  set Gravitational acceleration = 12\nend\n",
          "g = 12 m/s^2", "is not the Earth's (9.81 m/s^2)");
    // Westergaard's added mass at a level other than the reservoir mesh's
    // (the Gmsh example's water reaches z = 25 m): the static stage alone.
    check("level",
          case_text::gmsh_example_mesh() + case_text::quiet_output("level", 0) +
            "subsection Analysis\n  set Stages = static\nend\n"
            "subsection Reservoir\n  set Model = westergaard\n  set Water level from mesh = false\n"
            "  set Water level = 20\nend\n",
          "a Westergaard water level of 20 m beside a reservoir mesh up to 25 m",
          "but the reservoir's mesh reaches z = 25 m");
    // The damping ratio at the modal stage's first mode (item 16): zeta =
    // alpha / (2 omega) + beta omega / 2 with the Rayleigh coefficients the
    // run reports; the column's first mode (2.55 Hz) lies below First
    // frequency = 20 Hz, so it is damped by 28 %, not the 5 % asked for
    // between 20 and 50 Hz, and is warned about.
    const std::string modal = column("modal", short_record) +
                              "subsection Analysis\n  set Stages = static, modal, dynamic\nend\n"
                              "subsection Modal analysis\n  set Number of modes = 2\nend\n"
                              "subsection Damping\n  set First frequency = 20\n"
                              "  set Second frequency = 50\nend\n";
    check("modal", modal, "the first mode outside First - Second frequency",
          "outside Damping/First frequency - Second frequency");
    {
      const auto   s     = summary("modal");
      const double f     = number(s, {"modal", "mode 1", "frequency [Hz]"});
      const double omega = 2 * M_PI * f;
      const double alpha = number(s, {"dynamic", "rayleigh alpha [s^-1]"});
      const double beta  = number(s, {"dynamic", "rayleigh beta [s]"});
      archdam::testing::check_relative(
        "  summary.json: the damping ratio at the first mode against alpha / (2 omega) + beta "
        "omega / 2",
        number(s, {"dynamic", "damping ratio at the first mode"}),
        alpha / (2 * omega) + beta * omega / 2, 1e-10);
    }
  }

  /// Run archdam on @p file with the override @p assignment; its exit code
  /// and error message on the log.
  void
  run_set(const std::string &what, const std::string &file, const std::string &assignment)
  {
    std::string err;
    const int   code = archdam::testing::run_in_process(archdam::run_command_line, "archdam",
                                                      {file, "--set", assignment}, err);
    log() << "  " << what << ": exit code " << code << (err.empty() ? "" : ", " + err)
          << std::endl;
  }

  void
  earlier_results()
  {
    log() << "E. an earlier run's results in the output directory (item 6)" << std::endl;
    namespace fs      = std::filesystem;
    const auto exists = [](const std::string &name) {
      return archdam::testing::yes(fs::exists("again/" + name));
    };
    // A record of an earlier, longer run that this one does not write, and
    // a file of the user's.
    const auto earlier = [] {
      write_input("again/joints_00999.vtu", "an earlier run's\n");
      write_input("again/notes.txt", "the user's\n");
    };
    write_input("again.prm", column("again", short_record));
    run("again.prm");
    earlier();
    run("again.prm");
    log() << "  replace (the default): joints_00999.vtu removed: "
          << archdam::testing::yes(!fs::exists("again/joints_00999.vtu"))
          << ", notes.txt kept: " << exists("notes.txt")
          << ", this run's summary.json and histories.csv there: " << exists("summary.json")
          << ", " << exists("histories.csv") << std::endl;
    earlier();
    run_set("keep", "again.prm", "Output/Earlier results=keep");
    log() << "  keep: joints_00999.vtu still there: " << exists("joints_00999.vtu") << std::endl;
    run_set("refuse", "again.prm", "Output/Earlier results=refuse");
    log() << "  refuse: joints_00999.vtu still there: " << exists("joints_00999.vtu")
          << std::endl;
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
  earlier_results();
}
