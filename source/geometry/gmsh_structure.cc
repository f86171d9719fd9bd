#include <archdam/base/input_error.h>
#include <archdam/geometry/gmsh_structure.h>

#include <algorithm>
#include <array>
#include <cctype>
#include <charconv>
#include <climits>
#include <cmath>
#include <cstdlib>
#include <map>
#include <set>
#include <unordered_set>
#include <vector>

namespace archdam::geometry
{
  namespace
  {
    /// Ids GridIn stores: material and boundary ids 0-254 (255 is deal.II's
    /// invalid material id and internal-face boundary id).
    constexpr long long max_id = 254;

    /// The whitespace-separated words of the file, as std::istream reads them.
    class Words
    {
    public:
      Words(const std::string &text, const std::string &where)
        : text(text)
        , where(where)
      {}

      /// The next word, or "" at the end of the file.
      std::string
      next()
      {
        while (pos < text.size() && std::isspace(static_cast<unsigned char>(text[pos])))
          line += text[pos++] == '\n';
        const std::size_t start = pos;
        while (pos < text.size() && !std::isspace(static_cast<unsigned char>(text[pos])))
          ++pos;
        return text.substr(start, pos - start);
      }

      /// The line of the last word read.
      unsigned int
      line_number() const
      {
        return line;
      }

      [[noreturn]] void
      fail(const std::string &what) const
      {
        throw InputError(where + " is malformed at line " + std::to_string(line) + ": " + what +
                         ".");
      }

      void
      expect(const std::string &marker)
      {
        const std::string word = next();
        if (word != marker)
          fail("expected " + marker + ", found " + shown(word));
      }

      /// An integer in [min, max], written as digits with an optional '-'.
      long long
      integer(const std::string &what, const long long min, const long long max)
      {
        const std::string word  = next();
        long long         value = 0;
        const auto [end, error] = std::from_chars(word.data(), word.data() + word.size(), value);
        if (word.empty() || error != std::errc() || end != word.data() + word.size())
          fail("expected " + what + " (an integer), found " + shown(word));
        if (value < min || value > max)
          fail(what + " " + word + " is outside " + std::to_string(min) + " to " +
               std::to_string(max));
        return value;
      }

      /// A finite number in decimal notation (what std::istream and strtod
      /// read alike).
      double
      real(const std::string &what)
      {
        const std::string word = next();
        bool              ok   = !word.empty();
        for (const char c : word)
          ok = ok && (std::isdigit(static_cast<unsigned char>(c)) || c == '-' || c == '+' ||
                      c == '.' || c == 'e' || c == 'E');
        char        *end   = nullptr;
        const double value = ok ? std::strtod(word.c_str(), &end) : 0.;
        if (!ok || end != word.c_str() + word.size() || !std::isfinite(value))
          fail("expected " + what + " (a finite number), found " + shown(word));
        return value;
      }

      /// A count of items of at least @p words_each words that must fit in
      /// the rest of the file (each word takes two characters or more with
      /// its separator).
      long long
      count(const std::string &what, const long long words_each)
      {
        const long long n    = integer(what, 0, INT_MAX);
        const long long left = static_cast<long long>(text.size() - pos) / 2 + 1;
        if (n > left / words_each)
          fail(what + " " + std::to_string(n) +
               " is more than the rest of the file holds (truncated file, or a wrong count?)");
        return n;
      }

    private:
      static std::string
      shown(const std::string &word)
      {
        if (word.empty())
          return "the end of the file";
        return "'" + (word.size() > 40 ? word.substr(0, 40) + "..." : word) + "'";
      }

      const std::string &text;
      const std::string  where;
      std::size_t        pos  = 0;
      unsigned int       line = 1;
    };

    /// Nodes of a Gmsh element type ArchDam reads, 0 for a volume or face
    /// type that is not a hexahedron or quadrangle.
    unsigned int
    nodes_of(Words &words, const long long type)
    {
      switch (type)
        {
          case 1: // line
            return 2;
          case 3: // quadrangle
            return 4;
          case 5: // hexahedron
            return 8;
          case 15: // point
            return 1;
          case 2: // triangle
          case 4: // tetrahedron
          case 6: // prism
          case 7: // pyramid
            return 0;
          default:
            words.fail("element type " + std::to_string(type) +
                       " is not one ArchDam reads (first-order hexahedra, type 5, and the "
                       "quadrangles 3, lines 1 and points 15 that carry boundary ids)");
        }
    }

    /// One element's nodes: defined in $Nodes, none twice.
    std::array<long long, 8>
    read_element_nodes(Words &words, const unsigned int n, const std::unordered_set<long long> &nodes)
    {
      std::array<long long, 8> element{};
      for (unsigned int i = 0; i < n; ++i)
        {
          element[i] = words.integer("a node tag", 1, INT_MAX);
          if (nodes.count(element[i]) == 0)
            words.fail("an element refers to node " + std::to_string(element[i]) +
                       ", which $Nodes does not define");
          for (unsigned int j = 0; j < i; ++j)
            if (element[j] == element[i])
              words.fail("an element lists node " + std::to_string(element[i]) + " twice");
        }
      return element;
    }

