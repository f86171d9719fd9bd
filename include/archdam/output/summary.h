#pragma once

#include <deal.II/base/conditional_ostream.h>

#include <iosfwd>
#include <map>
#include <string>
#include <utility>
#include <vector>

namespace archdam::output
{
  /**
   * `summary.json`: a small JSON document built from named entries (numbers,
   * strings, and nested objects), written by rank 0 to a temporary name and
   * renamed, so a reader never sees half a file.
   */
  class Summary
  {
  public:
    void
    set(const std::string &path, double value);
    void
    set(const std::string &path, const std::string &value);
    /// Keep @p text as the next of the summary's warnings (warnings/N).
    void
    add_warning(const std::string &text);
    /// Write as JSON; keys with '/' become nested objects (a '/' inside
    /// brackets, as in a unit [m/s^2], belongs to the key).
    void
    write(const std::string &filename) const;

    /// The entries so far, for a checkpoint (output/checkpoint.h); load()
    /// replaces them.
    void
    save(std::ostream &out) const;
    void
    load(std::istream &in);

  private:
    // path -> JSON-encoded value, in insertion order
    std::vector<std::pair<std::string, std::string>> entries;
  };

  /// Say @p text on @p screen as a warning and keep it in @p summary: what
  /// does not stop the run but may make its results other than the user
  /// expects.
  void
  warn(Summary &summary, const dealii::ConditionalOStream &screen, const std::string &text);
} // namespace archdam::output
