#include <archdam/base/case_file.h>
#include <archdam/base/data_files.h>
#include <archdam/base/input_error.h>
#include <archdam/base/selection.h>
#include <archdam/parameters/parameters.h>

#include <deal.II/base/exceptions.h>

#include <boost/property_tree/json_parser.hpp>
#include <boost/property_tree/ptree.hpp>
#include <deal.II/base/utilities.h>

#include <algorithm>
#include <filesystem>
#include <functional>
#include <sstream>

namespace archdam
{
  using namespace dealii;

  void
  Parameters::add_parameters(ParameterHandler &prm)
  {
    const auto section = [&prm](const std::string &name, const auto &declare) {
      prm.enter_subsection(name);
      declare();
      prm.leave_subsection();
    };
    section("Mesh", [&] { mesh.add_parameters(prm); });
    section("Finite element", [&] { finite_element.add_parameters(prm); });
    section("Materials", [&] { materials.add_parameters(prm); });
    section("Damping", [&] { damping.add_parameters(prm); });
    section("Time integration", [&] { time_integration.add_parameters(prm); });
    section("Foundation", [&] { foundation.add_parameters(prm); });
    section("Contraction joints", [&] { joints.add_parameters(prm); });
    section("Reservoir", [&] { reservoir.add_parameters(prm); });
    section("Ground motion", [&] { ground_motion.add_parameters(prm); });
    section("Static loads", [&] { static_loads.add_parameters(prm); });
    section("Analysis", [&] { analysis.add_parameters(prm); });
    section("Modal analysis", [&] { modal.add_parameters(prm); });
    section("Record suite", [&] { suite.add_parameters(prm); });
    section("Monitors", [&] { monitors.add_parameters(prm); });
    section("Output", [&] { output.add_parameters(prm); });
    section("Checkpoints", [&] { checkpoints.add_parameters(prm); });
    section("Evaluation", [&] { evaluation.add_parameters(prm); });
  }

  namespace
  {
    /// The "additional information" of a deal.II exception, without the
    /// source location and stack trace meant for developers.
    std::string
    user_message(const ExceptionBase &e)
    {
      std::ostringstream s;
      e.print_info(s);
      std::string clean;
      for (const auto &line : Utilities::split_string_list(s.str(), '\n'))
        clean += (clean.empty() ? "" : " ") + Utilities::trim(line);
      return clean;
    }

    /// Apply one "Section/Subsection/Name=value" override.
    void
    apply_override(ParameterHandler &prm, const std::string &assignment)
    {
      const auto eq = assignment.find('=');
      if (eq == std::string::npos)
        throw InputError("--set \"" + assignment +
                         "\": expected \"Section/Subsection/Name=value\".");
      const std::string path  = Utilities::trim(assignment.substr(0, eq));
      const std::string value = Utilities::trim(assignment.substr(eq + 1));
      const auto        parts = Utilities::split_string_list(path, '/');
      if (parts.size() < 2)
        throw InputError("--set \"" + assignment +
                         "\": the parameter needs its section, as in "
                         "\"Time integration/Time step=0.005\".");

      // A misspelt section is reported as such instead of being created.
      const std::vector<std::string> sections(parts.begin(), parts.end() - 1);
      if (!prm.subsection_path_exists(sections))
        throw InputError("--set \"" + assignment + "\": no section \"" +
                         path.substr(0, path.find_last_of('/')) +
                         "\" (see archdam --print-parameters).");
      for (const auto &s : sections)
        prm.enter_subsection(s);
      try
        {
          prm.set(parts.back(), value);
        }
      catch (const ParameterHandler::ExcEntryUndeclared &)
        {
          for (unsigned int i = 0; i + 1 < parts.size(); ++i)
            prm.leave_subsection();
          throw InputError("--set \"" + assignment + "\": no parameter \"" + parts.back() +
                           "\" in section \"" + path.substr(0, path.find_last_of('/')) +
                           "\" (see archdam --print-parameters).");
        }
      catch (const ExceptionBase &e)
        {
          for (unsigned int i = 0; i + 1 < parts.size(); ++i)
            prm.leave_subsection();
          throw InputError("--set \"" + assignment + "\": " + user_message(e));
        }
      for (unsigned int i = 0; i + 1 < parts.size(); ++i)
        prm.leave_subsection();
    }

