#pragma once

#include <string>
#include <utility>
#include <vector>

namespace archdam
{
  /**
   * The text of a case file with its `include` lines replaced by the files
   * they name, so that every command reads a case the same way.
   *
   * A relative name in `include NAME` is taken relative to the folder of the
   * file that holds the line (not the working directory). A file that
   * includes itself, directly or through others, an included file that is
   * missing, a case file that is empty or is not a regular file are
   * InputErrors naming the file (and the include chain).
   *
   * Each line of the joined text remembers the file and line it came from, so
   * that a message about "Line <n> of file <case>" can be said of the file the
   * user wrote (locate()). An entry set twice in the same section of one file
   * is kept (the last one wins, as always) and reported in warnings, naming
   * both lines; an entry of an included file set again by the including file is
   * the intended way to change a case and is not reported.
   */
  struct CaseText
  {
    /// The joined text, one line per line of the files.
    std::string text;

    /// For each line of @p text (0-based), the file and its 1-based line.
    std::vector<std::pair<std::string, unsigned int>> origin;

    /// One sentence per entry set twice in one section of one file.
    std::vector<std::string> warnings;

    /// "line N of file F" for the 1-based line @p line of the joined text.
    std::string
    locate(unsigned int line) const;

    /// @p message with every "Line <n> of file <...>" of the joined text
    /// replaced by the file and line that the user wrote.
    std::string
    relocate(const std::string &message) const;
  };

  /// Read the case file @p filename and everything it includes.
  CaseText
  read_case_text(const std::string &filename);
} // namespace archdam
