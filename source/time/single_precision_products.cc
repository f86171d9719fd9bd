#include <archdam/base/petsc_check.h>
#include <archdam/time/single_precision_products.h>

#include <petscmat.h>

#include <algorithm>
#include <limits>

namespace archdam::time
{
  using namespace dealii;

  namespace
  {
    /// With First, y_i -= sum over the row's entries of sum_k v_k x_k, K
    /// matrices (the vectors' entries K + 1 apart); with Second, z_i = the
    /// row's sum of v_m w (w in the last slot).
    template <unsigned int K, bool First, bool Second>
    void
    subtract_rows(const PetscInt n_rows, const std::uint64_t *row_start,
                  const std::uint32_t *columns, const float *values, const double *x, double *y,
                  const unsigned int m, double *z)
    {
      for (PetscInt i = 0; i < n_rows; ++i)
        {
          double sum = 0., second = 0.;
          for (std::uint64_t e = row_start[i]; e < row_start[i + 1]; ++e)
            {
              const double *xc = x + static_cast<std::size_t>(columns[e]) * (K + 1);
              const float  *v  = values + e * K;
              if constexpr (First)
                for (unsigned int k = 0; k < K; ++k)
                  sum += static_cast<double>(v[k]) * xc[k];
              if constexpr (Second)
                second += static_cast<double>(v[m]) * xc[K];
            }
          if constexpr (First)
            y[i] -= sum;
          if constexpr (Second)
            z[i] = second;
        }
    }

    /// The kernel for K matrices, the sum (First) and the second product.
    template <unsigned int K>
    auto
    kernel_for(const bool first, const bool second)
    {
      return first ? (second ? subtract_rows<K, true, true> : subtract_rows<K, true, false>) :
                     subtract_rows<K, false, true>;
    }
  } // namespace

  SinglePrecisionProducts::SinglePrecisionProducts(
    const std::vector<const SparseMatrix *> &matrices)
    : n_matrices(matrices.size())
  {
    AssertThrow(n_matrices >= 1 && n_matrices <= 3,
                ExcMessage("SinglePrecisionProducts sums the products of one to three matrices."));
    PetscInt last_row = 0;
    petsc_check(MatGetOwnershipRange(static_cast<Mat>(*matrices[0]), &first_row, &last_row));
    n_rows = last_row - first_row;
    for (const SparseMatrix *A : matrices)
      {
        PetscInt a = 0, b = 0;
        petsc_check(MatGetOwnershipRange(static_cast<Mat>(*A), &a, &b));
        AssertThrow(a == first_row && b == last_row && A->m() == matrices[0]->m() &&
                      A->n() == matrices[0]->n(),
                    ExcMessage("SinglePrecisionProducts: the matrices differ in size or in "
                               "their rows' distribution."));
      }
    AssertThrow(matrices[0]->n() < std::numeric_limits<std::uint32_t>::max(),
                ExcMessage("SinglePrecisionProducts holds columns in 32 bits."));

    // The union of the rows' patterns, global columns first (a row's
    // columns come sorted from MatGetRow), the ghosts numbered after; sized
    // by a first pass over the rows, so that nothing is held twice.
    struct Entry
    {
      PetscInt     column;
      unsigned int matrix;
      double       value;
    };
    std::vector<Entry> row;
    const auto         merge_row = [&](const PetscInt i) {
      row.clear();
      for (unsigned int k = 0; k < n_matrices; ++k)
        {
          const Mat          A = static_cast<Mat>(*matrices[k]);
          PetscInt           n = 0;
          const PetscInt    *c = nullptr;
          const PetscScalar *v = nullptr;
          petsc_check(MatGetRow(A, i, &n, &c, &v));
          for (PetscInt j = 0; j < n; ++j)
            if (v[j] != 0.)
              row.push_back({c[j], k, v[j]});
          petsc_check(MatRestoreRow(A, i, &n, &c, &v));
        }
      std::stable_sort(row.begin(), row.end(),
                       [](const Entry &a, const Entry &b) { return a.column < b.column; });
    };
    const auto new_column = [&](const std::size_t j) {
      return j == 0 || row[j].column != row[j - 1].column;
    };
    row_start.reserve(n_rows + 1);
    row_start.push_back(0);
    for (PetscInt i = first_row; i < last_row; ++i)
      {
        merge_row(i);
        std::uint64_t n = 0;
        for (std::size_t j = 0; j < row.size(); ++j)
          n += new_column(j);
        row_start.push_back(row_start.back() + n);
      }
    columns.resize(row_start.back());
    values.assign(row_start.back() * n_matrices, 0.f);
    std::vector<PetscInt> ghosts;
    for (PetscInt i = first_row; i < last_row; ++i)
      {
        merge_row(i);
        std::uint64_t e = row_start[i - first_row];
        for (std::size_t j = 0; j < row.size(); ++j)
          {
            if (j > 0 && new_column(j))
              ++e;
            const PetscInt c = row[j].column;
            columns[e]       = static_cast<std::uint32_t>(c);
            if (new_column(j) && (c < first_row || c >= last_row))
              ghosts.push_back(c);
            values[e * n_matrices + row[j].matrix] = static_cast<float>(row[j].value);
          }
      }
    std::sort(ghosts.begin(), ghosts.end());
    ghosts.erase(std::unique(ghosts.begin(), ghosts.end()), ghosts.end());
    for (auto &c : columns)
      c = static_cast<PetscInt>(c) >= first_row && static_cast<PetscInt>(c) < last_row ?
            c - first_row :
            n_rows + (std::lower_bound(ghosts.begin(), ghosts.end(), c) - ghosts.begin());
    interleaved.resize((n_rows + ghosts.size()) * (n_matrices + 1));

    n_ghosts = static_cast<PetscInt>(ghosts.size());
    Vec model_vector;
    petsc_check(MatCreateVecs(static_cast<Mat>(*matrices[0]), &model_vector, nullptr));
    IS from;
    petsc_check(ISCreateGeneral(PETSC_COMM_SELF, static_cast<PetscInt>(ghosts.size()),
                                ghosts.data(), PETSC_COPY_VALUES, &from));
    petsc_check(VecCreateSeq(PETSC_COMM_SELF, n_ghosts, &ghost_values));
    petsc_check(VecScatterCreate(model_vector, from, ghost_values, nullptr, &ghost_scatter));
    petsc_check(ISDestroy(&from));
    petsc_check(VecDestroy(&model_vector));
  }

