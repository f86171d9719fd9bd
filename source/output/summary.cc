#include <archdam/base/binary_io.h>
#include <archdam/output/atomic_file.h>
#include <archdam/output/summary.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <functional>
#include <sstream>

namespace archdam::output
{
  namespace
  {
    std::string
    quoted(const std::string &s)
    {
      std::string r = "\"";
      for (const char c : s)
        switch (c)
          {
            case '"':
              r += "\\\"";
              break;
            case '\\':
              r += "\\\\";
              break;
            case '\n':
              r += "\\n";
              break;
            case '\t':
              r += "\\t";
              break;
            case '\r':
              r += "\\r";
              break;
            default:
              // every other control character as \u00XX (JSON allows none
              // raw); bytes of UTF-8 letters (>= 0x80) stay as they are
              if (static_cast<unsigned char>(c) < 0x20)
                {
                  char code[8];
                  std::snprintf(code, sizeof(code), "\\u%04x", static_cast<unsigned char>(c));
                  r += code;
                }
              else
                r += c;
          }
      return r + "\"";
    }

    /// The keys of a path: split at '/', except inside a unit in brackets
    /// ("peaks/C.ax [m/s^2]/value" has three keys).
    std::vector<std::string>
    keys_of(const std::string &path)
    {
      std::vector<std::string> keys(1);
      int                      depth = 0;
      for (const char c : path)
        {
          depth += (c == '[') - (c == ']');
          if (c == '/' && depth == 0)
            keys.emplace_back();
          else
            keys.back() += c;
        }
      return keys;
    }

    void
    upsert(std::vector<std::pair<std::string, std::string>> &entries,
           const std::string &path, const std::string &json)
    {
      for (auto &e : entries)
        if (e.first == path)
          {
            e.second = json;
            return;
          }
      entries.emplace_back(path, json);
    }
  } // namespace

  void
  Summary::set(const std::string &path, const double value)
  {
    std::ostringstream s;
    s.precision(12);
    if (std::isfinite(value))
      s << value;
    else
      s << "null";
    upsert(entries, path, s.str());
  }

  void
  Summary::set(const std::string &path, const std::string &value)
  {
    upsert(entries, path, quoted(value));
  }

  void
  Summary::add_warning(const std::string &text)
  {
    const std::string prefix = "warnings/";
    const auto n = std::count_if(entries.begin(), entries.end(), [&](const auto &entry) {
      return entry.first.compare(0, prefix.size(), prefix) == 0;
    });
    set(prefix + std::to_string(n + 1), text);
  }

  void
  warn(Summary &summary, const dealii::ConditionalOStream &screen, const std::string &text)
  {
    screen << "Warning: " << text << std::endl;
    summary.add_warning(text);
  }

  void
  Summary::write(const std::string &filename) const
  {
    // Build a tree of keys, preserving first-insertion order at each level.
    struct Node
    {
      std::vector<std::pair<std::string, Node>> children;
      std::string                               value;
      Node &
      child(const std::string &key)
      {
        for (auto &c : children)
          if (c.first == key)
            return c.second;
        children.emplace_back(key, Node());
        return children.back().second;
      }
    } root;
    for (const auto &[path, json] : entries)
      {
        Node *n = &root;
        for (const auto &key : keys_of(path))
          n = &n->child(key);
        n->value = json;
      }

    std::ostringstream out;
    const std::function<void(const Node &, unsigned int)> print = [&](const Node  &n,
                                                                      unsigned int depth) {
      if (n.children.empty())
        {
          out << n.value;
          return;
        }
      out << "{\n";
      for (unsigned int i = 0; i < n.children.size(); ++i)
        {
          out << std::string(2 * (depth + 1), ' ') << quoted(n.children[i].first) << ": ";
          print(n.children[i].second, depth + 1);
          out << (i + 1 < n.children.size() ? ",\n" : "\n");
        }
      out << std::string(2 * depth, ' ') << "}";
    };
    print(root, 0);
    out << "\n";

    write_atomically(filename, [&](std::ostream &f) { f << out.str(); });
  }

  void
  Summary::save(std::ostream &out) const
  {
    binary::write(out, entries);
  }

  void
  Summary::load(std::istream &in)
  {
    binary::read(in, entries);
  }
} // namespace archdam::output
