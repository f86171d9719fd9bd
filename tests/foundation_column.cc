// Radiation through the bottom of 1-D columns over a half-space
// (doc/verification.md, "Foundation radiation"; doc/theory/foundation.md §4-§5): a shear (SV)
// column and a compression (P) column, each a stack of Q2 hexahedra whose
// DOFs are tied plane by plane, so that the motion is u(z, t) and the exact
// solution is d'Alembert's.
//
// A. Outgoing pulse: a downgoing pulse u(z, t) = g(t + (z - z0)/c) starts in
//    the middle of the column (nodal values of u, v, a of the exact wave) with
//    no seismic input. After it has passed the bottom, the energy left in the
//    column is what the boundary reflected: reported as a fraction of the
//    initial (incident) energy, below 2 % for the MTF and the viscous boundary.
//    The fixed boundary must reflect nearly all of it (the test can fail).
// B. Seismic input: the control motion g at the free surface. The surface
//    must move as g(t - H/c) (the free field, doc/theory/foundation.md §4) within 5 % of
//    the peak: the average acceleration rule lengthens periods by
//    (omega dt)^2/12, 0.4 % at the pulse's upper frequency 2/T = 33 Hz with
//    dt = 1 ms, which over the ~15 periods of travel shifts its phase by some
//    per cent of a period (Q2 cells of 5 m add less: 12 nodes per wavelength
//    there); the boundary adds its own small error. After the reflected pulse
//    has left through the bottom the energy left must again be below 2 % of
//    the largest energy during the run (the incident energy).
// C. Damping per material (doc/theory/solid.md §4, doc/theory/foundation.md §4):
//    the SV column's seismic input with its lower 120 m damped as rock and
//    its upper 80 m as an undamped "dam" (same elastic constants, dam
//    material id), once with a mass-proportional rock damping (alpha = 5/s)
//    and once stiffness proportional (zeta = 5 % at 10 Hz). The surface
//    motion is compared with the closed form of the layered column: the
//    incident wave g/2 of the undamped half-space below the bottom (what the
//    boundary prescribes) through a Kelvin-Voigt / telegraph layer of
//    complex wavenumber k = sqrt(rho (w^2 - i w alpha) / (G (1 + i w beta)))
//    and the undamped layer to the free surface, summed over frequencies
//    (Haskell's layer matrices, doc/verification.md). Tolerance 5 % of the
//    pulse's peak, as B. The same comparison with the rock's damping over
//    the whole column, and with none, must fail: the check sees where each
//    material's damping acts.
// D. The free field through the damped rock (doc/theory/foundation.md §4):
//    first the free field alone, at the depths 0, 100 and 200 m, against the
//    closed form u_c(w) cos(k s) of the damped half-space summed over
//    frequencies here (k as in C, the damping tapered above the band limit
//    as the free field defines it), to 1e-3 of the peak; then the whole
//    column damped as rock, stiffness proportional (5 % at 20 Hz) or mass
//    proportional (alpha = 5 1/s), shaken by a 0.1 s pulse (content at 0,
//    10 and 20 Hz) whose free field is deconvolved through that damping
//    (band limit 20 Hz): the free surface moves as the control motion,
//    g(t - T), within 2 % of its peak, for the MTF and the viscous boundary,
//    SV and P. With the undamped free field the same column misses by more
//    than 5 % (the loss that the deconvolution removes, printed).

#include <archdam/physics/foundation/massed_foundation.h>

#include <complex>
#include <memory>
#include <tuple>

#include "foundation_tests.h"

using namespace dealii;
using namespace archdam;
using namespace archdam::physics;

namespace
{
  using foundation::TransmittingBoundary;

  const double H = 200., w = 5., dt = 1e-3;
  const testing::Sin4Pulse g{0.01, 0.06};

  struct Result
  {
    double reflected = 0., surface_error = 0.;
    /// (t, u at the surface) after every step (seismic input)
    std::vector<std::pair<double, double>> surface;
  };

