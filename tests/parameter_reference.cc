// The parameter reference (issue "core", must show 2): every parameter that
// `archdam --print-parameters` lists has a documentation string and a pattern,
// and the reference shipped in doc/parameters.prm is exactly what the program
// prints today, so the documentation cannot go stale
// (regenerate with scripts/make-parameter-reference.sh).

#include <archdam/parameters/parameters.h>

#include <boost/property_tree/json_parser.hpp>
#include <boost/property_tree/ptree.hpp>

#include <fstream>
#include <sstream>

#include "archdam_tests.h"

namespace
{
  // Walk the JSON tree; an entry is a node with a "value" child.
  void
  walk(const boost::property_tree::ptree &node, const std::string &path, unsigned int &n_entries,
       std::vector<std::string> &undocumented)
  {
    for (const auto &[key, child] : node)
      if (child.get_child_optional("value"))
        {
          ++n_entries;
          if (child.get<std::string>("documentation", "").size() < 10 ||
              child.get<std::string>("pattern_description", "").empty())
            undocumented.push_back(path + key);
        }
      else
        walk(child, path + key + "/", n_entries, undocumented);
  }
} // namespace

int
main(int argc, char **argv)
{
  dealii::Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  auto                                    &log = archdam::testing::log();

  std::stringstream json;
  archdam::print_parameters(json, "json");
  boost::property_tree::ptree tree;
  boost::property_tree::read_json(json, tree);
  unsigned int             n_entries = 0;
  std::vector<std::string> undocumented;
  walk(tree, "", n_entries, undocumented);
  log << "parameters listed: more than 40: " << (n_entries > 40 ? "yes" : "NO") << std::endl;
  log << "parameters without documentation or pattern: " << undocumented.size() << std::endl;
  for (const auto &u : undocumented)
    log << "  " << u << std::endl;

  std::ostringstream prm;
  archdam::print_parameters(prm, "text");
  std::ifstream     file(SOURCE_DIR "/../doc/parameters.prm");
  std::stringstream shipped;
  shipped << file.rdbuf();
  log << "doc/parameters.prm matches --print-parameters: "
      << (shipped.str() == prm.str() ? "yes" : "NO (run scripts/make-parameter-reference.sh)")
      << std::endl;
}
