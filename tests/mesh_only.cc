// `archdam CASE.prm --mesh-only` on the Gmsh example (issue 3): exit code 0,
// the report on screen, and in Output/Directory mesh.vtu, mesh_boundary.vtu
// and summary.json, which parse and hold what the .msh file holds. Run
// serially and under mpirun -np 2 (rank 0 writes; same output).
//
// References, counted here from the .msh file's element block (independent of
// deal.II) or from the .geo numbers (gmsh_example.h):
//  - cells of mesh.vtu and their material ids: the hexahedra of the .msh file
//    with their physical tags;
//  - faces of mesh_boundary.vtu per boundary id: ids 1-5 as many as the
//    quadrilaterals of physical surfaces 1-5 in the file; ids 6 and 7 (the
//    two sides of the water-solid interface) as many as the water cells'
//    faces on the dam face and on the rock, (WL/h)(W/h) + (Lu/h)(W/h);
//    ids 100-103 one joint's (T/h)(H/h) faces each; id 0 the rest: the
//    surfaces of the rock, water and dam boxes less the dam base (interior),
//    plus the joint faces, less all of the above;
//  - summary.json: the report's cells per region and volumes.

#include <archdam/application/command_line.h>

#include "archdam_tests.h"
#include "gmsh_example.h"

#include <filesystem>
#include <fstream>
#include <map>
#include <regex>
#include <sstream>

using archdam::testing::log;
namespace ex = archdam::testing::gmsh_example;
using archdam::testing::yes;

namespace
{
  std::string
  read(const std::string &name)
  {
    std::ifstream      in(name);
    std::ostringstream s;
    s << in.rdbuf();
    return s.str();
  }

  /// The integers of the VTU cell data array @p name.
  std::vector<int>
  cell_data(const std::string &vtu, const std::string &name)
  {
    std::vector<int> values;
    const auto       start = vtu.find("Name=\"" + name + "\"");
    if (start == std::string::npos)
      return values;
    const auto         begin = vtu.find('>', start) + 1;
    std::istringstream in(vtu.substr(begin, vtu.find("</DataArray>", begin) - begin));
    for (int v; in >> v;)
      values.push_back(v);
    return values;
  }

  unsigned int
  number_of_cells(const std::string &vtu)
  {
    std::smatch m;
    return std::regex_search(vtu, m, std::regex("NumberOfCells=\"([0-9]+)\"")) ?
             std::stoul(m[1]) :
             0;
  }

  /// "key": value inside the JSON object that follows "object": {.
  double
  json_number(const std::string &json, const std::string &object, const std::string &key)
  {
    const auto  at = json.find("\"" + object + "\": {");
    std::smatch m;
    const std::string rest = at == std::string::npos ? "" : json.substr(at);
    return std::regex_search(rest, m, std::regex("\"" + key + "\": ([-0-9.e+]+)")) ?
             std::stod(m[1]) :
             -1;
  }
} // namespace

