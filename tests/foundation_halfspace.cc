// A vertical surface load pulse on a 3-D half-space (doc/verification.md,
// "Foundation radiation"): the receiver response of a small rock box with a
// transmitting boundary must match that of a much larger box until the
// reflection from the larger box's boundary reaches the receiver.
//
// Quarter model (planes of symmetry x = 0 and y = 0), a load with no net
// impulse, P(t) = P0 sin(2 pi t / T) sin^2(pi t / T) for t < T = 0.06 s, at the
// origin, receiver on the surface at (20, 0, 0) m, rock c_s = 1000 m/s,
// c_p = 1732 m/s, Q2 cells of 10 m, dt = 2 ms.
// - small box 60 x 60 x 60 m: a wave reflected by its side x = 60 m reaches
//   the receiver after (60 + 40)/c_p = 0.058 s, inside the window;
// - reference box 120 x 120 x 120 m, fixed boundary: its earliest reflection
//   (side x = 120 m, path 220 m) arrives at 220/c_p = 0.127 s; the window is
//   t < 0.125 s. Same mesh size, time step and element: the two differ only
//   by what the boundary sends back.
// Tolerances on the largest difference over the window, relative to the peak
// receiver displacement: 10 % for the MTF and 15 % for the viscous boundary.
// Both are exact only for plane waves at normal incidence; here the waves
// reach the sides obliquely, partly as Rayleigh waves, and the boundary is
// only one to two shear wavelengths from the load (c_s T = 60 m), where a
// local boundary is known to reflect some per cent (dashpots more than an
// MTF of order 2 at oblique incidence). The fixed boundary of the small box
// must miss by more than 20 %, which shows that the comparison can fail.

#include <archdam/physics/foundation/massed_foundation.h>

#include "foundation_tests.h"

using namespace dealii;
using namespace archdam;
using namespace archdam::physics;

namespace
{
  using foundation::TransmittingBoundary;

  const double dt = 2e-3, T = 0.06, window = 0.125;

  /// u_x and u_z at the receiver at every step of the window.
  std::vector<std::array<double, 2>>
  receiver_history(const double size, const TransmittingBoundary boundary)
  {
    foundation::FoundationParameters fp;
    fp.model                 = foundation::Model::massed;
    fp.transmitting_boundary = boundary;
    solid::MaterialParameters materials;
    materials.rock = testing::test_rock();

    parallel::shared::Triangulation<3> tria(MPI_COMM_WORLD);
    const unsigned int                 n = std::lround(size / 10);
    testing::rock_box(tria, Point<3>(0, 0, -size), Point<3>(size, size, 0), {n, n, n},
                      ids::foundation_sides, true);
    fe::FiniteElementParameters fep;
    fe::FESpace                 space(tria, fep);
    space.setup(fp.fixed_boundaries(),
                [&](AffineConstraints<double> &c) { testing::constrain_symmetry(space, c); });
    archdam::SparseMatrix M, K;
    solid::assemble_mass_and_stiffness(space, materials, solid::InertiaOf::dam_and_rock, M, K);

    const foundation::FreeField free_field({}, materials.rock, 0., -size);
    const auto foundation_boundary = foundation::make_massed_foundation(fp, space, materials, solid::InertiaOf::dam_and_rock,
                                        free_field, dt);
    auto &massed = *foundation_boundary;
    massed.add_springs(K);
    time::NewmarkParameters tp;
    tp.time_step = dt;
    time::NewmarkIntegrator newmark(tp, M, K, {0., 0.}, space.constraints, massed.dashpots());

    types::global_dof_index load_dof = 0;
    std::array<types::global_dof_index, 2> receiver{};
    for (const auto &[i, pc] : testing::dof_positions(space))
      {
        if (pc.first.distance(Point<3>()) < 1e-6 && pc.second == 2)
          load_dof = i;
        if (pc.first.distance(Point<3>(20, 0, 0)) < 1e-6 && (pc.second == 0 || pc.second == 2))
          receiver[pc.second / 2] = i;
      }

    time::NewmarkState s;
    archdam::Vector             load;
    for (archdam::Vector *v : {&s.u, &s.v, &s.a, &load})
      space.reinit(*v);
    massed.start(s.u);
    std::vector<std::array<double, 2>> history;
    const double P0 = -1e6 / 4; // quarter of a 1 MN downward load
    for (unsigned int k = 1; k * dt < window; ++k)
      {
        const double t = k * dt;
        load           = 0.;
        if (space.locally_owned.is_element(load_dof))
          load(load_dof) =
            t < T ? P0 * std::sin(2 * M_PI * t / T) * std::pow(std::sin(M_PI * t / T), 2) : 0.;
        load.compress(VectorOperation::insert);
        massed.advance(newmark, load, s);
        std::array<double, 2> r;
        for (unsigned int c = 0; c < 2; ++c)
          r[c] = Utilities::MPI::sum(space.locally_owned.is_element(receiver[c]) ?
                                       double(s.u(receiver[c])) :
                                       0.,
                                     MPI_COMM_WORLD);
        history.push_back(r);
      }
    return history;
  }
} // namespace

int
main(int argc, char **argv)
{
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  const auto reference = receiver_history(120, TransmittingBoundary::fixed);
  std::array<double, 2> peak{};
  for (const auto &r : reference)
    for (unsigned int c = 0; c < 2; ++c)
      peak[c] = std::max(peak[c], std::abs(r[c]));

  for (const auto boundary :
       {TransmittingBoundary::mtf, TransmittingBoundary::viscous, TransmittingBoundary::fixed})
    {
      const bool fixed = boundary == TransmittingBoundary::fixed;
      const auto small = receiver_history(60, boundary);
      testing::log() << "60 m box, "
                     << selection_name(boundary, foundation::transmitting_boundary_names())
                     << " boundary, against the 120 m box:" << std::endl;
      for (unsigned int c = 0; c < 2; ++c)
        {
          double error = 0.;
          for (unsigned int k = 0; k < small.size(); ++k)
            error = std::max(error, std::abs(small[k][c] - reference[k][c]) / peak[c]);
          const std::string what = std::string("  receiver u_") + "xz"[c] +
                                   ": max difference / peak" +
                                   (fixed ? " above 0.2: " : "");
          if (fixed)
            testing::log() << what << (error > 0.2 ? "yes" : "NO") << std::endl;
          else
            testing::check_below(what, error,
                                 boundary == TransmittingBoundary::mtf ? 0.10 : 0.15);
          testing::log() << "    (" << std::setprecision(0) << std::fixed << 100 * error
                         << " %)" << std::defaultfloat << std::setprecision(6) << std::endl;
        }
    }
}
