// Reservoir input that describes no valid model gives one clear InputError
// (main() prints it and exits with code 1): the test prints each message as
// the user sees it and checks that it is an InputError, not another
// exception or a silently wrong result.

#include <archdam/analysis/simulation.h>
#include <archdam/parameters/parameters.h>
#include <archdam/physics/reservoir/fluid_operators.h>

#include <deal.II/grid/grid_tools.h>

#include "archdam_tests.h"
#include "reservoir_reference.h"

using namespace archdam;
using namespace archdam::testing;
namespace reservoir = archdam::physics::reservoir;

int
main(int argc, char **argv)
{
  dealii::Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  std::ostringstream                       quiet;

  check_input_error("compressible water with a sound speed of 0", [] {
    parameters_from_string("subsection Reservoir\n set Model = compressible\n"
                           " set Sound speed = 0\nend\n");
  });
  check_input_error("Westergaard added mass with a water density of 0", [] {
    parameters_from_string("subsection Reservoir\n set Model = westergaard\n"
                           " set Water density = 0\nend\n");
  });
  check_input_error("compressible water on the box mesh, which has no reservoir", [&] {
    const Parameters p = parameters_from_string("subsection Reservoir\n set Model = "
                                                "compressible\nend\n");
    analysis::Simulation sim(p, MPI_COMM_WORLD, quiet);
    sim.setup_model();
  });

  const Channel ch;
  check_input_error("a water level other than the top of the water cells, compressible water", [&] {
    dealii::parallel::shared::Triangulation<dim> tria(MPI_COMM_WORLD);
    make_channel(ch, 3, 2, 0, tria);
    reservoir::ReservoirParameters rp;
    rp.model           = reservoir::Model::compressible;
    rp.level_from_mesh = false;
    rp.water_level     = 40.;
    reservoir::water_level(rp, tria);
  });
  // Westergaard's added mass on the channel's dam, 50 m high from z = 0.
  for (const double level : {400., -5.})
    check_input_error("Westergaard added mass with a water level of " + std::to_string(int(level)) +
                        " m on a dam from z = 0 to 50 m",
                      [&] {
                        dealii::parallel::shared::Triangulation<dim> tria(MPI_COMM_WORLD);
                        make_channel(ch, 3, 2, 0, tria);
                        reservoir::ReservoirParameters rp;
                        rp.model           = reservoir::Model::westergaard;
                        rp.level_from_mesh = false;
                        rp.water_level     = level;
                        reservoir::water_level(rp, tria);
                      });
  check_input_error("water and dam faces that do not meet face to face", [&] {
    dealii::parallel::shared::Triangulation<dim> tria(MPI_COMM_WORLD);
    make_channel(ch, 3, 2, 0, tria);
    // lift the dam by a quarter of a water cell: its wetted faces now
    // straddle two water faces
    std::vector<bool> moved(tria.n_vertices(), false);
    for (const auto &cell : tria.active_cell_iterators())
      if (cell->material_id() != ids::water)
        for (const unsigned int v : cell->vertex_indices())
          if (!moved[cell->vertex_index(v)])
            {
              cell->vertex(v)[2] += ch.H / 8;
              moved[cell->vertex_index(v)] = true;
            }
    fe::FESpace space(tria, fe::FiniteElementParameters{});
    space.setup({});
    reservoir::match_interface_faces(space);
  });
}
