#include <archdam/analysis/simulation.h>
#include <archdam/base/input_error.h>
#include <archdam/base/on_rank_zero.h>
#include <archdam/base/version.h>
#include <archdam/geometry/ids.h>
#include <archdam/output/mesh_writer.h>

#include <deal.II/base/utilities.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <regex>
#include <sstream>

namespace archdam::analysis
{
  using namespace dealii;

  Simulation::Simulation(const Parameters &p, const MPI_Comm comm, std::ostream &out)
    : p(p)
    , comm(comm)
    , screen(out, Utilities::MPI::this_mpi_process(comm) == 0)
    // No communicator: the timer must not communicate in its destructor when
    // an input error unwinds the stack; statistics over ranks are gathered
    // explicitly at the end.
    , timer(screen, TimerOutput::never, TimerOutput::wall_times)
  {
    step_solve.reset(); // (a deal.II timer starts when made)
  }

  void
  Simulation::run(const bool resume)
  {
    screen << "ArchDam: case '" << p.analysis.case_name << "'" << std::endl;
    create_output_directory();
    if (resume)
      {
        if (!p.analysis.runs("dynamic"))
          throw InputError("--resume continues a dynamic stage, and Analysis/Stages has none.");
        resume_from = std::make_unique<output::CheckpointManifest>(
          output::CheckpointFiles(p.output.directory, comm).read_manifest(p.fingerprint));
        screen << "Resuming the dynamic stage after step " << resume_from->step << " (t = "
               << resume_from->time << " s)" << std::endl;
      }

    if (!resume)
      output::handle_earlier_results(p.output.directory, p.output.earlier_results, comm);
    if (!built_model)
      setup_model();
    check_plausibility();
    if (resume_from)
      check_checkpoint();
    else if (p.analysis.runs("dynamic"))
      check_dynamic_steps();
    if (p.analysis.runs("static") && !resume_from)
      run_static_stage();
    if (p.analysis.runs("modal") && !resume_from)
      run_modal_stage();
    if (p.analysis.runs("dynamic"))
      run_dynamic_stage();
    write_summary();

    if (p.output.timer_summary)
      timer.print_wall_time_statistics(comm);
  }

  void
  Simulation::create_output_directory()
  {
    on_rank_zero(comm, [&] {
      std::error_code ec;
      std::filesystem::create_directories(p.output.directory, ec);
      if (ec)
        throw InputError("Output/Directory: cannot create '" + p.output.directory +
                         "': " + ec.message() + ".");
    });
  }

  void
  Simulation::run_mesh_only()
  {
    screen << "ArchDam: case '" << p.analysis.case_name << "', mesh only" << std::endl;
    create_output_directory();
    Triangulation<dim> model;
    Model::build_mesh(p, screen, summary, model, false);
    summary.set("case", p.analysis.case_name);
    summary.set("model/cells", model.n_active_cells());
    summary.set("model/mpi processes", Utilities::MPI::n_mpi_processes(comm));
    summary.set("model/element degree", p.finite_element.degree);
    on_rank_zero(comm, [&] {
      output::write_mesh_vtu(model, p.output.directory + "/mesh");
      summary.write(p.output.directory + "/summary.json");
    });
    screen << "Wrote " << p.output.directory << "/mesh.vtu, mesh_boundary.vtu and "
           << "summary.json" << std::endl;
  }

  const Model &
  Simulation::setup_model()
  {
    TimerOutput::Scope t(timer, "setup");
    built_model = std::make_unique<Model>(p, comm, screen, summary);
    for (Vector *v : {&u_static, &current.u, &current.v, &current.a})
      model().space().reinit(*v);
    make_recorders();
    return model();
  }

  void
  Simulation::external_load(const double t, Vector &load) const
  {
    // The static loads act from the static stage on; without it the dynamic
    // stage starts unloaded and at rest, a consistent initial state (a0 = 0).
    if (p.analysis.runs("static"))
      load = model().static_load();
    else
      load = 0.;
    if (foundation()) // total motion: the input enters at the boundary
      {
        // and the dam's mass term acts on v - iota v_r (doc/theory/solid.md §4).
        if (const auto *reference = model().reference_motion())
          {
            const Tensor<1, dim> vr = reference->velocity(t);
            for (unsigned int d = 0; d < dim; ++d)
              load.add(vr[d], model().reference_loads()[d]);
          }
        return;
      }
    const Tensor<1, dim> ag = model().ground_motion().acceleration(t);
    for (unsigned int d = 0; d < dim; ++d)
      if (ag[d] != 0.)
        {
          load.add(-ag[d], model().influence_loads()[d]);
          if (coupled)
            load.add(-ag[d], coupled->fluid_influence[d]);
        }
  }

