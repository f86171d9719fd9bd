#include <archdam/analysis/simulation.h>
#include <archdam/application/command_line.h>
#include <archdam/application/python_script.h>
#include <archdam/application/record_suite.h>
#include <archdam/base/input_error.h>
#include <archdam/base/interrupt.h>
#include <archdam/base/run_stopped.h>
#include <archdam/base/version.h>
#include <archdam/output/run_lock.h>
#include <archdam/parameters/parameters.h>

#include <deal.II/base/exceptions.h>
#include <deal.II/base/config.h>
#include <deal.II/base/mpi.h>

#include <dmumps_c.h>
#include <petscversion.h>

#include <iostream>
#include <optional>
#include <sstream>
#include <string>
#include <vector>

namespace archdam
{
  using namespace dealii;

  namespace
  {
    const char *usage =
      "Usage:\n"
      "  archdam CASE.prm [--set \"Section/Subsection/Name=value\"]... [--mesh-only | --resume |\n"
      "                   --free-field-check | --record NAME [--resume] | --gather]\n"
      "  archdam --print-parameters [text|json|xml|latex]\n"
      "  archdam --help | --version\n";

    const char *help =
      "ArchDam: nonlinear earthquake analysis of concrete arch dams with contraction\n"
      "joints, reservoir and foundation.\n\n"
      "Options:\n"
      "  CASE.prm                  the case file to run (its includes are read relative\n"
      "                            to the file that names them)\n"
      "  --set \"Sec/Name=value\"    change one parameter of the case (repeatable; as\n"
      "                            if the line were at the end of the case file)\n"
      "  --mesh-only               build and check the mesh, write it and its report,\n"
      "                            then stop (no analysis)\n"
      "  --resume                  continue a run from its last checkpoint in the same\n"
      "                            output folder\n"
      "  --free-field-check        run the case's rock alone (a column, no dam) under\n"
      "                            its ground motion: the motion at the free surface and\n"
      "                            at the dam's base against the control motion and the\n"
      "                            free field (massed rock), then stop\n"
      "  --record NAME             of a record suite, run record NAME only (as the\n"
      "                            whole suite would, scale included): the records as\n"
      "                            independent jobs\n"
      "  --gather                  of a record suite, run nothing: write the suite's\n"
      "                            statistics from its records' finished runs\n"
      "  --print-parameters [FMT]  every parameter with its default, allowed values and\n"
      "                            documentation (FMT: text (default), json, xml, latex)\n"
      "  --help, -h                this text\n"
      "  --version                 ArchDam's version and those of deal.II, PETSc, MUMPS\n\n"
      "Example:\n"
      "  archdam prm/box_dam_on_rock.prm --set \"Time integration/End time=1\"\n"
      "  mpirun -np 2 archdam prm/paper_235m_dam.prm\n\n"
      "Documentation: doc/user-guide.md (running a case, results), doc/parameters.prm\n"
      "(every parameter), doc/bad-input.md (messages), doc/verification.md; the\n"
      "motion tool: archdam-motion --help.\n";

    std::string
    versions()
    {
      return std::string("ArchDam ") + archdam::version() + "\ndeal.II " + DEAL_II_PACKAGE_VERSION +
             "\nPETSc " + std::to_string(PETSC_VERSION_MAJOR) + "." +
             std::to_string(PETSC_VERSION_MINOR) + "." + std::to_string(PETSC_VERSION_SUBMINOR) +
             "\nMUMPS " + MUMPS_VERSION + "\n";
    }

    /// Write one message line to @p err in a single write: under mpiexec the
    /// standard output and error of rank 0 reach the terminal (or log file)
    /// through separate channels, and a message written in pieces can be cut
    /// by a line of the run's output.
    void
    say(std::ostream &err, const std::string &prefix, const std::string &message)
    {
      err << (prefix + message + '\n') << std::flush;
    }

