#include <archdam/analysis/model.h>
#include <archdam/base/input_error.h>
#include <archdam/geometry/ids.h>
#include <archdam/geometry/mesh.h>
#include <archdam/geometry/support.h>
#include <archdam/loads/response_spectrum.h>
#include <archdam/output/mesh_report.h>
#include <archdam/physics/reservoir/wetted_face_loads.h>

#include <algorithm>
#include <cmath>
#include <iomanip>
#include <sstream>
#include <tuple>
#include <limits>

namespace archdam::analysis
{
  using namespace dealii;

  namespace
  {
    /// What the model is shaken by, as read, scaled and processed: each
    /// component's PGA (with its time), PGV, PGD (integrated from rest, exact
    /// for an acceleration linear between samples) and duration, on the
    /// screen and in the summary (doc/theory/results.md §6).
    void
    report_ground_motion(const loads::GroundMotion &motion, const ConditionalOStream &screen,
                         output::Summary &summary)
    {
      for (unsigned int d = 0; d < dim; ++d)
        if (motion.has_component(d))
          {
            const auto  &record  = motion.record(d);
            const auto   history = loads::integrate(record);
            double       pgv = 0., pgd = 0.;
            for (unsigned int k = 0; k < history.times.size(); ++k)
              {
                pgv = std::max(pgv, std::abs(history.velocity[k]));
                pgd = std::max(pgd, std::abs(history.displacement[k]));
              }
            const double      pga      = record.peak();
            const double      duration = record.times.back() - record.times.front();
            const std::string key      = std::string("ground motion/") + "xyz"[d] + "/";
            summary.set(key + "PGA [m/s^2]", pga);
            summary.set(key + "PGA [g]", pga / loads::standard_gravity);
            summary.set(key + "PGA time [s]", record.time_of_peak());
            summary.set(key + "PGV [m/s]", pgv);
            summary.set(key + "PGD [m]", pgd);
            summary.set(key + "duration [s]", duration);
            summary.set(key + "processing", motion.processing(d));
            screen << "Ground motion in " << "xyz"[d] << ": PGA " << std::setprecision(4)
                   << pga / loads::standard_gravity << " g (" << pga << " m/s^2) at t = "
                   << record.time_of_peak() << " s, PGV " << 100. * pgv << " cm/s, PGD "
                   << 100. * pgd << " cm, " << duration << " s; processing: "
                   << motion.processing(d) << std::endl;
          }
    }

    /**
     * What the massed foundation's free field makes of the control motion
     * (doc/theory/foundation.md §4): per component its peak acceleration
     * and 5 %-damped pseudo-acceleration spectrum (0.05 to 2 s) at the free
     * surface and at the dam's base (@p z_base), as ratios to the control
     * motion's, on the screen and in the summary under "free field".
     */
    void
    report_free_field(const physics::foundation::FreeField &free_field,
                      const loads::GroundMotion            &motion,
                      const double                          z_surface,
                      const double                          z_base,
                      const ConditionalOStream             &screen,
                      output::Summary                      &summary)
    {
      const auto periods = loads::log_spaced_periods(0.05, 2., 40);
      for (unsigned int d = 0; d < dim; ++d)
        if (motion.has_component(d))
          {
            const auto  &control = motion.record(d);
            const double dt      = control.times.size() > 1 ? control.times[1] - control.times[0] : 0.;
            if (!(dt > 0.))
              continue;
            const auto target = loads::response_spectrum(control, periods, 0.05);
            const std::string key = std::string("free field/") + "xyz"[d] + "/";
            summary.set(key + "dam base z [m]", z_base);
            std::ostringstream line;
            line << std::setprecision(3);
            for (const auto &[where, z] : {std::pair<std::string, double>{"free surface", z_surface},
                                           {"dam's base", z_base}})
              {
                // The free field at z, sampled as the record, from the delay on.
                loads::AccelerationRecord at_z{control.source, control.times, control.values};
                for (unsigned int k = 0; k < at_z.times.size(); ++k)
                  at_z.values[k] =
                    free_field.acceleration(z, at_z.times[k] + free_field.delay(d))[d];
                const auto   spectrum = loads::response_spectrum(at_z, periods, 0.05);
                double       low = std::numeric_limits<double>::max(), high = 0.;
                for (unsigned int i = 0; i < periods.size(); ++i)
                  {
                    const double r = spectrum.pseudo_acceleration[i] / target.pseudo_acceleration[i];
                    low            = std::min(low, r);
                    high           = std::max(high, r);
                  }
                const double pga = at_z.peak() / control.peak();
                summary.set(key + where + "/PGA ratio to the control motion", pga);
                summary.set(key + where + "/spectrum ratio 0.05-2 s, least", low);
                summary.set(key + where + "/spectrum ratio 0.05-2 s, largest", high);
                line << (z == z_surface ? "" : "; ") << "at the " << where << " (z = " << z
                     << " m) PGA " << pga << " of the control motion's, 5 % spectrum " << low
                     << " to " << high << " of it (0.05-2 s)";
              }
            screen << "Free field in " << "xyz"[d] << ": " << line.str() << "." << std::endl;
          }
    }
  } // namespace

