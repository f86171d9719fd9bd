#include <archdam/analysis/simulation.h>
#include <archdam/base/input_error.h>
#include <archdam/geometry/ids.h>
#include <archdam/physics/solid/solid_operators.h>

#include <deal.II/base/utilities.h>

#include <filesystem>
#include <iomanip>

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
  Simulation::run()
  {
    screen << "ArchDam: case '" << p.analysis.case_name << "'" << std::endl;
    if (Utilities::MPI::this_mpi_process(comm) == 0)
      {
        std::error_code ec;
        std::filesystem::create_directories(p.output.directory, ec);
        if (ec)
          throw InputError("Output/Directory: cannot create '" + p.output.directory +
                           "': " + ec.message() + ".");
      }
    MPI_Barrier(comm);

    if (!fe_space)
      setup_model();
    if (p.analysis.runs("static"))
      run_static_stage();
    if (p.analysis.runs("dynamic"))
      run_dynamic_stage();
    write_summary();

    if (p.output.timer_summary)
      timer.print_wall_time_statistics(comm);
  }

  void
  Simulation::setup_model()
  {
    TimerOutput::Scope t(timer, "setup");
    // The reservoir is empty until the water physics exists (numerics.md §4).
    geometry::create_mesh(p.mesh, triangulation, false);
    joint_faces = joints::pair_joint_faces(triangulation);
    fe_space    = std::make_unique<fe::FESpace>(triangulation, p.finite_element);
    fe_space->setup(p.foundation.fixed_boundaries(), [&](AffineConstraints<double> &c) {
      // Contraction joints/Model = glued: the monolithic dam.
      if (!p.joints.frictional())
        joints::tie_joint_dofs(fe_space->dof_handler, joint_faces, fe_space->locally_relevant,
                               c);
    });
    if (p.joints.frictional())
      {
        node_pairs = std::make_unique<joints::NodePairs>(*fe_space, joint_faces);
        screen << "Joints: " << node_pairs->n_joints() << " in frictional contact, "
               << node_pairs->size() << " node pairs" << std::endl;
      }

    unsigned int n_dam = 0, n_rock = 0;
    for (const auto &cell : triangulation.active_cell_iterators())
      (ids::is_dam(cell->material_id()) ? n_dam : n_rock) += 1;
    screen << "Mesh: " << triangulation.n_active_cells() << " cells (dam " << n_dam
           << ", rock " << n_rock << "), " << fe_space->dof_handler.n_dofs() << " DOFs"
           << std::endl;

    const auto inertia = p.foundation.rock_has_mass() ? physics::solid::InertiaOf::dam_and_rock :
                                                        physics::solid::InertiaOf::dam;
    physics::solid::assemble_mass_and_stiffness(*fe_space, p.materials, inertia, mass_matrix,
                                                stiffness_matrix);

    // Static load: self-weight b = -g e_z (numerics.md §6).
    Tensor<1, dim> gravity;
    gravity[dim - 1] = p.static_loads.gravity ? -p.static_loads.g : 0.;
    physics::solid::assemble_inertia_load(*fe_space, p.materials,
                                          p.static_loads.gravity_on_rock ?
                                            physics::solid::InertiaOf::dam_and_rock :
                                            physics::solid::InertiaOf::dam,
                                          gravity, static_load);
    // Influence loads M iota_d of the relative formulation (numerics.md §5).
    for (unsigned int d = 0; d < dim; ++d)
      physics::solid::assemble_inertia_load(*fe_space, p.materials, inertia,
                                            Point<dim>::unit_vector(d), influence_load[d]);

    ground_motion = std::make_unique<loads::GroundMotion>(p.ground_motion, p.base_directory);
    monitor = std::make_unique<output::Monitors>(p.monitors, *fe_space, p.materials);
    fields  = std::make_unique<output::FieldWriter>(p.output, *fe_space, p.materials);

    for (Vector *v : {&u_static, &current.u, &current.v, &current.a})
      fe_space->reinit(*v);
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
    const Tensor<1, dim> ag = ground_motion->acceleration(t);
    for (unsigned int d = 0; d < dim; ++d)
      if (ag[d] != 0.)
        load.add(-ag[d], influence_load[d]);
  }

  void
  Simulation::write_fields()
  {
    if (p.output.field_interval == 0)
      return;
    TimerOutput::Scope t(timer, "output");
    fields->write(current);
    Vector u;
    fe_space->reinit_ghosted(u);
    u = current.u;
    const auto peak = physics::solid::peak_major_principal_stress(*fe_space, p.materials, u);
    if (peak.value > peak_stress.value)
      {
        peak_stress      = peak;
        peak_stress_time = current.time;
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

    if (history && !history->rows().empty())
      {
        const auto &rows  = history->rows();
        const auto &names = history->columns();
        screen << "Peak values (monitors):" << std::endl;
        for (unsigned int c = 1; c < names.size(); ++c)
          {
            unsigned int best = 0;
            for (unsigned int r = 0; r < rows.size(); ++r)
              if (std::abs(rows[r][c]) > std::abs(rows[best][c]))
                best = r;
            summary.set("peaks/" + names[c] + "/value", rows[best][c]);
            summary.set("peaks/" + names[c] + "/time [s]", rows[best][0]);
            screen << "  peak " << names[c] << " = " << std::setprecision(4) << rows[best][c]
                   << " at t = " << rows[best][0] << " s" << std::endl;
          }
      }
    if (p.output.field_interval > 0 && fe_space->dof_handler.n_dofs() > 0)
      {
        summary.set("peaks/major principal stress in the dam [Pa]/value", peak_stress.value);
        summary.set("peaks/major principal stress in the dam [Pa]/time [s]", peak_stress_time);
        for (unsigned int d = 0; d < dim; ++d)
          summary.set("peaks/major principal stress in the dam [Pa]/" +
                        std::string(1, "xyz"[d]) + " [m]",
                      peak_stress.where[d]);
        summary.set("peaks/major principal stress in the dam [Pa]/note",
                    "maximum over quadrature points at field output times");
      }

    if (node_pairs)
      summarize_joints();

    for (const auto &[stage, seconds] : timer.get_summary_data(TimerOutput::total_wall_time))
      summary.set("wall time [s]/" + stage, seconds);

    if (Utilities::MPI::this_mpi_process(comm) == 0)
      summary.write(p.output.directory + "/summary.json");
  }
} // namespace archdam::analysis
