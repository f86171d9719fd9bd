// The Gmsh example of prm/ (gmsh_blocks.geo) in numbers: its dimensions, cell
// size and ids as written in the .geo file, and what follows from them in
// closed form. Shared by the tests of the Gmsh route; nothing here reads the
// mesh.
#pragma once

#include <array>
#include <sstream>
#include <string>
#include <vector>

namespace archdam::testing::gmsh_example
{
  inline const std::string directory = SOURCE_DIR "/../prm/";
  inline const std::string v2        = directory + "gmsh_blocks_v2.msh";
  inline const std::string v4        = directory + "gmsh_blocks_v4.msh";

  // gmsh_blocks.geo: dam x in [0, T], y in [-W/2, W/2], z in [0, H], three
  // blocks of width W/3 from +y (block 0) to -y; rock x in [-Lu, T + Ld],
  // z in [-D, 0]; water x in [-Lu, 0], z in [0, WL]; every box edge is split
  // into cells of size h.
  constexpr double T = 10, W = 30, H = 30, WL = 25, D = 20, Lu = 30, Ld = 30, h = 5;
  constexpr unsigned int n_blocks = 3;

  // cells along each direction
  constexpr unsigned int nx_up = Lu / h, nx_dam = T / h, nx_down = Ld / h;
  constexpr unsigned int ny = W / h, ny_block = W / 3 / h;
  constexpr unsigned int nz_rock = D / h, nz_wet = WL / h, nz_dry = (H - WL) / h;

  constexpr double dam_volume   = T * W * H;
  constexpr double water_volume = Lu * W * WL;
  constexpr double rock_volume  = (Lu + T + Ld) * W * D;
  constexpr double wetted_area  = W * WL;

  constexpr unsigned int dam_cells   = nx_dam * ny * (nz_wet + nz_dry);
  constexpr unsigned int rock_cells  = (nx_up + nx_dam + nx_down) * ny * nz_rock;
  constexpr unsigned int water_cells = nx_up * ny * nz_wet;

  /// Faces of one joint (the plane between two blocks): through the
  /// thickness x over the height.
  constexpr unsigned int joint_faces = nx_dam * (nz_wet + nz_dry);
  /// Its nodes for elements of degree @p p, (p nx + 1)(p nz + 1) on the
  /// structured joint, less those on its edge against the rock (shared).
  constexpr unsigned int
  joint_node_pairs(const unsigned int p)
  {
    return (p * nx_dam + 1) * (p * (nz_wet + nz_dry) + 1) - (p * nx_dam + 1);
  }
  /// The corners of a hexahedron in Gmsh's order, as (i, j, k) offsets
  /// from its first corner along x, y, z.
  constexpr std::array<std::array<int, 3>, 8> hex_corners{{{{0, 0, 0}},
                                                           {{1, 0, 0}},
                                                           {{1, 1, 0}},
                                                           {{0, 1, 0}},
                                                           {{0, 0, 1}},
                                                           {{1, 0, 1}},
                                                           {{1, 1, 1}},
                                                           {{0, 1, 1}}}};

  /// Two unit cubes side by side along @p axis, each its own dam block
  /// (10, 11), as a Gmsh 2.2 file's text with 12 or 16 nodes: the 16-node
  /// file does not connect them; @p gap > 0 moves the second one that far
  /// away along the axis. Node tags 1, 3, 5, 7 lie on the first cube's face
  /// at 0 along the axis.
  inline std::string
  two_cubes(const bool connected, const unsigned int gap = 0, const unsigned int axis = 0)
  {
    std::ostringstream s;
    s << "$MeshFormat\n2.2 0 8\n$EndMeshFormat\n$Nodes\n" << (connected ? 12 : 16) << "\n";
    unsigned int                           tag = 1;
    std::vector<std::vector<unsigned int>> hex(2);
    for (unsigned int c = 0; c < 2; ++c)
      for (unsigned int k = 0; k < 2; ++k)
        for (unsigned int j = 0; j < 2; ++j)
          for (unsigned int i = 0; i < 2; ++i)
            {
              if (connected && c == 1 && i == 0)
                {
                  hex[c].push_back(hex[0][1 + 2 * j + 4 * k]); // the shared face's node
                  continue;
                }
              // (along, j, k) turned cyclically onto (x, y, z): the same
              // orientation for every axis
              unsigned int x[3];
              x[axis]           = c * (1 + gap) + i;
              x[(axis + 1) % 3] = j;
              x[(axis + 2) % 3] = k;
              s << tag << ' ' << x[0] << ' ' << x[1] << ' ' << x[2] << "\n";
              hex[c].push_back(tag++);
            }
    s << "$EndNodes\n$Elements\n2\n";
    const unsigned int gmsh_order[8] = {0, 1, 3, 2, 4, 5, 7, 6};
    for (unsigned int c = 0; c < 2; ++c)
      {
        s << c + 1 << " 5 2 " << 10 + c << " 1";
        for (const unsigned int v : gmsh_order)
          s << ' ' << hex[c][v];
        s << "\n";
      }
    s << "$EndElements\n";
    return s.str();
  }
} // namespace archdam::testing::gmsh_example