  void
  Simulation::write_summary()
  {
    summary.set("case", p.analysis.case_name);
    summary.set("version", archdam::version());
    summary.set("model/cells", model().triangulation().n_active_cells());
    summary.set("model/dofs", model().space().dof_handler.n_dofs());
    summary.set("model/mpi processes", Utilities::MPI::n_mpi_processes(comm));
    summary.set("model/element degree", p.finite_element.degree);

    if (model().joint_pairs())
      summarize_joints();

    for (const auto &[stage, seconds] : timer.get_summary_data(TimerOutput::total_wall_time))
      summary.set("wall time [s]/" + stage, seconds);

    on_rank_zero(comm, [&] { summary.write(p.output.directory + "/summary.json"); });
    say_where_results_are();
  }

  void
  Simulation::check_plausibility()
  {
    // Allowed by the parameters' ranges, but no dam's concrete or rock
    // (doc/bad-input.md): a modulus in kPa or MPa, a unit weight given as the
    // density.
    const auto check_material = [&](const std::string &name,
                                    const physics::solid::ElasticMaterial &m,
                                    const double lowest_modulus) {
      std::ostringstream text;
      if (m.youngs_modulus < lowest_modulus)
        text << "Materials/" << name << "/Young's modulus = " << m.youngs_modulus
             << " Pa is below " << lowest_modulus / 1e9
             << " GPa, softer than any dam's " << (name == "Rock" ? "rock" : "concrete")
             << ": is it in kPa or MPa? (22 GPa is 2.2e10 Pa.)";
      else if (m.density > 5000.)
        text << "Materials/" << name << "/Density = " << m.density
             << " kg/m^3 is twice any " << (name == "Rock" ? "rock" : "concrete")
             << "'s: is it a unit weight in N/m^3? (24 kN/m^3 is 24000/9.81 = 2446.5 kg/m^3.)";
      if (!text.str().empty())
        warn(text.str());
    };
    bool rock = false;
    for (const auto &cell : model().triangulation().active_cell_iterators())
      rock = rock || cell->material_id() == ids::rock;
    if (p.static_loads.gravity && std::abs(p.static_loads.g - 9.81) > 1.)
      {
        std::ostringstream text;
        text << "Static loads/Gravitational acceleration = " << p.static_loads.g
             << " m/s^2 is not the Earth's (9.81 m/s^2).";
        warn(text.str());
      }
    check_material("Concrete", p.materials.concrete, 1e9);
    if (rock)
      check_material("Rock", p.materials.rock, 1e8);

    // Westergaard's added mass takes the level as given; a reservoir mesh
    // that says otherwise is probably the level meant.
    namespace reservoir = physics::reservoir;
    if (p.reservoir.model == reservoir::Model::westergaard && !p.reservoir.level_from_mesh)
      {
        const auto top = reservoir::top_of_water(model().triangulation());
        if (top && std::abs(*top - p.reservoir.water_level) > 1e-6 * std::max(1., std::abs(*top)))
          {
            std::ostringstream text;
            text << "Reservoir/Water level = " << p.reservoir.water_level
                 << " m, but the reservoir's mesh reaches z = " << *top
                 << " m: Westergaard's added mass takes the level given (set 'Water level "
                 << "from mesh' to take the mesh's).";
            warn(text.str());
          }
      }
  }

  void
  Simulation::warn(const std::string &text)
  {
    output::warn(summary, screen, text);
  }

  void
  Simulation::say_where_results_are()
  {
    if (!screen.is_active())
      return;
    // The files a user opens: the series are named once, not each record
    // (NAME_00012.vtu, .h5 and the per-process pieces).
    static const std::regex     record(R"(.*_[0-9]{4,}(\.[0-9]+)?\.(vtu|pvtu|h5)$)");
    std::vector<std::string>    names;
    std::error_code             ec;
    for (const auto &entry : std::filesystem::directory_iterator(p.output.directory, ec))
      {
        const std::string name = entry.path().filename().string();
        if (name[0] != '.' && !std::regex_match(name, record))
          names.push_back(name + (entry.is_directory() ? "/" : ""));
      }
    std::sort(names.begin(), names.end());
    std::string list;
    for (const auto &name : names)
      list += (list.empty() ? "" : ", ") + name;
    screen << "Results in '" << p.output.directory << "': " << list << " (doc/user-guide.md, \"Results\")" << std::endl;
  }

} // namespace archdam::analysis
