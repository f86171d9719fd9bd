// Bad input the earlier error tests do not reach, as the user meets it on the
// command line (doc/bad-input.md lists every row with its test): each case
// must end with exit code 1 and one message naming the parameter (or file)
// and what is wrong, never a crash, a hang or a run with a silently wrong
// value. Each case is a valid short case (a box dam of two blocks, one
// contraction joint) with one thing made wrong, mostly by --set.

#include "case_text.h"
#include "command_line_tests.h"

#include <archdam/output/run_lock.h>

#include <filesystem>
#include <regex>

using archdam::testing::run_archdam;
using archdam::testing::write_input;

namespace
{
  /// The good case with one more parameter.
  void
  run_set(const std::string &what, const std::string &assignment)
  {
    run_archdam(what, {"good.prm", "--set", assignment});
  }

  /// The good case with frictional joints and one more parameter.
  void
  run_joints(const std::string &what, const std::string &assignment)
  {
    run_archdam(what, {"good.prm", "--set", "Contraction joints/Model=frictional contact",
                       "--set", assignment});
  }

  const std::string good_case = archdam::testing::case_text::short_box_case(
    "    set Number of blocks = 2\n    set Cells in y = 2\n");

  // A PEER record whose one sample, 1e308 g, is a number but not in m/s^2.
  const char *huge_at2 = "PEER NGA STRONG MOTION DATABASE RECORD\n"
                         "test record\n"
                         "ACCELERATION TIME SERIES IN UNITS OF G\n"
                         "NPTS=    3, DT=   .0100 SEC\n"
                         "  .1000E-01  1.0000E+308  .2000E-01\n";

  /// run_archdam(), with what changes from run to run or machine to
  /// machine in the message (process number, host, start time; the
  /// machine's memory) replaced by "...".
  void
  run_masked(const std::string &what, const std::vector<std::string> &args)
  {
    std::string err;
    const int   code =
      archdam::testing::run_in_process(archdam::run_command_line, "archdam", args, err);
    err = std::regex_replace(err, std::regex(R"(\(process [0-9]+ on [^,]*, started [^)]*\))"),
                             "(process ..., started ...)");
    err = std::regex_replace(err, std::regex(R"(this machine has [0-9.e+]+ GB)"),
                             "this machine has ... GB");
    archdam::testing::log() << "* " << what << "\n  exit code " << code << "\n  " << err
                            << std::endl;
  }

  /// A .msh file (format 2.2) of one unit hexahedron of material @p id.
  std::string
  gmsh_hexahedron(const int id)
  {
    return "$MeshFormat\n2.2 0 8\n$EndMeshFormat\n$Nodes\n8\n1 0 0 0\n2 1 0 0\n"
           "3 1 1 0\n4 0 1 0\n5 0 0 1\n6 1 0 1\n7 1 1 1\n8 0 1 1\n$EndNodes\n"
           "$Elements\n1\n1 5 2 " +
           std::to_string(id) + " 1 1 2 3 4 5 6 7 8\n$EndElements\n";
  }
} // namespace

