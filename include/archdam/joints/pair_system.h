#pragma once

#include <archdam/base/types.h>

#include <deal.II/lac/lapack_full_matrix.h>
#include <deal.II/lac/vector.h>

#include <array>
#include <functional>
#include <vector>

namespace archdam::joints
{
  /// Row dim i + k of the fixed-state contact system (doc/theory/joints.md
  /// §6), in parts: sum_l flex[l] (h C)(dim i + l, .) + sum_l own[l]
  /// e_{dim i + l}, rows of h C with coefficients plus entries on the pair's
  /// own unknowns, and its right-hand side.
  struct SystemRow
  {
    std::array<double, dim> flex{}, own{};
    double                  rhs = 0.;
  };

  /**
   * The fixed-state system of the contact problem on a set of pairs (all of
   * them, or one joint's: doc/theory/joints.md §6 and §12), dense, one row
   * per pair unknown. Its base A0 is the system with every pair in stick,
   * h C itself, which does not change with the states: its LU is built once,
   * and the rows R that differ from it (a slipping pair's tangential rows, a
   * separated pair's rows) are taken in by the Sherman-Morrison-Woodbury
   * formula:
   *   A = A0 + E_R dR,  Z = A0^{-1} E_R (kept per row),
   *   x = y - Z T^{-1} t,  y = A0^{-1} b,  T = I + dR Z = A_R Z,
   *   t = dR y = A_R y - b_R
   * (A_R the new rows; A0_R Z = I and A0_R y = b_R). Every row of the law is
   * rows of h C plus entries on the pair's own unknowns, so T and t come
   * from entries of Z, y and b alone. Two consequences save the solve's
   * passes over the dense LU (doc/theory/joints.md §6):
   * - y follows the last solve's: where b differs from the last b only in
   *   rows with a column of Z (within a step the stick rows' b stays the
   *   same; the slipping pairs' rows change), y = y_last + sum_a (b_a -
   *   b_last,a) A0^{-1} e_a;
   * - A0 x = b - E_R t: h C times the solution, the flexibility's part of
   *   the relative displacement, comes without a product with h C
   *   (base_times_solution()).
   */
  class PairSystem
  {
  public:
    /// The system on @p pairs (indices into NodePairs), its unknowns in
    /// that order, dim per pair.
    explicit PairSystem(std::vector<unsigned int> pairs);

    const std::vector<unsigned int> &
    pairs() const
    {
      return pair_indices;
    }

    /// How solve() reached the solution.
    enum class Solve
    {
      factorized, ///< the base's LU built (the first solve, or after forget())
      updated,    ///< the kept LU with the rows that differ from the base
      kept        ///< the kept LU as it is (every pair in stick)
    };

    /**
     * Solve the system whose row dim i + k is @p row_of(i, k) (i an index
     * into NodePairs) with h C = @p hc times @p C_rows (C by rows, @p m
     * pair unknowns in all). The solution, dim per pair in the order of
     * pairs(), is left in @p x.
     */
    Solve
    solve(const std::vector<double> &C_rows, unsigned int m, double hc,
          const std::function<SystemRow(unsigned int, unsigned int)> &row_of,
          dealii::Vector<double>                                     &x);

    /// A0 x for the last solve's x (h C times it on the system's unknowns),
    /// from the update's own vectors: b - E_R t.
    const dealii::Vector<double> &
    base_times_solution() const
    {
      return base_product;
    }

    /// The next solve() factorizes anew.
    void
    forget();

    /// What the kept LU and its update columns hold [bytes].
    std::size_t
    memory() const;

  private:
    std::vector<unsigned int> pair_indices;
    /// For every unknown of the system, the pair unknown it is (dim i + k).
    std::vector<unsigned int> unknowns;
    /// The base's LU (empty before the first solve), the h it was built
    /// with, and base^{-1} e_j for the rows j that have differed from it
    /// (empty where not needed yet).
    dealii::LAPACKFullMatrix<double>    base;
    double                              base_hc = 0.;
    std::vector<dealii::Vector<double>> update_columns;
    /// The last solve's b and y = A0^{-1} b (empty after a factorization),
    /// and A0 x.
    dealii::Vector<double> last_b, last_y, base_product;
  };
} // namespace archdam::joints
