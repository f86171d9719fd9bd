// The factorization condensed on an interface (time/condensed_factorization.h)
// against the plain factorization of the same matrix (time/factorized_operator.h,
// PETSc's MUMPS Cholesky), a second method:
// - S^{-1} = (A^{-1})_ΓΓ: the interface block of A^{-1} e_g for every interface
//   unknown g (the Schur complement's inverse is that block of the inverse);
// - condense(), S x_Γ = y - q_Γ, expand() = A^{-1} (b - q) for a random b and
//   a load q on the interface, the whole solution (the joints' contact step);
// on a symmetric positive definite matrix (a 3-D Laplacian plus a mass term,
// the shape of K̄) and on a symmetric indefinite one (its block on half of the
// unknowns negated, the shape of the coupled solid-water
// matrix), the interface spread over the unknowns and, under MPI, the ranks.
// And the BLAS products with one column that MUMPS's solves are made of
// (time/single_column_products.h): dgemm and sgemm with one to five
// columns (every transposition, leading dimensions larger than the blocks,
// trailing zero columns) against the product summed here, forwarded to
// gemv or to the library's product, and the condensed solves going through
// it.
// The other orders (SCOTCH's nested dissection, MUMPS's PORD) give the same
// solves; the block low-rank factors are compressed and give the full-rank
// factors' solves to about their tolerance; the factors in single precision
// take half the memory and give them to about single precision's round-off
// times the condition number, and to double's after one step of iterative
// refinement.

#include <archdam/time/condensed_factorization.h>
#include <archdam/time/factorized_operator.h>
#include <archdam/time/single_column_products.h>

#include <deal.II/lac/dynamic_sparsity_pattern.h>

#include "archdam_tests.h"

#include <array>
#include <cmath>
#include <limits>
#include <random>

using namespace archdam;
using namespace dealii;

extern "C" void
dgemm_(const char *, const char *, const int *, const int *, const int *, const double *,
       const double *, const int *, const double *, const int *, const double *, double *,
       const int *);
extern "C" void
sgemm_(const char *, const char *, const int *, const int *, const int *, const float *,
       const float *, const int *, const float *, const int *, const float *, float *,
       const int *);

namespace
{
  void
  gemm(const char *ta, const char *tb, const int *m, const int *n, const int *k,
       const double *alpha, const double *a, const int *lda, const double *b, const int *ldb,
       const double *beta, double *c, const int *ldc)
  {
    dgemm_(ta, tb, m, n, k, alpha, a, lda, b, ldb, beta, c, ldc);
  }

  void
  gemm(const char *ta, const char *tb, const int *m, const int *n, const int *k,
       const float *alpha, const float *a, const int *lda, const float *b, const int *ldb,
       const float *beta, float *c, const int *ldc)
  {
    sgemm_(ta, tb, m, n, k, alpha, a, lda, b, ldb, beta, c, ldc);
  }

