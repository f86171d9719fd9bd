#include <archdam/time/factorized_operator.h>

#include <deal.II/lac/exceptions.h>

namespace archdam::time
{
  using namespace dealii;

  namespace
  {
    void
    check(const PetscErrorCode ierr)
    {
      AssertThrow(ierr == 0, ExcPETScError(ierr));
    }
  } // namespace

  FactorizedOperator::~FactorizedOperator()
  {
    if (ksp != nullptr)
      KSPDestroy(&ksp);
  }

  void
  FactorizedOperator::factorize(const SparseMatrix &A, const bool positive_definite)
  {
    factorize(static_cast<Mat>(A), positive_definite);
  }

  void
  FactorizedOperator::factorize(Mat mat, const bool positive_definite)
  {
    if (ksp != nullptr)
      check(KSPDestroy(&ksp));
    check(MatSetOption(mat, MAT_SYMMETRIC, PETSC_TRUE));
    check(MatSetOption(mat, MAT_SPD, positive_definite ? PETSC_TRUE : PETSC_FALSE));

    MPI_Comm comm;
    check(PetscObjectGetComm(reinterpret_cast<PetscObject>(mat), &comm));
    check(KSPCreate(comm, &ksp));
    check(KSPSetOperators(ksp, mat, mat));
    check(KSPSetType(ksp, KSPPREONLY));
    PC pc;
    check(KSPGetPC(ksp, &pc));
    check(PCSetType(pc, PCCHOLESKY));
    check(PCFactorSetMatSolverType(pc, MATSOLVERMUMPS));
    check(KSPSetUp(ksp)); // the factorization happens here, once
  }

  void
  FactorizedOperator::solve(Vector &x, const Vector &b) const
  {
    Assert(ksp != nullptr, ExcMessage("solve() before factorize()"));
    check(KSPSolve(ksp, b, x));
  }

  void
  FactorizedOperator::solve(Mat X, Mat B) const
  {
    Assert(ksp != nullptr, ExcMessage("solve() before factorize()"));
    check(KSPMatSolve(ksp, B, X));
  }
} // namespace archdam::time