    void
    check(const Parameters &p)
    {
      p.time_integration.check();
      p.reservoir.check();
      p.damping.check();
      output::parse_monitor_points(p.monitors.points);
      if (p.analysis.stages.empty())
        throw InputError("Analysis/Stages: nothing to run.");
      if (p.joints.frictional() && p.analysis.runs("dynamic") &&
          p.joints.contact_in_time == joints::ContactInTime::step_impulse &&
          p.joints.solver != joints::Solver::mixed)
        throw InputError("Contraction joints/Contact in time = step impulse needs Solver = "
                         "mixed (the monolithic reference solver holds the pairs at their "
                         "positions only): with Solver = monolithic, set Contact in time = "
                         "trapezoidal.");
      // The compressed and the single-precision factor are the one
      // condensed on the joints' pairs (time::CondensedFactorization); a
      // case without it would ignore them.
      const std::string condensed_only =
        " the factor condensed on the joints' node pairs (Contraction joints/Model = "
        "frictional contact, Solver = mixed); this case has no such factor: ";
      const bool condensed = p.joints.frictional() && p.joints.solver == joints::Solver::mixed;
      if (p.time_integration.low_rank_tolerance > 0. && !condensed)
        throw InputError("Time integration/Low-rank tolerance compresses" + condensed_only +
                         "set it to 0.");
      if (p.time_integration.factor_precision != time::Precision::double_precision &&
          !condensed)
        throw InputError("Time integration/Factor precision = single applies to" +
                         condensed_only + "set it to double.");
      // The static loads are applied in the static stage only, and the
      // dynamic stage starts from its state: without it they would be lost.
      if (p.analysis.runs("dynamic") && !p.analysis.runs("static"))
        {
          const auto refuse = [](const std::string &load) {
            throw InputError("Static loads/" + load +
                             " = true, but Analysis/Stages has no static stage to apply it in "
                             "(the dynamic stage would start unloaded at rest): add static to "
                             "Stages, or set " + load + " = false.");
          };
          if (p.static_loads.gravity)
            refuse("Gravity");
          if (p.static_loads.hydrostatic && p.reservoir.model != physics::reservoir::Model::none)
            refuse("Hydrostatic pressure");
          if (!loads::parse_temperature_table(p.static_loads.temperature_change).empty())
            throw InputError("Static loads/Temperature change is given, but Analysis/Stages has "
                             "no static stage to apply it in: add static to Stages, or leave "
                             "Temperature change empty.");
        }
      loads::parse_temperature_table(p.static_loads.temperature_change);
      p.checkpoints.check();
      p.evaluation.check();
      if (p.evaluation.evaluate && p.evaluation.joint_band > 0. && p.joints.per_joint.empty() &&
          !(p.joints.law.tensile_strength > 0.))
        throw InputError("Evaluation/Joint band width measures the arch stress near the joints "
                         "against their tensile strength, and Contraction joints/Tensile "
                         "strength is 0: give the joints one, or set the band to 0.");
      p.suite.check();
      // Every record of a suite is there before the first run starts.
      for (const auto &r : p.suite.parse())
        {
          if (!p.analysis.runs("dynamic"))
            throw InputError("Record suite/Records is given, but Analysis/Stages has no dynamic "
                             "stage to run the records in: add dynamic to Stages, or leave "
                             "Records empty.");
          for (unsigned int d = 0; d < 3; ++d)
            if (!r.file[d].empty())
              {
                const std::string what = "Record suite/Records (record '" + r.name +
                                         "', direction " + std::string(1, "xyz"[d]) + ")";
                const std::string file = find_input_file(r.file[d], p.base_directory, what);
                if (!std::filesystem::is_regular_file(file))
                  throw InputError(what + ": no file '" + file + "'.");
              }
        }
    }

    /// Every value outside Output and Checkpoints, "path = value" a line,
    /// hashed (Parameters::fingerprint).
    std::string
    fingerprint_of(const ParameterHandler &prm)
    {
      std::stringstream json;
      prm.print_parameters(json, ParameterHandler::JSON);
      boost::property_tree::ptree tree;
      boost::property_tree::read_json(json, tree);
      tree.erase("Output");
      tree.erase("Checkpoints");
      std::string values;
      const std::function<void(const boost::property_tree::ptree &, const std::string &)> walk =
        [&](const boost::property_tree::ptree &node, const std::string &path) {
          for (const auto &[key, child] : node)
            if (const auto value = child.get_optional<std::string>("value"))
              values += path + key + " = " + *value + "\n";
            else if (!child.empty())
              walk(child, path + key + "/");
        };
      walk(tree, "");
      std::ostringstream hex;
      hex << std::hex << output::fnv1a(values);
      return hex.str();
    }
  } // namespace

