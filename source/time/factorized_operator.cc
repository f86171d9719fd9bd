#include <archdam/base/petsc_check.h>
#include <archdam/time/factorized_operator.h>

#include <deal.II/lac/exceptions.h>

namespace archdam::time
{
  using namespace dealii;

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
      petsc_check(KSPDestroy(&ksp));
    petsc_check(MatSetOption(mat, MAT_SYMMETRIC, PETSC_TRUE));
    petsc_check(MatSetOption(mat, MAT_SPD, positive_definite ? PETSC_TRUE : PETSC_FALSE));

    MPI_Comm comm;
    petsc_check(PetscObjectGetComm(reinterpret_cast<PetscObject>(mat), &comm));
    petsc_check(KSPCreate(comm, &ksp));
    petsc_check(KSPSetOperators(ksp, mat, mat));
    petsc_check(KSPSetType(ksp, KSPPREONLY));
    PC pc;
    petsc_check(KSPGetPC(ksp, &pc));
    petsc_check(PCSetType(pc, PCCHOLESKY));
    petsc_check(PCFactorSetMatSolverType(pc, MATSOLVERMUMPS));
    petsc_check(KSPSetUp(ksp)); // the factorization happens here, once
  }

  void
  FactorizedOperator::solve(Vector &x, const Vector &b) const
  {
    Assert(ksp != nullptr, ExcMessage("solve() before factorize()"));
    petsc_check(KSPSolve(ksp, b, x));
  }

  void
  FactorizedOperator::solve(Mat X, Mat B) const
  {
    Assert(ksp != nullptr, ExcMessage("solve() before factorize()"));
    petsc_check(KSPMatSolve(ksp, B, X));
  }
} // namespace archdam::time
