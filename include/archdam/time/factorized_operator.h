#pragma once

#include <archdam/base/types.h>

#include <petscksp.h>

namespace archdam::time
{
  /**
   * A sparse matrix factorized once by MUMPS through PETSc (KSPPREONLY with a
   * Cholesky/LDL^T factorization, KSPSetUp called once), then applied by
   * back-substitution as often as needed. performance.md explains the choice:
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
    void
    factorize(const SparseMatrix &A, bool positive_definite);

    /// x = A^{-1} b, one back-substitution.
    void
    solve(Vector &x, const Vector &b) const;

    bool
    is_factorized() const
    {
      return ksp != nullptr;
    }

  private:
    KSP ksp = nullptr;
  };
} // namespace archdam::time
