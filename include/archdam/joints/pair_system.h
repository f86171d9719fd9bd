#pragma once

#include <archdam/base/types.h>
#include <archdam/joints/contact_law.h>

#include <deal.II/base/tensor.h>
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

  /// What a pair's rows of the fixed-state system depend on besides C, h
  /// and its augmentation: while it is the same, so are the rows.
  struct RowsOfPair
  {
    PairState                      state;
    dealii::Tensor<1, dim>         direction;
    double                         kappa, friction;
    bool
    operator==(const RowsOfPair &o) const
    {
      return state == o.state && direction == o.direction && kappa == o.kappa &&
             friction == o.friction;
    }
  };

  /**
   * The fixed-state system of the contact problem on a set of pairs (all of
   * them, or one joint's: doc/theory/joints.md §6 and §12), dense, one row
   * per pair unknown. The LU of the system as it was at its last
   * factorization (the base A0) is kept, and the rows R that changed since
   * are taken in by the Sherman-Morrison-Woodbury formula:
   *   A = A0 + E_R dR,  Z = A0^{-1} E_R (kept per row while A0 is),
   *   x = y - Z T^{-1} t,  y = A0^{-1} b,  T = I + dR Z = A_R Z,
   *   t = dR y = A_R y - b_R
   * (A_R the new rows; A0_R Z = I and A0_R y = b_R). A0 is refactorized
   * when R grows beyond a quarter of the rows.
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
      factorized, ///< a new LU of the whole system
      updated,    ///< the kept LU with the rows that changed
      kept        ///< the kept LU as it is
    };

    /**
     * Solve the system whose row dim i + k is @p row_of(i, k) (i an index
     * into NodePairs) with h C = @p hc times @p C_rows (C by rows, @p m
     * pair unknowns in all); @p rows_of(i) says when pair i's rows differ
     * from the base's. The solution, dim per pair in the order of pairs(),
     * is left in @p x.
     */
    Solve
    solve(const std::vector<double> &C_rows, unsigned int m, double hc,
          const std::function<SystemRow(unsigned int, unsigned int)> &row_of,
          const std::function<RowsOfPair(unsigned int)>               &rows_of,
          dealii::Vector<double>                                     &x);

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
    /// The base's LU, what its rows were made of (none before the first),
    /// and base^{-1} e_j for the rows j changed since (empty where not
    /// needed).
    dealii::LAPACKFullMatrix<double>    base;
    std::vector<RowsOfPair>             base_rows;
    std::vector<dealii::Vector<double>> update_columns;
  };
} // namespace archdam::joints