  /// C = alpha op(A) op(B) + beta C through dgemm_ (sgemm_ for float)
  /// against the sums of the definition, in double, for one to five
  /// columns: one goes to gemv, two to four to the library's own product
  /// (time/single_column_products.h), five to the BLAS's gemm; each also
  /// with op(B)'s trailing columns zero (the product then has the leading
  /// ones alone, C's others are scaled by beta). With beta = 0, C's entries
  /// are not read (NaN there stays out of the result, as BLAS defines it).
  template <typename Real>
  void
  check_narrow_products(const std::string &name, const double tolerance)
  {
    std::mt19937                           random(3);
    std::uniform_real_distribution<double> uniform(-1., 1.);
    const int                              m = 37, k = 150, lda = 151, ldb = 153, ldc = 40;
    std::uint64_t                          forwarded = 0;
    const std::uint64_t before = time::single_column_products_forwarded();
    double                                 worst = 0.;
    for (const int n : {1, 2, 3, 4, 5})
      for (const char ta : {'N', 'T'})
        for (const char tb : {'N', 'T'})
          for (const Real beta : {Real(-1.3), Real(0)})
            for (const bool trailing_zero : {false, true})
            {
              std::vector<Real> A(lda * std::max(m, k)), B(ldb * std::max(k, n)), C(ldc * n);
              for (auto *v : {&A, &B, &C})
                for (auto &x : *v)
                  x = uniform(random);
              if (beta == Real(0))
                std::fill(C.begin(), C.end(), std::numeric_limits<Real>::quiet_NaN());
              std::vector<double> reference(C.size());
              const Real          alpha = 0.7;
              const auto a = [&](int i, int l) { return ta == 'N' ? A[i + l * lda] : A[l + i * lda]; };
              // with trailing_zero, op(B)'s columns after the first (after the
              // second with four or five) are zero
              if (trailing_zero)
                for (int l = 0; l < k; ++l)
                  for (int j = n < 4 ? 1 : 2; j < n; ++j)
                    (tb == 'N' ? B[l + j * ldb] : B[j + l * ldb]) = 0;
              const auto b = [&](int l, int j) { return tb == 'N' ? B[l + j * ldb] : B[j + l * ldb]; };
              for (int j = 0; j < n; ++j)
                for (int i = 0; i < m; ++i)
                  {
                    double sum = 0.;
                    for (int l = 0; l < k; ++l)
                      sum += double(a(i, l)) * double(b(l, j));
                    reference[i + j * ldc] =
                      double(alpha) * sum + (beta == Real(0) ? 0. : double(beta) * C[i + j * ldc]);
                  }
              gemm(&ta, &tb, &m, &n, &k, &alpha, A.data(), &lda, B.data(), &ldb, &beta, C.data(),
                   &ldc);
              for (int j = 0; j < n; ++j)
                for (int i = 0; i < m; ++i)
                  {
                    const double d = std::abs(C[i + j * ldc] - reference[i + j * ldc]);
                    worst          = std::isnan(d) ? 1e300 : std::max(worst, d);
                  }
              forwarded += n <= 4;
            }
    testing::check_below(name + " with one to five columns, every transposition, beta 0 "
                                "and not, trailing columns zero and not, against the sums, "
                                "largest difference",
                         worst, tolerance);
    testing::log() << "the " << forwarded << " " << name << " products with one to four "
                   << "columns went to gemv or to the library's product, those with five did "
                   << "not: "
                   << testing::yes(time::single_column_products_forwarded() - before == forwarded)
                   << std::endl;
  }

  /// A on an n^3 grid: 7-point Laplacian plus @p mass on the diagonal; with
  /// @p indefinite the block of the second half of the unknowns with itself
  /// is negated, which keeps A symmetric and makes it indefinite. Rows and
  /// columns are scaled by 10^-1 ... 10^1 (as displacements and pressures
  /// are), so that MUMPS's scaling of the matrix is exercised.
  void
  make_matrix(const unsigned int n, const double mass, const bool indefinite, archdam::SparseMatrix &A,
              const IndexSet &owned)
  {
    const unsigned int     N = n * n * n;
    DynamicSparsityPattern dsp(N, N);
    const auto id = [n](unsigned int i, unsigned int j, unsigned int k) { return (k * n + j) * n + i; };
    std::vector<std::tuple<unsigned int, unsigned int, double>> entries;
    for (unsigned int k = 0; k < n; ++k)
      for (unsigned int j = 0; j < n; ++j)
        for (unsigned int i = 0; i < n; ++i)
          {
            const unsigned int r = id(i, j, k);
            entries.emplace_back(r, r, 6. + mass);
            if (i + 1 < n)
              entries.emplace_back(r, id(i + 1, j, k), -1.);
            if (j + 1 < n)
              entries.emplace_back(r, id(i, j + 1, k), -1.);
            if (k + 1 < n)
              entries.emplace_back(r, id(i, j, k + 1), -1.);
          }
    for (const auto &[r, c, v] : entries)
      {
        dsp.add(r, c);
        dsp.add(c, r);
      }
    A.reinit(owned, owned, dsp, MPI_COMM_WORLD);
    for (const auto &[r, c, v] : entries)
      {
        const auto   scale = [](const unsigned int i) {
          return std::pow(10., 0.5 * (static_cast<double>((37 * i) % 5) - 2.));
        };
        const double value = scale(r) * scale(c) * (indefinite && r >= N / 2 && c >= N / 2 ? -v : v);
        if (owned.is_element(r))
          A.set(r, c, value);
        if (r != c && owned.is_element(c))
          A.set(c, r, value);
      }
    A.compress(VectorOperation::insert);
  }

