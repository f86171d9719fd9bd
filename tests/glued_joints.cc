// The splitter and glued joints (issue "mesh", doc/theory/conventions.md §6;
// doc/verification.md: with the joints locked the joint model reproduces the
// monolithic dam's response).
//
// A box dam of 4 blocks on rock is split into blocks (3 joints); with
// `Contraction joints/Model = glued` the pairs are tied. Shown:
//  - the joint faces pair 1:1, with coincident vertices, opposite normals,
//    side 1 on block k and side 2 on block k + 1; the node pairs per joint are
//    the vertices of the joint plane that do not touch the rock (those stay
//    shared: the blocks are grouted into the foundation), counted here from the
//    mesh parameters;
//  - every boundary face carries one of the documented ids;
//  - a second method: the same mesh with one block (no joints at all) gives the
//    same static and dynamic response. Both are direct solves of the same
//    discrete problem written two ways, so they agree to round-off: 1e-9 of
//    the peak value (the condition number of Kbar here is ~1e6).

#include <archdam/analysis/simulation.h>
#include <archdam/geometry/ids.h>
#include <archdam/geometry/splitter.h>

#include "archdam_tests.h"
#include "case_text.h"

using namespace dealii;
using namespace archdam;

namespace
{
  std::string
  model(const unsigned int n_blocks)
  {
    return R"(
subsection Mesh
  subsection Box
    set Length = 8
    set Width = 24
    set Height = 16
    set Number of blocks = )" +
           std::to_string(n_blocks) + R"(
    set Cells in x = 2
    set Cells in y = 4
    set Cells in z = 3
    set Rock depth = 8
    set Rock extent = 8
    set Rock cell size = 8
  end
end
subsection Time integration
  set Time step = 0.01
  set End time = 0.3
end
subsection Ground motion
  subsection Component x
    set File = )" + testing::case_text::el_centro_file("180") + R"(
  end
  subsection Component y
    set File = )" + testing::case_text::el_centro_file("270") + R"(
    set Scale factor = 20
  end
end
subsection Monitors
  # crest on a joint plane (y = 12), crest between joints, heel on a joint
  set Points = joint_crest: 4, 12, 16; block_crest: 8, 3, 16; joint_heel: 0, 6, 0
  set Quantities = displacement, acceleration, principal stress
end
)" + testing::case_text::quiet_output("results_" + std::to_string(n_blocks), 0);
  }

  Tensor<1, dim>
  normal(const Triangulation<dim>::face_iterator &f)
  {
    // (v1 - v0) x (v2 - v0) for a planar quadrilateral, scaled to unit length
    Tensor<1, dim> n = cross_product_3d(f->vertex(1) - f->vertex(0), f->vertex(2) - f->vertex(0));
    return n / n.norm();
  }
} // namespace

