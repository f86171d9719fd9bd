#pragma once

#include <string>

namespace archdam::geometry
{
  /**
   * The structure of an ASCII .msh file of format 2.x or 4.1, checked before
   * deal.II's GridIn::read_msh() reads it (read_gmsh()). GridIn trusts the
   * file: in a release build a count larger than the file (it allocates it),
   * an element naming a node $Nodes does not define or naming one node
   * twice, an entity dimension outside 0-3 or a physical id above 254 (the
   * largest material or boundary id) end in undefined behaviour or a
   * silently wrong mesh; the fuzz target fuzz_gmsh_mesh found them
   * (doc/verification.md, "Fuzzing"). Here every number must parse whole,
   * every count must fit in the rest of the file, node tags are unique, and
   * the sections come in the order GridIn reads them. Each problem is an
   * InputError "<where> is malformed at line L: ...".
   *
   * Elements of types other than first-order hexahedra (5) and the
   * quadrangles (3), lines (1) and points (15) that carry boundary ids are
   * rejected too: tetrahedra, prisms and the like with the message that the
   * mesh must be hexahedral.
   */
  void
  check_gmsh_structure(const std::string &text, const std::string &where);
} // namespace archdam::geometry