  /// x = A^{-1} (b - q) through condense(), S x_Γ = y - q, expand().
  void
  solve_with_interface_load(const time::CondensedFactorization &factor, const archdam::Vector &b,
                            const std::vector<double> &q, archdam::Vector &x,
                            const dealii::Vector<double> *q2 = nullptr,
                            archdam::Vector              *x2 = nullptr)
  {
    dealii::Vector<double> y;
    factor.condense(b, y, q2 != nullptr);
    for (unsigned int g = 0; g < q.size(); ++g)
      y[g] -= q[g];
    factor.solve_interface(y);
    factor.expand(y, x, q2, x2);
  }

  /// Random entries in [-1, 1] for b (of @p N unknowns, the same on every
  /// rank) and then for a load on the @p k interface unknowns, returned.
  std::vector<double>
  random_loads(const unsigned int N, const unsigned int k, std::mt19937 &random,
               archdam::Vector &b)
  {
    std::uniform_real_distribution<double> uniform(-1., 1.);
    const IndexSet                         owned = b.locally_owned_elements();
    for (unsigned int g = 0; g < N; ++g)
      {
        const double v = uniform(random); // the same sequence on every rank
        if (owned.is_element(g))
          b(g) = v;
      }
    b.compress(VectorOperation::insert);
    std::vector<double> q(k);
    for (auto &v : q)
      v = uniform(random);
    return q;
  }

  /// The interface: every 17th unknown (spread over the grid and the ranks).
  std::vector<types::global_dof_index>
  spread_interface(const unsigned int N)
  {
    std::vector<types::global_dof_index> gamma;
    for (unsigned int g = 3; g < N; g += 17)
      gamma.push_back(g);
    return gamma;
  }

  IndexSet
  owned_rows(const unsigned int N)
  {
    const unsigned int n_ranks = Utilities::MPI::n_mpi_processes(MPI_COMM_WORLD);
    const unsigned int rank    = Utilities::MPI::this_mpi_process(MPI_COMM_WORLD);
    IndexSet           owned(N);
    owned.add_range(N * rank / n_ranks, N * (rank + 1) / n_ranks);
    return owned;
  }

  /// The matrix of make_matrix() on an n^3 grid into @p A; the rows owned
  /// here and the interface.
  std::pair<IndexSet, std::vector<types::global_dof_index>>
  grid_problem(const unsigned int n, const bool indefinite, archdam::SparseMatrix &A)
  {
    const IndexSet owned = owned_rows(n * n * n);
    make_matrix(n, 0.5, indefinite, A, owned);
    return {owned, spread_interface(n * n * n)};
  }

