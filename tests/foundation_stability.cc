// Long-run stability of the multi-transmitting boundary (doc/verification.md,
// "Foundation radiation": 20 000 steps with MTF and no input show no drift and
// no growth; doc/theory/foundation.md §6: drift removed by the stabilized form, high
// frequencies kept down by c_a dt / h <= 1).
//
// A 30 x 30 x 30 m rock box (2 x 2 x 2 Q2 cells, nodes 7.5 m apart, free top,
// MTF of order 2 on the bottom and the four sides, default c_a and
// stabilization rate: gamma = 2 /s x 2 ms = 0.004),
// dt = 2 ms (c_p dt / h = 0.46), no damping, no numerical dissipation (average
// acceleration): nothing but the boundary removes energy, so any instability
// of the boundary shows as growth.
// 1. No input: released from a small irregular displacement field (every
//    frequency the mesh carries), 20 000 steps.
// 2. After a pulse: a vertical surface load pulse of 0.05 s at the top centre,
//    then 20 000 steps in all.
// Reported: the largest |u_i| over the first 1000 steps and over the last
// 1000, and the largest |u_i| at the end relative to the peak; no growth
// means the late maximum is below the early one, no drift means the motion
// has decayed (below 1 % of the early maximum at the end).

#include <archdam/physics/foundation/massed_foundation.h>

#include "foundation_tests.h"

using namespace dealii;
using namespace archdam;
using namespace archdam::physics;

namespace
{
  const double       dt      = 2e-3;
  const unsigned int n_steps = 20000;

  void
  run(const bool pulse)
  {
    foundation::FoundationParameters fp;
    fp.model = foundation::Model::massed;
    solid::MaterialParameters materials;
    materials.rock = testing::test_rock();

    parallel::shared::Triangulation<3> tria(MPI_COMM_WORLD);
    testing::rock_box(tria, Point<3>(-15, -15, -30), Point<3>(15, 15, 0), {2, 2, 2},
                      ids::foundation_sides);
    fe::FiniteElementParameters fep;
    fe::FESpace                 space(tria, fep);
    space.setup(fp.fixed_boundaries());
    archdam::SparseMatrix M, K;
    solid::assemble_mass_and_stiffness(space, materials, solid::InertiaOf::dam_and_rock, M, K);
    const foundation::FreeField  free_field({}, materials.rock, 0., -30.);
    const auto foundation_boundary = foundation::make_massed_foundation(fp, space, materials, solid::InertiaOf::dam_and_rock,
                                        free_field, dt);
    auto &massed = *foundation_boundary;
    time::NewmarkParameters tp;
    tp.time_step = dt;
    time::NewmarkIntegrator newmark(tp, M, K, {0., 0.}, space.constraints, massed.dashpots());

    time::NewmarkState s;
    archdam::Vector             load;
    for (archdam::Vector *v : {&s.u, &s.v, &s.a, &load})
      space.reinit(*v);
    massed.start(s.u);

    types::global_dof_index top = 0;
    for (const auto &[i, pc] : testing::dof_positions(space))
      {
        if (pc.first.distance(Point<3>()) < 1e-6 && pc.second == 2)
          top = i;
        // irregular field of amplitude 1 mm on the free DOFs
        if (!pulse && space.locally_owned.is_element(i) && !space.constraints.is_constrained(i))
          s.u(i) = 1e-3 * std::sin(12.9898 * pc.first[0] + 78.233 * pc.first[1] +
                                     37.719 * pc.first[2] + 4.1 * pc.second);
      }
    s.u.compress(VectorOperation::insert);

    double early = 0., late = 0.;
    for (unsigned int n = 1; n <= n_steps; ++n)
      {
        load = 0.;
        if (pulse && space.locally_owned.is_element(top))
          load(top) = n * dt < 0.05 ? -1e6 * std::pow(std::sin(M_PI * n * dt / 0.05), 2) : 0.;
        load.compress(VectorOperation::insert);
        massed.advance(newmark, load, s);
        const double u = s.u.linfty_norm();
        if (n <= 1000)
          early = std::max(early, u);
        if (n > n_steps - 1000)
          late = std::max(late, u);
        AssertThrow(std::isfinite(u), ExcMessage("the motion is not finite"));
      }
    const double final_u = s.u.linfty_norm();
    testing::log() << (pulse ? "after a surface pulse" : "no input, irregular initial field")
                   << ", " << n_steps << " steps (" << std::setprecision(3) << n_steps * dt
                   << " s):" << std::endl
                   << "  max |u_i| over the first 1000 steps: " << std::setprecision(2)
                   << std::scientific << early << " m" << std::defaultfloat << std::setprecision(6) << std::endl;
    testing::check_below("  no growth: max |u_i| over the last 1000 steps / first", late / early,
                         1.);
    testing::check_below("  no drift: max |u_i| at the end / first", final_u / early, 0.01);
    // the motion has left through the boundary, not merely stopped growing
    testing::check_below("  decayed: max |u_i| over the last 1000 steps / first", late / early,
                         1e-6);
  }
} // namespace

int
main(int argc, char **argv)
{
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  run(false);
  run(true);
}