    /**
     * The faces of the hexahedra and quadrangles read so far, by their node
     * set: two elements on the same nodes must have the same face (the same
     * four edges), and a face belongs to two hexahedra at most, which share
     * no other face. deal.II assumes all this (in a release build a tangled
     * cell, twisted so that its face runs through other edges than its
     * neighbour's, goes unnoticed into the mesh's connectivity).
     */
    class Faces
    {
    public:
      void
      add(Words &words, const std::array<long long, 8> &element, const unsigned int n)
      {
        // Gmsh's node order: bottom 0-1-2-3, top 4-5-6-7, sides; a
        // quadrangle is its own face 0-1-2-3.
        static const unsigned int cycles[6][4] = {
          {0, 1, 2, 3}, {4, 5, 6, 7}, {0, 1, 5, 4}, {1, 2, 6, 5}, {2, 3, 7, 6}, {3, 0, 4, 7}};
        const bool         hex  = n == 8;
        const unsigned int line = words.line_number();
        for (unsigned int f = 0; f < (hex ? 6 : 1); ++f)
          {
            std::array<long long, 4>                         key;
            std::array<std::pair<long long, long long>, 4> edges;
            for (unsigned int i = 0; i < 4; ++i)
              {
                const long long a = element[cycles[f][i]], b = element[cycles[f][(i + 1) % 4]];
                key[i]   = a;
                edges[i] = {std::min(a, b), std::max(a, b)};
              }
            std::sort(key.begin(), key.end());
            std::sort(edges.begin(), edges.end());
            auto &face = faces[key];
            if (face.line == 0)
              face = {edges, line, {}};
            else if (face.edges != edges)
              words.fail("this element and the one at line " + std::to_string(face.line) +
                         " have a face on the same nodes " + nodes_text(key) +
                         " with different edges: one of them has its nodes in a tangled order "
                         "(it is twisted and overlaps its neighbours); check the node order of "
                         "the hexahedra there");
            if (!hex)
              continue;
            if (face.hexahedra.size() == 2)
              words.fail("a third hexahedron on the face of nodes " + nodes_text(key) +
                         " of the hexahedra at lines " + std::to_string(face.hexahedra[0]) +
                         " and " + std::to_string(face.hexahedra[1]) +
                         ": the hexahedra overlap");
            if (face.hexahedra.size() == 1 && !neighbours.emplace(face.hexahedra[0], line).second)
              words.fail("this hexahedron shares two faces with the one at line " +
                         std::to_string(face.hexahedra[0]) +
                         ": the hexahedra overlap (an element given twice?)");
            face.hexahedra.push_back(line);
          }
      }

    private:
      static std::string
      nodes_text(const std::array<long long, 4> &key)
      {
        return std::to_string(key[0]) + " " + std::to_string(key[1]) + " " +
               std::to_string(key[2]) + " " + std::to_string(key[3]);
      }

      struct Face
      {
        std::array<std::pair<long long, long long>, 4> edges;
        unsigned int                                   line = 0;
        /// The lines of the hexahedra on the face.
        std::vector<unsigned int> hexahedra;
      };
      std::map<std::array<long long, 4>, Face>      faces;
      std::set<std::pair<unsigned int, unsigned int>> neighbours;
    };
  } // namespace

