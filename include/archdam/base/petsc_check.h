#pragma once

#include <deal.II/lac/exceptions.h>

#include <petscsys.h>

namespace archdam
{
  /// A PETSc call that failed becomes deal.II's exception with PETSc's code.
  inline void
  petsc_check(const PetscErrorCode ierr)
  {
    AssertThrow(ierr == 0, dealii::ExcPETScError(ierr));
  }
} // namespace archdam
