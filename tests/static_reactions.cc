// The static resultants on the dam ("user holes, second round", item 5;
// doc/theory/loading-sequence.md §1): a concrete block of thickness T, width
// B and height H on a fixed base, cut across its width into two blocks by a
// frictional contraction joint, under its weight and the water that fills a
// reservoir in front of it to its crest (Gmsh meshes written here, h = 2 m
// and 1 m, Q2; the static stage by the mixed method's one solve).
// References, in closed form: the water pushes the block downstream with
// rho_w g H^2 B / 2 acting at H / 3, so about the centroid of the base the
// reactions carry
//   base shear  R_x = -rho_w g H^2 B / 2,
//   overturning M_y = -rho_w g H^3 B / 6 (the weight acts over the centroid),
//   vertical    R_z = rho_c g T B H (the weight);
// the reactions (the residual at the base's nodes) to 1e-9 of each, on both
// meshes. The support's force integrated from the stress on the base, the
// second check the run reports, converges to the same: its out of balance
// must fall from the coarse mesh to the fine one.

#include <archdam/application/command_line.h>

#include <boost/property_tree/json_parser.hpp>
#include <boost/property_tree/ptree.hpp>

#include "archdam_tests.h"
#include "case_text.h"
#include "command_line_tests.h"
#include "gmsh_example.h"

#include <array>
#include <cmath>
#include <iomanip>
#include <map>
#include <sstream>

using archdam::testing::log;

namespace
{
  constexpr double T = 4., B = 8., H = 12., Lw = 8.; // dam x, y, z; water x
  constexpr double E = 25e9, rho = 2400., rho_w = 1000., g = 9.81;

  /// Gmsh 2.2 text: cells of size @p h; the dam x in [0, T], its blocks y in
  /// [0, B/2] (10) and [B/2, B] (11), z in [0, H], base physical surface 1
  /// (fixed); water (2) x in [-Lw, 0], its bottom and banks 5, upstream
  /// end 4, free surface 3.
  std::string
  block_with_water(const double h)
  {
    const int nw = std::lround(Lw / h), nd = std::lround(T / h), ny = std::lround(B / h),
              nz = std::lround(H / h);
    std::map<std::array<int, 3>, unsigned int> tag;
    std::ostringstream                          nodes, elements;
    const auto node = [&](const int i, const int j, const int k) {
      const auto [it, added] =
        tag.emplace(std::array<int, 3>{{i, j, k}}, static_cast<unsigned int>(tag.size() + 1));
      if (added)
        nodes << it->second << ' ' << (i - nw) * h << ' ' << j * h << ' ' << k * h << "\n";
      return it->second;
    };
    unsigned int n_elements = 0;
    using Corner    = std::array<int, 3>;
    const auto quad = [&](const unsigned int id, const Corner &a, const Corner &b,
                          const Corner &c, const Corner &d) {
      elements << ++n_elements << " 3 2 " << id << " 1";
      for (const Corner &x : {a, b, c, d})
        elements << ' ' << node(x[0], x[1], x[2]);
      elements << "\n";
    };
    for (int k = 0; k < nz; ++k)
      for (int j = 0; j < ny; ++j)
        for (int i = 0; i < nw + nd; ++i)
          {
            const bool water = i < nw;
            elements << ++n_elements << " 5 2 " << (water ? 2 : (2 * j < ny ? 10 : 11)) << " 1";
            for (const auto &[a, b, c] : archdam::testing::gmsh_example::hex_corners)
              elements << ' ' << node(i + a, j + b, k + c);
            elements << "\n";
            if (k == 0)
              quad(water ? 5 : 1, Corner{{i, j, 0}}, Corner{{i + 1, j, 0}},
                   Corner{{i + 1, j + 1, 0}}, Corner{{i, j + 1, 0}});
            if (!water)
              continue;
            if (k == nz - 1)
              quad(3, Corner{{i, j, nz}}, Corner{{i + 1, j, nz}},
                   Corner{{i + 1, j + 1, nz}}, Corner{{i, j + 1, nz}});
            if (i == 0)
              quad(4, Corner{{0, j, k}}, Corner{{0, j + 1, k}},
                   Corner{{0, j + 1, k + 1}}, Corner{{0, j, k + 1}});
            for (const int side : {0, ny})
              if (j == (side == 0 ? 0 : ny - 1))
                quad(5, Corner{{i, side, k}}, Corner{{i + 1, side, k}},
                     Corner{{i + 1, side, k + 1}}, Corner{{i, side, k + 1}});
          }
    return "$MeshFormat\n2.2 0 8\n$EndMeshFormat\n$Nodes\n" + std::to_string(tag.size()) +
           "\n" + nodes.str() + "$EndNodes\n$Elements\n" + std::to_string(n_elements) + "\n" +
           elements.str() + "$EndElements\n";
  }

