#pragma once

#include <cstdint>

namespace archdam::time
{
  /**
   * The BLAS matrix product dgemm with one column (C = alpha op(A) op(B) +
   * beta C, op(B) of width n = 1) as the matrix-vector product dgemv.
   *
   * MUMPS's solve phase applies each front of the factor to the right-hand
   * side with dgemm, with as many columns as right-hand sides: one in every
   * step of the dynamic stage. OpenBLAS 0.3.21 (Debian 12) first copies
   * ("packs") the factor's block for every dgemm call, so a product with one
   * column reads the factor, writes the copy and reads it again: about three
   * times the memory traffic of dgemv, which reads the block once, in a
   * solve whose speed is set by memory traffic (doc/performance.md §9).
   * Later OpenBLAS versions forward such calls to gemv themselves on some
   * processors (0.3.28); on x86-64 not by default.
   *
   * The library defines the Fortran symbol dgemm_ itself: the dynamic linker
   * binds the BLAS calls of every library loaded after it (MUMPS, PETSc,
   * deal.II's LAPACK wrappers) to this definition, which calls dgemv_ for
   * n = 1 and the BLAS's own dgemm_ (found with dlsym(RTLD_NEXT)) for every
   * other product. The result is the same product, summed in another order
   * (round-off). sgemm_, which a single-precision factor's solves call
   * (Time integration/Factor precision), goes to sgemv_ the same way.
   *
   * Products with two to four columns (a step's solve with the joints'
   * position correction beside it, CondensedFactorization::expand) would
   * be packed too: they go to a product of the library's own that reads
   * each entry of A once for all columns (AVX2 where the processor has it),
   * and op(B)'s trailing columns that are zero only scale C's, so that a
   * zero second right-hand side costs no second pass over the factor.
   */

  /// How many dgemm and sgemm calls of this process went to gemv or to the
  /// library's own product (for the tests and the benchmarks: 0 means the
  /// forwarding is not in effect).
  std::uint64_t
  single_column_products_forwarded();

  /// Forward products with one column to dgemv (@p forward, the default) or
  /// leave every product to the BLAS's dgemm: for the benchmark that
  /// measures the two side by side (bench/factor_orders.cc).
  void
  forward_single_column_products(bool forward);
} // namespace archdam::time
