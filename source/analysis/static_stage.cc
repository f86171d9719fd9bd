#include <archdam/analysis/simulation.h>
#include <archdam/analysis/static_resultants.h>
#include <archdam/base/input_error.h>
#include <archdam/time/factorized_operator.h>

#include <deal.II/grid/grid_tools.h>

#include <cmath>
#include <iomanip>
#include <sstream>

namespace archdam::analysis
{
  using namespace dealii;

  /**
   * Static stage (doc/theory/loading-sequence.md §1): K u = F_static with the fixed
   * boundary, solved with a Cholesky factorization of K. The dynamic stage
   * starts from this state at rest.
   */
  void
  Simulation::run_static_stage()
  {
    {
      TimerOutput::Scope   t(timer, "static");
      // With water, K + Q + G: the water rows are only there to be
      // nonsingular and carry no load, so the hydrodynamic pressure stays 0.
      SparseMatrix with_water;
      if (model().fluid())
        physics::reservoir::linear_combination(with_water, {{1., &model().stiffness()},
                                                            {1., &model().fluid()->Q},
                                                            {1., &model().fluid()->G}});
      const SparseMatrix      &K = model().fluid() ? with_water : model().stiffness();
      Vector rhs = model().static_load();
      model().space().constraints.set_zero(rhs);
      if (model().joint_pairs() &&
          p.joints.static_solution == joints::StaticSolution::dynamic_relaxation)
        {
          screen << "Static stage: dynamic relaxation with the joints ("
                 << model().space().dof_handler.n_dofs() << " DOFs)" << std::endl;
          relax_static_with_joints(K, rhs);
        }
      else
        {
          screen << "Static stage: factorizing K (" << model().space().dof_handler.n_dofs()
                 << " DOFs)" << std::endl;
          time::FactorizedOperator stiffness_factor;
          stiffness_factor.factorize(K, true, condensed_interface());
          screen << "  factors: " << std::setprecision(4) << stiffness_factor.factor_entries()
                 << " entries" << std::endl;
          if (model().joint_pairs())
            solve_static_with_joints(K, stiffness_factor, rhs);
          else
            stiffness_factor.solve(u_static, rhs);
        }
      model().space().constraints.distribute(u_static);
      current.u = u_static;
    }

    const double max_u = u_static.linfty_norm();
    if (!std::isfinite(max_u))
      throw InputError("Static stage: the displacement is not finite; the model is "
                       "singular (is every part of it supported?).");
    screen << "Static stage: max |u_i| = " << std::setprecision(4) << max_u << " m"
           << std::endl;
    check_static_state(max_u);
    summary.set("static/max nodal displacement component [m]", max_u);
    report_static_resultants();
    for (unsigned int k = 0; k < model().monitors().monitor_points().size(); ++k)
      {
        const auto u = model().monitors().displacement(k, u_static);
        for (unsigned int d = 0; d < dim; ++d)
          summary.set("static/" + model().monitors().monitor_points()[k].name + ".u" +
                        std::string(1, "xyz"[d]) + " [m]",
                      u[d]);
      }
    // The static state's largest tension in the dam (the dynamic stage's
    // peak comes from the stress envelope, output/stress_envelope.h).
    Vector u;
    model().space().reinit_ghosted(u);
    u               = u_static;
    const auto peak = physics::solid::peak_major_principal_stress(model().space(), p.materials,
                                                                   model().temperature(), u);
    const std::string key = "static/major principal stress in the dam [Pa]/";
    summary.set(key + "largest", peak.value);
    for (unsigned int d = 0; d < dim; ++d)
      summary.set(key + std::string(1, "xyz"[d]) + " [m]", peak.where[d]);
    summary.set(key + "note", "the largest over the quadrature points of the dam's cells");
    if (p.output.field_interval > 0)
      {
        TimerOutput::Scope t(timer, "output");
        own_recorder<output::FieldWriter>()->write(current);
      }
  }

  void
  Simulation::check_static_state(const double max_u) const
  {
    // A dam under its loads moves by millimetres to centimetres; a static
    // displacement of 1 % of the model's size is a strain of order 1e-2 in a
    // small-strain model (concrete cracks at 1e-4): the loads or the
    // stiffness are in other units, and the dynamic stage would only diverge.
    const auto   box  = GridTools::compute_bounding_box(model().triangulation());
    const double size = box.get_boundary_points().first.distance(box.get_boundary_points().second);
    if (max_u <= 1e-2 * size)
      return;
    std::ostringstream text;
    text << std::setprecision(4) << "Static stage: the largest displacement, " << max_u
         << " m, is more than 1 % of the model's size (" << size
         << " m), which no dam under its own weight and its water reaches: check "
         << "Static loads/Gravitational acceleration (" << p.static_loads.g << " m/s^2), the "
         << "Materials' Young's moduli and densities (their units) and the water level.";
    throw InputError(text.str());
  }

  void
  Simulation::report_static_resultants()
  {
    namespace reservoir = physics::reservoir;
    Tensor<1, dim> gravity;
    gravity[dim - 1] = p.static_loads.gravity ? -p.static_loads.g : 0.;
    const bool   hydrostatic =
      p.static_loads.hydrostatic && p.reservoir.model != reservoir::Model::none;
    const double level = hydrostatic ? reservoir::water_level(p.reservoir, model().triangulation()) : 0.;
    const double rho_g = p.reservoir.density * p.static_loads.g;
    Vector       u;
    model().space().reinit_ghosted(u);
    u            = u_static;
    const auto r = static_resultants(model().space(), p.materials, model().temperature(), u, gravity, [&](const double z) {
      return hydrostatic && z < level ? rho_g * (level - z) : 0.;
    });
    if (screen.is_active())
      r.print(screen.get_stream());
    const std::string key = "static/resultants on the dam [N]/";
    for (const auto &[name, force] : {std::pair{"weight", r.weight},
                                      {"water", r.water},
                                      {"support", r.reaction},
                                      {"support from the stress", r.support_stress},
                                      {"moments [N m]/weight", r.weight_moment},
                                      {"moments [N m]/water", r.water_moment},
                                      {"moments [N m]/support", r.reaction_moment},
                                      {"moments [N m]/about [m]", Tensor<1, dim>(r.centroid)}})
      for (unsigned int d = 0; d < dim; ++d)
        summary.set(key + name + "/" + "xyz"[d], force[d]);
    summary.set(key + "out of balance", r.out_of_balance());
    summary.set(key + "out of balance of the stress", r.stress_out_of_balance());
    summary.set(key + "note", "support: the reactions, the residual of the dam's equations at "
                              "the support's nodes; support from the stress: int sigma n dA "
                              "over the support's faces, a check of the stress");
    if (r.out_of_balance() > StaticResultants::warning_threshold)
      {
        std::ostringstream text;
        text << std::setprecision(2) << "Static stage: the reactions balance the loads on the "
             << "dam only to " << r.out_of_balance() << " of them (more than "
             << StaticResultants::warning_threshold << "): the static state is not in "
             << "equilibrium to that error (doc/theory/loading-sequence.md §1).";
        warn(text.str());
      }
  }
} // namespace archdam::analysis
