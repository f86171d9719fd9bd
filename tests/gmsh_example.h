// The Gmsh example of prm/ (gmsh_blocks.geo) in numbers: its dimensions, cell
// size and ids as written in the .geo file, and what follows from them in
// closed form. Shared by the tests of the Gmsh route; nothing here reads the
// mesh.
#pragma once

#include <string>

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
} // namespace archdam::testing::gmsh_example
