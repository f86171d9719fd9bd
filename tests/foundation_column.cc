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

#include <archdam/physics/foundation/massed_foundation.h>

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
  };

  Result
  run(const unsigned int component, const TransmittingBoundary boundary, const bool seismic)
  {
    foundation::FoundationParameters fp;
    fp.model                 = foundation::Model::massed;
    fp.transmitting_boundary = boundary;
    solid::MaterialParameters materials;
    materials.rock = testing::test_rock();
    const double c = component == 2 ? foundation::pressure_wave_speed(materials.rock) :
                                      foundation::shear_wave_speed(materials.rock);

    parallel::shared::Triangulation<3> tria(MPI_COMM_WORLD);
    testing::rock_box(tria, Point<3>(0, 0, -H), Point<3>(w, w, 0), {1, 1, 40}, 0);
    fe::FiniteElementParameters fep;
    fe::FESpace                 space(tria, fep);
    space.setup(fp.fixed_boundaries(),
                [&](AffineConstraints<double> &cons) { testing::tie_column(space, cons); });

    archdam::SparseMatrix M, K;
    solid::assemble_mass_and_stiffness(space, materials, solid::InertiaOf::dam_and_rock, M, K);

    std::array<foundation::ControlMotion, 3> control;
    if (seismic)
      {
        std::vector<double> a;
        const double        h = dt / 4;
        for (unsigned int k = 0; k * h <= g.T + h; ++k)
          a.push_back(g.second(k * h));
        control[component] = foundation::ControlMotion(loads::uniform_record(a, h));
      }
    const foundation::FreeField free_field(control, materials.rock, 0., -H);
    const auto foundation_boundary = foundation::make_massed_foundation(fp, space, materials, solid::InertiaOf::dam_and_rock,
                                        free_field, dt);
    auto &massed = *foundation_boundary;
    massed.add_springs(K);
    time::NewmarkParameters tp;
    tp.time_step = dt;
    time::NewmarkIntegrator newmark(tp, M, K, {0., 0.}, space.constraints, massed.dashpots());

    time::NewmarkState s;
    for (archdam::Vector *v : {&s.u, &s.v, &s.a})
      space.reinit(*v);
    massed.start(s.u); // reference state: at rest, undeformed
    if (!seismic)
      {
        // downgoing pulse centred at mid-depth
        const double z0 = -H / 2 - c * g.T / 2;
        for (const auto &[i, pc] : testing::dof_positions(space))
          if (pc.second == component && space.locally_owned.is_element(i))
            {
              const double tau = (pc.first[2] - z0) / c;
              s.u(i)           = g.value(tau);
              s.v(i)           = g.first(tau);
              s.a(i)           = g.second(tau);
            }
        for (archdam::Vector *v : {&s.u, &s.v, &s.a})
          v->compress(VectorOperation::insert);
      }

    // the surface DOF of this component (the master of the top plane)
    types::global_dof_index top = numbers::invalid_dof_index;
    for (const auto &[i, pc] : testing::dof_positions(space))
      if (pc.second == component && std::abs(pc.first[2]) < 1e-6 && top == numbers::invalid_dof_index)
        top = i;

    const double       end     = seismic ? 2 * H / c + 2 * g.T + 0.15 : 0.2;
    const unsigned int n_steps = std::lround(end / dt);
    archdam::Vector             load;
    space.reinit(load);
    double E0 = testing::elastic_energy(M, K, space.constraints, s), E_max = E0;
    Result r;
    for (unsigned int n = 1; n <= n_steps; ++n)
      {
        massed.advance(newmark, load, s);
        const double E = testing::elastic_energy(M, K, space.constraints, s);
        E_max          = std::max(E_max, E);
        if (seismic)
          {
            const double u_top = Utilities::MPI::sum(
              space.locally_owned.is_element(top) ? double(s.u(top)) : 0., MPI_COMM_WORLD);
            r.surface_error =
              std::max(r.surface_error, std::abs(u_top - g.value(s.time - H / c)) / g.A);
          }
        if (n == n_steps)
          r.reflected = E / E_max;
      }
    return r;
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
}
