// Bad meshes end with one clear message and exit code 1 (issue 3, "errors"):
// each case is a small edit of the Gmsh example (prm/gmsh_blocks_v2.msh) or a
// small file a user could really produce, run through the command line with
// --mesh-only. The test prints the exit code and the message as the user sees
// it; the reference is that every case gives exit code 1 and names the
// problem, and that the unedited example passes (exit code 0).
//  - files that cannot be read: missing (in the case file's folder and in the
//    data folder), not a .msh (the .geo, also one found in the data folder),
//    truncated, binary, an unsupported version;
//  - an inverted cell (a node moved through the cell), a tangled node order
//    (a twisted cell overlapping its neighbours) and a degenerate cell;
//  - a material id no material defines (5, and 0: a cell outside every
//    physical volume);
//  - boundary ids: a water face without an id, a water id on a rock face, an
//    id reserved for the splitter;
//  - a joint face without a partner: two blocks meshed separately (coincident
//    faces that share no nodes);
//  - dam blocks with a gap in their numbers (a Gmsh volume dropped for want
//    of a physical group leaves a hole) and two neighbouring blocks that do
//    not touch (no joint between them);
//  - with frictional joints and the mixed method, a block held by its joint
//    alone (the static stage would need K^-1, and so would the self-weight
//    on the ungrouted cantilevers; accepted with the joints grouted before
//    the self-weight and the monolithic solver, or the static stage by
//    dynamic relaxation);
//  - a physical surface inside the model (on a joint);
//  - malformed files, each caught before deal.II's GridIn reads them (the
//    fuzz target fuzz_gmsh_mesh found what GridIn does not check): a count
//    larger than the file, an element naming an undefined node or one node
//    twice, a node defined twice, a coordinate that is not a number, an id
//    above 254, an element type ArchDam does not read, a number that is not
//    an integer, a misspelt section, and in format 4.1 an entity with two
//    physical groups, parametric nodes, block sums that differ from the
//    header, an entity dimension out of range, $Entities in a format-2 file;
//    hexahedra that overlap (one given twice, a third on a face).

#include <archdam/application/command_line.h>

#include "archdam_tests.h"
#include "gmsh_example.h"

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <functional>
#include <sstream>
#include <vector>

using archdam::testing::log;
namespace ex = archdam::testing::gmsh_example;

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

  void
  write(const std::string &name, const std::string &text)
  {
    if (dealii::Utilities::MPI::this_mpi_process(MPI_COMM_WORLD) == 0)
      std::ofstream(name) << text;
    MPI_Barrier(MPI_COMM_WORLD);
  }

  /// The example's format-2.2 text with its element lines edited: @p edit
  /// gets the fields of each element line (number, type, number of tags,
  /// physical tag, entity tag, nodes...) and returns false to drop it.
  std::string
  edit_elements(const std::function<bool(std::vector<long> &)> &edit)
  {
    std::istringstream in(read(ex::v2));
    std::ostringstream head, body;
    std::string        line;
    while (std::getline(in, line) && line != "$Elements")
      head << line << "\n";
    head << line << "\n";
    unsigned int n, kept = 0;
    in >> n;
    std::getline(in, line);
    for (unsigned int e = 0; e < n; ++e)
      {
        std::getline(in, line);
        std::istringstream l(line);
        std::vector<long>  f;
        for (long v; l >> v;)
          f.push_back(v);
        if (!edit(f))
          continue;
        ++kept;
        for (unsigned int i = 0; i < f.size(); ++i)
          body << (i ? " " : "") << f[i];
        body << "\n";
      }
    return head.str() + std::to_string(kept) + "\n" + body.str() + "$EndElements\n";
  }

  /// --mesh-only on @p msh, with further @p settings of the case file.
  void
  run(const std::string &what, const std::string &msh, const std::string &settings = "")
  {
    write("mesh_error.prm", "subsection Mesh\n  set Source = gmsh\n  subsection Gmsh\n"
                            "    set File = " + msh + "\n  end\nend\n"
                            "subsection Output\n  set Directory = mesh_error_results\nend\n" +
                              settings);
    const char        *args[] = {"archdam", "mesh_error.prm", "--mesh-only"};
    std::ostringstream out, err;
    const int          code = archdam::run_command_line(3, args, out, err);
    log() << "* " << what << "\n  exit code " << code << "\n  " << err.str() << std::endl;
  }

} // namespace

