#include <archdam/base/petsc_check.h>
#include <archdam/time/factorized_operator.h>

#include <deal.II/lac/exceptions.h>
#include <deal.II/lac/vector.h>

namespace archdam::time
{
  using namespace dealii;

  FactorizedOperator::~FactorizedOperator()
  {
    if (ksp != nullptr)
      KSPDestroy(&ksp);
  }

  void
  FactorizedOperator::factorize(const SparseMatrix &A, const bool positive_definite,
                                const std::vector<types::global_dof_index> &interface,
                                const double          low_rank_tolerance,
                                const Precision precision)
  {
    if (interface.empty())
      factorize(static_cast<Mat>(A), positive_definite);
    else
      {
        if (ksp != nullptr)
          petsc_check(KSPDestroy(&ksp));
        condensed_factor.reset(); // never two factorizations at once
        condensed_factor =
          std::make_unique<CondensedFactorization>(A, positive_definite, interface,
                                                   CondensedFactorization::Ordering::nested_dissection,
                                                   low_rank_tolerance, precision);
      }
  }

  void
  FactorizedOperator::factorize(Mat mat, const bool positive_definite)
  {
    if (ksp != nullptr)
      petsc_check(KSPDestroy(&ksp));
    condensed_factor.reset();
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
    if (condensed_factor)
      {
        // forward elimination, the interface's Schur complement, backward
        dealii::Vector<double> x_gamma;
        condensed_factor->condense(b, x_gamma);
        condensed_factor->solve_interface(x_gamma);
        condensed_factor->expand(x_gamma, x);
        return;
      }
    Assert(ksp != nullptr, ExcMessage("solve() before factorize()"));
    petsc_check(KSPSolve(ksp, b, x));
  }

  void
  FactorizedOperator::solve(Mat X, Mat B) const
  {
    AssertThrow(ksp != nullptr,
                ExcMessage("multi-column solve() needs the plain factorization"));
    petsc_check(KSPMatSolve(ksp, B, X));
  }

  double
  FactorizedOperator::factor_entries() const
  {
    if (condensed_factor)
      return condensed_factor->statistics().entries;
    if (ksp == nullptr)
      return 0.;
    PC  pc;
    Mat factor;
    petsc_check(KSPGetPC(ksp, &pc));
    petsc_check(PCFactorGetMatrix(pc, &factor));
    PetscInt n = 0;
    petsc_check(MatMumpsGetInfog(factor, 29, &n));
    // INFOG(29) < 0 counts millions (MUMPS's convention for large factors).
    return n < 0 ? -1e6 * n : double(n);
  }
} // namespace archdam::time
