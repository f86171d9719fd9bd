// The output of dynamic runs read by a real VTK reader (issue 8, must-show 2):
// Debian's VTK for Python (python3-vtk9, installed by
// scripts/install-dependencies.sh) opens the PVD series the way ParaView
// does, through tests/vtk_output.py: the PVD is parsed as XML, each .pvtu
// record is read by vtkXMLPUnstructuredGridReader (with its .vtu pieces, one
// per MPI process) and each joint .vtu by vtkXMLUnstructuredGridReader. If
// VTK is missing the script says so and the test fails.
//
// 1. Two cantilever blocks side by side (a 2 m x 4 m x 20 m column cut by one
//    vertical joint at y = 2 m, frictional contact), clamped at z = 0, nu = 0,
//    Q2, self-weight in the static stage, then 6 steps of the dynamic stage
//    without ground motion, fields every 2 steps.
//    Expected, independently of the run:
//     - times: the static output at 0, then k x 2 x dt (solution.pvd), and
//       the joint series at 0 (joints_static.pvd) and 0, 2 dt, 4 dt, 6 dt;
//     - counts: deal.II writes each cell of degree p as a patch of p^3
//       subcells and (p + 1)^3 points (no merging across cells), so
//       2 x 2 x 8 = 32 cells per block give 64 x 8 VTK cells and 64 x 27
//       points; the joint series has one point (VTK_VERTEX) per node pair:
//       the Q2 nodes of the joint face, (2 x 2 + 1) x (2 x 8 + 1) = 85, less
//       the 5 on the clamped base, whose both sides are fixed and never move
//       apart: 80;
//     - arrays and components: displacement, velocity, acceleration (3),
//       pressure and its rates (1), stress (9), major and minor principal
//       stress (1), material id and subdomain (1); joint, opening, slip,
//       normal and shear stress, state (1);
//     - values: with nu = 0 each block is a laterally free column, and the
//       joint between them carries nothing (sigma_yy = 0), so both blocks
//       hold the closed form u_z = -(rho g / E)(H z - z^2 / 2),
//       sigma_zz = -rho g (H - z) of tests/gravity_column.cc, which Q2
//       reproduces exactly; without ground motion the dynamic stage starts
//       at rest in this equilibrium and stays there. Checked at every point
//       of every dataset to 1e-6 of the largest displacement and stress
//       (the VTU files hold Float32, 6e-8 relative per value and
//       coordinate; the solution itself is exact to round-off, see
//       tests/gravity_column.cc). The joint's pairs lie on y = 2 m, with no
//       opening, slip or stress.
// 2. The Gmsh example (prm/gmsh_blocks_v4.msh: 3 blocks, rock, 180 water
//    cells) with compressible water, Q1, 4 steps of El Centro: 588 cells and
//    588 x 8 points per dataset, material ids 1, 2, 10-12; the pressure is 0
//    at the static output (the field is the hydrodynamic pressure), nonzero
//    in the water later, exactly 0 on solid points and the displacement
//    exactly 0 on water points (each field lives on its own cells).
// 3. In both runs, the HDF5/XDMF output (written too, default Field formats)
//    against the VTU output of the same run, every array value by value
//    (tests/xdmf_output.py: the XDMF parsed as XML and its arrays read with
//    h5py, as Debian 12's VTK has no XDMF reader): the same points, the same
//    arrays with all their components (the stress tensor's nine), and the same
//    values to 1e-6 of each array's largest magnitude (Float32 in the VTU).

#include <archdam/analysis/simulation.h>
#include <archdam/parameters/parameters.h>

#include <deal.II/base/mpi.h>

#include "archdam_tests.h"
#include "case_text.h"

#include <cstdio>
#include <filesystem>
#include <iomanip>
#include <sstream>
#include <string>

using namespace dealii;
using namespace archdam;
using archdam::testing::log;
namespace case_text = archdam::testing::case_text;

namespace
{
  constexpr double       H = 20., E = 25e9, rho = 2500., g = 9.81, dt = 0.01;
  constexpr unsigned int nx = 2, ny = 4, nz = 8, degree = 2;

  const std::string solution_arrays =
    "displacement:3,velocity:3,acceleration:3,pressure:1,pressure_rate:1,"
    "pressure_acceleration:1,stress:9,major_principal_stress:1,minor_principal_stress:1,"
    "material_id:1,subdomain:1";
  const std::string joint_arrays =
    "joint:1,opening:1,slip:1,normal_stress:1,shear_stress:1,state:1";

  bool all_passed = true;

  /// Run the script tests/@p script with @p arguments on rank 0 and print
  /// what it says. Collective.
  void
  run_script(const std::string &script, const std::string &arguments)
  {
    int status = 0;
    if (Utilities::MPI::this_mpi_process(MPI_COMM_WORLD) == 0)
      {
        const std::string command =
          "/usr/bin/python3 " SOURCE_DIR "/" + script + " " + arguments + " 2>&1";
        FILE *pipe = popen(command.c_str(), "r");
        char  line[1024];
        while (pipe && fgets(line, sizeof line, pipe))
          log() << line;
        status = pipe ? pclose(pipe) : -1;
      }
    status     = Utilities::MPI::broadcast(MPI_COMM_WORLD, status, 0);
    all_passed = all_passed && status == 0;
  }

  /// Read @p pvd with tests/vtk_output.py.
  void
  read_with_vtk(const std::string &pvd, const std::string &arguments)
  {
    run_script("vtk_output.py", pvd + " " + arguments);
  }