int
main(int argc, char **argv)
{
  dealii::Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);

  run("the example itself (accepted)", ex::v2);
  // A fixed data folder (the default one differs between machines): a
  // relative name is looked for next to the case file, then there.
  setenv("ARCHDAM_DATA_DIR", "mesh_data", 1);
  run("missing file", "no_such_mesh.msh");
  if (dealii::Utilities::MPI::this_mpi_process(MPI_COMM_WORLD) == 0)
    std::filesystem::create_directories("mesh_data");
  write("mesh_data/in_data_folder.geo", read(ex::directory + "gmsh_blocks.geo"));
  run("a file found in the data folder (the .geo script)", "in_data_folder.geo");
  write("script.geo", read(ex::directory + "gmsh_blocks.geo"));
  run("not a .msh file (the .geo script)", "script.geo");
  {
    const std::string text = read(ex::v2);
    write("truncated.msh", text.substr(0, text.size() / 2));
    run("truncated file (first half of the example)", "truncated.msh");
    std::string binary = text;
    binary.replace(binary.find("2.2 0 8"), 7, "2.2 1 8");
    write("binary.msh", binary);
    run("binary .msh (header 2.2 1 8)", "binary.msh");
    std::string old = text;
    old.replace(old.find("2.2 0 8"), 7, "4.0 0 8");
    write("version40.msh", old);
    run("format 4.0", "version40.msh");
  }

  // the first dam hexahedron (physical tag 11, block 1) edited
  const auto first_of = [](const long physical, const std::function<void(std::vector<long> &)> &f) {
    bool done = false;
    return edit_elements([&, physical](std::vector<long> &e) {
      if (!done && e[1] == 5 && e[3] == physical)
        {
          f(e);
          done = true;
        }
      return true;
    });
  };
  write("tangled.msh", first_of(11, [](auto &e) { std::swap(e[5 + 6], e[5 + 7]); }));
  run("a tangled hexahedron (two top nodes swapped)", "tangled.msh");
  {
    // node 26 of the example (the dam's downstream corner at (10, -15, 0))
    // moved 10 m down, through the rock cell below it
    std::string text = read(ex::v2);
    const auto  at   = text.find("\n26 ");
    const auto  end  = text.find('\n', at + 1);
    std::istringstream node(text.substr(at + 1, end - at - 1));
    double             tag, x, y, z;
    node >> tag >> x >> y >> z;
    text.replace(at + 1, end - at - 1,
                 "26 " + std::to_string(x) + " " + std::to_string(y) + " " + std::to_string(z - 10));
    write("inverted.msh", text);
    run("an inverted cell: node 26 moved 10 m down, through the rock cell below it", "inverted.msh");
  }
  write("degenerate.msh", first_of(11, [](auto &e) { e[5 + 7] = e[5 + 6]; }));
  run("a hexahedron naming one node twice", "degenerate.msh");
  write("material5.msh", first_of(1, [](auto &e) { e[3] = 5; }));
  run("material id 5 (physical volume 5) on a rock cell", "material5.msh");
  write("material0.msh", first_of(11, [](auto &e) { e[3] = 0; }));
  run("a dam cell outside every physical volume (material id 0)", "material0.msh");

  write("water_face_without_id.msh",
        edit_elements([](std::vector<long> &e) { return !(e[1] == 3 && e[3] == 4); }));
  run("the reservoir's upstream end without its physical surface 4", "water_face_without_id.msh");
  bool changed = false;
  write("water_id_on_rock.msh", edit_elements([&](std::vector<long> &e) {
          if (!changed && e[1] == 3 && e[3] == 1)
            {
              e[3]    = 3;
              changed = true;
            }
          return true;
        }));
  run("a rock bottom face in physical surface 3 (water free surface)", "water_id_on_rock.msh");
  changed = false;
  write("reserved_id.msh", edit_elements([&](std::vector<long> &e) {
          if (!changed && e[1] == 3 && e[3] == 2)
            {
              e[3]    = 7;
              changed = true;
            }
          return true;
        }));
  run("a rock side face in physical surface 7 (the splitter's id)", "reserved_id.msh");

  write("connected_blocks.msh", ex::two_cubes(true));
  run("two dam blocks sharing their joint's nodes (accepted)", "connected_blocks.msh");
  {
    // block 0 fixed on its far face x = 0 (nodes 1 3 7 5, physical surface
    // 1), block 1 held by the joint alone: the static stage of the mixed
    // method has no K^-1 for it, nor has the self-weight on the ungrouted
    // cantilevers; the monolithic solver holds it, the joints grouted first
    std::string text = ex::two_cubes(true);
    text.replace(text.find("$Elements\n2\n"), 12, "$Elements\n3\n");
    text.replace(text.find("$EndElements"), 0, "3 3 2 1 1 1 3 7 5\n");
    write("hanging_block.msh", text);
    const std::string joints =
      "subsection Contraction joints\n  set Model = frictional contact\n  set Solver = ";
    run("frictional joints, mixed method: block 1 held by its joint alone", "hanging_block.msh",
        joints + "mixed\nend\n");
    run("the same with the monolithic solver (accepted)", "hanging_block.msh",
        joints + "monolithic\n  set Contact in time = trapezoidal\nend\n");
    run("the same with the mixed method and the static stage by dynamic relaxation (accepted)",
        "hanging_block.msh", joints + "mixed\n  set Static solution = dynamic relaxation\nend\n");
    run("the same with the joints grouted after the self-weight", "hanging_block.msh",
        joints + "monolithic\n  set Contact in time = trapezoidal\n"
                 "  set Grouting = after self-weight\nend\n");
  }
  write("separate_blocks.msh", ex::two_cubes(false));
  run("two dam blocks meshed separately: joint faces without a partner", "separate_blocks.msh");
  write("blocks_apart.msh", ex::two_cubes(false, 1));
  run("dam blocks 10 and 11 that do not touch (no joint between them)", "blocks_apart.msh");
  // The example with the middle block's volume dropped (a Gmsh volume
  // without a physical group is not saved): a hole between blocks 10 and 12,
  // with water beside it.
  write("middle_block_missing.msh", edit_elements([](const std::vector<long> &e) {
          return !(e[1] == 5 && e[3] == 11);
        }));
  run("the example without its middle block (a hole between blocks 10 and 12)",
      "middle_block_missing.msh");
  {
    // a quadrilateral on the joint between the two connected blocks
    std::string text = ex::two_cubes(true);
    text.replace(text.find("$Elements\n2\n"), 12, "$Elements\n3\n3 3 2 100 1 2 4 8 6\n");
    write("joint_surface.msh", text);
    run("a physical surface (100) on the joint, inside the model", "joint_surface.msh");
  }

  // malformed files: one edit of the example (format 2.2 or 4.1) each
  const auto edited = [](const std::string &file, const std::string &from, const std::string &to) {
    std::string text = read(file);
    text.replace(text.find(from), from.size(), to);
    return text;
  };
  const auto malformed = [&](const std::string &what, const std::string &name,
                             const std::string &text) {
    write(name, text);
    run(what, name);
  };
  malformed("a node count larger than the file (line 5: 10^9 nodes)", "node_count.msh",
            edited(ex::v2, "$Nodes\n861\n", "$Nodes\n1000000000\n"));
  malformed("an element naming an undefined node (line 870: node 99999)", "undefined_node.msh",
            edit_elements([&](std::vector<long> &e) {
              if (e[0] == 1)
                e[5] = 99999;
              return true;
            }));
  malformed("node 1 defined twice (line 7)", "node_twice.msh",
            edited(ex::v2, "\n2 -30 -15 0\n", "\n1 -30 -15 0\n"));
  malformed("a coordinate 'nan' (line 7)", "nan.msh",
            edited(ex::v2, "\n2 -30 -15 0\n", "\n2 -30 -15 nan\n"));
  malformed("physical volume 300 on a rock hexahedron (line 1240)", "material300.msh",
            first_of(1, [](auto &e) { e[3] = 300; }));
  malformed("element type 17 (a 20-node hexahedron, line 870)", "type17.msh",
            edit_elements([&](std::vector<long> &e) {
              if (e[0] == 1)
                e[1] = 17;
              return true;
            }));
  malformed("the element count written 958.0 (line 869)", "count_not_integer.msh",
            edited(ex::v2, "$Elements\n958\n", "$Elements\n958.0\n"));
  malformed("$Nodez instead of $Nodes (line 4)", "misspelt.msh", edited(ex::v2, "$Nodes", "$Nodez"));
  malformed("format 4.1: a point entity with two physical groups (line 6)", "two_physicals.msh",
            edited(ex::v4, "\n1 -30 -15 -20 0 \n", "\n1 -30 -15 -20 2 7 8 \n"));
  malformed("format 4.1: a node block with parametric coordinates (line 268)", "parametric.msh",
            edited(ex::v4, "\n0 1 0 1\n", "\n0 1 1 1\n"));
  malformed("format 4.1: the $Nodes header says 862 nodes, the blocks hold 861", "node_sum.msh",
            edited(ex::v4, "\n241 861 1 861\n", "\n241 862 1 861\n"));
  malformed("format 4.1: element block of entity dimension 7 (line 2234)", "entity_dimension.msh",
            edited(ex::v4, "\n2 1 3 8\n", "\n7 1 3 8\n"));
  malformed("format 4.1: the $Elements header says 959 elements, the blocks hold 958",
            "element_sum.msh", edited(ex::v4, "\n47 958 1 958\n", "\n47 959 1 958\n"));
  malformed("format 4.1 $Entities in a file whose header says 2.2 (line 4)", "entities_v2.msh",
            edited(ex::v4, "4.1 0 8", "2.2 0 8"));
  {
    // a third hexahedron on the two connected blocks (nodes 1-8 block 0,
    // 9-12 block 1's far side; the joint face is 2 4 6 8): block 0 again,
    // then block 1 again listed from the joint face (its bottom) up
    std::string blocks = ex::two_cubes(true);
    blocks.replace(blocks.find("$Elements\n2\n"), 12, "$Elements\n3\n");
    const auto with = [&](const std::string &third) {
      std::string text = blocks;
      return text.replace(text.find("$EndElements"), 0, third + "\n");
    };
    malformed("block 0 given twice (line 23)", "twice.msh", with("3 5 2 10 1 1 2 4 3 5 6 8 7"));
    malformed("a third hexahedron on the joint face (line 23)", "third.msh",
              with("3 5 2 11 1 2 4 8 6 9 10 12 11"));
  }
  {
    // node 1, the model's corner (-30, -15, -20), belongs to one rock cell
    // only: moved onto node 53, a corner of the same cell, it collapses an
    // edge of that cell and of no other
    std::string        text = read(ex::v2);
    const auto         at   = text.find("\n53 ");
    std::istringstream node(text.substr(at + 1, text.find('\n', at + 1) - at - 1));
    std::string        tag, x, y, z;
    node >> tag >> x >> y >> z;
    malformed("a degenerate hexahedron (node 1 moved onto node 53)", "collapsed_edge.msh",
              edited(ex::v2, "\n1 -30 -15 -20\n", "\n1 " + x + " " + y + " " + z + "\n"));
  }
}
