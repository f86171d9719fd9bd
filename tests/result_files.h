// What a run leaves in its output directory must be readable whatever moment
// the run ended at (output/atomic_file.h): checks shared by the tests of the
// divergence stop and of killed runs. Each check parses a file with a reader
// that knows nothing of ArchDam's writers (boost's JSON and XML parsers, a
// strict CSV reader).
#pragma once

#include <boost/property_tree/json_parser.hpp>
#include <boost/property_tree/xml_parser.hpp>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

namespace archdam::testing
{
  /// A CSV history: a header, then rows of numbers, each with as many fields
  /// as the header, the file ending with a complete line.
  struct CsvHistory
  {
    bool                             valid = false;
    std::string                      problem;
    std::vector<std::vector<double>> rows;
  };

  inline std::vector<std::string>
  csv_fields(const std::string &line)
  {
    std::vector<std::string> fields;
    std::stringstream        s(line);
    for (std::string f; std::getline(s, f, ',');)
      fields.push_back(f);
    if (!line.empty() && line.back() == ',')
      fields.emplace_back();
    return fields;
  }

  inline CsvHistory
  read_csv_history(const std::string &file)
  {
    CsvHistory    h;
    std::ifstream in(file, std::ios::binary);
    if (!in)
      {
        h.problem = "missing";
        return h;
      }
    const std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    if (text.empty() || text.back() != '\n')
      {
        h.problem = "does not end with a complete line";
        return h;
      }
    std::stringstream lines(text);
    std::string       line;
    std::getline(lines, line);
    const std::size_t n_columns = csv_fields(line).size();
    while (std::getline(lines, line))
      {
        const auto           fields = csv_fields(line);
        std::vector<double> row;
        for (const auto &f : fields)
          {
            char        *end = nullptr;
            const double x   = std::strtod(f.c_str(), &end);
            if (f.empty() || *end != '\0')
              {
                h.problem = "row " + std::to_string(h.rows.size() + 1) + ": '" + f +
                            "' is not a number";
                return h;
              }
            row.push_back(x);
          }
        if (row.size() != n_columns)
          {
            h.problem = "row " + std::to_string(h.rows.size() + 1) + " has " +
                        std::to_string(row.size()) + " fields, the header " +
                        std::to_string(n_columns);
            return h;
          }
        h.rows.push_back(row);
      }
    h.valid = true;
    return h;
  }

  /// Parse @p file as JSON; "" if it parses, else the parser's message.
  inline std::string
  json_problem(const std::string &file, boost::property_tree::ptree &tree)
  {
    try
      {
        boost::property_tree::read_json(file, tree);
        return "";
      }
    catch (const std::exception &e)
      {
        return e.what();
      }
  }

  /**
   * A ParaView time series: @p pvd parses as XML, and so does every file it
   * names (a .pvtu record and the .vtu pieces it names in turn), all of them
   * existing. Returns "" or the first problem; @p n_files counts the files.
   */
  inline std::string
  pvd_problem(const std::string &directory, const std::string &pvd, unsigned int &n_files)
  {
    namespace pt = boost::property_tree;
    n_files      = 0;
    const auto parse = [&](const std::string &name, pt::ptree &tree) -> std::string {
      try
        {
          pt::read_xml(directory + "/" + name, tree);
          ++n_files;
          return "";
        }
      catch (const std::exception &e)
        {
          return name + ": " + e.what();
        }
    };
    pt::ptree tree;
    if (auto problem = parse(pvd, tree); !problem.empty())
      return problem;
    for (const auto &[tag, dataset] : tree.get_child("VTKFile.Collection"))
      if (tag == "DataSet")
        {
          const auto file = dataset.get<std::string>("<xmlattr>.file");
          pt::ptree  record;
          if (auto problem = parse(file, record); !problem.empty())
            return problem;
          if (file.size() > 5 && file.substr(file.size() - 5) == ".pvtu")
            for (const auto &[piece_tag, piece] : record.get_child("VTKFile.PUnstructuredGrid"))
              if (piece_tag == "Piece")
                {
                  pt::ptree vtu;
                  if (auto problem = parse(piece.get<std::string>("<xmlattr>.Source"), vtu);
                      !problem.empty())
                    return problem;
                }
        }
    return "";
  }
} // namespace archdam::testing