  double
  entry(const boost::property_tree::ptree &summary, const std::string &name, const char axis)
  {
    const auto &resultants = summary.get_child(boost::property_tree::ptree::path_type(
      "static|resultants on the dam [N]", '|'));
    return resultants.get<double>(boost::property_tree::ptree::path_type(
      name + "|" + std::string(1, axis), '|'));
  }
} // namespace

int
main(int argc, char **argv)
{
  dealii::Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  std::vector<double>                      stress_balance;
  for (const double h : {2., 1.})
    {
      const std::string name = h == 2. ? "coarse" : "fine";
      archdam::testing::write_input(name + ".msh", block_with_water(h));
      std::ostringstream prm;
      prm << "subsection Mesh\n  set Source = gmsh\n  subsection Gmsh\n    set File = " << name
          << ".msh\n  end\nend\n"
          << "subsection Finite element\n  set Degree = 2\nend\n"
          << archdam::testing::case_text::concrete_under_gravity(E, rho, g)
          << "subsection Reservoir\n  set Model = incompressible\n  set Water density = "
          << rho_w << "\nend\n"
          << "subsection Contraction joints\n  set Model = frictional contact\n"
          << "  set Static solution = one solve\nend\n"
          << "subsection Analysis\n  set Stages = static\nend\n"
          << archdam::testing::case_text::quiet_output(name, 0);
      archdam::testing::write_input(name + ".prm", prm.str());
      std::string err;
      const int   code = archdam::testing::run_in_process(archdam::run_command_line, "archdam",
                                                        {name + ".prm"}, err);
      log() << "h = " << h << " m: exit code " << code << (err.empty() ? "" : ", " + err)
            << std::endl;
      boost::property_tree::ptree summary;
      boost::property_tree::read_json(name + "/summary.json", summary);
      using archdam::testing::check_relative;
      check_relative("  base shear R_x [N] (reactions) against -rho_w g H^2 B / 2",
                     entry(summary, "support", 'x'), -rho_w * g * H * H * B / 2, 1e-9);
      check_relative("  vertical reaction R_z [N] against the weight rho_c g T B H",
                     entry(summary, "support", 'z'), rho * g * T * B * H, 1e-9);
      check_relative("  overturning moment M_y [N m] (reactions) about the base's centroid "
                     "against -rho_w g H^3 B / 6",
                     entry(summary, "moments [N m]|support", 'y'), -rho_w * g * H * H * H * B / 6,
                     1e-9);
      check_relative("  the water's moment M_y [N m] against rho_w g H^3 B / 6",
                     entry(summary, "moments [N m]|water", 'y'), rho_w * g * H * H * H * B / 6,
                     1e-9);
      stress_balance.push_back(summary.get<double>(boost::property_tree::ptree::path_type(
        "static|resultants on the dam [N]|out of balance of the stress", '|')));
      log() << "  out of balance of the stress-integrated support: " << std::setprecision(2)
            << stress_balance.back() << std::endl;
    }
  log() << "the stress-integrated support's out of balance falls from h = 2 m to 1 m: "
        << archdam::testing::yes(stress_balance[1] < stress_balance[0]) << std::endl;
}
