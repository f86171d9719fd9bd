#include <archdam/base/case_file.h>
#include <archdam/base/input_error.h>

#include <filesystem>
#include <fstream>
#include <map>
#include <regex>
#include <sstream>
#include <tuple>

namespace archdam
{
  namespace
  {
    namespace fs = std::filesystem;

    std::string
    trim(const std::string &s)
    {
      const auto first = s.find_first_not_of(" \t\r");
      if (first == std::string::npos)
        return "";
      return s.substr(first, s.find_last_not_of(" \t\r") - first + 1);
    }

    /// The words of a line without its comment, spaces collapsed.
    std::string
    statement(const std::string &line)
    {
      return trim(line.substr(0, line.find('#')));
    }

    struct Reader
    {
      CaseText &result;

      /// (file, section path, entry) -> the line that set it first.
      std::map<std::tuple<std::string, std::string, std::string>, unsigned int> entries;

      /// The section path as the parser will see it (shared by all files,
      /// as an included file continues in the section of its include line).
      std::vector<std::string> sections;

      /// The files being read, outermost first.
      std::vector<fs::path> chain;

      void
      read(const std::string &name, const std::string &where)
      {
        const fs::path  path(name);
        std::error_code ec;
        if (fs::is_directory(path, ec))
          throw InputError(where + "'" + name + "' is a folder, not a case file.");
        std::ifstream in(name);
        if (!in)
          throw InputError(where.empty() ? "Cannot open the parameter file '" + name + "'." :
                                           where + "'" + name + "' cannot be opened.");

        const fs::path canonical = fs::weakly_canonical(path, ec);
        for (const auto &open : chain)
          if (open == canonical)
            {
              std::string cycle;
              for (const auto &f : chain)
                cycle += f.filename().string() + " -> ";
              throw InputError(where + "'" + name + "' includes itself (" + cycle +
                               path.filename().string() + "); an include must not come back "
                               "to a file that is being read.");
            }
        chain.push_back(canonical);

        std::string  line;
        unsigned int number = 0;
        while (std::getline(in, line))
          {
            ++number;
            // A UTF-8 byte-order mark, which some editors write and no one
            // sees, is no part of the first line.
            if (number == 1 && line.rfind("\xEF\xBB\xBF", 0) == 0)
              line.erase(0, 3);
            const std::string s = statement(line);
            if (s.rfind("include ", 0) == 0 || s == "include")
              {
                const std::string included = trim(s.substr(7));
                if (included.empty())
                  throw InputError("Line " + std::to_string(number) + " of file " + name +
                                   ": 'include' names no file.");
                const fs::path target = fs::path(included).is_absolute() ?
                                          fs::path(included) :
                                          path.parent_path() / included;
                read(target.string(), "Line " + std::to_string(number) + " of file " + name +
                                        ": the included file ");
                continue;
              }
            if (s.rfind("subsection ", 0) == 0)
              sections.push_back(trim(s.substr(11)));
            else if (s == "end" && !sections.empty())
              sections.pop_back();
            else if (s.rfind("set ", 0) == 0 && s.find('=') != std::string::npos)
              {
                const std::string entry = trim(s.substr(4, s.find('=') - 4));
                std::string       section;
                for (const auto &sub : sections)
                  section += sub + "/";
                const auto key           = std::make_tuple(name, section, entry);
                const auto [it, is_new] = entries.emplace(key, number);
                if (!is_new)
                  result.warnings.push_back(
                    "'" + section + entry + "' is set twice in " + name + ", in line " +
                    std::to_string(it->second) + " and in line " + std::to_string(number) +
                    "; the second value is used.");
              }
            result.text += line + '\n';
            result.origin.emplace_back(name, number);
          }
        chain.pop_back();
      }
    };
  } // namespace

  std::string
  CaseText::locate(const unsigned int line) const
  {
    if (line == 0 || line > origin.size())
      return "line " + std::to_string(line);
    return "line " + std::to_string(origin[line - 1].second) + " of file " +
           origin[line - 1].first;
  }

  std::string
  CaseText::relocate(const std::string &message) const
  {
    static const std::regex where(R"(Line <(\d+)> of file <[^>:]*)");
    std::string             out;
    auto                    rest = message.cbegin();
    for (std::sregex_iterator m(message.begin(), message.end(), where), end; m != end; ++m)
      {
        out.append(rest, (*m)[0].first);
        const unsigned int line = std::stoul((*m)[1].str());
        if (line >= 1 && line <= origin.size())
          out += "Line <" + std::to_string(origin[line - 1].second) + "> of file <" +
                 origin[line - 1].first;
        else
          out += (*m)[0].str();
        rest = (*m)[0].second;
      }
    out.append(rest, message.cend());
    return out;
  }

  CaseText
  read_case_text(const std::string &filename)
  {
    CaseText result;
    Reader   reader{result, {}, {}, {}};
    reader.read(filename, "");
    bool sets_something = false;
    for (std::istringstream lines(result.text); !sets_something;)
      {
        std::string line;
        if (!std::getline(lines, line))
          break;
        sets_something = statement(line).rfind("set ", 0) == 0;
      }
    if (!sets_something)
      throw InputError("The case file '" + filename +
                       "' sets no parameter (it is empty or holds only comments); "
                       "see archdam --print-parameters for what a case can set.");
    return result;
  }
} // namespace archdam
