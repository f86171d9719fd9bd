#pragma once

#include <archdam/base/types.h>

#include <petscvec.h>

#include <cstdint>
#include <vector>

namespace archdam::time
{
  /**
   * The sum of the products of a few sparse matrices with their own vectors,
   *   y -= sum_k A_k x_k,
   * in one pass over the union of the matrices' patterns, the entries held
   * in single precision (doc/performance.md §11). A step's effective load
   * needs such a sum (M, D and K, and the prescribed boundary's columns of
   * each: eq. 2.3); PETSc's products, one matrix at a time, read a column
   * index and a value in double for every entry of every matrix, 12 bytes,
   * and a sparse product's speed is set by the bytes it reads. Here an
   * entry of the union costs its index and one value in single precision per
   * matrix: for two matrices on one pattern 12 bytes against 24.
   *
   * The entries are rounded to single precision and the sums are formed in
   * double, so each row of the sum is exact to 2^-24 times
   * sum_k sum_j |A_k(i, j) x_k(j)| (measured in tests/single_precision_products).
   * Entries that are zero in every matrix are not kept. Under MPI every
   * rank holds its rows, the vectors' entries it needs from other ranks
   * brought by one scatter per vector.
   */
  class SinglePrecisionProducts
  {
  public:
    /// The matrices' entries now (each of the same size and row distribution).
    explicit SinglePrecisionProducts(const std::vector<const SparseMatrix *> &matrices);
    ~SinglePrecisionProducts();
    SinglePrecisionProducts(const SinglePrecisionProducts &) = delete;
    SinglePrecisionProducts &
    operator=(const SinglePrecisionProducts &) = delete;

    /// y -= sum_k A_k x[k], one vector per matrix, in the constructor's order.
    void
    subtract_from(const std::vector<const Vector *> &x, Vector &y) const;

    /// subtract_from(), and in the same pass z = A_k w: a product with one
    /// of the matrices for the price of w's entries, the entries read once.
    void
    subtract_from(const std::vector<const Vector *> &x, Vector &y, unsigned int k,
                  const Vector &w, Vector &z) const;

    /// y = A_k x alone (the pass reads every matrix's entries all the same:
    /// it costs a whole subtract_from()).
    void
    vmult(unsigned int k, const Vector &x, Vector &y) const;

    /// The entries kept (on this rank), of the union of the patterns.
    std::uint64_t
    entries() const
    {
      return columns.size();
    }

    /// What the entries, their indices and the work vectors hold [bytes].
    std::size_t
    memory() const;

  private:
    unsigned int n_matrices;
    /// The rows this rank owns, [first_row, first_row + n_rows).
    PetscInt first_row = 0, n_rows = 0, n_ghosts = 0;
    /// Compressed rows: row i's entries are [row_start[i], row_start[i + 1]);
    /// a column below n_rows is the owned row first_row + column, above it
    /// the ghost column - n_rows.
    std::vector<std::uint64_t> row_start;
    std::vector<std::uint32_t> columns;
    /// n_matrices values per entry, the matrices' in turn.
    std::vector<float> values;
    /// The other ranks' entries the rows need, and the scatter that brings them.
    VecScatter ghost_scatter = nullptr;
    Vec        ghost_values  = nullptr;
    /// The vectors' entries, owned then ghosts, n_matrices + 1 per entry
    /// (the last for the second product's vector).
    mutable std::vector<double> interleaved;

    /// x's owned and ghost entries into slot k of `interleaved`.
    void
    gather(unsigned int k, const Vector &x) const;
    /// y -= the sum with the vectors gathered (unless @p y is null), and
    /// with @p z, z = A_k w (w in the last slot).
    void
    subtract_gathered(Vector *y, unsigned int k = 0, Vector *z = nullptr) const;
  };
} // namespace archdam::time
