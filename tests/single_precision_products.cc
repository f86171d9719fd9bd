// The sum of sparse products with the entries in single precision
// (time/single_precision_products.h) against PETSc's products in double, one
// matrix at a time, a second method: y0 - sum_k A_k x_k for one, two and three
// matrices, on the 27-point grid pattern, on the same pattern with other values
// and explicit zeros, and on a pattern of a few columns (the prescribed
// boundary's kind), with entries and vectors spread over ten orders of
// magnitude. Every row must agree to the bound of rounding the entries,
// 2^-24 sum_k sum_j |A_k(i, j) x_k(j)| (the sums are formed in double), and
// the largest error must be a sizeable part of that bound (the entries are
// indeed rounded). The product of one matrix alone from the same storage
// (SinglePrecisionProducts::vmult) the same way, and its product with another
// vector formed in the sum's pass, which must leave the sum bit for bit as it
// was. The entries kept are counted against the union of the
// nonzero entries, counted here. Under MPI the rows, and so the columns
// other ranks own, are spread over the ranks.

#include <archdam/time/single_precision_products.h>

#include <deal.II/lac/dynamic_sparsity_pattern.h>

#include "archdam_tests.h"

#include <cmath>
#include <map>
#include <random>

using namespace archdam;
using namespace dealii;

namespace
{
  constexpr unsigned int n = 9, N = n * n * n;

  IndexSet
  owned_rows()
  {
    const unsigned int n_ranks = Utilities::MPI::n_mpi_processes(MPI_COMM_WORLD);
    const unsigned int rank    = Utilities::MPI::this_mpi_process(MPI_COMM_WORLD);
    IndexSet           owned(N);
    owned.add_range(N * rank / n_ranks, N * (rank + 1) / n_ranks);
    return owned;
  }

  /// A value that is the same on every rank for entry (r, c) of matrix @p k,
  /// over ten orders of magnitude, zero for some entries of matrix 1.
  double
  value(const unsigned int k, const unsigned int r, const unsigned int c)
  {
    std::mt19937                           random(1000003u * r + 7919u * c + 13u * k);
    std::uniform_real_distribution<double> uniform(-1., 1.);
    const double                           v = uniform(random) * std::pow(10., (r + 3 * c) % 11 - 5.);
    return k == 1 && (r + c) % 4 == 0 ? 0. : v;
  }

  /// Matrix k: 0 and 1 on the 27-point pattern of the n^3 grid (1 with a
  /// quarter of its entries explicit zeros), 2 the columns of every 13th
  /// unknown (all rows that couple to them).
  void
  make_matrix(const unsigned int k, const IndexSet &owned, archdam::SparseMatrix &A,
              std::map<std::pair<unsigned int, unsigned int>, bool> &nonzero,
              const bool absolute = false)
  {
    DynamicSparsityPattern dsp(N, N);
    std::vector<std::pair<unsigned int, unsigned int>> entries;
    const auto id = [](int i, int j, int l) { return (l * n + j) * n + i; };
    for (int l = 0; l < static_cast<int>(n); ++l)
      for (int j = 0; j < static_cast<int>(n); ++j)
        for (int i = 0; i < static_cast<int>(n); ++i)
          for (int dl = -1; dl <= 1; ++dl)
            for (int dj = -1; dj <= 1; ++dj)
              for (int di = -1; di <= 1; ++di)
                {
                  const int a = i + di, b = j + dj, c = l + dl;
                  if (a < 0 || b < 0 || c < 0 || a >= static_cast<int>(n) ||
                      b >= static_cast<int>(n) || c >= static_cast<int>(n))
                    continue;
                  const unsigned int row = id(i, j, l), column = id(a, b, c);
                  if (k < 2 || column % 13 == 0)
                    entries.emplace_back(row, column);
                }
    for (const auto &[r, c] : entries)
      dsp.add(r, c);
    A.reinit(owned, owned, dsp, MPI_COMM_WORLD);
    for (const auto &[r, c] : entries)
      if (owned.is_element(r))
        {
          A.set(r, c, absolute ? std::abs(value(k, r, c)) : value(k, r, c));
          if (value(k, r, c) != 0.)
            nonzero[{r, c}] = true;
        }
    A.compress(VectorOperation::insert);
  }

  void
  random_vector(const unsigned int seed, archdam::Vector &x)
  {
    std::mt19937                           random(seed);
    std::uniform_real_distribution<double> uniform(-1., 1.);
    const IndexSet                         owned = x.locally_owned_elements();
    for (unsigned int g = 0; g < N; ++g)
      {
        const double v = uniform(random) * std::pow(10., g % 7 - 3.); // every rank the same
        if (owned.is_element(g))
          x(g) = v;
      }
    x.compress(VectorOperation::insert);
  }

