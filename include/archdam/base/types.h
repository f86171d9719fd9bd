#pragma once

#include <deal.II/lac/petsc_sparse_matrix.h>
#include <deal.II/lac/petsc_vector.h>

namespace archdam
{
  /// ArchDam models are three-dimensional (doc/theory/conventions.md §3: x stream,
  /// y cross-stream, z up).
  constexpr unsigned int dim = 3;

  /// Linear algebra stack: PETSc, chosen by measurement for its MUMPS
  /// Cholesky factorization and multi-column solves (doc/performance.md §5).
  using Vector       = dealii::PETScWrappers::MPI::Vector;
  using SparseMatrix = dealii::PETScWrappers::MPI::SparseMatrix;
} // namespace archdam