int
main(int argc, char **argv)
{
  dealii::Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  const bool root = dealii::Utilities::MPI::this_mpi_process(MPI_COMM_WORLD) == 0;
  const std::string dir = "mesh_only_results";
  if (root)
    {
      std::filesystem::remove_all(dir);
      std::ofstream("mesh_only.prm") << "subsection Mesh\n  set Source = gmsh\n"
                                     << "  subsection Gmsh\n    set File = " << ex::v4
                                     << "\n  end\nend\nsubsection Output\n"
                                     << "  set Directory = " << dir << "\nend\n";
    }
  MPI_Barrier(MPI_COMM_WORLD);

  std::ostringstream out, err;
  const char        *args[] = {"archdam", "mesh_only.prm", "--mesh-only"};
  const int          code   = archdam::run_command_line(3, args, out, err);
  log() << "exit code " << code << (err.str().empty() ? "" : ", error: " + err.str()) << std::endl;
  log() << "report on screen: " << yes(!root || out.str().find("Mesh report:") != std::string::npos)
        << std::endl;
  MPI_Barrier(MPI_COMM_WORLD);

  // --- the .msh file's own counts: hexahedra per physical volume, quads per
  // physical surface (format 2.2: type, number of tags, physical tag) ---
  std::map<int, unsigned int> msh_cells, msh_faces;
  {
    std::istringstream in(read(ex::v2));
    std::string        line;
    while (std::getline(in, line) && line != "$Elements")
      ;
    unsigned int n;
    in >> n;
    for (unsigned int e = 0; e < n; ++e)
      {
        unsigned int tag, type, n_tags;
        int          physical;
        in >> tag >> type >> n_tags >> physical;
        std::getline(in, line);
        (type == 5 ? msh_cells : msh_faces)[physical] += 1;
      }
  }
  unsigned int msh_hexes = 0;
  for (const auto &[m, c] : msh_cells)
    msh_hexes += c;

  const std::string cells = read(dir + "/mesh.vtu"), faces = read(dir + "/mesh_boundary.vtu");
  const auto        material = cell_data(cells, "material id");
  std::map<int, unsigned int> vtu_cells;
  for (const int m : material)
    vtu_cells[m] += 1;
  log() << "mesh.vtu: " << number_of_cells(cells) << " cells, the .msh file's " << msh_hexes
        << " hexahedra with the same material ids: "
        << yes(number_of_cells(cells) == msh_hexes && material.size() == msh_hexes &&
               vtu_cells == msh_cells)
        << "; region and block arrays present: "
        << yes(cell_data(cells, "region").size() == msh_hexes &&
               cell_data(cells, "block").size() == msh_hexes)
        << std::endl;

  std::map<int, unsigned int> vtu_faces;
  for (const int id : cell_data(faces, "boundary id"))
    vtu_faces[id] += 1;
  std::map<int, unsigned int> expected = msh_faces;
  const unsigned int interface = ex::nz_wet * ex::ny + ex::nx_up * ex::ny;
  expected[6] = expected[7] = interface;
  for (const int id : {100, 101, 102, 103})
    expected[id] = ex::joint_faces;
  // all outer faces of the structured boxes, then the ids above
  const unsigned int nz_dam = ex::nz_wet + ex::nz_dry, nx = ex::nx_up + ex::nx_dam + ex::nx_down;
  const auto surface = [](unsigned int a, unsigned int b, unsigned int c) {
    return 2 * (a * b + b * c + a * c);
  };
  // rock + water + dam blocks, each a structured box; the interfaces between
  // them are faces of both (as interface or joint ids) except dam-rock (interior)
  unsigned int outer = surface(nx, ex::ny, ex::nz_rock) + surface(ex::nx_up, ex::ny, ex::nz_wet) +
                       surface(ex::nx_dam, ex::ny, nz_dam) - 2 * ex::nx_dam * ex::ny;
  for (const auto &[id, n] : expected)
    outer -= n;
  // the joints are inside the dam box above; add them back as faces
  outer += 4 * ex::joint_faces;
  expected[0] = outer;
  log() << "mesh_boundary.vtu: faces per boundary id";
  for (const auto &[id, n] : vtu_faces)
    log() << ' ' << id << ": " << n;
  log() << "\n  equal to the counts from the .msh file (ids 1-5) and the .geo numbers (0, 6, 7, "
           "100-103): "
        << yes(vtu_faces == expected) << std::endl;

  const std::string json = read(dir + "/summary.json");
  log() << "summary.json: mesh/dam, rock, water cells "
        << json_number(json, "dam", "cells") << ", " << json_number(json, "rock", "cells") << ", "
        << json_number(json, "water", "cells") << "; dam volume "
        << json_number(json, "mesh", "dam volume \\[m\\^3\\]") << " m^3; as the .msh file and T W H: "
        << yes(json_number(json, "dam", "cells") == msh_cells[10] + msh_cells[11] + msh_cells[12] &&
               json_number(json, "rock", "cells") == msh_cells[1] &&
               json_number(json, "water", "cells") == msh_cells[2] &&
               std::abs(json_number(json, "mesh", "dam volume \\[m\\^3\\]") - ex::dam_volume) < 1e-6)
        << std::endl;
}
