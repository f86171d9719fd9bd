// The run report (issue "evaluation", must show 4; doc/user-guide.md, "The
// run report"): the coarse arch dam with 13 frictional joints
// (prm/arch_dam_joints_coarse.prm), 0.3 s of El Centro, a monitor at the
// crown's crest and the face evaluation on, run as a user runs it (the
// command line, in process). Its report.html is read here:
//  - it is one self-contained page: every image is a PNG embedded as a data
//    URI (its bytes decoded here, the PNG signature checked), and nothing
//    is loaded from elsewhere (no http(s):// address, no src or href to a
//    file but the page itself);
//  - it holds each section an engineer looks for;
//  - its numbers are the run's: each joint's peak opening and peak slip of
//    summary.json, in mm with 6 digits, is a cell of the joints' table, and
//    so is every monitor peak.

#include <archdam/application/command_line.h>

#include "archdam_tests.h"
#include "child_process.h"
#include "command_line_tests.h"

#include <boost/property_tree/json_parser.hpp>
#include <boost/property_tree/ptree.hpp>

#include <cstdio>

using namespace dealii;

namespace
{
  /// The bytes of a base64 text.
  std::string
  decode_base64(const std::string &text)
  {
    const std::string alphabet =
      "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";
    std::string  bytes;
    unsigned int buffer = 0, bits = 0;
    for (const char c : text)
      {
        const auto k = alphabet.find(c);
        if (k == std::string::npos)
          continue; // padding
        buffer = (buffer << 6) | k;
        bits += 6;
        if (bits >= 8)
          {
            bits -= 8;
            bytes.push_back(static_cast<char>((buffer >> bits) & 0xFF));
          }
      }
    return bytes;
  }

  std::string
  cell(const double value)
  {
    char text[64];
    std::snprintf(text, sizeof(text), "%.6g", value);
    return std::string(">") + text + "</td>";
  }
} // namespace

int
main(int argc, char **argv)
{
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  auto                            &log = archdam::testing::log();
  std::string                      err;
  const int code = archdam::testing::run_in_process(
    archdam::run_command_line, "archdam",
    {SOURCE_DIR "/../prm/arch_dam_joints_coarse.prm", "--set", "Time integration/End time=0.3",
     "--set", "Output/Directory=report_run", "--set", "Output/Field output interval=0", "--set",
     "Output/Progress=false", "--set", "Output/Timer summary=false", "--set",
     "Evaluation/Evaluate=true", "--set", "Evaluation/Tensile strength=1e6", "--set",
     "Monitors/Points=crest: 0, 0, 235", "--set", "Monitors/Quantities=displacement"},
    err);
  log << "exit code " << code << " " << err << std::endl;
  if (Utilities::MPI::this_mpi_process(MPI_COMM_WORLD) != 0)
    return 0;

  const std::string page = archdam::testing::read_file("report_run/report.html");
  log << "report.html written: " << archdam::testing::yes(!page.empty()) << std::endl;

  // Self-contained: the images are embedded PNGs, nothing else is fetched.
  // (scanned by hand: std::regex recurses per character and overflows the
  // stack on a base64 text of a few hundred kB)
  unsigned int      images = 0, png = 0, links = 0;
  const std::string data   = "src=\"data:image/png;base64,";
  for (auto at = page.find("<img"); at != std::string::npos; at = page.find("<img", at + 1))
    {
      ++images;
      const auto start = page.find(data, at);
      if (start != std::string::npos && start < page.find('>', at))
        png += decode_base64(page.substr(start + data.size(), 16)).substr(0, 8) ==
               std::string("\x89PNG\r\n\x1a\n", 8);
    }
  for (const std::string reference : {"src=\"", "href=\""})
    for (auto at = page.find(reference); at != std::string::npos;
         at = page.find(reference, at + 1))
      links += page.compare(at + reference.size(), 5, "data:") != 0;
  for (const std::string address : {"http://", "https://"})
    for (auto at = page.find(address); at != std::string::npos; at = page.find(address, at + 1))
      ++links;
  log << "images: " << images << ", each a PNG: " << archdam::testing::yes(png == images)
      << "\nreferences to other files or addresses: " << links << std::endl;

  for (const std::string section :
       {"Warnings", "Model", "Input motion", "Static state", "Contraction joints: openings and slips",
        "Joint openings along the height", "Peaks of the monitored quantities",
        "Stresses on the faces", "Demand-capacity ratio: arch DCR",
        "Demand-capacity ratio: cantilever DCR", "Energy balance"})
    log << "section '" << section << "': "
        << archdam::testing::yes(page.find("<h2>" + section + "</h2>") != std::string::npos)
        << std::endl;

  // The numbers are the run's.
  boost::property_tree::ptree summary;
  boost::property_tree::read_json("report_run/summary.json", summary);
  const auto value = [&](const std::string &path) {
    return summary.get<double>(boost::property_tree::ptree::path_type(path, '|'));
  };
  unsigned int found = 0, n = 0;
  for (unsigned int j = 0; j < 13; ++j)
    for (const std::string q : {"peak opening [m]", "peak slip [m]"})
      {
        ++n;
        found += page.find(cell(1e3 * value("dynamic|joints|joint " + std::to_string(j) + "|" + q))) !=
                 std::string::npos;
      }
  for (const std::string q : {"crest.ux [m]", "crest.uy [m]", "crest.uz [m]"})
    {
      ++n;
      found += page.find(cell(value("peaks|" + q + "|value"))) != std::string::npos;
    }
  log << "the summary's joint peaks (mm) and monitor peaks found in the page: " << found << " of "
      << n << std::endl;
}
