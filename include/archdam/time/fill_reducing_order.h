#pragma once

#include <cstdint>
#include <vector>

namespace archdam::time
{
  /// The library whose nested dissection orders the graph.
  enum class Dissector
  {
    metis, ///< METIS_NodeND
    scotch ///< SCOTCH_graphOrder with SCOTCH's default strategy
  };

  /**
   * A fill-reducing elimination order of a symmetric sparse matrix by nested
   * dissection, METIS's or SCOTCH's (doc/performance.md §8). The matrix is
   * given by the positions of one triangle, 1-based as MUMPS takes them
   * (@p rows[k], @p cols[k]; the diagonal may be among them, no position twice). The
   * unknowns of one node couple with the same neighbours, so unknowns with
   * identical rows are merged into one weighted vertex first: the graph that
   * is dissected is the mesh's node graph, about a third of the unknowns and
   * a ninth of the edges of an elasticity matrix.
   *
   * Returns the unknowns (0-based) in elimination order.
   */
  std::vector<std::int32_t>
  nested_dissection_order(std::int32_t n, const std::vector<std::int32_t> &rows,
                          const std::vector<std::int32_t> &cols,
                          Dissector dissector = Dissector::metis);
} // namespace archdam::time