  /// The sum of k = 0 .. @p count - 1 against PETSc's products.
  void
  check_sum(const unsigned int count)
  {
    const IndexSet                                        owned = owned_rows();
    std::map<std::pair<unsigned int, unsigned int>, bool> nonzero;
    std::vector<archdam::SparseMatrix>                    A(count);
    std::vector<archdam::Vector>                          x(count);
    std::vector<const archdam::SparseMatrix *>            matrices;
    std::vector<const archdam::Vector *>                  vectors;
    // one, two, three matrices: the grid with explicit zeros; it and the
    // columns; the grid, the grid with zeros and the columns
    const auto kind = [count](const unsigned int k) { return count == 3 ? k : k + 1; };
    for (unsigned int k = 0; k < count; ++k)
      {
        make_matrix(kind(k), owned, A[k], nonzero);
        x[k].reinit(owned, MPI_COMM_WORLD);
        random_vector(17 + k, x[k]);
        matrices.push_back(&A[k]);
        vectors.push_back(&x[k]);
      }
    archdam::Vector y(owned, MPI_COMM_WORLD), reference(owned, MPI_COMM_WORLD),
      product(owned, MPI_COMM_WORLD), bound(owned, MPI_COMM_WORLD);
    random_vector(5, y);
    reference = y;
    for (unsigned int k = 0; k < count; ++k)
      {
        A[k].vmult(product, x[k]);
        reference -= product;
      }
    // sum_j |A_k(i, j) x_k(j)|, with the absolute values of both, and its
    // sum over k
    for (unsigned int k = 0; k < count; ++k)
      {
        archdam::SparseMatrix abs_A;
        make_matrix(kind(k), owned, abs_A, nonzero, true);
        archdam::Vector abs_x(x[k]);
        for (const auto i : owned)
          abs_x(i) = std::abs(x[k](i));
        abs_x.compress(VectorOperation::insert);
        abs_A.vmult(product, abs_x);
        bound += product;
      }
    // the largest error of @p value against @p exact as a part of its row's bound
    const auto worst_of = [&](const archdam::Vector &value, const archdam::Vector &exact,
                              const archdam::Vector &row_bound) {
      double worst = 0.;
      for (const auto i : owned)
        worst = std::max(worst, std::abs(value(i) - exact(i)) /
                                  (std::ldexp(row_bound(i), -24) + 1e-300));
      return Utilities::MPI::max(worst, MPI_COMM_WORLD);
    };

    const time::SinglePrecisionProducts sum(matrices);
    sum.subtract_from(vectors, y);
    const double worst = worst_of(y, reference, bound);

    // the last matrix's product alone, from the same storage, and its
    // product with another vector in the same pass as the sum, which must
    // leave the sum bit for bit as it was
    const unsigned int    last = count - 1;
    archdam::SparseMatrix abs_last;
    make_matrix(kind(last), owned, abs_last, nonzero, true);
    // the last matrix's product with @p v against PETSc's, as a part of its bound
    const auto worst_of_last = [&](const archdam::Vector &v, const archdam::Vector &value) {
      archdam::Vector abs_v(v), last_bound(owned, MPI_COMM_WORLD);
      for (const auto i : owned)
        abs_v(i) = std::abs(v(i));
      abs_v.compress(VectorOperation::insert);
      abs_last.vmult(last_bound, abs_v);
      A[last].vmult(reference, v);
      return worst_of(value, reference, last_bound);
    };
    sum.vmult(last, x[last], product);
    const double    worst_alone = worst_of_last(x[last], product);
    archdam::Vector w(owned, MPI_COMM_WORLD), y_again(owned, MPI_COMM_WORLD);
    random_vector(29, w);
    random_vector(5, y_again);
    sum.subtract_from(vectors, y_again, last, w, product);
    const double worst_second = worst_of_last(w, product);
    y_again -= y;
    const auto kept  = Utilities::MPI::sum(sum.entries(), MPI_COMM_WORLD);
    const auto union_nonzero =
      Utilities::MPI::sum(static_cast<std::uint64_t>(nonzero.size()), MPI_COMM_WORLD);

    auto             &out  = testing::log();
    const std::string what = std::vector<std::string>{"one matrix", "two matrices",
                                                      "three matrices"}[count - 1];
    out << what << ": every row within 2^-24 sum |A_k(i, j) x_k(j)| of PETSc's products "
        << "in double: " << testing::yes(worst <= 1. + 1e-6)
        << "; the largest error at least 0.05 of that bound (the entries rounded): "
        << testing::yes(worst >= 0.05) << std::endl;
    out << what << ": the last one's product alone within its bound: "
        << testing::yes(worst_alone <= 1. + 1e-6 && worst_alone >= 0.05) << std::endl;
    out << what << ": the sum with the last one's product with another vector in the same "
        << "pass: the sum bit for bit the same: " << testing::yes(y_again.linfty_norm() == 0.)
        << "; the product within its bound: "
        << testing::yes(worst_second <= 1. + 1e-6 && worst_second >= 0.05) << std::endl;
    out << what << ": entries kept = the nonzero entries of the patterns' union ("
        << union_nonzero << "): " << testing::yes(kept == union_nonzero) << std::endl;
  }
} // namespace

int
main(int argc, char **argv)
{
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  for (const unsigned int count : {1u, 2u, 3u})
    check_sum(count);
  return 0;
}