int
main(int argc, char **argv)
{
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  auto                            &log = testing::log();
  std::ostringstream               quiet;

  const Parameters     p4 = parameters_from_string(model(4));
  analysis::Simulation blocks(p4, MPI_COMM_WORLD, quiet);
  blocks.run();
  const Parameters     p1 = parameters_from_string(model(1));
  analysis::Simulation monolith(p1, MPI_COMM_WORLD, quiet);
  monolith.run();

  // Pairing and ids.
  const auto &tria  = blocks.model().space().dof_handler.get_triangulation();
  const auto  pairs = joints::pair_joint_faces(tria);
  std::set<unsigned int> joints_seen;
  double                 max_distance = 0., max_normal_sum = 0.;
  bool                   sides_ok     = true;
  for (const auto &pr : pairs)
    {
      joints_seen.insert(pr.joint);
      const auto f1 = pr.cell_1->face(pr.face_1), f2 = pr.cell_2->face(pr.face_2);
      for (const unsigned int v : f1->vertex_indices())
        {
          double d = 1e300;
          for (const unsigned int w : f2->vertex_indices())
            d = std::min(d, f1->vertex(v).distance(f2->vertex(w)));
          max_distance = std::max(max_distance, d);
        }
      // outward normals: the cell's face normal with the orientation flag
      const Tensor<1, dim> n1 = (pr.cell_1->face_orientation(pr.face_1) ? 1. : -1.) *
                                (pr.face_1 % 2 == 0 ? -1. : 1.) * normal(f1);
      const Tensor<1, dim> n2 = (pr.cell_2->face_orientation(pr.face_2) ? 1. : -1.) *
                                (pr.face_2 % 2 == 0 ? -1. : 1.) * normal(f2);
      max_normal_sum = std::max(max_normal_sum, (n1 + n2).norm());
      sides_ok = sides_ok && pr.cell_1->material_id() == ids::first_dam_block + pr.joint &&
                 pr.cell_2->material_id() == ids::first_dam_block + pr.joint + 1 &&
                 f1->boundary_id() == geometry::joint_side_1(pr.joint) &&
                 f2->boundary_id() == geometry::joint_side_2(pr.joint);
    }
  log << "joints: " << joints_seen.size() << " (expected 3)" << std::endl;
  log << "face pairs: " << pairs.size() << " (expected 3 joints x 2 x 3 cells = 18)"
      << std::endl;
  testing::check_below("largest distance between paired vertices [m]", max_distance, 1e-12);
  testing::check_below("largest |n1 + n2| of paired outward normals", max_normal_sum, 1e-12);
  log << "side 1 on block k, side 2 on block k+1, ids 100+2k / 101+2k: "
      << (sides_ok ? "yes" : "NO") << std::endl;
  const auto counts = joints::count_joint_nodes(pairs, 3);
  // joint plane: (2 + 1) x (3 + 1) vertices, the bottom row (3) touches rock
  for (unsigned int j = 0; j < 3; ++j)
    log << "joint " << j << ": " << counts[j].faces << " faces, " << counts[j].node_pairs
        << " node pairs (expected 6 and 9)" << std::endl;

  std::set<types::boundary_id> allowed{0, 1, 2, 100, 101, 102, 103, 104, 105}, found;
  bool                         all_documented = true;
  for (const auto &face : tria.active_face_iterators())
    if (face->at_boundary())
      {
        found.insert(face->boundary_id());
        all_documented = all_documented && allowed.count(face->boundary_id());
      }
  log << "boundary ids found:";
  for (const auto id : found)
    log << " " << id;
  log << "; all documented: " << (all_documented ? "yes" : "NO") << std::endl;

  // Second method: the monolithic dam.
  log << "DOFs: " << blocks.model().space().dof_handler.n_dofs() << " with joints, "
      << monolith.model().space().dof_handler.n_dofs() << " monolithic" << std::endl;
  const auto &a = blocks.recorder<archdam::output::MonitorHistories>()->rows(), &b = monolith.recorder<archdam::output::MonitorHistories>()->rows();
  const auto &names = monolith.recorder<archdam::output::MonitorHistories>()->columns();
  log << "history rows: " << a.size() << " and " << b.size() << std::endl;
  // Round-off scales with the size of the field, not of one component that
  // happens to be near zero (the vertical acceleration on the joint plane):
  // each difference is measured against the peak of all columns in the same
  // unit.
  const auto unit = [](const std::string &name) { return name.substr(name.find('[')); };
  for (unsigned int c = 1; c < names.size(); ++c)
    {
      double diff = 0., peak = 0.;
      for (unsigned int r = 0; r < b.size(); ++r)
        {
          diff = std::max(diff, std::abs(a[r][c] - b[r][c]));
          for (unsigned int k = 1; k < names.size(); ++k)
            if (unit(names[k]) == unit(names[c]))
              peak = std::max(peak, std::abs(b[r][k]));
        }
      testing::check_below("  " + names[c] + ": max |glued - monolithic| / peak " +
                             unit(names[c]),
                           diff / peak, 1e-9);
    }
}