  /// MUMPS's block low-rank factors (ICNTL(35), CNTL(7) = 1e-6) against the
  /// full-rank factors on a grid whose fronts are large enough to be
  /// compressed (24^3 unknowns; 0.90 of the entries here): fewer entries,
  /// the same solve to within a few orders of the tolerance
  /// (bench_factor_orders measures them on the reference case); a negative
  /// tolerance is refused.
  void
  check_low_rank(const std::string &name, const bool indefinite)
  {
    const unsigned int    n = 24, N = n * n * n;
    archdam::SparseMatrix A;
    const auto [owned, gamma] = grid_problem(n, indefinite, A);
    using Ordering            = time::CondensedFactorization::Ordering;
    const time::CondensedFactorization full(A, !indefinite, gamma);
    const time::CondensedFactorization low_rank(A, !indefinite, gamma,
                                                Ordering::nested_dissection, 1e-6);
    testing::check_below(name + ": block low-rank factors with CNTL(7) = 1e-6, their entries "
                                "against the full-rank factors'",
                         low_rank.statistics().entries / full.statistics().entries, 0.95);

    std::mt19937    random(11);
    archdam::Vector b(owned, MPI_COMM_WORLD), x_full(owned, MPI_COMM_WORLD),
      x_low(owned, MPI_COMM_WORLD);
    const std::vector<double> q = random_loads(N, gamma.size(), random, b);
    solve_with_interface_load(full, b, q, x_full);
    solve_with_interface_load(low_rank, b, q, x_low);
    x_low -= x_full;
    testing::check_below(name + ": block low-rank factors, the solve against the full-rank "
                                "factors', largest difference relative to the solution's largest",
                         x_low.linfty_norm() / x_full.linfty_norm(), 1e-4);

    bool refused = false;
    try
      {
        time::CondensedFactorization(A, !indefinite, gamma, Ordering::nested_dissection, -1e-9);
      }
    catch (const ExceptionBase &e)
      {
        refused = std::string(e.what()).find("low-rank tolerance") != std::string::npos;
      }
    testing::log() << name << ": a negative low-rank tolerance refused: " << testing::yes(refused)
                   << std::endl;
  }

  /// The factor in single precision (time::Precision): half the
  /// bytes of the double factor, its solves through sgemv (products of one
  /// column), and the solve of A x = b - q (the interface load q) and of a
  /// load on the interface alone against the double factor's: apart by
  /// about the scaled matrix's condition number times single precision's
  /// unit round-off (6e-8), far above double's round-off (so the solve is
  /// in single) and, after one step of iterative refinement in double with
  /// the same factor, at double's round-off times the same factor again
  /// (a wrong factor would not refine so). Measured: 3.6e-7 and 2.9e-7 for
  /// the two matrices, 1.2e-7 for the interface load.
  void
  check_single_precision(const std::string &name, const bool indefinite)
  {
    const unsigned int    n = 24, N = n * n * n;
    archdam::SparseMatrix A;
    const auto [owned, gamma] = grid_problem(n, indefinite, A);
    using Ordering            = time::CondensedFactorization::Ordering;
    const time::CondensedFactorization full(A, !indefinite, gamma);
    const time::CondensedFactorization single(A, !indefinite, gamma, Ordering::nested_dissection,
                                              0., time::Precision::single_precision);
    testing::check_below(name + ": the single-precision factor's memory against the double one's",
                         single.statistics().memory / full.statistics().memory, 0.6);

    std::mt19937    random(13);
    archdam::Vector b(owned, MPI_COMM_WORLD), x_full(owned, MPI_COMM_WORLD),
      x_single(owned, MPI_COMM_WORLD), residual(owned, MPI_COMM_WORLD),
      dx(owned, MPI_COMM_WORLD);
    const std::vector<double> q = random_loads(N, gamma.size(), random, b);
    solve_with_interface_load(full, b, q, x_full);
    const std::uint64_t forwarded_before = time::single_column_products_forwarded();
    solve_with_interface_load(single, b, q, x_single);
    testing::log() << name << ": the single-precision solve's products of one column go to "
                   << "sgemv: "
                   << testing::yes(Utilities::MPI::max(time::single_column_products_forwarded() -
                                                         forwarded_before,
                                                       MPI_COMM_WORLD) > 0)
                   << std::endl;
    const auto difference = [&](const archdam::Vector &x) {
      archdam::Vector d(x);
      d -= x_full;
      return d.linfty_norm() / x_full.linfty_norm();
    };
    const double unrefined = difference(x_single);
    testing::log() << name << ": the single-precision solve against the double one, largest "
                   << "difference relative to the solution's largest, between 1e-9 and 1e-5: "
                   << testing::yes(unrefined > 1e-9 && unrefined < 1e-5) << std::endl;

    // One step of refinement: r = (b - q) - A x, x += A~^{-1} r.
    for (unsigned int g = 0; g < gamma.size(); ++g)
      if (owned.is_element(gamma[g]))
        b(gamma[g]) -= q[g];
    b.compress(VectorOperation::add);
    A.vmult(residual, x_single);
    residual.sadd(-1., 1., b);
    solve_with_interface_load(single, residual, std::vector<double>(gamma.size(), 0.), dx);
    x_single += dx;
    testing::check_below(name + ": after one step of iterative refinement in double, largest "
                                "difference relative to the solution's largest",
                         difference(x_single), 1e-10);

    // A load on the interface alone (the position correction's solve),
    // beside the solve with b.
    std::uniform_real_distribution<double> uniform(-1., 1.);
    dealii::Vector<double>                 q2(gamma.size());
    for (auto &v : q2)
      v = uniform(random);
    solve_with_interface_load(full, b, q, dx, &q2, &x_full);
    solve_with_interface_load(single, b, q, dx, &q2, &x_single);
    const double interface_only = difference(x_single);
    testing::log() << name << ": a load on the interface alone, single against double, largest "
                   << "difference relative to the solution's largest, between 1e-9 and 1e-5: "
                   << testing::yes(interface_only > 1e-9 && interface_only < 1e-5) << std::endl;
  }