  void
  check_gmsh_structure(const std::string &text, const std::string &where)
  {
    Words words(text, where);
    words.expect("$MeshFormat");
    const bool v41 = words.real("the format version") == 4.1;
    words.integer("the file type", 0, 0);
    words.integer("the size of a double", sizeof(double), sizeof(double));
    words.expect("$EndMeshFormat");

    std::string section = words.next();
    // Sections GridIn skips, to their end marker.
    const auto skip = [&](const std::string &end) {
      for (std::string word = words.next(); word != end; word = words.next())
        if (word.empty())
          words.fail("expected " + end + ", found the end of the file");
      section = words.next();
    };
    if (section == "$PhysicalNames")
      skip("$EndPhysicalNames");

    // Format 4.1: the entities and their physical groups, GridIn's material
    // and boundary ids.
    if (section == "$Entities")
      {
        if (!v41)
          words.fail("$Entities belongs to format 4.1, but the file says it is format 2");
        std::array<long long, 4> n;
        for (unsigned int d = 0; d < 4; ++d)
          n[d] = words.count("the number of entities", 5);
        for (unsigned int d = 0; d < 4; ++d)
          for (long long e = 0; e < n[d]; ++e)
            {
              words.integer("an entity tag", INT_MIN, INT_MAX);
              for (unsigned int c = 0; c < (d == 0 ? 3 : 6); ++c)
                words.real("a coordinate of an entity's bounding box");
              if (words.integer("the number of physical groups of an entity (ArchDam reads "
                                "one at most)",
                                0, 1) == 1)
                words.integer(d == 0 ? "a physical group of a point" :
                                       "a physical group of a curve, surface or volume (a "
                                       "boundary or material id)",
                              d == 0 ? INT_MIN : 0, d == 0 ? INT_MAX : max_id);
              if (d > 0)
                for (long long b = words.count("the number of bounding entities", 1); b > 0; --b)
                  words.integer("a bounding entity", INT_MIN, INT_MAX);
            }
        words.expect("$EndEntities");
        section = words.next();
      }
    if (section == "$PartitionedEntities")
      skip("$EndPartitionedEntities");
    if (section != "$Nodes")
      words.fail("expected $Nodes, found '" + section.substr(0, 40) + "'");

    std::unordered_set<long long> nodes;
    const auto read_nodes = [&](const long long n, const bool tags_first) {
      for (long long i = 0; i < n; ++i)
        {
          const long long tag = words.integer("a node tag", 1, INT_MAX);
          if (!nodes.insert(tag).second)
            words.fail("node " + std::to_string(tag) + " is defined twice");
          if (!tags_first)
            for (unsigned int d = 0; d < 3; ++d)
              words.real("a node coordinate");
        }
      if (tags_first)
        for (long long i = 0; i < 3 * n; ++i)
          words.real("a node coordinate");
    };
    if (v41)
      {
        const long long n_blocks = words.count("the number of node blocks", 4);
        const long long n_nodes  = words.count("the number of nodes", 4);
        words.integer("the smallest node tag", 0, INT_MAX);
        words.integer("the largest node tag", 0, INT_MAX);
        long long total = 0;
        for (long long b = 0; b < n_blocks; ++b)
          {
            words.integer("an entity dimension", 0, 3);
            words.integer("an entity tag", INT_MIN, INT_MAX);
            words.integer("the parametric flag of a node block (ArchDam reads none: save "
                          "with Mesh.SaveParametric = 0)",
                          0, 0);
            const long long n = words.count("the number of nodes of a block", 4);
            read_nodes(n, true);
            total += n;
          }
        if (total != n_nodes)
          words.fail("the node blocks hold " + std::to_string(total) +
                     " nodes, the $Nodes header says " + std::to_string(n_nodes));
      }
    else
      read_nodes(words.count("the number of nodes", 4), false);
    words.expect("$EndNodes");
    words.expect("$Elements");

    // Element type and nodes; a non-hexahedral one ends the check with the
    // message read_gmsh() gives for it.
    bool       other_cells = false;
    Faces      faces;
    const auto read_element = [&](const long long type) {
      const unsigned int n = nodes_of(words, type);
      other_cells          = other_cells || n == 0;
      if (n == 0)
        return;
      const auto element = read_element_nodes(words, n, nodes);
      if (n >= 4)
        faces.add(words, element, n);
    };
    if (v41)
      {
        const long long n_blocks   = words.count("the number of element blocks", 4);
        const long long n_elements = words.count("the number of elements", 2);
        words.integer("the smallest element tag", 0, INT_MAX);
        words.integer("the largest element tag", 0, INT_MAX);
        long long total = 0;
        for (long long b = 0; b < n_blocks && !other_cells; ++b)
          {
            words.integer("an entity dimension", 0, 3);
            words.integer("an entity tag", INT_MIN, INT_MAX);
            const long long type = words.integer("an element type", 1, INT_MAX);
            const long long n    = words.count("the number of elements of a block", 2);
            for (long long e = 0; e < n && !other_cells; ++e)
              {
                words.integer("an element tag", 1, INT_MAX);
                read_element(type);
              }
            total += n;
          }
        if (!other_cells && total != n_elements)
          words.fail("the element blocks hold " + std::to_string(total) +
                     " elements, the $Elements header says " + std::to_string(n_elements));
      }
    else
      for (long long e = words.count("the number of elements", 4); e > 0 && !other_cells; --e)
        {
          words.integer("an element number", 1, INT_MAX);
          const long long type   = words.integer("an element type", 1, INT_MAX);
          const long long n_tags = words.count("the number of tags of an element", 1);
          for (long long t = 0; t < n_tags; ++t)
            if (t == 0 && type != 15)
              words.integer("the physical group of an element (a boundary or material id)", 0,
                            max_id);
            else
              words.integer("a tag of an element", INT_MIN, INT_MAX);
          read_element(type);
        }
    if (other_cells)
      throw InputError(where + " holds cells other than hexahedra; ArchDam needs a hexahedral "
                               "mesh (in Gmsh: Transfinite and Recombine, or "
                               "Mesh.SubdivisionAlgorithm = 2).");
    words.expect("$EndElements");
  }
} // namespace archdam::geometry