  Parameters
  read_parameters(const std::string &filename, const std::vector<std::string> &overrides)
  {
    // Includes resolved relative to each including file (base/case_file.h);
    // the parser's line numbers are those of the joined text, said again of
    // the file the user wrote.
    const CaseText    text      = read_case_text(filename);
    const auto        slash     = filename.find_last_of('/');
    const std::string directory = slash == std::string::npos ? "." : filename.substr(0, slash);

    Parameters       p;
    ParameterHandler prm;
    p.add_parameters(prm);
    try
      {
        std::istringstream in(text.text);
        prm.parse_input(in, filename, "", false);
      }
    catch (const ExceptionBase &e)
      {
        throw InputError(text.relocate(user_message(e)));
      }
    p.warnings = text.warnings;
    for (const auto &o : overrides)
      apply_override(prm, o);

    p.base_directory = directory;
    p.fingerprint    = fingerprint_of(prm);
    if (p.analysis.case_name.empty())
      {
        const std::string base = filename.substr(slash == std::string::npos ? 0 : slash + 1);
        p.analysis.case_name   = base.substr(0, base.find_last_of('.'));
      }
    check(p);
    return p;
  }

  Parameters
  parameters_from_string(const std::string &text)
  {
    Parameters       p;
    ParameterHandler prm;
    p.add_parameters(prm);
    prm.parse_input_from_string(text, "", false);
    p.base_directory = ".";
    p.fingerprint    = fingerprint_of(prm);
    check(p);
    return p;
  }

  namespace
  {
    /// One parameter file in which every entry shows its documentation, its
    /// allowed values and its default: the reference and a template at once.
    void
    print_reference(const boost::property_tree::ptree &node, const unsigned int depth,
                    std::ostream &out)
    {
      const std::string indent(2 * depth, ' ');
      for (const auto &[key, child] : node)
        if (child.get_child_optional("value"))
          {
            std::string line;
            for (const auto &word : Utilities::split_string_list(
                   child.get<std::string>("documentation") + " Allowed: " +
                     child.get<std::string>("pattern_description"),
                   ' '))
              {
                if (!line.empty() && indent.size() + 2 + line.size() + word.size() > 79)
                  {
                    out << indent << "#" << line << '\n';
                    line.clear();
                  }
                line += " " + word;
              }
            out << indent << "#" << line << '\n'
                << indent << "set " << key << " = " << child.get<std::string>("default_value")
                << "\n\n";
          }
        else
          {
            out << indent << "subsection " << key << "\n\n";
            print_reference(child, depth + 1, out);
            out << indent << "end\n\n";
          }
    }
  } // namespace

  void
  print_parameters(std::ostream &out, const std::string &format)
  {
    // The formats of --print-parameters; text is ArchDam's own reference.
    enum class Format
    {
      text,
      json,
      xml,
      latex
    };
    const SelectionNames<Format> formats = {{"text", Format::text},
                                            {"json", Format::json},
                                            {"xml", Format::xml},
                                            {"latex", Format::latex}};
    const auto chosen = std::find_if(formats.begin(), formats.end(),
                                     [&](const auto &f) { return f.first == format; });
    if (chosen == formats.end())
      throw InputError("--print-parameters: unknown format '" + format +
                       "' (text, json, xml or latex).");
    Parameters       p;
    ParameterHandler prm;
    p.add_parameters(prm);
    switch (chosen->second)
      {
        case Format::json:
          prm.print_parameters(out, ParameterHandler::JSON);
          break;
        case Format::xml:
          prm.print_parameters(out, ParameterHandler::XML);
          break;
        case Format::latex:
          prm.print_parameters(out, ParameterHandler::LaTeX);
          break;
        case Format::text:
          {
            std::stringstream json;
            prm.print_parameters(json, ParameterHandler::JSON);
            boost::property_tree::ptree tree;
            boost::property_tree::read_json(json, tree);
            out << "# ArchDam parameters: every entry with its documentation, allowed values\n"
                   "# and default. A case file sets only what differs from the default.\n\n";
            print_reference(tree, 0, out);
          }
      }
  }
} // namespace archdam
