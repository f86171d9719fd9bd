#pragma once

#include <archdam/base/types.h>
#include <archdam/time/condensed_factorization.h>

#include <petscksp.h>

#include <memory>
#include <vector>

namespace archdam::time
{
  /**
   * A sparse matrix factorized once by MUMPS through PETSc (KSPPREONLY with a
   * Cholesky/LDL^T factorization, KSPSetUp called once), then applied by
   * back-substitution as often as needed. doc/performance.md §5-§6 explains the choice:
   * the fastest factorization measured here, and explicit control over when the
   * factorization happens (deal.II's SparseDirectMUMPS refactorizes or ignores a
   * new matrix silently).
   */
  class FactorizedOperator
  {
  public:
    FactorizedOperator() = default;
    FactorizedOperator(const FactorizedOperator &) = delete;
    FactorizedOperator &
    operator=(const FactorizedOperator &) = delete;
    ~FactorizedOperator();

    /// Factorize the symmetric matrix A (kept referenced by PETSc).
    /// `positive_definite` selects Cholesky (true) or symmetric LDL^T.
    /// With an @p interface, the factorization is condensed on it instead
    /// (CondensedFactorization: MUMPS directly, the interface eliminated
    /// last); solve() then runs its three parts, and a @p
    /// low_rank_tolerance > 0 asks for its block low-rank factors with that
    /// dropping tolerance, and @p precision for its arithmetic
    /// (doc/performance.md §8).
    void
    factorize(const SparseMatrix &A, bool positive_definite,
              const std::vector<dealii::types::global_dof_index> &interface = {},
              double          low_rank_tolerance = 0.,
              Precision precision          = Precision::double_precision);

    /// The same for a matrix PETSc holds directly (kept referenced by PETSc).
    void
    factorize(Mat A, bool positive_definite);

    /// x = A^{-1} b, one back-substitution.
    void
    solve(Vector &x, const Vector &b) const;

    /// X = A^{-1} B for every column of the dense matrix B at once
    /// (KSPMatSolve: one multi-column back-substitution, doc/performance.md §6).
    void
    solve(Mat X, Mat B) const;

    /// Entries in the factors (MUMPS's INFOG(29), summed over the processes;
    /// the condensed factorization's sparse part): the memory and time a
    /// solve costs grow with it.
    double
    factor_entries() const;

    /// The condensed factorization, if factorize() was given an interface.
    const CondensedFactorization *
    condensed() const
    {
      return condensed_factor.get();
    }

  private:
    KSP                                     ksp = nullptr;
    std::unique_ptr<CondensedFactorization> condensed_factor;
  };
} // namespace archdam::time
