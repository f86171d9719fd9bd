#pragma once

#include <archdam/base/types.h>

#include <deal.II/base/timer.h>
#include <deal.II/lac/lapack_full_matrix.h>
#include <deal.II/lac/vector.h>

#include <memory>
#include <variant>
#include <vector>

namespace archdam::time
{
  /// The arithmetic in which a stored operator is held and applied: a
  /// sparse factor (doc/performance.md §8: single precision halves the
  /// factor's bytes and so the memory traffic of the substitutions, at a
  /// solve error of about the condition number times 6e-8), or the entries
  /// of the matrices in a step's effective load (§11).
  enum class Precision
  {
    double_precision,
    single_precision
  };

  /**
   * A symmetric sparse matrix A factorized once by MUMPS with the unknowns
   * of an interface set Γ eliminated last, so that the factorization also
   * yields the Schur complement S = A_ΓΓ - A_ΓI A_II^{-1} A_IΓ (dense, on
   * every rank). A solve of A x = b with a load on Γ that is known only
   * after the interface is looked at splits into
   *   condense(): y = b_Γ - A_ΓI A_II^{-1} b_I  (forward elimination),
   *   the interface problem S x_Γ = y - (load on Γ), solved by the caller,
   *   expand():   x_I = A_II^{-1} (b_I - A_IΓ x_Γ)  (backward substitution),
   * which together cost one back-substitution (MUMPS's reduced right-hand
   * side, ICNTL(19) and ICNTL(26)). The contact problem of the joints is
   * such an interface problem (doc/theory/joints.md §4-§5, paper eq. 2.5-2.8).
   * Under MPI the matrix enters distributed; the right-hand side, the
   * reduced right-hand side and the solution pass through rank 0.
   */
  class CondensedFactorization
  {
  public:
    /// The fill-reducing order of the unknowns before the interface.
    enum class Ordering
    {
      nested_dissection, ///< METIS's (time/fill_reducing_order.h)
      scotch,            ///< SCOTCH's nested dissection (time/fill_reducing_order.h)
      pord               ///< MUMPS's PORD
    };

    /// Factorize A (Cholesky if @p positive_definite, else LDL^T) with the
    /// global unknowns @p interface (sorted, the same on every rank) last.
    /// A @p low_rank_tolerance > 0 asks for MUMPS's block low-rank
    /// factorization with that dropping tolerance (ICNTL(35) = 2, CNTL(7)):
    /// the factors are kept and used in the solves compressed, and the
    /// solves are approximate to about that tolerance. 0, the default, is
    /// the exact (full-rank) factorization; doc/performance.md §8 gives the
    /// measurements behind that default. With @p precision single the factor
    /// and the Schur complement are computed in single precision (the
    /// matrix scaled first, so that its entries are of order one): the
    /// interfaces stay in double, and a solve is exact to about the
    /// condition number of the scaled matrix times 6e-8.
    CondensedFactorization(const SparseMatrix &A, bool positive_definite,
                           const std::vector<dealii::types::global_dof_index> &interface,
                           Ordering        ordering           = Ordering::nested_dissection,
                           double          low_rank_tolerance = 0.,
                           Precision precision          = Precision::double_precision);
    ~CondensedFactorization();
    CondensedFactorization(const CondensedFactorization &) = delete;
    CondensedFactorization &
    operator=(const CondensedFactorization &) = delete;

    /// The interface unknowns, in the order of S and of the reduced vectors.
    const std::vector<dealii::types::global_dof_index> &
    interface() const
    {
      return gamma;
    }

    /// What the sparse factorization holds and cost.
    struct Statistics
    {
      double entries    = 0.; ///< entries the factors hold (INFOG(29); low rank: INFOG(35))
      double operations = 0.; ///< floating-point operations of the elimination (RINFOG(3))
      double memory     = 0.; ///< bytes used by the factorization, all processes (INFOG(22))
    };
    const Statistics &
    statistics() const
    {
      return stats;
    }

    /// The wall time spent so far in condense()'s forward elimination and
    /// expand()'s backward substitution [s] (the calls into MUMPS).
    struct SolveTimes
    {
      double elimination  = 0.;
      double substitution = 0.;
    };
    SolveTimes
    solve_times() const;

    /// v = S^{-1} v (S factorized densely, on every rank).
    void
    solve_interface(dealii::Vector<double> &v) const;
    /// V = S^{-1} V for every column of V.
    void
    solve_interface(dealii::LAPACKFullMatrix<double> &V) const;

    /// y = b_Γ - A_ΓI A_II^{-1} b_I, on every rank. Must be followed by
    /// expand() before the next condense(). With @p with_interface_load a
    /// second right-hand side, zero, rides along, so that the expand() can
    /// also give the response to a load on the interface known only then.
    void
    condense(const Vector &b, dealii::Vector<double> &y, bool with_interface_load = false) const;

    /// The full solution x from the interface values x_Γ (the same on every
    /// rank) and the right-hand side of the last condense(). With @p q (the
    /// condense() with the interface load's room), also x_q = A^{-1} b_q for
    /// the b_q that is q on the interface and zero off it: S x_q,Γ = q, and
    /// x_q's backward substitution is the same pass over the factor as x's
    /// (two right-hand sides read the factor's entries once; the forward
    /// elimination has nothing to eliminate off the interface).
    void
    expand(const dealii::Vector<double> &x_gamma, Vector &x,
           const dealii::Vector<double> *q = nullptr, Vector *x_q = nullptr) const;

  private:
    template <typename Real>
    struct Mumps;
    std::variant<std::unique_ptr<Mumps<double>>, std::unique_ptr<Mumps<float>>> mumps;
    template <typename Real>
    void
    factorize(Mumps<Real> &m, const SparseMatrix &A, bool positive_definite, Ordering ordering,
              double low_rank_tolerance);
    std::vector<dealii::types::global_dof_index>     gamma;
    dealii::LAPACKFullMatrix<double>         schur; ///< of D A D, factorized
    std::vector<double>                      gamma_scaling; ///< D on Γ
    Statistics                               stats;
    mutable dealii::Timer                    elimination, substitution;
  };
} // namespace archdam::time
