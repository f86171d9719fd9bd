#include <archdam/analysis/simulation.h>
#include <archdam/application/command_line.h>
#include <archdam/base/input_error.h>
#include <archdam/base/run_stopped.h>
#include <archdam/parameters/parameters.h>

#include <deal.II/base/exceptions.h>
#include <deal.II/base/mpi.h>

#include <iostream>
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
      "  archdam CASE.prm [--set \"Section/Subsection/Name=value\"]... [--mesh-only | --resume]\n"
      "  archdam --print-parameters [text|json|xml|latex]\n"
      "  archdam --help\n";

    int
    run(const std::vector<std::string> &args, std::ostream &out)
    {
      if (args.empty())
        throw InputError(std::string("No case file given.\n") + usage);
      if (args[0] == "--help" || args[0] == "-h")
        {
          out << usage;
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
      bool                     mesh_only = false, resume = false;
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

      const Parameters      p = read_parameters(case_file, overrides);
      analysis::Simulation  simulation(p, MPI_COMM_WORLD, out);
      if (mesh_only)
        simulation.run_mesh_only();
      else
        simulation.run(resume);
      return 0;
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
  } // namespace

  int
  run_command_line(const int argc, const char *const *argv, std::ostream &out, std::ostream &err)
  {
    const bool talk = Utilities::MPI::this_mpi_process(MPI_COMM_WORLD) == 0;
    try
      {
        return run(std::vector<std::string>(argv + 1, argv + argc), out);
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
