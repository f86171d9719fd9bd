#include <archdam/analysis/simulation.h>
#include <archdam/base/input_error.h>
#include <archdam/base/on_rank_zero.h>
#include <archdam/geometry/ids.h>
#include <archdam/loads/response_spectrum.h>
#include <archdam/output/atomic_file.h>
#include <archdam/physics/foundation/site_column.h>

#include <algorithm>
#include <cmath>
#include <iomanip>
#include <limits>

namespace archdam::analysis
{
  using namespace dealii;

  namespace
  {
    /// The largest |S_a / S_ref - 1| over the periods.
    double
    spectrum_deviation(const loads::ResponseSpectrum &s, const loads::ResponseSpectrum &ref)
    {
      double e = 0.;
      for (unsigned int i = 0; i < s.periods.size(); ++i)
        e = std::max(e, std::abs(s.pseudo_acceleration[i] / ref.pseudo_acceleration[i] - 1.));
      return e;
    }
  } // namespace

  void
  Simulation::run_free_field_check()
  {
    screen << "ArchDam: case '" << p.analysis.case_name << "', free-field check" << std::endl;
    if (!p.foundation.rock_has_mass())
      throw InputError("--free-field-check: the case's rock is massless (Foundation/Model = "
                       "massless): the ground motion acts on the dam's base itself, there is no "
                       "free field to check.");
    const loads::GroundMotion motion(p.ground_motion, p.base_directory);
    if (motion.empty())
      throw InputError("--free-field-check: the case has no ground motion.");
    create_output_directory();

    // The rock's free surface and bottom, the dam's base, and the rock's
    // coarsest cell (its height): the column is meshed no finer than that.
    Triangulation<dim> mesh;
    Model::build_mesh(p, screen, summary, mesh, false);
    double z_s = -std::numeric_limits<double>::max(), z_b = -z_s, z_base = -z_s, h = 0.;
    for (const auto &cell : mesh.active_cell_iterators())
      {
        double low = std::numeric_limits<double>::max(), high = -low;
        for (const auto v : cell->vertex_indices())
          {
            const double z = cell->vertex(v)[dim - 1];
            low            = std::min(low, z);
            high           = std::max(high, z);
            z_b            = std::min(z_b, z);
          }
        if (cell->material_id() == ids::rock)
          {
            z_s = std::max(z_s, high);
            h   = std::max(h, high - low);
          }
        if (ids::is_dam(cell->material_id()))
          z_base = std::min(z_base, low);
      }
    if (!(z_base < z_s))
      z_base = z_s;

    const auto free_field = physics::foundation::FreeField::of_ground_motion(
      motion, p.materials.rock, Model::free_field_damping(p), z_s, z_b);
    const physics::foundation::SiteColumn column{p.foundation, p.materials.rock, p.damping,
                                                 p.finite_element.degree, h};
    const double dt      = p.time_integration.time_step;
    const auto   periods = loads::log_spaced_periods(0.05, 2., 40);
    screen << "Free-field check: a column of the rock alone from its free surface (z = " << z_s
           << " m) to the model's bottom (z = " << z_b << " m), cells of at most " << h
           << " m, the dam's base at z = " << z_base << " m; time step " << dt << " s"
           << std::endl;

    for (unsigned int d = 0; d < dim; ++d)
      if (motion.has_component(d))
        {
          const auto c = column.compare(free_field, motion, d, z_base, dt, comm);
          const auto &t = c.t, &control = c.control, &surface = c.surface, &base = c.base,
                     &closed_form = c.free_field;
          const auto spectrum = [&](const std::vector<double> &a) {
            return loads::response_spectrum(loads::AccelerationRecord{"", t, a}, periods, 0.05);
          };
          const auto   s_control = spectrum(control), s_surface = spectrum(surface),
                     s_base = spectrum(base), s_closed = spectrum(closed_form);
          const auto peak = [](const std::vector<double> &a) {
            double m = 0.;
            for (const double x : a)
              m = std::max(m, std::abs(x));
            return m;
          };
          const double pga_surface = peak(surface) / peak(control),
                       pga_base    = peak(base) / peak(closed_form);
          const double e_surface = spectrum_deviation(s_surface, s_control),
                       e_base    = spectrum_deviation(s_base, s_closed);

          const std::string key = std::string("free field check/") + "xyz"[d] + "/";
          summary.set(key + "surface PGA ratio to the control's", pga_surface);
          summary.set(key + "surface spectrum, largest deviation from the control's (0.05-2 s)",
                      e_surface);
          summary.set(key + "dam base z [m]", z_base);
          summary.set(key + "dam base PGA ratio to the free field's", pga_base);
          summary.set(key + "dam base spectrum, largest deviation from the free field's (0.05-2 s)",
                      e_base);
          summary.set(key + "dam base PGA ratio to the control's", peak(base) / peak(control));
          screen << std::setprecision(3) << "  " << "xyz"[d] << ": at the free surface PGA "
                 << pga_surface << " of the control motion's, its 5 % spectrum within "
                 << 100 * e_surface << " % of the control's (0.05-2 s); at the dam's base PGA "
                 << pga_base << " of the free field's there (" << peak(base) / peak(control)
                 << " of the control's), spectrum within " << 100 * e_base << " %" << std::endl;

          on_rank_zero(comm, [&] {
            const std::string name = p.output.directory + "/free_field_" + "xyz"[d];
            output::write_atomically(name + ".csv", [&](std::ostream &out) {
              out << std::setprecision(8)
                  << "time from the arrival [s],control [m/s^2],column at the surface [m/s^2],"
                     "column at the dam's base [m/s^2],free field at the dam's base [m/s^2]\n";
              for (unsigned int k = 0; k < t.size(); ++k)
                out << t[k] << ',' << control[k] << ',' << surface[k] << ',' << base[k] << ','
                    << closed_form[k] << '\n';
            });
            output::write_atomically(name + "_spectra.csv", [&](std::ostream &out) {
              out << std::setprecision(8)
                  << "period [s],control [m/s^2],column at the surface [m/s^2],column at the "
                     "dam's base [m/s^2],free field at the dam's base [m/s^2]\n";
              for (unsigned int i = 0; i < periods.size(); ++i)
                out << periods[i] << ',' << s_control.pseudo_acceleration[i] << ','
                    << s_surface.pseudo_acceleration[i] << ',' << s_base.pseudo_acceleration[i]
                    << ',' << s_closed.pseudo_acceleration[i] << '\n';
            });
          });
        }
    summary.set("case", p.analysis.case_name);
    on_rank_zero(comm, [&] { summary.write(p.output.directory + "/summary.json"); });
    screen << "Wrote " << p.output.directory
           << "/free_field_*.csv (histories and 5 % spectra) and summary.json" << std::endl;
  }
} // namespace archdam::analysis
