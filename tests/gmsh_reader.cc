// The Gmsh reader keeps every vertex where the file puts it, also when the
// file holds elements outside any physical group (issue 3: deal.II 9.4.1's
// GridIn::read_msh(file name), which goes through the gmsh library, has been
// seen to scramble vertex coordinates in that case, without an error;
// geometry::read_gmsh() parses the text with GridIn::read_msh(std::istream &)).
//
// The test writes .msh files (format 4.1 and 2.2) of a 3 x 2 x 2 block of
// hexahedra with irregular vertex positions, node tags that are neither
// consecutive nor in order, nodes spread over several entity blocks, and
// elements outside every physical group: faces of a surface entity without a
// physical group, and a point element. It parses the node and element blocks
// itself (a few lines, independent of deal.II) and compares, cell by cell, the
// 8 corner coordinates read by read_gmsh() with the coordinates of the nodes
// the file names for that element (exact: both are the decimal numbers of the
// file). It also checks the ids: physical volume 10 -> material 10, physical
// surface 1 -> boundary id 1, faces outside any physical surface -> 0.

#include <archdam/geometry/gmsh_mesh.h>

#include <deal.II/grid/tria.h>

#include "archdam_tests.h"

#include <algorithm>
#include <array>
#include <fstream>
#include <map>
#include <sstream>
#include <tuple>

using namespace dealii;
using archdam::testing::log;

namespace
{
  constexpr unsigned int nx = 3, ny = 2, nz = 2;

  unsigned int
  node_tag(const unsigned int i, const unsigned int j, const unsigned int k)
  {
    // neither consecutive nor increasing with the position
    return 1000 - 7 * (i + (nx + 1) * (j + (ny + 1) * k));
  }

  std::array<double, 3>
  position(const unsigned int i, const unsigned int j, const unsigned int k)
  {
    // an irregular but valid grid
    return {{2.5 * i + 0.3 * std::sin(1. + i + 2 * j + 3 * k), 1.75 * j + 0.2 * std::cos(1. + 3 * i + k),
             1.5 * k + 0.25 * std::sin(2. + i * j + k)}};
  }

  /// Gmsh's hexahedron node order: bottom face counter-clockwise, then top.
  std::array<unsigned int, 8>
  hex_nodes(const unsigned int i, const unsigned int j, const unsigned int k)
  {
    return {{node_tag(i, j, k), node_tag(i + 1, j, k), node_tag(i + 1, j + 1, k),
             node_tag(i, j + 1, k), node_tag(i, j, k + 1), node_tag(i + 1, j, k + 1),
             node_tag(i + 1, j + 1, k + 1), node_tag(i, j + 1, k + 1)}};
  }

  std::string
  node_line(const unsigned int i, const unsigned int j, const unsigned int k)
  {
    std::ostringstream s;
    s.precision(17);
    const auto x = position(i, j, k);
    s << x[0] << ' ' << x[1] << ' ' << x[2];
    return s.str();
  }