  /// With @p damping, the column's upper @p dam_layer metres are dam cells and
  /// the damping matrix is assembled per material; else no damping. The
  /// seismic input is the pulse @p pulse, its free field that of the
  /// half-space damped by @p free_field (undamped by default).
  Result
  run(const unsigned int component, const TransmittingBoundary boundary, const bool seismic,
      const solid::DampingParameters *damping = nullptr, const double dam_layer = 0.,
      const foundation::FreeFieldDamping &free_field_damping = {},
      const testing::Sin4Pulse          &pulse              = g)
  {
    foundation::FoundationParameters fp;
    fp.model                 = foundation::Model::massed;
    fp.transmitting_boundary = boundary;
    solid::MaterialParameters materials;
    materials.rock     = testing::test_rock();
    materials.concrete = materials.rock;
    const double c = component == 2 ? foundation::pressure_wave_speed(materials.rock) :
                                      foundation::shear_wave_speed(materials.rock);

    parallel::shared::Triangulation<3> tria(MPI_COMM_WORLD);
    testing::rock_box(tria, Point<3>(0, 0, -H), Point<3>(w, w, 0), {1, 1, 40}, 0);
    for (const auto &cell : tria.active_cell_iterators())
      if (cell->center()[2] > -dam_layer)
        cell->set_material_id(ids::first_dam_block);
    fe::FiniteElementParameters fep;
    fe::FESpace                 space(tria, fep);
    space.setup(fp.fixed_boundaries(),
                [&](AffineConstraints<double> &cons) { testing::tie_column(space, cons); });

    archdam::SparseMatrix M, K, D;
    solid::assemble_mass_and_stiffness(space, materials, solid::InertiaOf::dam_and_rock, M, K,
                                       damping, &D);

    std::array<loads::AccelerationRecord, 3> control;
    if (seismic)
      {
        std::vector<double> a;
        const double        h = dt / 4;
        for (unsigned int k = 0; k * h <= pulse.T + h; ++k)
          a.push_back(pulse.second(k * h));
        control[component] = loads::uniform_record(a, h);
      }
    const foundation::FreeField free_field(control, materials.rock, free_field_damping, 0., -H);
    const auto foundation_boundary = foundation::make_massed_foundation(fp, space, materials, solid::InertiaOf::dam_and_rock,
                                        free_field, dt, damping);
    auto &massed = *foundation_boundary;
    massed.add_springs(K);
    time::NewmarkParameters tp;
    tp.time_step = dt;
    const auto newmark =
      damping ? std::make_unique<time::NewmarkIntegrator>(tp, M, D, K, space.constraints, true,
                                                          massed.dashpots()) :
                std::make_unique<time::NewmarkIntegrator>(tp, M, K, std::pair{0., 0.},
                                                          space.constraints, massed.dashpots());

    time::NewmarkState s;
    for (archdam::Vector *v : {&s.u, &s.v, &s.a})
      space.reinit(*v);
    massed.start(s.u); // reference state: at rest, undeformed
    if (!seismic)
      {
        // downgoing pulse centred at mid-depth
        const double z0 = -H / 2 - c * pulse.T / 2;
        for (const auto &[i, pc] : testing::dof_positions(space))
          if (pc.second == component && space.locally_owned.is_element(i))
            {
              const double tau = (pc.first[2] - z0) / c;
              s.u(i)           = pulse.value(tau);
              s.v(i)           = pulse.first(tau);
              s.a(i)           = pulse.second(tau);
            }
        for (archdam::Vector *v : {&s.u, &s.v, &s.a})
          v->compress(VectorOperation::insert);
      }

    // the surface DOF of this component (the master of the top plane)
    types::global_dof_index top = numbers::invalid_dof_index;
    for (const auto &[i, pc] : testing::dof_positions(space))
      if (pc.second == component && std::abs(pc.first[2]) < 1e-6 && top == numbers::invalid_dof_index)
        top = i;

    const double       end     = seismic ? free_field.delay(component) + H / c + 2 * pulse.T + 0.15 : 0.2;
    const unsigned int n_steps = std::lround(end / dt);
    archdam::Vector             load;
    space.reinit(load);
    double E0 = testing::elastic_energy(M, K, space.constraints, s), E_max = E0;
    Result r;
    for (unsigned int n = 1; n <= n_steps; ++n)
      {
        massed.advance(*newmark, load, s);
        const double E = testing::elastic_energy(M, K, space.constraints, s);
        E_max          = std::max(E_max, E);
        if (seismic)
          {
            const double u_top = Utilities::MPI::sum(
              space.locally_owned.is_element(top) ? double(s.u(top)) : 0., MPI_COMM_WORLD);
            r.surface_error =
              std::max(r.surface_error,
                       std::abs(u_top - pulse.value(s.time - free_field.delay(component))) /
                         pulse.A);
            r.surface.emplace_back(s.time, u_top);
          }
        if (n == n_steps)
          r.reflected = E / E_max;
      }
    return r;
  }