  SinglePrecisionProducts::~SinglePrecisionProducts()
  {
    if (ghost_scatter != nullptr)
      VecScatterDestroy(&ghost_scatter);
    if (ghost_values != nullptr)
      VecDestroy(&ghost_values);
  }

  std::size_t
  SinglePrecisionProducts::memory() const
  {
    return row_start.size() * sizeof(std::uint64_t) + columns.size() * sizeof(std::uint32_t) +
           values.size() * sizeof(float) + interleaved.size() * sizeof(double);
  }

  void
  SinglePrecisionProducts::gather(const unsigned int k, const Vector &x) const
  {
    const Vec          xk = static_cast<const Vec &>(x);
    const PetscScalar *owned;
    petsc_check(VecGetArrayRead(xk, &owned));
    for (PetscInt i = 0; i < n_rows; ++i)
      interleaved[i * (n_matrices + 1) + k] = owned[i];
    petsc_check(VecRestoreArrayRead(xk, &owned));
    petsc_check(VecScatterBegin(ghost_scatter, xk, ghost_values, INSERT_VALUES, SCATTER_FORWARD));
    petsc_check(VecScatterEnd(ghost_scatter, xk, ghost_values, INSERT_VALUES, SCATTER_FORWARD));
    const PetscScalar *ghost;
    petsc_check(VecGetArrayRead(ghost_values, &ghost));
    for (PetscInt g = 0; g < n_ghosts; ++g)
      interleaved[(n_rows + g) * (n_matrices + 1) + k] = ghost[g];
    petsc_check(VecRestoreArrayRead(ghost_values, &ghost));
  }

  void
  SinglePrecisionProducts::subtract_gathered(Vector *y, const unsigned int k, Vector *z) const
  {
    PetscScalar *out = nullptr, *second = nullptr;
    if (y != nullptr)
      petsc_check(VecGetArray(static_cast<const Vec &>(*y), &out));
    if (z != nullptr)
      petsc_check(VecGetArray(static_cast<const Vec &>(*z), &second));
    const bool first = y != nullptr, second_product = z != nullptr;
    const auto kernel = n_matrices == 1 ? kernel_for<1>(first, second_product) :
                        n_matrices == 2 ? kernel_for<2>(first, second_product) :
                                          kernel_for<3>(first, second_product);
    kernel(n_rows, row_start.data(), columns.data(), values.data(), interleaved.data(), out, k,
           second);
    if (z != nullptr)
      petsc_check(VecRestoreArray(static_cast<const Vec &>(*z), &second));
    if (y != nullptr)
      petsc_check(VecRestoreArray(static_cast<const Vec &>(*y), &out));
  }

  void
  SinglePrecisionProducts::subtract_from(const std::vector<const Vector *> &x, Vector &y) const
  {
    AssertDimension(x.size(), n_matrices);
    for (unsigned int k = 0; k < n_matrices; ++k)
      gather(k, *x[k]);
    subtract_gathered(&y);
  }

  void
  SinglePrecisionProducts::subtract_from(const std::vector<const Vector *> &x, Vector &y,
                                         const unsigned int k, const Vector &w, Vector &z) const
  {
    AssertDimension(x.size(), n_matrices);
    AssertIndexRange(k, n_matrices);
    for (unsigned int j = 0; j < n_matrices; ++j)
      gather(j, *x[j]);
    gather(n_matrices, w);
    subtract_gathered(&y, k, &z);
  }

  void
  SinglePrecisionProducts::vmult(const unsigned int k, const Vector &x, Vector &y) const
  {
    AssertIndexRange(k, n_matrices);
    gather(n_matrices, x);
    subtract_gathered(nullptr, k, &y);
  }
} // namespace archdam::time
