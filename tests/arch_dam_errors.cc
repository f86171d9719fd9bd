// Arch dam parameters that describe no valid dam or model give one clear
// InputError message (main() prints it and exits with code 1). Each case is a
// plausible user mistake; the test prints the message as the user sees it and
// checks that an InputError (not another exception) was thrown, and that the
// reference dam itself is accepted. It also lists the parameter names of
// `Mesh/Arch dam` (names of released parameters must not change) and reads a
// bad value from prm text, as a case file would give it.

#include <archdam/base/input_error.h>
#include <archdam/geometry/arch_dam_mesh.h>

#include <deal.II/base/parameter_handler.h>
#include <deal.II/grid/tria.h>

#include "archdam_tests.h"

#include <functional>

using namespace dealii;
using namespace archdam;
using archdam::testing::log;

namespace
{
  void
  expect_error(const std::string &what, const std::function<void(geometry::ArchDamParameters &)> &change)
  {
    testing::check_input_error(what, [&] {
      geometry::ArchDamParameters p;
      change(p);
      Triangulation<3> tria;
      geometry::generate_arch_dam(p, tria);
    });
  }
} // namespace

int
main(int argc, char **argv)
{
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);

  {
    geometry::ArchDamParameters p;
    p.cells_over_height = 4;
    Triangulation<3> tria;
    geometry::generate_arch_dam(p, tria);
    log() << "* the reference dam (4 layers): accepted, " << tria.n_active_cells() << " cells"
          << std::endl;
  }
  {
    geometry::ArchDamParameters p;
    ParameterHandler            prm;
    prm.enter_subsection("Mesh");
    prm.enter_subsection("Arch dam");
    p.add_parameters(prm);
    prm.leave_subsection();
    prm.leave_subsection();
    std::ostringstream names;
    prm.print_parameters(names, ParameterHandler::ShortPRM);
    log() << "* Mesh/Arch dam parameters and defaults:\n" << names.str();
    prm.parse_input_from_string("subsection Mesh\n  subsection Arch dam\n"
                                "    set Water level = 250\n  end\nend\n");
    Triangulation<3> tria;
    try
      {
        geometry::generate_arch_dam(p, tria);
        log() << "* Water level = 250 from prm text\n  accepted: NO" << std::endl;
      }
    catch (const InputError &e)
      {
        log() << "* Water level = 250 from prm text\n  InputError: yes\n  " << e.what()
              << std::endl;
      }
  }
  expect_error("canyon wider than the base arch (Canyon width at base = 170 m, radius 80 m)",
               [](auto &p) { p.canyon_width_base = 170; });
  expect_error("crest arch of 202 degrees (Crest length = 600 m, radius 170 m)",
               [](auto &p) { p.crest_length = 600; });
  expect_error("water above the crest (Water level = 250 m)", [](auto &p) { p.water_level = 250; });
  expect_error("foundation too short downstream (Foundation extent downstream = 0.05)",
               [](auto &p) { p.foundation_downstream = 0.05; });
  expect_error("abutments too thick for the base arch (Abutment thickening at base = 3.5)",
               [](auto &p) { p.abutment_thickening_base = 3.5; });
  expect_error("one layer cannot hold the water level (Cells over height = 1)",
               [](auto &p) { p.cells_over_height = 1; });
  expect_error("a low water level needs more layers (Water level = 40 m, Cells over height = 4)",
               [](auto &p) {
                 p.water_level       = 40;
                 p.cells_over_height = 4;
               });
  expect_error("reservoir shorter than the dam's overhang (Reservoir length = 0.05)",
               [](auto &p) { p.reservoir_length = 0.05; });
  expect_error("no blocks (Number of blocks = 0)", [](auto &p) { p.n_blocks = 0; });
}
