#include <archdam/analysis/simulation.h>
#include <archdam/base/input_error.h>
#include <archdam/base/on_rank_zero.h>
#include <archdam/geometry/ids.h>
#include <archdam/geometry/support.h>
#include <archdam/output/mesh_report.h>
#include <archdam/output/mesh_writer.h>
#include <archdam/physics/reservoir/wetted_face_loads.h>
#include <archdam/physics/solid/solid_operators.h>

#include <deal.II/base/utilities.h>

#include <algorithm>
#include <filesystem>
#include <iomanip>
#include <limits>
#include <regex>

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
    , triangulation(comm)
  {}

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

    if (!fe_space)
      setup_model();
    if (resume_from)
      check_checkpoint();
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
  Simulation::build_mesh(Triangulation<dim> &model)
  {
    screen << "Building the mesh (Mesh/Source = "
           << selection_name(p.mesh.source, geometry::mesh_source_names()) << ")" << std::endl;
    geometry::build_model_mesh(p.mesh, p.base_directory, model);
    const auto report = output::make_mesh_report(model, p.finite_element.degree);
    if (screen.is_active())
      report.print(screen.get_stream());
    report.add_to(summary);
    check_static_support(model);
  }

  void
  Simulation::check_static_support(const Triangulation<dim> &model) const
  {
    if (!p.joints.frictional() || p.joints.solver != joints::Solver::mixed ||
        !p.analysis.runs("static"))
      return;
    const auto blocks = geometry::blocks_held_by_joints_alone(model);
    if (blocks.empty())
      return;
    std::string list;
    for (const unsigned int k : blocks)
      list += (list.empty() ? "" : ", ") + std::to_string(k);
    throw InputError(
      "Static stage: dam block" + std::string(blocks.size() > 1 ? "s " : " ") + list +
      (blocks.size() > 1 ? " rest" : " rests") +
      " on joints alone: no part of " + (blocks.size() > 1 ? "them" : "it") +
      " is tied to the rock or to the model's outer boundary (ids 1, 2). The mixed method "
      "solves the static stage with K, which has no inverse for such a block "
      "(doc/theory/joints.md §8). Use Contraction joints/Solver = monolithic, whose "
      "penalty springs hold the block on its joints, or tie the block to the rock.");
  }

  void
  Simulation::run_mesh_only()
  {
    screen << "ArchDam: case '" << p.analysis.case_name << "', mesh only" << std::endl;
    create_output_directory();
    Triangulation<dim> model;
    build_mesh(model);
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

  void
  Simulation::setup_model()
  {
    TimerOutput::Scope t(timer, "setup");
    // The water cells stay unless the reservoir is empty (doc/theory/reservoir.md §7);
    // they carry the pressure only in the compressible and incompressible
    // models.
    namespace reservoir = physics::reservoir;
    const auto         water = p.reservoir.model;
    Triangulation<dim> model;
    build_mesh(model);
    if (water == reservoir::Model::none)
      geometry::remove_water(model);
    triangulation.copy_triangulation(model);
    joint_faces = joints::pair_joint_faces(triangulation);
    fe_space    = std::make_unique<fe::FESpace>(triangulation, p.finite_element);
    fe_space->pressure_in_water = p.reservoir.has_pressure();
    fe_space->setup(p.foundation.fixed_boundaries(), [&](AffineConstraints<double> &c) {
      // Contraction joints/Model = glued: the monolithic dam.
      if (!p.joints.frictional())
        joints::tie_joint_dofs(fe_space->dof_handler, joint_faces, fe_space->locally_relevant,
                               c);
      reservoir::constrain_free_surface(*fe_space, p.reservoir, c);
    });
    if (p.joints.frictional())
      {
        node_pairs = std::make_unique<joints::NodePairs>(*fe_space, joint_faces);
        p.joints.check_per_joint(node_pairs->n_joints());
        screen << "Joints: " << node_pairs->n_joints() << " in frictional contact, "
               << node_pairs->size() << " node pairs" << std::endl;
      }
    if (p.reservoir.has_pressure())
      {
        interface_pairs = reservoir::match_interface_faces(*fe_space);
        fe_space->add_couplings = [this](DynamicSparsityPattern &dsp) {
          reservoir::add_interface_couplings(*fe_space, interface_pairs, dsp);
        };
      }

    unsigned int n_dam = 0, n_rock = 0, n_water = 0;
    for (const auto &cell : triangulation.active_cell_iterators())
      (ids::is_dam(cell->material_id())        ? n_dam :
       cell->material_id() == ids::water ? n_water :
                                                 n_rock) += 1;
    screen << "Mesh: " << triangulation.n_active_cells() << " cells (dam " << n_dam
           << ", rock " << n_rock << (n_water > 0 ? ", water " + std::to_string(n_water) : "")
           << "), " << fe_space->dof_handler.n_dofs() << " DOFs" << std::endl;

    const auto inertia = p.foundation.rock_has_mass() ? physics::solid::InertiaOf::dam_and_rock :
                                                        physics::solid::InertiaOf::dam;
    physics::solid::assemble_mass_and_stiffness(*fe_space, p.materials, inertia, mass_matrix,
                                                stiffness_matrix);
    const double level =
      water == reservoir::Model::none ? 0. : reservoir::water_level(p.reservoir, triangulation);
    if (water == reservoir::Model::westergaard)
      reservoir::add_westergaard_mass(*fe_space, p.reservoir.density, level, mass_matrix);
    if (p.reservoir.has_pressure())
      {
        fluid_operators = std::make_unique<reservoir::FluidOperators>();
        reservoir::assemble_fluid_operators(*fe_space, p.reservoir, p.static_loads.g,
                                            interface_pairs, *fluid_operators);
      }

    // Static load: self-weight b = -g e_z (doc/theory/loading-sequence.md §1).
    Tensor<1, dim> gravity;
    gravity[dim - 1] = p.static_loads.gravity ? -p.static_loads.g : 0.;
    physics::solid::assemble_inertia_load(*fe_space, p.materials,
                                          p.static_loads.gravity_on_rock ?
                                            physics::solid::InertiaOf::dam_and_rock :
                                            physics::solid::InertiaOf::dam,
                                          gravity, static_load);
    if (p.static_loads.hydrostatic && water != reservoir::Model::none)
      reservoir::add_hydrostatic_load(*fe_space, p.reservoir.density, p.static_loads.g, level,
                                      static_load);
    // Influence loads M iota_d of the relative formulation (doc/theory/foundation.md §2).
    for (unsigned int d = 0; d < dim; ++d)
      physics::solid::assemble_inertia_load(*fe_space, p.materials, inertia,
                                            Point<dim>::unit_vector(d), influence_load[d]);

    ground_motion = std::make_unique<loads::GroundMotion>(p.ground_motion, p.base_directory);
    if (p.foundation.rock_has_mass())
      setup_massed_foundation(inertia);
    monitor = std::make_unique<output::Monitors>(p.monitors, *fe_space, p.materials);
    for (Vector *v : {&u_static, &current.u, &current.v, &current.a})
      fe_space->reinit(*v);
    make_recorders();
  }

  void
  Simulation::external_load(const double t, Vector &load) const
  {
    // The static loads act from the static stage on; without it the dynamic
    // stage starts unloaded and at rest, a consistent initial state (a0 = 0).
    if (p.analysis.runs("static"))
      load = static_load;
    else
      load = 0.;
    if (massed_foundation) // total motion: the input enters at the boundary
      return;
    const Tensor<1, dim> ag = ground_motion->acceleration(t);
    for (unsigned int d = 0; d < dim; ++d)
      if (ag[d] != 0.)
        {
          load.add(-ag[d], influence_load[d]);
          if (coupled)
            load.add(-ag[d], coupled->fluid_influence[d]);
        }
  }

  void
  Simulation::write_summary()
  {
    summary.set("case", p.analysis.case_name);
    summary.set("model/cells", triangulation.n_active_cells());
    summary.set("model/dofs", fe_space->dof_handler.n_dofs());
    summary.set("model/mpi processes", Utilities::MPI::n_mpi_processes(comm));
    summary.set("model/element degree", p.finite_element.degree);

    if (node_pairs)
      summarize_joints();

    for (const auto &[stage, seconds] : timer.get_summary_data(TimerOutput::total_wall_time))
      summary.set("wall time [s]/" + stage, seconds);

    on_rank_zero(comm, [&] { summary.write(p.output.directory + "/summary.json"); });
    say_where_results_are();
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

  void
  Simulation::setup_massed_foundation(const physics::solid::InertiaOf inertia)
  {
    // The free surface of the half-space is the top of the rock, its bottom
    // the model's (doc/theory/foundation.md §4).
    double z_top = -std::numeric_limits<double>::max(), z_bottom = -z_top;
    for (const auto &cell : triangulation.active_cell_iterators())
      for (const auto v : cell->vertex_indices())
        {
          z_bottom = std::min(z_bottom, cell->vertex(v)[dim - 1]);
          if (cell->material_id() == ids::rock)
            z_top = std::max(z_top, cell->vertex(v)[dim - 1]);
        }
    free_field = std::make_unique<physics::foundation::FreeField>(
      physics::foundation::FreeField::of_ground_motion(*ground_motion, p.materials.rock, z_top,
                                                       z_bottom));
    massed_foundation = physics::foundation::make_massed_foundation(
      p.foundation, *fe_space, p.materials, inertia, *free_field, p.time_integration.time_step);
    massed_foundation->add_springs(stiffness_matrix);
    using physics::foundation::TransmittingBoundary;
    const TransmittingBoundary boundary = p.foundation.transmitting_boundary;
    if (boundary == TransmittingBoundary::viscous && p.foundation.spring_distance == 0. &&
        p.analysis.runs("static"))
      throw InputError("Foundation: the viscous boundary without springs (Spring distance = 0) "
                       "does not support the model in the static stage; set Spring distance "
                       "> 0, or use the MTF or the fixed boundary.");
    screen << "Massed foundation: "
           << selection_name(boundary, physics::foundation::transmitting_boundary_names())
           << " boundary; free surface at z = " << z_top << " m, bottom at z = " << z_bottom
           << " m; the ground motion reaches the surface after " << std::setprecision(4)
           << free_field->delay(0) << " s (horizontal), " << free_field->delay(dim - 1)
           << " s (vertical)";
    if (const std::string details = massed_foundation->details(); !details.empty())
      screen << "; " << details;
    screen << std::endl;
  }
} // namespace archdam::analysis