    int
    run(const std::vector<std::string> &args, std::ostream &out, std::ostream &warnings)
    {
      if (args.empty())
        throw InputError(std::string("No case file given.\n") + usage);
      if (args[0] == "--help" || args[0] == "-h")
        {
          out << usage << '\n' << help;
          return 0;
        }
      if (args[0] == "--version")
        {
          out << versions();
          return 0;
        }
      if (args[0] == "--print-parameters")
        {
          if (args.size() > 2)
            throw InputError("--print-parameters takes at most one format.");
          if (Utilities::MPI::this_mpi_process(MPI_COMM_WORLD) == 0)
            print_parameters(out, args.size() == 2 ? args[1] : "text");
          return 0;
        }

      std::string              case_file;
      std::vector<std::string> overrides;
      bool        mesh_only = false, resume = false, free_field_check = false, gather = false;
      std::string record;
      for (unsigned int i = 0; i < args.size(); ++i)
        if (args[i] == "--set")
          {
            if (i + 1 == args.size())
              throw InputError("--set needs an argument \"Section/Name=value\".");
            overrides.push_back(args[++i]);
          }
        else if (args[i].rfind("--set=", 0) == 0)
          overrides.push_back(args[i].substr(6));
        else if (args[i] == "--mesh-only")
          mesh_only = true;
        else if (args[i] == "--resume")
          resume = true;
        else if (args[i] == "--free-field-check")
          free_field_check = true;
        else if (args[i] == "--record")
          {
            if (i + 1 == args.size() || args[i + 1].empty() || args[i + 1].rfind("-", 0) == 0)
              throw InputError("--record needs the name of one of the suite's records.");
            if (!record.empty())
              throw InputError("--record runs one record; got '" + record + "' and '" +
                               args[i + 1] + "' (start one job per record).");
            record = args[++i];
          }
        else if (args[i] == "--gather")
          gather = true;
        else if (args[i].rfind("-", 0) == 0)
          throw InputError("Unknown option '" + args[i] + "'.\n" + usage);
        else if (case_file.empty())
          case_file = args[i];
        else
          throw InputError("Only one case file, got '" + case_file + "' and '" + args[i] +
                           "'.");
      if (case_file.empty())
        throw InputError(std::string("No case file given.\n") + usage);
      if (mesh_only && resume)
        throw InputError("--mesh-only and --resume exclude each other.");
      if (free_field_check && (mesh_only || resume))
        throw InputError("--free-field-check runs no analysis: it excludes --mesh-only and "
                         "--resume.");

      const bool suite_option = !record.empty() || gather;
      if (gather && !record.empty())
        throw InputError("--gather and --record exclude each other: run the records (--record "
                         "NAME, a job each), then gather them (--gather).");
      if (gather && resume)
        throw InputError("--gather runs nothing, so there is nothing to resume: continue a "
                         "record's run with --record NAME --resume.");
      if (suite_option && (mesh_only || free_field_check))
        throw InputError(std::string(gather ? "--gather" : "--record") +
                         " runs or gathers a suite's records: it excludes --mesh-only and "
                         "--free-field-check.");

      const Parameters p = read_parameters(case_file, overrides);
      if (suite_option && p.suite.parse().empty())
        throw InputError(std::string(gather ? "--gather" : "--record") +
                         " applies to a record suite, and the case has none (Record "
                         "suite/Records is empty).");
      if (Utilities::MPI::this_mpi_process(MPI_COMM_WORLD) == 0)
        for (const auto &w : p.warnings)
          say(warnings, "archdam: warning: ", w);
      // One run at a time in the output folder; a record's run of a suite
      // (--record) holds its record's folder (run_record_suite()), so that
      // the records can run at the same time as independent jobs.
      const std::optional<output::RunLock> lock =
        record.empty() ? std::make_optional<output::RunLock>(p.output.directory, p.analysis.case_name,
                                                             MPI_COMM_WORLD) :
                         std::nullopt;
      if (!p.suite.parse().empty() && !mesh_only && !free_field_check)
        {
          if (!record.empty())
            interrupt::catch_signals();
          application::run_record_suite(case_file, overrides, p, MPI_COMM_WORLD, out,
                                        gather           ? application::SuiteRun::gather :
                                        !record.empty() ? application::SuiteRun::one_record :
                                                          application::SuiteRun::all,
                                        record, resume);
          return 0;
        }
      analysis::Simulation simulation(p, MPI_COMM_WORLD, out);
      interrupt::catch_signals();
      if (mesh_only)
        simulation.run_mesh_only();
      else if (free_field_check)
        simulation.run_free_field_check();
      else
        {
          simulation.run(resume);
          if (p.output.report && Utilities::MPI::this_mpi_process(MPI_COMM_WORLD) == 0)
            application::write_report(p.output.directory, out);
        }
      return 0;
    }

  } // namespace

  int
  run_command_line(const int argc, const char *const *argv, std::ostream &out, std::ostream &err)
  {
    const bool talk = Utilities::MPI::this_mpi_process(MPI_COMM_WORLD) == 0;
    try
      {
        return run(std::vector<std::string>(argv + 1, argv + argc), out, err);
      }
    catch (const InputError &e)
      {
        if (talk)
          say(err, "archdam: error: ", e.what());
        return 1;
      }
    catch (const RunStopped &e)
      {
        if (talk)
          say(err, "archdam: run stopped: ", e.what());
        return 1;
      }
    catch (const ExceptionBase &e)
      {
        if (talk)
          {
            std::ostringstream info;
            e.print_info(info);
            say(err, "archdam: error: ", info.str());
          }
        return 1;
      }
    catch (const std::exception &e)
      {
        if (talk)
          say(err, "archdam: internal error: ", e.what());
        return 2;
      }
  }
} // namespace archdam