  /// Format 4.1: nodes in two entity blocks (the volume's and the top
  /// surface's), hexahedra in volume 1 (physical 10), bottom quads in surface 1
  /// (physical 1), top quads in surface 2 and a point element in point 1,
  /// both outside every physical group.
  std::string
  msh41()
  {
    std::ostringstream s;
    const unsigned int n_nodes = (nx + 1) * (ny + 1) * (nz + 1);
    s << "$MeshFormat\n4.1 0 8\n$EndMeshFormat\n"
      << "$Entities\n1 0 2 1\n"
      << "1 0 0 0 0\n"                                  // point 1: no physical
      << "1 0 0 0 10 5 0 1 1 0\n"                       // surface 1: physical 1
      << "2 0 0 3 10 5 3 0 0\n"                         // surface 2: none
      << "1 0 0 0 10 5 3 1 10 2 1 2\n"                  // volume 1: physical 10
      << "$EndEntities\n";
    // nodes: those with k = nz in surface 2's block, all others in volume 1's,
    // each block listed from the last node to the first
    std::vector<std::array<unsigned int, 3>> top, rest;
    for (unsigned int k = 0; k <= nz; ++k)
      for (unsigned int j = 0; j <= ny; ++j)
        for (unsigned int i = 0; i <= nx; ++i)
          (k == nz ? top : rest).push_back({{i, j, k}});
    std::reverse(top.begin(), top.end());
    std::reverse(rest.begin(), rest.end());
    s << "$Nodes\n2 " << n_nodes << " " << node_tag(nx, ny, nz) << " " << node_tag(0, 0, 0) << "\n";
    for (const auto &[dim, tag, block] : {std::make_tuple(2, 2, &top), std::make_tuple(3, 1, &rest)})
      {
        s << dim << ' ' << tag << " 0 " << block->size() << "\n";
        for (const auto &n : *block)
          s << node_tag(n[0], n[1], n[2]) << "\n";
        for (const auto &n : *block)
          s << node_line(n[0], n[1], n[2]) << "\n";
      }
    s << "$EndNodes\n";
    const unsigned int n_hex = nx * ny * nz, n_quad = nx * ny;
    s << "$Elements\n4 " << n_hex + 2 * n_quad + 1 << " 1 " << n_hex + 2 * n_quad + 1 << "\n";
    unsigned int e = 1;
    s << "0 1 15 1\n" << e++ << " " << node_tag(0, 0, 0) << "\n";
    s << "2 1 3 " << n_quad << "\n";
    for (unsigned int j = 0; j < ny; ++j)
      for (unsigned int i = 0; i < nx; ++i)
        s << e++ << " " << node_tag(i, j, 0) << " " << node_tag(i, j + 1, 0) << " "
          << node_tag(i + 1, j + 1, 0) << " " << node_tag(i + 1, j, 0) << "\n";
    s << "2 2 3 " << n_quad << "\n";
    for (unsigned int j = 0; j < ny; ++j)
      for (unsigned int i = 0; i < nx; ++i)
        s << e++ << " " << node_tag(i, j, nz) << " " << node_tag(i + 1, j, nz) << " "
          << node_tag(i + 1, j + 1, nz) << " " << node_tag(i, j + 1, nz) << "\n";
    s << "3 1 5 " << n_hex << "\n";
    for (unsigned int k = 0; k < nz; ++k)
      for (unsigned int j = 0; j < ny; ++j)
        for (unsigned int i = 0; i < nx; ++i)
          {
            s << e++;
            for (const auto t : hex_nodes(i, j, k))
              s << ' ' << t;
            s << "\n";
          }
    s << "$EndElements\n";
    return s.str();
  }

  /// Format 2.2: the same mesh; the elements outside every physical group
  /// carry physical tag 0, as Gmsh writes them.
  std::string
  msh22()
  {
    std::ostringstream s;
    s << "$MeshFormat\n2.2 0 8\n$EndMeshFormat\n$Nodes\n" << (nx + 1) * (ny + 1) * (nz + 1) << "\n";
    for (int k = nz; k >= 0; --k)
      for (int j = ny; j >= 0; --j)
        for (int i = nx; i >= 0; --i)
          s << node_tag(i, j, k) << ' ' << node_line(i, j, k) << "\n";
    s << "$EndNodes\n$Elements\n" << 1 + 2 * nx * ny + nx * ny * nz << "\n";
    unsigned int e = 1;
    s << e++ << " 15 2 0 1 " << node_tag(0, 0, 0) << "\n";
    for (unsigned int j = 0; j < ny; ++j)
      for (unsigned int i = 0; i < nx; ++i)
        {
          s << e++ << " 3 2 1 1 " << node_tag(i, j, 0) << " " << node_tag(i, j + 1, 0) << " "
            << node_tag(i + 1, j + 1, 0) << " " << node_tag(i + 1, j, 0) << "\n";
          s << e++ << " 3 2 0 2 " << node_tag(i, j, nz) << " " << node_tag(i + 1, j, nz) << " "
            << node_tag(i + 1, j + 1, nz) << " " << node_tag(i, j + 1, nz) << "\n";
        }
    for (unsigned int k = 0; k < nz; ++k)
      for (unsigned int j = 0; j < ny; ++j)
        for (unsigned int i = 0; i < nx; ++i)
          {
            s << e++ << " 5 2 10 1";
            for (const auto t : hex_nodes(i, j, k))
              s << ' ' << t;
            s << "\n";
          }
    s << "$EndElements\n";
    return s.str();
  }