  void
  check(const std::string &name, const bool indefinite)
  {
    const unsigned int    n = 12, N = n * n * n;
    archdam::SparseMatrix A;
    const auto [owned, gamma] = grid_problem(n, indefinite, A);
    const unsigned int k      = gamma.size();

    time::FactorizedOperator     plain;
    // MUMPS's LDL^T through PETSc for the indefinite case (Cholesky would fail).
    plain.factorize(A, !indefinite);
    time::CondensedFactorization condensed(A, !indefinite, gamma);
    // An interface that is not sorted, unique DOFs of A is refused, with
    // its own message (MUMPS might fail on some of them by itself).
    for (const auto &[what, wrong] :
         std::vector<std::pair<std::string, std::vector<types::global_dof_index>>>{
           {"unsorted", {5, 3}}, {"repeated", {3, 3}}, {"beyond the matrix", {3, N}}})
      {
        bool refused = false;
        try
          {
            time::CondensedFactorization(A, !indefinite, wrong);
          }
        catch (const ExceptionBase &e)
          {
            refused = std::string(e.what()).find("condensed interface must be sorted") !=
                      std::string::npos;
          }
        testing::log() << name << ": an interface " << what
                       << " refused: " << testing::yes(refused) << std::endl;
      }

    // S^{-1} against (A^{-1})_ΓΓ, column by column.
    archdam::Vector e(owned, MPI_COMM_WORLD), column(owned, MPI_COMM_WORLD);
    double worst_inverse = 0., largest = 0.;
    for (unsigned int c = 0; c < k; c += 7)
      {
        e = 0.;
        if (owned.is_element(gamma[c]))
          e(gamma[c]) = 1.;
        e.compress(VectorOperation::insert);
        plain.solve(column, e);
        dealii::Vector<double> s(k);
        s[c] = 1.;
        condensed.solve_interface(s);
        for (unsigned int r = 0; r < k; ++r)
          {
            const double reference = Utilities::MPI::sum(
              owned.is_element(gamma[r]) ? double(column(gamma[r])) : 0., MPI_COMM_WORLD);
            largest       = std::max(largest, std::abs(reference));
            worst_inverse = std::max(worst_inverse, std::abs(s[r] - reference));
          }
      }
    testing::check_below(name + ": S^-1 against the interface block of A^-1, largest "
                                "difference relative to its largest entry",
                         worst_inverse / largest, 1e-10);

    // Condensed solves with a load on the interface against A^{-1} (b - q),
    // three in a row with different b and q (each reuses the set-up of the
    // one before, and must not reuse its condensation): with one right-hand
    // side; with the room for a load on the interface alone but none given;
    // with that load q' too, whose response A^{-1} q' (the joints' position
    // correction) comes from the same expansion.
    std::mt19937                           random(7);
    std::uniform_real_distribution<double> uniform(-1., 1.);
    archdam::Vector b(owned, MPI_COMM_WORLD), x(owned, MPI_COMM_WORLD),
      reference(owned, MPI_COMM_WORLD);
    std::vector<double> q(k);
    const std::array<std::string, 3> solves{{"one right-hand side",
                                             "room for an interface load, none given",
                                             "an interface load beside"}};
    for (unsigned int repeat = 0; repeat < solves.size(); ++repeat)
      {
        for (auto &v : q)
          v = uniform(random);
        for (unsigned int g = 0; g < N; ++g)
          {
            const double v = uniform(random); // the same sequence on every rank
            if (owned.is_element(g))
              b(g) = v;
          }
        b.compress(VectorOperation::insert);
        archdam::Vector b_minus_q(b);
        for (unsigned int g = 0; g < k; ++g)
          if (owned.is_element(gamma[g]))
            b_minus_q(gamma[g]) -= q[g];
        b_minus_q.compress(VectorOperation::add);
        plain.solve(reference, b_minus_q);

        // A load on the interface alone, q'.
        dealii::Vector<double> q2(k);
        for (auto &v : q2)
          v = uniform(random);
        archdam::Vector q2_full(owned, MPI_COMM_WORLD), x2(owned, MPI_COMM_WORLD),
          reference2(owned, MPI_COMM_WORLD);

        const std::uint64_t forwarded_before = time::single_column_products_forwarded();
        if (repeat == 0)
          solve_with_interface_load(condensed, b, q, x);
        else
          {
            // the room without a load: the second column's x_Γ is zero
            dealii::Vector<double> y;
            condensed.condense(b, y, true);
            for (unsigned int g = 0; g < k; ++g)
              y[g] -= q[g];
            condensed.solve_interface(y);
            condensed.expand(y, x, repeat == 2 ? &q2 : nullptr, repeat == 2 ? &x2 : nullptr);
          }
        if (repeat == 0)
          testing::log() << name << ": MUMPS's forward elimination and backward substitution "
                         << "made products with one column through dgemv: "
                         << testing::yes(Utilities::MPI::min(
                              time::single_column_products_forwarded() > forwarded_before ? 1 : 0,
                              MPI_COMM_WORLD) == 1)
                         << std::endl;
        x -= reference;
        testing::check_below(name + ": condense, interface solve, expand against A^-1 (b - q), " +
                               solves[repeat] +
                               ", largest difference relative to the solution's largest",
                             x.linfty_norm() / reference.linfty_norm(), 1e-10);
        if (repeat < 2)
          continue;
        for (unsigned int g = 0; g < k; ++g)
          if (owned.is_element(gamma[g]))
            q2_full(gamma[g]) = q2[g];
        q2_full.compress(VectorOperation::insert);
        plain.solve(reference2, q2_full);
        x2 -= reference2;
        testing::check_below(name + ": a load on the interface alone, from the same expansion, "
                                    "against A^-1 q', largest difference relative to the "
                                    "solution's largest",
                             x2.linfty_norm() / reference2.linfty_norm(), 1e-10);
      }

    // SCOTCH's nested dissection instead of METIS's and MUMPS's PORD: the
    // same solution (an order that is not a permutation would fail in MUMPS
    // or solve wrongly).
    for (const auto &[order_name, order] :
         {std::pair<std::string, time::CondensedFactorization::Ordering>{
            "SCOTCH", time::CondensedFactorization::Ordering::scotch},
          {"PORD", time::CondensedFactorization::Ordering::pord}})
      {
        const time::CondensedFactorization other(A, !indefinite, gamma, order);
        solve_with_interface_load(other, b, q, x);
        x -= reference;
        testing::check_below(name + ": ordered by " + order_name +
                               ", the second solve against A^-1 (b - q), largest difference "
                               "relative to the solution's largest",
                             x.linfty_norm() / reference.linfty_norm(), 1e-10);
      }
  }
} // namespace

int
main(int argc, char **argv)
{
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  check_narrow_products<double>("dgemm", 1e-12);
  check_narrow_products<float>("sgemm", 1e-4);
  check("positive definite", false);
  check("indefinite", true);
  check_low_rank("positive definite", false);
  check_low_rank("indefinite", true);
  check_single_precision("positive definite", false);
  check_single_precision("indefinite", true);
}
