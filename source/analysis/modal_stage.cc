#include <archdam/analysis/simulation.h>
#include <archdam/analysis/mode_shapes.h>

#include <iomanip>

namespace archdam::analysis
{
  using namespace dealii;

  /**
   * Modal stage (doc/theory/loading-sequence.md §2): the lowest natural frequencies and
   * mode shapes of the model as built (foundation and reservoir models
   * included through M and K), with each mode's effective modal mass in the
   * three directions, Gamma_d^2 for the mass-normalized shape, as a fraction
   * of the mass that can move in that direction (the fixed DOFs excluded).
   * Westergaard's added mass is part of M; water with a pressure enters as
   * the coupled dam-water system (compute_coupled_modes(): undamped, the
   * radiation at the truncation and the bottom absorption left out), whose
   * shapes are normalized and their effective masses taken on the solid.
   */
  void
  Simulation::run_modal_stage()
  {
    {
      TimerOutput::Scope t(timer, "modal");
      // Pressure per unit displacement of a mode at about 3 Hz, the order of
      // an arch dam's lowest frequencies, only used to balance the pencil:
      // on the arch dam with compressible water 100 times more or less gives
      // the same frequencies (5 digits) and residuals below 1e-9 (4e-12).
      const double omega_0        = 2. * numbers::PI * 3.;
      const double pressure_scale = model().fluid() ?
                                      p.reservoir.density * omega_0 * omega_0 *
                                        physics::reservoir::water_level(p.reservoir, model().triangulation()) :
                                      0.;
      modes = model().fluid() ?
                compute_coupled_modes(model().mass(), model().stiffness(), *model().fluid(),
                                      p.reservoir.density, pressure_scale,
                                      model().space().constraints, p.modal) :
                compute_natural_modes(model().mass(), model().stiffness(), model().space().constraints,
                                      p.modal);
    }
    for (auto &shape : modes.shapes)
      model().space().constraints.distribute(shape);

    std::array<double, dim> moving_mass;
    for (unsigned int d = 0; d < dim; ++d)
      moving_mass[d] = model().influence_loads()[d].mean_value() * model().influence_loads()[d].size();

    screen << "Modal stage: " << modes.omega.size()
           << (model().fluid() ? " modes of the dam coupled with the water" : " modes")
           << " (largest relative residual " << std::scientific << std::setprecision(1)
           << modes.max_residual << std::defaultfloat << ")" << std::endl
           << "  mode  f [Hz]    T [s]     effective mass x, y, z [%]" << std::endl;
    std::array<double, dim> cumulative{};
    for (unsigned int k = 0; k < modes.omega.size(); ++k)
      {
        const double f     = modes.omega[k] / (2. * numbers::PI);
        const auto   gamma = participation_factors(modes.shapes[k], model().influence_loads());
        const std::string key = "modal/mode " + std::to_string(k + 1) + "/";
        summary.set(key + "frequency [Hz]", f);
        summary.set(key + "period [s]", 1. / f);
        screen << "  " << std::setw(4) << k + 1 << "  " << std::fixed << std::setprecision(4)
               << std::setw(8) << f << "  " << std::setw(8) << 1. / f << " ";
        for (unsigned int d = 0; d < dim; ++d)
          {
            const double ratio = moving_mass[d] > 0 ? gamma[d] * gamma[d] / moving_mass[d] : 0.;
            cumulative[d] += ratio;
            summary.set(key + "effective mass ratio " + std::string(1, "xyz"[d]), ratio);
            screen << " " << std::setw(6) << std::setprecision(1) << 100 * ratio;
          }
        screen << std::defaultfloat << std::endl;
      }
    for (unsigned int d = 0; d < dim; ++d)
      summary.set("modal/cumulative effective mass ratio " + std::string(1, "xyz"[d]),
                  cumulative[d]);
    summary.set("modal/largest relative residual", modes.max_residual);

    if (p.modal.write_mode_shapes)
      {
        TimerOutput::Scope t(timer, "output");
        write_mode_shapes(p.output.directory, model().space(), modes);
      }
  }
} // namespace archdam::analysis