  void
  Model::build_mesh(const Parameters &p, const ConditionalOStream &screen,
                    output::Summary &summary, Triangulation<dim> &model, const bool solves)
  {
    screen << "Building the mesh (Mesh/Source = "
           << selection_name(p.mesh.source, geometry::mesh_source_names()) << ")" << std::endl;
    geometry::check_model_size(p.mesh, p.finite_element.degree, solves);
    geometry::build_model_mesh(p.mesh, p.base_directory, model);
    const auto report = output::make_mesh_report(model, p.finite_element.degree);
    if (screen.is_active())
      report.print(screen.get_stream());
    report.add_to(summary);
    check_static_support(p, model);
  }

  void
  Model::check_static_support(const Parameters &p, const Triangulation<dim> &model)
  {
    // The static stage needs K^{-1} for the mixed method's one solve and for
    // the self-weight on the ungrouted cantilevers (doc/theory/joints.md §8);
    // the dynamic relaxation of the grouted dam steps with the mass, which
    // holds a block on its joints.
    const bool mixed = p.joints.solver == joints::Solver::mixed &&
                       p.joints.static_solution == joints::StaticSolution::one_solve;
    const bool ungrouted = p.joints.grouting == joints::Grouting::after_self_weight;
    if (!p.joints.frictional() || !(mixed || ungrouted) || !p.analysis.runs("static"))
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
      " is tied to the rock or to the model's outer boundary (ids 1, 2). " +
      (ungrouted ? "With Contraction joints/Grouting = after self-weight the static stage "
                   "first solves the self-weight on the ungrouted blocks with K" :
                   "The mixed method's one solve (Static solution = one solve) solves the "
                   "static stage with K") +
      ", which has no inverse for such a block (doc/theory/joints.md §8). Use Contraction "
      "joints/Static solution = dynamic relaxation with Grouting = before self-weight (the "
      "default): the static load comes on in a damped transient with the mass, which holds "
      "the block on its joints; or Solver = monolithic with Grouting = before self-weight and "
      "Contact in time = trapezoidal, whose penalty springs hold it; or tie the block to the "
      "rock.");
  }

  Model::Model(const Parameters &p, const MPI_Comm comm, const ConditionalOStream &screen,
               output::Summary &summary)
    : mesh(comm)
  {
    // The water cells stay unless the reservoir is empty (doc/theory/reservoir.md §7);
    // they carry the pressure only in the compressible and incompressible
    // models.
    namespace reservoir = physics::reservoir;
    const auto         water = p.reservoir.model;
    Triangulation<dim> model;
    build_mesh(p, screen, summary, model, true);
    if (water == reservoir::Model::none)
      geometry::remove_water(model);
    mesh.copy_triangulation(model);
    joint_faces = joints::pair_joint_faces(mesh);
    fe_space    = std::make_unique<fe::FESpace>(mesh, p.finite_element);
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
        interfaces = reservoir::match_interface_faces(*fe_space);
        fe_space->add_couplings = [this](DynamicSparsityPattern &dsp) {
          reservoir::add_interface_couplings(*fe_space, interfaces, dsp);
        };
      }

    unsigned int n_dam = 0, n_rock = 0, n_water = 0;
    for (const auto &cell : mesh.active_cell_iterators())
      (ids::is_dam(cell->material_id())        ? n_dam :
       cell->material_id() == ids::water ? n_water :
                                                 n_rock) += 1;
    screen << "Mesh: " << mesh.n_active_cells() << " cells (dam " << n_dam
           << ", rock " << n_rock << (n_water > 0 ? ", water " + std::to_string(n_water) : "")
           << "), " << fe_space->dof_handler.n_dofs() << " DOFs" << std::endl;

    const auto inertia = p.foundation.rock_has_mass() ? physics::solid::InertiaOf::dam_and_rock :
                                                        physics::solid::InertiaOf::dam;
    // D is assembled only when it is not alpha M + beta K of the whole
    // model: dam and rock damped differently, or a Westergaard added mass,
    // which the dam's alpha does not damp (doc/theory/solid.md §4).
    const auto [alpha_dam, beta_dam] = p.damping.rayleigh_coefficients();
    const bool per_material =
      !p.damping.uniform() || (water == reservoir::Model::westergaard && alpha_dam != 0.);
    physics::solid::assemble_mass_and_stiffness(*fe_space, p.materials, inertia, mass_matrix,
                                                stiffness_matrix,
                                                per_material ? &p.damping : nullptr,
                                                per_material ? &damping_matrix : nullptr);
    if (alpha_dam != 0. || beta_dam != 0.)
      physics::solid::assemble_dam_damping(*fe_space, p.materials, p.damping,
                                           dam_damping_matrix);
    const double level =
      water == reservoir::Model::none ? 0. : reservoir::water_level(p.reservoir, mesh);
    if (water == reservoir::Model::westergaard)
      reservoir::add_westergaard_mass(*fe_space, p.reservoir.density, level, mass_matrix);
    if (p.reservoir.has_pressure())
      {
        fluid_operators = std::make_unique<reservoir::FluidOperators>();
        reservoir::assemble_fluid_operators(*fe_space, p.reservoir, p.static_loads.g,
                                            interfaces, *fluid_operators);
      }

    // Static load: self-weight b = -g e_z (doc/theory/loading-sequence.md §1).
    Tensor<1, dim> gravity;
    gravity[dim - 1] = p.static_loads.gravity ? -p.static_loads.g : 0.;
    physics::solid::assemble_inertia_load(*fe_space, p.materials,
                                          p.static_loads.gravity_on_rock ?
                                            physics::solid::InertiaOf::dam_and_rock :
                                            physics::solid::InertiaOf::dam,
                                          gravity, weight_forces);
    fe_space->reinit(static_forces);
    static_forces = weight_forces;
    if (p.static_loads.hydrostatic && water != reservoir::Model::none)
      reservoir::add_hydrostatic_load(*fe_space, p.reservoir.density, p.static_loads.g, level,
                                      static_forces);
    // The temperature change since grouting (doc/theory/temperature.md §2).
    temperature_change = physics::solid::TemperatureField(
      loads::parse_temperature_table(p.static_loads.temperature_change), mesh);
    physics::solid::add_thermal_load(*fe_space, p.materials, temperature_change, static_forces);
    // Influence loads M iota_d of the relative formulation (doc/theory/foundation.md §2).
    for (unsigned int d = 0; d < dim; ++d)
      physics::solid::assemble_inertia_load(*fe_space, p.materials, inertia,
                                            Point<dim>::unit_vector(d), influence[d]);

    motion = std::make_unique<loads::GroundMotion>(p.ground_motion, p.base_directory);
    report_ground_motion(*motion, screen, summary);
    if (p.foundation.rock_has_mass())
      {
        setup_massed_foundation(p, inertia, screen);
        double z_base = std::numeric_limits<double>::max(), z_surface = -z_base;
        for (const auto &cell : mesh.active_cell_iterators())
          for (const auto v : cell->vertex_indices())
            {
              if (ids::is_dam(cell->material_id()))
                z_base = std::min(z_base, cell->vertex(v)[dim - 1]);
              if (cell->material_id() == ids::rock)
                z_surface = std::max(z_surface, cell->vertex(v)[dim - 1]);
            }
        if (n_dam > 0)
          report_free_field(*free_field, *motion, z_surface, z_base, screen, summary);
      }
    monitor = std::make_unique<output::Monitors>(p.monitors, *fe_space, p.materials,
                                                 temperature_change);
  }

  physics::foundation::FreeFieldDamping
  Model::free_field_damping(const Parameters &p)
  {
    physics::foundation::FreeFieldDamping rock_damping;
    rock_damping.band_limit = p.foundation.band_limit;
    if (p.foundation.free_field == physics::foundation::FreeFieldRock::damped)
      std::tie(rock_damping.alpha, rock_damping.beta) = p.damping.rock_coefficients();
    return rock_damping;
  }

  double
  Model::ground_motion_delay() const
  {
    double delay = 0.;
    for (unsigned int d = 0; d < dim && free_field; ++d)
      if (motion->has_component(d))
        delay = std::max(delay, free_field->delay(d));
    return delay;
  }

  void
  Model::setup_massed_foundation(const Parameters                &p,
                                 const physics::solid::InertiaOf  inertia,
                                 const ConditionalOStream        &screen)
  {
    // The free surface of the half-space is the top of the rock, its bottom
    // the model's (doc/theory/foundation.md §4).
    double z_top = -std::numeric_limits<double>::max(), z_bottom = -z_top;
    for (const auto &cell : mesh.active_cell_iterators())
      for (const auto v : cell->vertex_indices())
        {
          z_bottom = std::min(z_bottom, cell->vertex(v)[dim - 1]);
          if (cell->material_id() == ids::rock)
            z_top = std::max(z_top, cell->vertex(v)[dim - 1]);
        }
    const physics::foundation::FreeFieldDamping rock_damping = free_field_damping(p);
    free_field = std::make_unique<physics::foundation::FreeField>(
      physics::foundation::FreeField::of_ground_motion(*motion, p.materials.rock, rock_damping,
                                                       z_top, z_bottom));
    // The integrator with a general damping matrix (the coupled dam-water
    // system's, or the one assembled per material) needs its columns too.
    const bool general_damping = p.reservoir.has_pressure() || damping() != nullptr;
    massed_foundation = physics::foundation::make_massed_foundation(
      p.foundation, *fe_space, p.materials, inertia, *free_field, p.time_integration.time_step,
      general_damping ? &p.damping : nullptr);
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
    if (free_field->damped())
      screen << "; the free field deconvolved through the rock's damping (alpha = "
             << rock_damping.alpha << " 1/s, beta = " << rock_damping.beta
             << " s) up to " << rock_damping.band_limit << " Hz";
    if (const std::string details = massed_foundation->details(); !details.empty())
      screen << "; " << details;
    screen << std::endl;

    // The dam's mass term on the velocity relative to the ground
    // (doc/theory/solid.md §4): the load v_r,d(t) alpha_d M_dam iota_d.
    const double alpha_dam = p.damping.rayleigh_coefficients().first;
    bool has_dam = false;
    for (const auto &cell : mesh.active_cell_iterators())
      has_dam = has_dam || ids::is_dam(cell->material_id());
    if (p.damping.mass_term == physics::solid::MassDamping::relative && alpha_dam != 0. &&
        has_dam)
      {
        reference = std::make_unique<physics::foundation::ReferenceMotion>(*free_field, mesh);
        for (unsigned int d = 0; d < dim; ++d)
          {
            physics::solid::assemble_inertia_load(*fe_space, p.materials,
                                                  physics::solid::InertiaOf::dam,
                                                  Point<dim>::unit_vector(d),
                                                  reference_forces[d]);
            reference_forces[d] *= alpha_dam;
          }
        screen << "The dam's mass-proportional damping acts on its velocity relative to the "
               << "free field's mean over the dam-rock interface (" << std::setprecision(4)
               << reference->area << " m^2, z = " << reference->z_low << " to "
               << reference->z_high << " m)" << std::endl;
      }
  }
} // namespace archdam::analysis
