#include <archdam/time/fill_reducing_order.h>

#include <deal.II/base/exceptions.h>

#include <metis.h>

#include <cstdio> // scotch.h needs FILE
#include <scotch.h>

#include <algorithm>
#include <limits>
#include <numeric>
#include <string>

namespace archdam::time
{
  namespace
  {
    /// The symmetric graph of the triangle, without the diagonal: each row's
    /// neighbours sorted and unique (compressed rows).
    struct Graph
    {
      std::vector<std::int64_t> start;
      std::vector<std::int32_t> adjacent;

      Graph(const std::int32_t n, const std::vector<std::int32_t> &rows,
            const std::vector<std::int32_t> &cols)
        : start(n + 1, 0)
      {
        for (std::size_t k = 0; k < rows.size(); ++k)
          if (rows[k] != cols[k])
            {
              ++start[rows[k]]; // 1-based: counts row rows[k] - 1 at start[rows[k]]
              ++start[cols[k]];
            }
        std::partial_sum(start.begin(), start.end(), start.begin());
        adjacent.resize(start[n]);
        std::vector<std::int64_t> next(start.begin(), start.end() - 1);
        for (std::size_t k = 0; k < rows.size(); ++k)
          if (rows[k] != cols[k])
            {
              adjacent[next[rows[k] - 1]++] = cols[k] - 1;
              adjacent[next[cols[k] - 1]++] = rows[k] - 1;
            }
        for (std::int32_t i = 0; i < n; ++i)
          {
            const auto first = adjacent.begin() + start[i], last = adjacent.begin() + start[i + 1];
            std::sort(first, last);
            AssertThrow(std::adjacent_find(first, last) == last,
                        dealii::ExcMessage("nested_dissection_order: duplicate entries in a row."));
          }
      }

      std::int64_t
      degree(const std::int32_t i) const
      {
        return start[i + 1] - start[i];
      }
    };
  } // namespace