  /// The file's own node coordinates and hexahedra, parsed here: node tag ->
  /// (x, y, z), and the node tags of each hexahedron in file order.
  void
  parse(const std::string &text, std::map<unsigned int, std::array<double, 3>> &nodes,
        std::vector<std::array<unsigned int, 8>> &hexes)
  {
    std::istringstream in(text);
    std::string        line;
    double             version = 0;
    while (std::getline(in, line) && line != "$MeshFormat")
      ;
    in >> version;
    while (std::getline(in, line) && line != "$Nodes")
      ;
    if (version > 4)
      {
        unsigned int blocks, n, lo, hi;
        in >> blocks >> n >> lo >> hi;
        for (unsigned int b = 0; b < blocks; ++b)
          {
            unsigned int d, t, param, m;
            in >> d >> t >> param >> m;
            std::vector<unsigned int> tags(m);
            for (auto &tag : tags)
              in >> tag;
            for (const auto tag : tags)
              in >> nodes[tag][0] >> nodes[tag][1] >> nodes[tag][2];
          }
      }
    else
      {
        unsigned int n, tag;
        in >> n;
        for (unsigned int i = 0; i < n; ++i)
          {
            in >> tag;
            in >> nodes[tag][0] >> nodes[tag][1] >> nodes[tag][2];
          }
      }
    while (std::getline(in, line) && line != "$Elements")
      ;
    if (version > 4)
      {
        unsigned int blocks, n, lo, hi;
        in >> blocks >> n >> lo >> hi;
        for (unsigned int b = 0; b < blocks; ++b)
          {
            unsigned int d, t, type, m;
            in >> d >> t >> type >> m;
            const unsigned int n_nodes = type == 5 ? 8 : type == 3 ? 4 : 1;
            for (unsigned int e = 0; e < m; ++e)
              {
                unsigned int tag, node;
                std::array<unsigned int, 8> hex;
                in >> tag;
                for (unsigned int i = 0; i < n_nodes; ++i)
                  in >> (type == 5 ? hex[i] : node);
                if (type == 5)
                  hexes.push_back(hex);
              }
          }
      }
    else
      {
        unsigned int n;
        in >> n;
        std::getline(in, line);
        for (unsigned int e = 0; e < n; ++e)
          {
            std::getline(in, line);
            std::istringstream l(line);
            unsigned int       tag, type, n_tags, x;
            l >> tag >> type >> n_tags;
            for (unsigned int i = 0; i < n_tags; ++i)
              l >> x;
            if (type == 5)
              {
                std::array<unsigned int, 8> hex;
                for (auto &v : hex)
                  l >> v;
                hexes.push_back(hex);
              }
          }
      }
  }

  void
  check(const std::string &name, const std::string &text)
  {
    // rank 0 writes the file, the others wait for it
    if (Utilities::MPI::this_mpi_process(MPI_COMM_WORLD) == 0)
      std::ofstream(name) << text;
    MPI_Barrier(MPI_COMM_WORLD);

    std::map<unsigned int, std::array<double, 3>> nodes;
    std::vector<std::array<unsigned int, 8>>      hexes;
    parse(text, nodes, hexes);

    Triangulation<3> tria;
    archdam::geometry::read_gmsh(name, tria);

    unsigned int wrong_cells = 0, wrong_material = 0, checked = 0;
    std::map<unsigned int, unsigned int> faces_per_id;
    auto cell = tria.begin_active();
    for (const auto &hex : hexes)
      {
        if (cell == tria.end())
          break;
        std::vector<std::array<double, 3>> expected, read;
        for (const auto tag : hex)
          expected.push_back(nodes.at(tag));
        for (unsigned int v = 0; v < 8; ++v)
          read.push_back({{cell->vertex(v)[0], cell->vertex(v)[1], cell->vertex(v)[2]}});
        std::sort(expected.begin(), expected.end());
        std::sort(read.begin(), read.end());
        wrong_cells += expected != read;
        wrong_material += cell->material_id() != 10;
        for (unsigned int f = 0; f < 6; ++f)
          if (cell->at_boundary(f))
            {
              const double z = cell->face(f)->center()[2];
              const bool   bottom = z < 0.5, top = z > 1.5 * nz - 0.5;
              // bottom: physical surface 1; top and sides: outside any group
              faces_per_id[cell->face(f)->boundary_id()] += 1;
              if (bottom != (cell->face(f)->boundary_id() == 1) || (top && cell->face(f)->boundary_id() != 0))
                ++wrong_material;
            }
        ++cell;
        ++checked;
      }
    log() << name << ": " << tria.n_active_cells() << " cells (the file has " << hexes.size()
          << " hexahedra, " << nodes.size() << " nodes); cells whose 8 corners differ from "
          << "the file's nodes: " << wrong_cells << " of " << checked
          << ", none expected: " << (wrong_cells == 0 && checked == hexes.size() ? "yes" : "NO")
          << std::endl;
    log() << "  material 10 on every cell, boundary id 1 on the " << nx * ny
          << " bottom faces and 0 on the others (outside every physical surface): "
          << (wrong_material == 0 && faces_per_id[1] == nx * ny ? "yes" : "NO") << std::endl;
  }
} // namespace

int
main(int argc, char **argv)
{
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  check("unassigned_elements_v41.msh", msh41());
  check("unassigned_elements_v22.msh", msh22());
}
