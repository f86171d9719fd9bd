// Benchmark: per-step cost of the foundation's transmitting boundary
// (doc/theory/foundation.md §5-§8) against the plain step with a fixed boundary, in ONE
// process run on a rock box with free top and MTF (or viscous) bottom and
// sides.
//
//   bench_foundation_boundary [cells per side, default 12] [steps, default 40]
//
// Printed: DOFs and boundary DOFs; per step the boundary update alone (MTF:
// the prescribed values from the stored history, and the interpolation of
// the new state at the stencil points; viscous: the free-field forces), the
// whole step with the MTF, with the viscous boundary and with the fixed
// boundary (massless-style homogeneous constraints), alternating rounds.

#include <archdam/geometry/ids.h>
#include <archdam/physics/foundation/massed_foundation.h>

#include <deal.II/base/mpi.h>
#include <deal.II/base/timer.h>
#include <deal.II/distributed/shared_tria.h>
#include <deal.II/grid/grid_generator.h>

#include <iomanip>
#include <iostream>

using namespace dealii;
using namespace archdam;
using namespace archdam::physics;

namespace
{
  struct Run
  {
    double step = 0., update = 0.;
    unsigned int dofs = 0, boundary = 0;
  };

  /// One line of the output: the boundary, and whether the step updates it
  /// ("none": the fixed boundary, plain steps).
  struct Variant
  {
    const char                      *label;
    foundation::TransmittingBoundary boundary;
    bool                             update;
  };

  Run
  run(const unsigned int n, const unsigned int steps, const Variant &variant)
  {
    foundation::FoundationParameters fp;
    fp.model                 = foundation::Model::massed;
    fp.transmitting_boundary = variant.boundary;
    solid::MaterialParameters materials;
    parallel::shared::Triangulation<3> tria(MPI_COMM_WORLD);
    const double L = 10. * n;
    GridGenerator::subdivided_hyper_rectangle(tria, {n, n, n}, Point<3>(0, 0, -L), Point<3>(L, L, 0));
    for (const auto &cell : tria.active_cell_iterators())
      {
        cell->set_material_id(ids::rock);
        for (const auto f : cell->face_indices())
          if (cell->face(f)->at_boundary())
            {
              const double z = cell->face(f)->center()[2];
              cell->face(f)->set_boundary_id(std::abs(z + L) < 1e-6 ? ids::foundation_bottom :
                                             std::abs(z) < 1e-6     ? ids::free_surface_solid :
                                                                      ids::foundation_sides);
            }
      }
    fe::FiniteElementParameters fep;
    fe::FESpace                 space(tria, fep);
    space.setup(fp.fixed_boundaries());
    archdam::SparseMatrix M, K;
    solid::assemble_mass_and_stiffness(space, materials, solid::InertiaOf::dam_and_rock, M, K);
    const double dt = 2e-3;
    std::array<foundation::ControlMotion, 3> control;
    std::vector<double>                      a;
    for (unsigned int k = 0; k < 200; ++k)
      a.push_back(std::sin(0.1 * k));
    control[0] = foundation::ControlMotion(loads::uniform_record(a, dt));
    const foundation::FreeField  ff(control, materials.rock, 0., -L);
    const auto foundation_boundary = foundation::make_massed_foundation(fp, space, materials, solid::InertiaOf::dam_and_rock, ff,
                                        dt);
    auto &massed = *foundation_boundary;
    massed.add_springs(K);
    time::NewmarkParameters tp;
    tp.time_step = dt;
    time::NewmarkIntegrator newmark(tp, M, K, {0., 0.}, space.constraints, massed.dashpots());
    time::NewmarkState s;
    archdam::Vector    load;
    for (archdam::Vector *v : {&s.u, &s.v, &s.a, &load})
      space.reinit(*v);
    massed.start(s.u);
    Run r;
    r.dofs     = space.dof_handler.n_dofs();
    r.boundary = massed.prescribed_dofs() ? massed.prescribed_dofs()->dofs.size() : 0;
    Timer timer;
    for (unsigned int k = 0; k < steps; ++k)
      if (variant.update)
        massed.advance(newmark, load, s);
      else
        newmark.advance(load, s);
    r.step   = timer.wall_time() / steps;
    r.update = massed.boundary_update_time() / steps;
    return r;
  }
} // namespace

int
main(int argc, char **argv)
{
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  const unsigned int n     = argc > 1 ? std::stoi(argv[1]) : 12;
  const unsigned int steps = argc > 2 ? std::stoi(argv[2]) : 40;
  using foundation::TransmittingBoundary;
  const Variant mtf{"MTF", TransmittingBoundary::mtf, true},
    viscous{"viscous", TransmittingBoundary::viscous, true},
    none{"none", TransmittingBoundary::fixed, false};
  for (const Variant &v : {mtf, viscous, none, mtf, viscous, none})
    {
      const Run r = run(n, steps, v);
      if (Utilities::MPI::this_mpi_process(MPI_COMM_WORLD) == 0)
        std::cout << std::left << std::setw(8) << v.label << " step [s] " << std::setw(10)
                  << std::setprecision(4) << r.step << " boundary update [s] " << std::setw(10)
                  << r.update << " (" << std::setprecision(2) << 100 * r.update / r.step
                  << " % of the step), DOFs " << r.dofs << ", MTF boundary DOFs " << r.boundary
                  << std::endl;
    }
}