  std::vector<std::int32_t>
  nested_dissection_order(const std::int32_t n, const std::vector<std::int32_t> &rows,
                          const std::vector<std::int32_t> &cols, const Dissector dissector)
  {
    AssertThrow(rows.size() == cols.size(),
                dealii::ExcMessage("nested_dissection_order: rows and columns differ in size."));
    const Graph graph(n, rows, cols);

    // Unknowns with the same closed neighbourhood {i} + adj(i): sort by a
    // hash of it, then compare the candidates exactly.
    std::vector<std::uint64_t> hash(n);
    for (std::int32_t i = 0; i < n; ++i)
      {
        std::uint64_t h = static_cast<std::uint64_t>(i) * 0x9E3779B97F4A7C15ull;
        for (std::int64_t k = graph.start[i]; k < graph.start[i + 1]; ++k)
          h += static_cast<std::uint64_t>(graph.adjacent[k]) * 0x9E3779B97F4A7C15ull;
        hash[i] = h ^ static_cast<std::uint64_t>(graph.degree(i));
      }
    std::vector<std::int32_t> by_hash(n);
    std::iota(by_hash.begin(), by_hash.end(), 0);
    std::sort(by_hash.begin(), by_hash.end(),
              [&](const std::int32_t a, const std::int32_t b) {
                return hash[a] != hash[b] ? hash[a] < hash[b] : a < b;
              });
    const auto same_closed_neighbourhood = [&](const std::int32_t a, const std::int32_t b) {
      if (graph.degree(a) != graph.degree(b))
        return false;
      // adj(a) + {a} = adj(b) + {b}: b in adj(a) and the rest equal.
      std::vector<std::int32_t> na(graph.adjacent.begin() + graph.start[a],
                                   graph.adjacent.begin() + graph.start[a + 1]);
      std::vector<std::int32_t> nb(graph.adjacent.begin() + graph.start[b],
                                   graph.adjacent.begin() + graph.start[b + 1]);
      na.insert(std::lower_bound(na.begin(), na.end(), a), a);
      nb.insert(std::lower_bound(nb.begin(), nb.end(), b), b);
      return na == nb;
    };
    std::vector<std::int32_t> group(n, -1), representative;
    for (std::int32_t k = 0; k < n; ++k)
      {
        const std::int32_t i = by_hash[k];
        if (group[i] >= 0)
          continue;
        group[i] = static_cast<std::int32_t>(representative.size());
        representative.push_back(i);
        for (std::int32_t l = k + 1; l < n && hash[by_hash[l]] == hash[i]; ++l)
          if (group[by_hash[l]] < 0 && same_closed_neighbourhood(i, by_hash[l]))
            group[by_hash[l]] = group[i];
      }

    // The compressed graph: a group's neighbours are the other groups of its
    // representative's neighbours; its weight the number of its unknowns.
    const auto n_groups = static_cast<idx_t>(representative.size());
    std::vector<idx_t> xadj(n_groups + 1, 0), adjncy, weight(n_groups, 0);
    for (std::int32_t i = 0; i < n; ++i)
      ++weight[group[i]];
    for (idx_t g = 0; g < n_groups; ++g)
      {
        const std::int32_t r     = representative[g];
        const auto         first = adjncy.size();
        for (std::int64_t k = graph.start[r]; k < graph.start[r + 1]; ++k)
          if (group[graph.adjacent[k]] != g)
            adjncy.push_back(group[graph.adjacent[k]]);
        std::sort(adjncy.begin() + first, adjncy.end());
        adjncy.erase(std::unique(adjncy.begin() + first, adjncy.end()), adjncy.end());
        AssertThrow(adjncy.size() < static_cast<std::size_t>(std::numeric_limits<idx_t>::max()),
                    dealii::ExcMessage("nested_dissection_order: the graph is too large to dissect."));
        xadj[g + 1] = static_cast<idx_t>(adjncy.size());
      }

    std::vector<idx_t> order(n_groups), position(n_groups);
    if (n_groups > 0 && dissector == Dissector::scotch)
      {
        // SCOTCH's permtab is METIS's position, its peritab METIS's order.
        static_assert(sizeof(SCOTCH_Num) == sizeof(idx_t),
                      "SCOTCH and METIS index the graph alike");
        SCOTCH_Graph graph_s;
        SCOTCH_Strat strategy;
        SCOTCH_graphInit(&graph_s);
        SCOTCH_stratInit(&strategy);
        int status = SCOTCH_graphBuild(&graph_s, 0, n_groups, xadj.data(), nullptr, weight.data(),
                                       nullptr, xadj[n_groups], adjncy.data(), nullptr);
        if (status == 0)
          status = SCOTCH_graphOrder(&graph_s, &strategy, position.data(), order.data(), nullptr,
                                     nullptr, nullptr);
        SCOTCH_stratExit(&strategy);
        SCOTCH_graphExit(&graph_s);
        AssertThrow(status == 0, dealii::ExcMessage("SCOTCH_graphOrder failed with status " +
                                                    std::to_string(status) + "."));
      }
    else if (n_groups > 0)
      {
        idx_t options[METIS_NOPTIONS];
        METIS_SetDefaultOptions(options);
        idx_t      nv     = n_groups;
        const int  status = METIS_NodeND(&nv, xadj.data(), adjncy.data(), weight.data(), options,
                                        order.data(), position.data());
        AssertThrow(status == METIS_OK,
                    dealii::ExcMessage("METIS_NodeND failed with status " +
                                       std::to_string(status) + "."));
      }

    // Groups in the dissection's order (order[p] is the group at position
    // p), each group's unknowns together.
    std::vector<std::int64_t> first_of(n_groups + 1, 0);
    for (idx_t p = 0; p < n_groups; ++p)
      first_of[p + 1] = first_of[p] + weight[order[p]];
    std::vector<std::int32_t> result(n);
    for (std::int32_t i = 0; i < n; ++i)
      result[first_of[position[group[i]]]++] = i;
    return result;
  }
} // namespace archdam::time