  /**
   * Part C's closed form: the surface motion of the column with an upper
   * layer (thickness @p top, Rayleigh coefficients @p top_damping) on a lower
   * one (to the bottom at -H, @p bottom_damping), over the undamped half-space
   * from which the incident wave g/2 comes. For exp(i w t), a layer of
   * G* = G (1 + i w beta) and k = sqrt(rho (w^2 - i w alpha) / G*) carries
   * (u, tau) from its top to a depth h below as
   *   u' = u cos(k h) - tau sin(k h) / (G* k),  tau' = G* k u sin(k h) + tau cos(k h);
   * from (1, 0) at the free surface to (u_b, tau_b) at the bottom, the
   * half-space's upgoing amplitude is A = (u_b + i tau_b / (k0 G)) / 2,
   * k0 = w / c, so the surface moves as g^(w) / (2 A). The time history is
   * u(t) = (1/pi) Re int_0^inf g^(w) / (2 A) exp(i w t) dw, summed at the
   * mid-points of 8 s^-1 steps up to 300 Hz (g^ by the trapezoidal rule).
   */
  class LayeredColumn
  {
  public:
    LayeredColumn(const solid::ElasticMaterial &rock, const double top,
                  const std::pair<double, double> top_damping,
                  const std::pair<double, double> bottom_damping)
    {
      using C             = std::complex<double>;
      const double G      = rock.mu(), rho = rock.density, c = std::sqrt(G / rho);
      const double period = 8., f_max = 300.;
      dw                  = 2 * M_PI / period;
      const unsigned int n_t = 2000;
      for (unsigned int j = 0; (j + 0.5) * dw < 2 * M_PI * f_max; ++j)
        {
          const double w = (j + 0.5) * dw;
          C            g_hat = 0.;
          for (unsigned int m = 1; m < n_t; ++m) // g vanishes at both ends
            {
              const double t = m * g.T / n_t;
              g_hat += g.value(t) * std::exp(C(0., -w * t)) * (g.T / n_t);
            }
          C u = 1., tau = 0.;
          for (const auto &[h, d] : {std::pair{top, top_damping}, std::pair{H - top, bottom_damping}})
            {
              const C G_star = G * C(1., w * d.second);
              const C k      = std::sqrt(rho * C(w * w, -w * d.first) / G_star);
              const C u_next = u * std::cos(k * h) - tau * std::sin(k * h) / (G_star * k);
              tau            = G_star * k * u * std::sin(k * h) + tau * std::cos(k * h);
              u              = u_next;
            }
          const C A = 0.5 * (u + C(0., 1.) * tau / (w / c * G));
          spectrum.emplace_back(w, g_hat / (2. * A));
        }
    }

    double
    surface(const double t) const
    {
      double u = 0.;
      for (const auto &[w, s] : spectrum)
        u += std::real(s * std::exp(std::complex<double>(0., w * t)));
      return u * dw / M_PI;
    }

  private:
    double                                               dw;
    std::vector<std::pair<double, std::complex<double>>> spectrum;
  };

  /**
   * Part D's closed form: the displacement at depth s of the damped
   * half-space whose free surface moves as @p pulse delayed by T,
   * (1/pi) Re int_0^inf g^(w) cos(k s) exp(i w (t - T)) dw with
   * k^2 = (w^2 - i w alpha tau) / (c^2 (1 + i w beta tau)), tau = 1 up to the
   * band limit f_b, (1 + cos(pi (f - f_b) / f_b)) / 2 up to 2 f_b, 0 above;
   * summed at the mid-points of 0.5 s^-1 steps up to 200 Hz (g^ by the
   * trapezoidal rule).
   */
  class DampedHalfSpace
  {
  public:
    DampedHalfSpace(const testing::Sin4Pulse &pulse, const double c,
                    const foundation::FreeFieldDamping &d)
    {
      using C                = std::complex<double>;
      const unsigned int n_t = 400;
      for (unsigned int j = 0; (j + 0.5) * dw < 2 * M_PI * 200.; ++j)
        {
          const double w = (j + 0.5) * dw, f = w / (2 * M_PI), f_b = d.band_limit;
          // The band limit's smooth step (doc/theory/foundation.md §4).
          const double x   = (f - f_b) / f_b;
          const double tau = x <= 0. ? 1. : x >= 1. ? 0. : 1. / (1. + std::exp(1. / (1. - x) - 1. / x));
          C g_hat = 0.;
          for (unsigned int m = 1; m < n_t; ++m)
            {
              const double tm = m * pulse.T / n_t;
              g_hat += pulse.value(tm) * std::exp(C(0., -w * tm)) * (pulse.T / n_t);
            }
          const C k = std::sqrt(C(w * w, -w * d.alpha * tau) / (c * c * C(1., w * d.beta * tau)));
          terms.push_back({w, g_hat, k});
        }
    }

