// Radiated energy in the energy balance (analysis/energy_balance.h;
// doc/verification.md, "Energy balance" and "Foundation radiation"): the shear
// (SV) column of foundation_column (200 m of rock, Q2 cells of 5 m tied
// plane by plane, so u = u(z, t)) on a massed foundation, total motion,
// seismic input as a vertically propagating wave whose surface motion is the
// pulse g(t) = 0.01 m sin^4(pi t / 0.06 s).
//
// Reference (closed form, plane waves): the incident wave u_in = g / 2 below
// the surface carries the energy flux rho c A v_in^2 through the column's
// section A. At the viscous boundary the free-field forces are the
// incident wave's traction plus its dashpot force, 2 rho c A v_in, while the
// incident pulse passes the bottom, and zero while the reflected one leaves
// (its traction and dashpot force cancel); the model's bottom moves with
// v_in, then with the reflected v_r of the same energy. So over the run
//   input = radiated = 2 rho c A int v_in^2 dt = (rho c A / 2) int g'^2 dt
// (the pulse is shorter than the travel time: incident and reflected pulses
// do not overlap at the bottom). Tolerance 5 %: the surface motion of this
// mesh and step is within 5 % of the free field (foundation_column).
// The balance input = kinetic + strain + radiated closes to round-off
// (1e-10): the viscous boundary is a damping like any other.
// With the MTF the boundary is a prescribed motion, and its work is the net
// input (input minus radiated): the balance closes to round-off as well; at
// t = 0.15 s, when the whole incident pulse is inside the column (it enters
// by 0.06 s and reaches the surface after H/c = 0.2 s), the column holds the
// incident energy rho c A int v_in^2 dt (the half of the viscous input above,
// 5 %), and once the pulse has left through the bottom the net work must be
// below 2 % of it (foundation_column's reflection bound). The kinetic and
// strain energies are the whole column's, the boundary nodes included (full
// operators from the prescribed columns): the work of the reactions on the
// boundary is what crosses it.

#include <archdam/analysis/energy_balance.h>
#include <archdam/physics/foundation/massed_foundation.h>

#include "foundation_tests.h"

using namespace dealii;
using namespace archdam;
using namespace archdam::physics;

namespace
{
  const double H = 200., w = 5., dt = 1e-3;
  const testing::Sin4Pulse g{0.01, 0.06};

  struct Result
  {
    analysis::EnergyTerms end;
    double                inside = 0.; ///< kinetic + strain at t = 0.15 s
  };

  Result
  run(const foundation::TransmittingBoundary boundary)
  {
    foundation::FoundationParameters fp;
    fp.model                 = foundation::Model::massed;
    fp.transmitting_boundary = boundary;
    solid::MaterialParameters materials;
    materials.rock = testing::test_rock();
    const double c = foundation::shear_wave_speed(materials.rock);

    parallel::shared::Triangulation<3> tria(MPI_COMM_WORLD);
    testing::rock_box(tria, Point<3>(0, 0, -H), Point<3>(w, w, 0), {1, 1, 40}, 0);
    fe::FiniteElementParameters fep;
    fe::FESpace                 space(tria, fep);
    space.setup(fp.fixed_boundaries(),
                [&](AffineConstraints<double> &cons) { testing::tie_column(space, cons); });
    archdam::SparseMatrix M, K;
    solid::assemble_mass_and_stiffness(space, materials, solid::InertiaOf::dam_and_rock, M, K);

    std::array<foundation::ControlMotion, 3> control;
    std::vector<double>                      a;
    const double                             h = dt / 4;
    for (unsigned int k = 0; k * h <= g.T + h; ++k)
      a.push_back(g.second(k * h));
    control[0] = foundation::ControlMotion(loads::uniform_record(a, h));
    const foundation::FreeField free_field(control, materials.rock, 0., -H);
    const auto foundation_boundary = foundation::make_massed_foundation(fp, space, materials, solid::InertiaOf::dam_and_rock,
                                        free_field, dt);
    auto &massed = *foundation_boundary;
    massed.add_springs(K);
    time::NewmarkParameters tp;
    tp.time_step = dt;
    time::NewmarkIntegrator newmark(tp, M, K, {0., 0.}, space.constraints, massed.dashpots());

    analysis::EnergyBalance::Model em;
    em.space      = &space;
    em.mass       = &M;
    em.stiffness  = &K;
    em.newmark    = tp;
    em.viscous    = massed.viscous_boundary();
    em.prescribed = massed.prescribed_dofs();
    analysis::EnergyBalance balance(em);

    time::NewmarkState s;
    archdam::Vector    load;
    for (archdam::Vector *v : {&s.u, &s.v, &s.a, &load})
      space.reinit(*v);
    massed.start(s.u);
    balance.start(s, nullptr);
    Result             r;
    const unsigned int n_steps = std::lround((2 * H / c + 2 * g.T + 0.15) / dt);
    for (unsigned int n = 1; n <= n_steps; ++n)
      {
        massed.advance(newmark, load, s);
        balance.add_step(s, Tensor<1, dim>(), nullptr);
        const auto e     = balance.terms();
        if (n == std::lround(0.15 / dt)) // the pulse is inside, away from both ends
          r.inside = e.kinetic + e.strain;
      }
    r.end = balance.terms();
    return r;
  }
} // namespace

int
main(int argc, char **argv)
{
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  const auto   rock = testing::test_rock();
  const double c    = foundation::shear_wave_speed(rock);
  // int g'^2 dt by the midpoint rule on 1e5 intervals (exact to ~1e-10)
  double       integral = 0.;
  const unsigned int n  = 100000;
  for (unsigned int k = 0; k < n; ++k)
    integral += std::pow(g.first((k + 0.5) * g.T / n), 2) * g.T / n;
  const double incident = rock.density * c * w * w / 2 * integral;

  auto &log = testing::log();
  log << "SV column, seismic input through the viscous boundary:" << std::endl;
  const Result viscous = run(foundation::TransmittingBoundary::viscous);
  testing::check_relative("  input work [J] (plane waves)", viscous.end.input, incident, 0.05);
  testing::check_relative("  radiated energy [J] (plane waves)", viscous.end.radiated, incident,
                          0.05);
  testing::check_below("  balance error", viscous.end.balance_error(), 1e-10);
  auto without = viscous.end;
  without.radiated = 0.;
  log << "  balance without the radiated energy open by more than 50 %: "
      << (without.balance_error() > 0.5 ? "yes" : "NO") << std::endl;

  log << "SV column, seismic input through the MTF:" << std::endl;
  const Result mtf = run(foundation::TransmittingBoundary::mtf);
  testing::check_below("  balance error", mtf.end.balance_error(), 1e-10);
  testing::check_relative("  energy in the column at t = 0.15 s [J] (incident energy)",
                          mtf.inside, incident / 2, 0.05);
  testing::check_below("  net boundary work after the pulse / incident energy",
                       std::abs(mtf.end.input) / (incident / 2), 0.02);
  if (std::getenv("ENERGY_BALANCE_NUMBERS")) // the terms, for the verification report
    std::cerr << "viscous: input " << viscous.end.input << " radiated " << viscous.end.radiated
            << " ref " << incident << " err " << viscous.end.balance_error()
            << " | MTF: net " << mtf.end.input << " inside " << mtf.inside << " err "
            << mtf.end.balance_error() << std::endl;
}