  /// The HDF5/XDMF output of the run in @p directory against its VTU output,
  /// array by array (tests/xdmf_output.py).
  void
  compare_xdmf_with_vtu(const std::string &directory)
  {
    log() << "solution.xdmf and its .h5 files against solution.pvd:" << std::endl;
    run_script("xdmf_output.py", directory);
  }

  /// "0,T,2T,...": @p n_outputs times of a series written every @p interval.
  std::string
  times(const unsigned int n_outputs, const double interval)
  {
    std::ostringstream out;
    out << std::setprecision(17) << 0.;
    for (unsigned int k = 1; k < n_outputs; ++k)
      out << "," << k * interval;
    return out.str();
  }

  std::string
  fresh_directory(const std::string &name)
  {
    if (Utilities::MPI::this_mpi_process(MPI_COMM_WORLD) == 0)
      std::filesystem::remove_all(name);
    MPI_Barrier(MPI_COMM_WORLD);
    return name;
  }

  void
  two_columns()
  {
    log() << "--- two cantilever blocks with a frictional joint, self-weight ---" << std::endl;
    const std::string  directory = fresh_directory("vtk_output_columns");
    std::ostringstream prm;
    prm << "subsection Mesh\n  set Source = box\n  subsection Box\n"
        << "    set Length = 2\n    set Width = 4\n    set Height = " << H << "\n"
        << "    set Number of blocks = 2\n    set Cells in x = " << nx << "\n"
        << "    set Cells in y = " << ny << "\n    set Cells in z = " << nz << "\n"
        << "    set Rock depth = 0\n  end\nend\n"
        << "subsection Finite element\n  set Degree = " << degree << "\nend\n"
        << case_text::concrete_under_gravity(E, rho, g)
        << "subsection Contraction joints\n  set Model = frictional contact\n"
        << "  set Friction coefficient = 0.7\nend\n"
        << "subsection Time integration\n  set Time step = " << dt << "\n"
        << "  set End time = " << 6 * dt << "\nend\n"
        << "subsection Analysis\n  set Case name = vtk_output\nend\n"
        << case_text::quiet_output(directory, 2);
    const Parameters   p = parameters_from_string(prm.str());
    std::ostringstream screen;
    analysis::Simulation sim(p, MPI_COMM_WORLD, screen);
    sim.run();

    const unsigned int n_cells = nx * ny * nz;
    const unsigned int cells   = sim.model().space().dof_handler.get_triangulation().n_active_cells();
    log() << "the run's mesh has " << nx << " x " << ny << " x " << nz << " cells: "
          << (cells == n_cells ? "yes" : "NO") << std::endl;
    const unsigned int pairs = (degree * nx + 1) * (degree * nz + 1) - (degree * nx + 1);
    log() << "the run reports " << pairs << " node pairs: "
          << (sim.model().joint_pairs() && sim.model().joint_pairs()->size() == pairs ? "yes" : "NO")
          << std::endl;

    const unsigned int ranks = Utilities::MPI::n_mpi_processes(MPI_COMM_WORLD);
    std::ostringstream column, plane, solution, counts;
    column << std::setprecision(17) << "--column " << H << "," << rho << "," << g << "," << E
           << "," << dt;
    plane << std::setprecision(17) << "--joint-plane 2," << rho << "," << g << "," << H;
    solution << " --cells " << n_cells * degree * degree * degree << " --points "
             << n_cells * (degree + 1) * (degree + 1) * (degree + 1) << " --pieces " << ranks
             << " --arrays " << solution_arrays << " --materials 10,11 ";
    read_with_vtk(directory + "/solution.pvd",
                  solution.str() + "--times " + times(4, 2 * dt) + " " + column.str());
    const std::string joints = " --cells " + std::to_string(pairs) + " --points " +
                               std::to_string(pairs) + " --pieces 1 --arrays " + joint_arrays +
                               " " + plane.str();
    read_with_vtk(directory + "/joints_static.pvd", joints + " --times 0");
    read_with_vtk(directory + "/joints_dynamic.pvd", joints + " --times " + times(4, 2 * dt));
    compare_xdmf_with_vtu(directory);
  }

  void
  water()
  {
    log() << "--- Gmsh example with compressible water, El Centro ---" << std::endl;
    const std::string directory = fresh_directory("vtk_output_water");
    const std::string prm       = case_text::gmsh_example_mesh() + case_text::linear_elements +
                            case_text::compressible_reservoir() +
                            case_text::time_integration(0.01, 0.04) + case_text::el_centro_x() +
                            "\nsubsection Analysis\n  set Case name = vtk_output_water\nend\n" +
                            case_text::quiet_output("vtk_output_water", 2);
    const Parameters   p = parameters_from_string(prm);
    std::ostringstream screen;
    analysis::Simulation sim(p, MPI_COMM_WORLD, screen);
    sim.run();
    const unsigned int cells = sim.model().space().dof_handler.get_triangulation().n_active_cells();
    log() << "the run's mesh has the 588 hexahedra of the .msh file: "
          << (cells == 588 ? "yes" : "NO") << std::endl;
    std::ostringstream arguments;
    arguments << "--cells 588 --points " << 588 * 8 << " --pieces "
              << Utilities::MPI::n_mpi_processes(MPI_COMM_WORLD) << " --arrays "
              << solution_arrays << " --materials 1,2,10,11,12 --water --times "
              << times(3, 0.02);
    read_with_vtk(directory + "/solution.pvd", arguments.str());
    compare_xdmf_with_vtu(directory);
  }
} // namespace

int
main(int argc, char **argv)
{
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  try
    {
      two_columns();
      water();
    }
  catch (const std::exception &e)
    {
      log() << "error: " << e.what() << std::endl;
      return 1;
    }
  return all_passed ? 0 : 1;
}