    double
    displacement(const double s, const double t_minus_T) const
    {
      double u = 0.;
      for (const auto &[w, g_hat, k] : terms)
        u += std::real(g_hat * std::cos(k * s) *
                       std::exp(std::complex<double>(0., w * t_minus_T)));
      return u * dw / M_PI;
    }

  private:
    const double dw = 2 * M_PI * 0.5;
    std::vector<std::tuple<double, std::complex<double>, std::complex<double>>> terms;
  };

  /// max_t |u(t) - exact(t)| / max g over a surface history.
  double
  error_against(const Result &r, const LayeredColumn &exact)
  {
    double e = 0.;
    for (const auto &[t, u] : r.surface)
      e = std::max(e, std::abs(u - exact.surface(t)) / g.A);
    return e;
  }
} // namespace

int
main(int argc, char **argv)
{
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  for (const unsigned int component : {0u, 2u})
    {
      const std::string name = component == 0 ? "shear (SV) column" : "P-wave column";
      for (const auto boundary : {TransmittingBoundary::mtf, TransmittingBoundary::viscous,
                                  TransmittingBoundary::fixed})
        {
          const Result a = run(component, boundary, false);
          testing::log() << name << ", "
                         << selection_name(boundary, foundation::transmitting_boundary_names())
                         << " boundary, outgoing pulse: reflected "
                         << "energy fraction " << std::setprecision(1) << std::fixed
                         << 100 * a.reflected << " %" << std::defaultfloat << std::setprecision(6) << std::endl;
          if (boundary == TransmittingBoundary::fixed)
            testing::log() << "  fixed boundary reflects more than 50 %: "
                           << (a.reflected > 0.5 ? "yes" : "NO") << std::endl;
          else
            testing::check_below("  reflected energy fraction", a.reflected, 0.02);
        }
      for (const auto boundary : {TransmittingBoundary::mtf, TransmittingBoundary::viscous})
        {
          const Result b = run(component, boundary, true);
          testing::log() << name << ", "
                         << selection_name(boundary, foundation::transmitting_boundary_names())
                         << " boundary, seismic input:" << std::endl;
          testing::check_below("  max |u_surface - g(t - H/c)| / max g", b.surface_error, 0.05);
          testing::check_below("  energy left after the pulse / incident energy", b.reflected,
                               0.02);
          testing::log() << "  (surface error " << std::setprecision(1) << std::fixed
                         << 100 * b.surface_error << " %, energy left " << 100 * b.reflected
                         << " %)" << std::defaultfloat << std::setprecision(6) << std::endl;
        }
    }

  // C. Damping per material.
  const double dam_layer = 80.;
  for (const bool stiffness : {false, true})
    {
      solid::DampingParameters dp; // the dam: undamped
      dp.mode = solid::DampingMode::coefficients;
      if (stiffness)
        {
          dp.rock.mode            = solid::DampingMode::stiffness_proportional;
          dp.rock.ratio           = 0.05;
          dp.rock.first_frequency = 10.;
        }
      else
        {
          dp.rock.mode  = solid::DampingMode::coefficients;
          dp.rock.alpha = 5.;
        }
      const auto rock = dp.rock_coefficients(), none = std::pair{0., 0.};
      testing::log() << "shear (SV) column, MTF boundary, seismic input, lower " << H - dam_layer
                     << " m rock damped "
                     << (stiffness ? "stiffness proportional (5 % at 10 Hz)" :
                                     "mass proportional (alpha = 5 1/s)")
                     << ", upper " << dam_layer << " m dam undamped:" << std::endl;
      const Result r   = run(0, TransmittingBoundary::mtf, true, &dp, dam_layer);
      const auto   rock_material = testing::test_rock();
      const double e   = error_against(r, LayeredColumn(rock_material, dam_layer, none, rock));
      testing::check_below("  max |u_surface - closed form| / max g", e, 0.05);
      const double e_all = error_against(r, LayeredColumn(rock_material, dam_layer, rock, rock));
      const double e_none = error_against(r, LayeredColumn(rock_material, dam_layer, none, none));
      testing::log() << "  the closed form with the rock's damping in both layers is off by more "
                        "than 5 %: "
                     << (e_all > 0.05 ? "yes" : "NO") << std::endl
                     << "  the undamped closed form is off by more than 5 %: "
                     << (e_none > 0.05 ? "yes" : "NO") << std::endl;
      double peak = 0.;
      for (const auto &[t, u] : r.surface)
        peak = std::max(peak, std::abs(u));
      testing::log() << "  (peak surface displacement " << std::setprecision(2) << std::fixed
                     << 100 * peak / g.A << " % of the control motion's; error " << 100 * e
                     << " %, " << 100 * e_all << " % and " << 100 * e_none
                     << " % against the closed forms damped in both layers and in none)"
                     << std::defaultfloat << std::setprecision(6) << std::endl;
    }

  // D. The free field through the damped rock.
  const testing::Sin4Pulse long_pulse{0.01, 0.1};
  for (const bool stiffness : {true, false})
    {
      solid::DampingParameters dp;
      dp.mode = solid::DampingMode::coefficients;
      if (stiffness)
        {
          dp.mode            = solid::DampingMode::stiffness_proportional;
          dp.ratio           = 0.05;
          dp.first_frequency = 20.;
        }
      else
        dp.alpha = 5.;
      dp.rock.mode = solid::DampingMode::same_as_dam;
      foundation::FreeFieldDamping deconvolved;
      std::tie(deconvolved.alpha, deconvolved.beta) = dp.rock_coefficients();
      const std::string what = stiffness ? "stiffness proportional (5 % at 20 Hz)" :
                                           "mass proportional (alpha = 5 1/s)";

      // The free field alone against the closed form.
      const auto rock = testing::test_rock();
      {
        std::array<loads::AccelerationRecord, 3> records;
        std::vector<double>                      a;
        const double                             h = dt / 4;
        for (unsigned int k = 0; k * h <= long_pulse.T + h; ++k)
          a.push_back(long_pulse.second(k * h));
        records[0] = loads::uniform_record(a, h);
        const foundation::FreeField ff(records, rock, deconvolved, 0., -H);
        const double          c = foundation::shear_wave_speed(rock), T = ff.delay(0);
        const DampedHalfSpace exact(long_pulse, c, deconvolved);
        double                e = 0.;
        for (const double depth : {0., 100., 200.})
          for (double t = 0.; t < T + H / c + long_pulse.T + 0.05; t += 2e-3)
            {
            e = std::max(e, std::abs(ff.displacement(-depth, t)[0] -
                                     exact.displacement(depth, t - T)) /
                              long_pulse.A);
            }
        testing::log() << "free field through the rock damped " << what
                       << ", against the closed form at the depths 0, 100 and 200 m:" << std::endl;
        testing::check_below("  max |u_ff - closed form| / max g", e, 1e-3);
        testing::log() << "  (" << std::setprecision(1) << std::scientific << e << ")"
                       << std::defaultfloat << std::setprecision(6) << std::endl;
      }

      for (const unsigned int component : {0u, 2u})
        for (const auto boundary : {TransmittingBoundary::mtf, TransmittingBoundary::viscous})
          {
            testing::log() << (component == 0 ? "shear (SV)" : "P-wave") << " column, "
                           << selection_name(boundary, foundation::transmitting_boundary_names())
                           << " boundary, the whole column damped " << what << ":" << std::endl;
            const Result r = run(component, boundary, true, &dp, 0., deconvolved, long_pulse);
            testing::check_below("  free field deconvolved: max |u_surface - g(t - T)| / max g",
                                 r.surface_error, 0.02);
            const Result u = run(component, boundary, true, &dp, 0., {}, long_pulse);
            testing::log() << "  the undamped free field misses by more than 5 %: "
                           << (u.surface_error > 0.05 ? "yes" : "NO") << std::endl
                           << "  (" << std::setprecision(2) << std::fixed << 100 * r.surface_error
                           << " % deconvolved, " << 100 * u.surface_error << " % undamped)"
                           << std::defaultfloat << std::setprecision(6) << std::endl;
          }
    }
}