int
main(int argc, char **argv)
{
  dealii::Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);

  write_input("good.prm", good_case);
  write_input("huge.AT2", huge_at2);
  write_input("rock_only.msh", gmsh_hexahedron(1));
  write_input("tetrahedron.msh", "$MeshFormat\n2.2 0 8\n$EndMeshFormat\n$Nodes\n4\n1 0 0 0\n"
                                 "2 1 0 0\n3 0 1 0\n4 0 0 1\n$EndNodes\n$Elements\n1\n"
                                 "1 4 2 10 1 1 2 3 4\n$EndElements\n");
  if (dealii::Utilities::MPI::this_mpi_process(MPI_COMM_WORLD) == 0)
    {
      for (const std::string blocked : {"blocked_histories", "blocked_summary"})
        std::filesystem::remove_all(blocked);
      std::filesystem::create_directories("blocked_histories/histories.csv");
      std::filesystem::create_directories("blocked_summary/summary.json");
    }
  MPI_Barrier(MPI_COMM_WORLD);

  // Command line
  run_archdam("two case files", {"good.prm", "good.prm"});
  write_input("includes_missing.prm", "include no_such_case.prm\n");
  run_archdam("a case file that includes a file that does not exist", {"includes_missing.prm"});
  run_archdam("--print-parameters with two formats", {"--print-parameters", "json", "xml"});
  run_archdam("--print-parameters with an unknown format", {"--print-parameters", "yaml"});

  // Values out of range, inconsistent values
  run_set("a time step of 0", "Time integration/Time step=0");
  run_archdam("the demand-capacity evaluation without a tensile strength",
              {"good.prm", "--set", "Evaluation/Evaluate=true"});
  run_archdam("a DCR level of 0",
              {"good.prm", "--set", "Evaluation/Evaluate=true", "--set",
               "Evaluation/Tensile strength=3e6", "--set", "Evaluation/DCR levels=0, 1.5, 2"});
  run_archdam("a performance curve without an area limit",
              {"good.prm", "--set", "Evaluation/Evaluate=true", "--set",
               "Evaluation/Tensile strength=3e6", "--set", "Evaluation/Allowed CID at DCR 1=0.4"});
  run_archdam("an allowed DCR of 1 for the performance curve",
              {"good.prm", "--set", "Evaluation/Evaluate=true", "--set",
               "Evaluation/Tensile strength=3e6", "--set", "Evaluation/Allowed CID at DCR 1=0.4",
               "--set", "Evaluation/Allowed overstressed share=0.2", "--set",
               "Evaluation/Allowed DCR=1"});
  run_archdam("a joint band with joints of no tensile strength",
              {"good.prm", "--set", "Evaluation/Evaluate=true", "--set",
               "Evaluation/Tensile strength=3e6", "--set", "Evaluation/Joint band width=2", "--set",
               "Contraction joints/Tensile strength=0"});
  run_set("an end time shorter than one time step", "Time integration/End time=0.004");
  run_set("a temperature table row without its ':'", "Static loads/Temperature change=0 -5, 3");
  run_set("temperature table elevations that do not increase",
          "Static loads/Temperature change=10: -5, 3; 5: -4, 2");
  run_set("a temperature change of 500 degrees", "Static loads/Temperature change=0: -500, 3");
  run_set("a temperature table that does not reach the dam's crest",
          "Static loads/Temperature change=0: -5, 3; 1: -5, 3");
  run_set("a thermal expansion coefficient of 1 per degree",
          "Materials/Concrete/Thermal expansion coefficient=1");
  run_archdam("damping frequencies in the wrong order",
      {"good.prm", "--set", "Damping/Mode=damping ratio", "--set",
       "Damping/First frequency=20", "--set", "Damping/Second frequency=10"});
  run_archdam("the rock's damping frequencies in the wrong order",
      {"good.prm", "--set", "Damping/Rock/Mode=damping ratio", "--set",
       "Damping/Rock/First frequency=20", "--set", "Damping/Rock/Second frequency=10"});
  run_set("a rock damping mode misspelt", "Damping/Rock/Mode=same as dam");
  run_set("no stage to run", "Analysis/Stages=");
  run_set("a record suite naming a record that is not there",
          "Record suite/Records=one: x = /no_such_folder/no_such_record.AT2");
  run_set("a record suite entry without its name",
          "Record suite/Records=x = ground_motions/RSN6_IMPVALL.I_I-ELC180.AT2");
  run_set("a record suite with a record's scale of 0",
          "Record suite/Records=one: x = ground_motions/RSN6_IMPVALL.I_I-ELC180.AT2 * 0");
  run_archdam("a record suite scaled to the target over periods in the wrong order",
              {"good.prm", "--set", "Record suite/Scale to target=true", "--set",
               "Record suite/Shortest period=2", "--set", "Record suite/Longest period=1"});
  run_set("a record suite with a name given twice",
          "Record suite/Records=one: x = ground_motions/RSN6_IMPVALL.I_I-ELC180.AT2; "
          "one: y = ground_motions/RSN6_IMPVALL.I_I-ELC270.AT2");
  run_set("an output directory inside a file", "Output/Directory=good.prm/results");
  run_set("a negative checkpoint interval", "Checkpoints/Interval (steps)=-5");
  run_set("a negative checkpoint wall-time interval", "Checkpoints/Wall-time interval (s)=-60");

  // Mesh
  run_set("box cells across the dam not a multiple of the blocks", "Mesh/Box/Cells in y=3");
  run_set("Mesh/Source = gmsh without a file", "Mesh/Source=gmsh");

  run_archdam("a Gmsh mesh without dam cells",
              {"good.prm", "--set", "Mesh/Source=gmsh", "--set", "Mesh/Gmsh/File=rock_only.msh"});
  run_archdam("a Gmsh mesh of tetrahedra",
              {"good.prm", "--set", "Mesh/Source=gmsh", "--set", "Mesh/Gmsh/File=tetrahedron.msh"});

  // Points outside their region
  const std::string blocks = "Mesh/Gmsh/File=" SOURCE_DIR "/../prm/gmsh_blocks_v4.msh";
  run_archdam("a pressure point outside the water",
      {"good.prm", "--set", "Mesh/Source=gmsh", "--set", blocks, "--set",
       "Reservoir/Model=compressible", "--set", "Reservoir/Pressure points=dry: 5, 5, 5"});

  // A full disk: the device /dev/full, on which every write fails with "no
  // space left on device", in place of a result file. One line with the file
  // and the system's reason.
  if (dealii::Utilities::MPI::this_mpi_process(MPI_COMM_WORLD) == 0)
    for (const auto &[directory, file] :
         {std::pair{"full_histories", "histories.csv"}, {"full_vtu", "solution_00000.0.vtu.tmp"},
          {"full_hdf5", "solution_00000.h5.tmp"}})
      {
        std::filesystem::remove_all(directory);
        std::filesystem::create_directories(directory);
        std::filesystem::create_symlink("/dev/full", std::string(directory) + "/" + file);
      }
  MPI_Barrier(MPI_COMM_WORLD);
  // (Output/Earlier results = keep: the obstacles carry the names of result
  // files, which a new run would otherwise remove first.)
  const std::string keep = "Output/Earlier results=keep";
  run_archdam("histories.csv on a full disk",
              {"good.prm", "--set", "Output/Directory=full_histories", "--set", keep});
  run_archdam("a VTU piece on a full disk",
              {"good.prm", "--set", "Output/Directory=full_vtu", "--set",
               "Output/Field output interval=1", "--set", "Output/Field formats=vtu", "--set",
               keep});
  run_archdam("an HDF5 field file on a full disk",
              {"good.prm", "--set", "Output/Directory=full_hdf5", "--set",
               "Output/Field output interval=1", "--set", "Output/Field formats=hdf5", "--set",
               keep});

  // Result files that cannot be written (a directory in the way)
  run_archdam("a directory where histories.csv goes",
              {"good.prm", "--set", "Output/Directory=blocked_histories", "--set", keep});
  run_archdam("a directory where summary.json goes",
              {"good.prm", "--set", "Output/Directory=blocked_summary", "--set", keep});

  // Monitors
  run_set("a monitor name with a blank", "Monitors/Points=dam crest: 5, 10, 20");
  run_set("a monitor point with two coordinates", "Monitors/Points=crest: 5, 10");
  run_set("a monitor coordinate that is not a number", "Monitors/Points=crest: 5, 10, top");
  run_set("a monitor name used twice", "Monitors/Points=a: 5, 10, 20; a: 5, 5, 20");

  // Case files: includes, empty files, folders, entries set twice
  write_input("self.prm", "include self.prm\n");
  write_input("ping.prm", "include pong.prm\n");
  write_input("pong.prm", "# the other half of a cycle\ninclude ping.prm\n");
  write_input("empty.prm", "");
  write_input("comments_only.prm", "# a case file with nothing set\n\n");
  write_input("twice.prm", good_case + "\nsubsection Time integration\n"
                                       "  set Time step = 0.01\n  set Time step = 0.005\nend\n");
  if (dealii::Utilities::MPI::this_mpi_process(MPI_COMM_WORLD) == 0)
    {
      std::filesystem::create_directories("a_folder.prm");
      std::filesystem::create_directories("cases/variants");
      std::filesystem::create_directories("cases/parts");
    }
  MPI_Barrier(MPI_COMM_WORLD);
  // A variant in a subfolder includes the base case one folder up, which
  // includes a part from its own subfolder: each name relative to the file
  // that holds it, whatever the working directory.
  write_input("cases/variants/variant.prm", "include ../base.prm\n");
  write_input("cases/base.prm", "include parts/time.prm\n" + good_case);
  write_input("cases/parts/time.prm",
              "subsection Time integration\n  set Time step = 0.01\nend\n");
  run_archdam("a case file that includes itself", {"self.prm"});
  run_archdam("two case files that include each other", {"ping.prm"});
  run_archdam("an empty case file", {"empty.prm"});
  run_archdam("a case file with only comments", {"comments_only.prm"});
  run_archdam("a case file that is a folder", {"a_folder.prm"});
  run_archdam("includes relative to each including file (runs)",
              {"cases/variants/variant.prm"});
  run_archdam("an entry set twice in one section (runs, with a warning)", {"twice.prm"});
  write_input("byte_order_mark.prm", "\xEF\xBB\xBF" + good_case.substr(good_case.find("subsection")));
  run_archdam("a case file that begins with a UTF-8 byte-order mark (runs)",
              {"byte_order_mark.prm"});

  // Values that are numbers but cannot be meant
  run_set("an end time of 1e9 s", "Time integration/End time=1e9");
  run_set("an end time of 1e308 s", "Time integration/End time=1e308");
  run_set("a time step of 1e-300 s", "Time integration/Time step=1e-300");
  run_set("a monitor coordinate nan", "Monitors/Points=crest: 5, nan, 20");
  run_set("a concrete density of 0", "Materials/Concrete/Density=0");
  run_set("a Young's modulus of 0", "Materials/Concrete/Young's modulus=0");
  run_set("a Young's modulus of 1e308", "Materials/Rock/Young's modulus=1e308");
  run_set("a scale factor of 1e308", "Ground motion/Component x/Scale factor=1e308");
  run_set("gravity without a static stage", "Analysis/Stages=dynamic");

  // One run at a time in an output directory: a run holds it (here this
  // process, as a second run started at the same time would), and a second
  // one, or a resumed one, stops before writing anything.
  {
    const archdam::output::RunLock running("busy", "good", MPI_COMM_WORLD);
    run_masked("a second run in the output directory of a running one",
               {"good.prm", "--set", "Output/Directory=busy"});
    run_masked("--resume in the output directory of a running run",
               {"good.prm", "--set", "Output/Directory=busy", "--resume"});
  }
  run_set("the same directory once the first run has ended (runs)", "Output/Directory=busy");

  // Ground motion
  run_set("a record sample beyond the range of double in m/s^2",
          "Ground motion/Component x/File=huge.AT2");
  write_input("short.csv", "0, 0.1\n0.02, 0.2\n");
  write_input("in_cm.csv", "0, 0\n0.01, 275\n0.02, -130\n0.03, 0\n");
  // The good case shaken in x by the two-column record @p file in @p units.
  const auto with_record = [](const std::string &file, const std::string &units,
                              std::vector<std::string> more) {
    std::vector<std::string> args{"good.prm", "--set", "Ground motion/Component x/File=" + file,
                                  "--set", "Ground motion/Component x/Format=two-column",
                                  "--set", "Ground motion/Component x/Units=" + units};
    args.insert(args.end(), more.begin(), more.end());
    return args;
  };
  run_archdam("a record in cm/s^2 read as g (PGA 275 g)", with_record("in_cm.csv", "g", {}));
  run_archdam("a time step not shorter than the ground motion (0.05 s on a record of 0.02 s)",
              with_record("short.csv", "m/s^2",
                          {"--set", "Time integration/Time step=0.05", "--set",
                           "Time integration/End time=0.1"}));

  // Contraction joints
  run_set("a negative friction coefficient", "Contraction joints/Friction coefficient=-0.5");
  run_set("a negative tensile strength", "Contraction joints/Tensile strength=-1e6");
  run_joints("Per joint without ':'", "Contraction joints/Per joint=0 Cohesion = 1e5");
  run_joints("Per joint with a joint that is not a number",
             "Contraction joints/Per joint=first: Cohesion = 1e5");
  run_joints("Per joint with a negative joint number",
             "Contraction joints/Per joint=-1: Cohesion = 1e5");
  run_joints("Per joint with a joint the model does not have",
             "Contraction joints/Per joint=3: Cohesion = 1e5");
  run_joints("Per joint with an unknown name",
             "Contraction joints/Per joint=0: Friction = 0.5");
  run_joints("Per joint without '='", "Contraction joints/Per joint=0: Cohesion 1e5");
  run_joints("Per joint with a value that is not a number",
             "Contraction joints/Per joint=0: Cohesion = high");
  run_joints("Per joint with a negative friction coefficient",
             "Contraction joints/Per joint=0: Friction coefficient = -0.2");
  run_joints("Per joint with an infinite cohesion", "Contraction joints/Per joint=0: Cohesion = inf");
  run_joints("Per joint with a hexadecimal value",
             "Contraction joints/Per joint=0: Tensile strength = 0x10");
  run_joints("Per joint with a hexadecimal joint number",
             "Contraction joints/Per joint=0x0: Cohesion = 1e5");
  run_joints("Per joint with a joint given twice",
             "Contraction joints/Per joint=0: Cohesion = 1e5; 0: Cohesion = 2e5");
  run_joints("a joint monitor point with two coordinates",
             "Contraction joints/Monitor points=crest: 5, 10");
  run_joints("a joint monitor coordinate that is not a number",
             "Contraction joints/Monitor points=crest: 5, ten, 20");
  run_archdam("joint monitor points in a dam of one block (no joints)",
      {"good.prm", "--set", "Mesh/Box/Number of blocks=1", "--set",
       "Contraction joints/Model=frictional contact", "--set",
       "Contraction joints/Monitor points=crest: 5, 10, 20"});
  run_archdam("a monolithic contact solver with a penalty too large to solve",
      {"good.prm", "--set", "Contraction joints/Model=frictional contact", "--set",
       "Contraction joints/Solver=monolithic", "--set", "Contraction joints/Contact in time=trapezoidal",
       "--set", "Contraction joints/Penalty factor=1e300"});
  // The mesh's size against the machine's memory, counted before the mesh
  // is made ("user holes, second round", item 8; the machine's memory masked).
  const auto run_sized = [](const std::string &what, const std::vector<std::string> &sets,
                            const bool mesh_only = false) {
    std::vector<std::string> args{"good.prm"};
    if (mesh_only)
      args.push_back("--mesh-only");
    for (const auto &s : sets)
      args.insert(args.end(), {"--set", s});
    run_masked(what, args);
  };
  run_set("a rock cell size of 0 on the box", "Mesh/Box/Rock cell size=0");
  run_sized("a rock cell size of 1 mm on the box",
            {"Mesh/Box/Rock depth=20", "Mesh/Box/Rock cell size=0.001"});
  run_sized("a rock cell size of 1 mm on the box, --mesh-only",
            {"Mesh/Box/Rock depth=20", "Mesh/Box/Rock cell size=0.001"}, true);
  run_sized("1000 cell layers over the arch dam's height",
            {"Mesh/Source=arch dam", "Mesh/Arch dam/Cells over height=1000"});
  run_sized("a rock cell size of 0 on the arch dam",
            {"Mesh/Source=arch dam", "Mesh/Arch dam/Rock cell size=0"});
  // An absurd static state (item 10): g = 1e9 m/s^2.
  run_set("a gravitational acceleration of 1e9 m/s^2",
          "Static loads/Gravitational acceleration=1e9");
  run_archdam("the step impulse with the monolithic contact solver",
      {"good.prm", "--set", "Contraction joints/Model=frictional contact", "--set",
       "Contraction joints/Solver=monolithic", "--set",
       "Contraction joints/Contact in time=step impulse"});
  run_set("a low-rank factor with glued joints", "Time integration/Low-rank tolerance=1e-8");
  run_set("a single-precision factor with glued joints",
          "Time integration/Factor precision=single");
}
