#include <archdam/time/single_column_products.h>

#include <dlfcn.h>

#include <algorithm>
#include <atomic>
#include <cstddef>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <vector>

// The Fortran BLAS interface (hidden string lengths are not passed: the
// character arguments are single letters, as every BLAS caller does).
template <typename Real>
using Gemm = void (*)(const char *, const char *, const int *, const int *, const int *,
                      const Real *, const Real *, const int *, const Real *, const int *,
                      const Real *, Real *, const int *);

extern "C" void
dgemv_(const char *trans, const int *m, const int *n, const double *alpha, const double *a,
       const int *lda, const double *x, const int *incx, const double *beta, double *y,
       const int *incy);

extern "C" void
sgemv_(const char *trans, const int *m, const int *n, const float *alpha, const float *a,
       const int *lda, const float *x, const int *incx, const float *beta, float *y,
       const int *incy);

namespace
{
  std::atomic<std::uint64_t> forwarded{0};
  std::atomic<bool>          forwarding{true};

  /// The BLAS's own gemm of this precision (@p name): the next definition in
  /// the search order after this library.
  template <typename Real>
  Gemm<Real>
  blas_gemm(const char *name)
  {
    static const Gemm<Real> next = [name] {
      const auto f = reinterpret_cast<Gemm<Real>>(dlsym(RTLD_NEXT, name));
      if (f == nullptr)
        {
          std::fprintf(stderr,
                       "archdam: error: no BLAS library with %s is loaded "
                       "(time/single_column_products.h).\n",
                       name);
          std::abort();
        }
      return f;
    }();
    return next;
  }

  bool
  transposed(const char *t)
  {
    return *t != 'N' && *t != 'n';
  }

  void
  gemv(const char *trans, const int *m, const int *n, const double *alpha, const double *a,
       const int *lda, const double *x, const int *incx, const double *beta, double *y,
       const int *incy)
  {
    dgemv_(trans, m, n, alpha, a, lda, x, incx, beta, y, incy);
  }

  void
  gemv(const char *trans, const int *m, const int *n, const float *alpha, const float *a,
       const int *lda, const float *x, const int *incx, const float *beta, float *y,
       const int *incy)
  {
    sgemv_(trans, m, n, alpha, a, lda, x, incx, beta, y, incy);
  }

  /// The widest product made by narrow_product().
  constexpr int widest_narrow = 4;

  /// 32 bytes of Real: one AVX2 register (two SSE2 registers otherwise).
  template <typename Real>
  using Lanes [[gnu::vector_size(32)]] = Real;

  template <typename Real>
  [[gnu::always_inline]] inline Lanes<Real>
  load(const Real *p)
  {
    Lanes<Real> v;
    std::memcpy(&v, p, sizeof(v));
    return v;
  }

  /// c (m x N) = alpha op(A) op(B) + beta c for a few columns N, reading
  /// A's entries from memory once: eight columns of A (op(A) = A) or one
  /// (op(A) = A^T) serve every column of op(B) from the registers. op(B),
  /// times alpha, is copied to contiguous columns first (@p x, k N).
  template <typename Real, int N>
  [[gnu::always_inline]] inline void
  narrow_product(const bool ta, const bool tb, const int m, const int k, const Real alpha,
                 const Real *a, const int lda, const Real *b, const int ldb, const Real beta,
                 Real *c, const int ldc, Real *x)
  {
    constexpr int L = sizeof(Lanes<Real>) / sizeof(Real);
    for (int r = 0; r < N; ++r)
      {
        Real *cr = c + std::size_t(r) * ldc;
        if (beta == Real(0))
          std::fill(cr, cr + m, Real(0));
        else if (beta != Real(1))
          for (int i = 0; i < m; ++i)
            cr[i] *= beta;
        for (int j = 0; j < k; ++j)
          x[std::size_t(r) * k + j] =
            alpha * (tb ? b[r + std::size_t(j) * ldb] : b[j + std::size_t(r) * ldb]);
      }
    if (!ta) // A is m x k: c(:, r) += A(:, j) x_r(j), eight columns of A at a time
      {
        constexpr int W = 8;
        int           j = 0;
        for (; j + W <= k; j += W)
          {
            const Real *aj = a + std::size_t(j) * lda;
            // the x_r(j) of the eight columns in every lane (held apart from
            // x: x and c could alias for the compiler)
            Lanes<Real> s[N][W];
            for (int r = 0; r < N; ++r)
              for (int l = 0; l < W; ++l)
                s[r][l] = Lanes<Real>{} + x[std::size_t(r) * k + j + l];
            int i = 0;
            for (; i + L <= m; i += L)
              {
                Lanes<Real> v[W];
                for (int l = 0; l < W; ++l)
                  v[l] = load(aj + std::size_t(l) * lda + i);
                for (int r = 0; r < N; ++r)
                  {
                    Real       *cr  = c + std::size_t(r) * ldc + i;
                    Lanes<Real> sum = load(cr);
                    for (int l = 0; l < W; ++l)
                      sum += v[l] * s[r][l];
                    std::memcpy(cr, &sum, sizeof(sum));
                  }
              }
            for (; i < m; ++i)
              for (int r = 0; r < N; ++r)
                {
                  Real sum = 0;
                  for (int l = 0; l < W; ++l)
                    sum += aj[std::size_t(l) * lda + i] * x[std::size_t(r) * k + j + l];
                  c[i + std::size_t(r) * ldc] += sum;
                }
          }
        for (; j < k; ++j)
          for (int r = 0; r < N; ++r)
            {
              const Real *aj = a + std::size_t(j) * lda;
              const Real  s  = x[std::size_t(r) * k + j];
              Real       *cr = c + std::size_t(r) * ldc;
              for (int i = 0; i < m; ++i)
                cr[i] += aj[i] * s;
            }
        return;
      }
    // A is k x m: c(i, r) += A(:, i) . x_r
    for (int i = 0; i < m; ++i)
      {
        const Real *ai = a + std::size_t(i) * lda;
        Lanes<Real> sum[N][2]{};
        int         j = 0;
        for (; j + 2 * L <= k; j += 2 * L)
          {
            const Lanes<Real> v0 = load(ai + j), v1 = load(ai + j + L);
            for (int r = 0; r < N; ++r)
              {
                const Real *xr = x + std::size_t(r) * k + j;
                sum[r][0] += v0 * load(xr);
                sum[r][1] += v1 * load(xr + L);
              }
          }
        for (int r = 0; r < N; ++r)
          {
            const Real       *xr    = x + std::size_t(r) * k;
            const Lanes<Real> lanes = sum[r][0] + sum[r][1];
            Real              total = 0;
            for (int l = 0; l < L; ++l)
              total += lanes[l];
            for (int jj = j; jj < k; ++jj)
              total += ai[jj] * xr[jj];
            c[i + std::size_t(r) * ldc] += total;
          }
      }
  }

  template <typename Real>
  [[gnu::always_inline]] inline void
  narrow_product_n(const bool ta, const bool tb, const int m, const int n, const int k,
                   const Real alpha, const Real *a, const int lda, const Real *b, const int ldb,
                   const Real beta, Real *c, const int ldc)
  {
    thread_local std::vector<Real> x;
    x.resize(std::size_t(n) * k);
    if (n == 2)
      narrow_product<Real, 2>(ta, tb, m, k, alpha, a, lda, b, ldb, beta, c, ldc, x.data());
    else if (n == 3)
      narrow_product<Real, 3>(ta, tb, m, k, alpha, a, lda, b, ldb, beta, c, ldc, x.data());
    else
      narrow_product<Real, 4>(ta, tb, m, k, alpha, a, lda, b, ldb, beta, c, ldc, x.data());
  }

  /// The kernel compiled for processors with AVX2 and FMA, and for any.
  template <typename Real>
  [[gnu::target("avx2,fma")]] void
  narrow_product_avx2(const bool ta, const bool tb, const int m, const int n, const int k,
                      const Real alpha, const Real *a, const int lda, const Real *b,
                      const int ldb, const Real beta, Real *c, const int ldc)
  {
    narrow_product_n(ta, tb, m, n, k, alpha, a, lda, b, ldb, beta, c, ldc);
  }

  template <typename Real>
  void
  narrow_product_any(const bool ta, const bool tb, const int m, const int n, const int k,
                     const Real alpha, const Real *a, const int lda, const Real *b,
                     const int ldb, const Real beta, Real *c, const int ldc)
  {
    narrow_product_n(ta, tb, m, n, k, alpha, a, lda, b, ldb, beta, c, ldc);
  }

  template <typename Real>
  void
  narrow_product_of(const bool ta, const bool tb, const int m, const int n, const int k,
                    const Real alpha, const Real *a, const int lda, const Real *b,
                    const int ldb, const Real beta, Real *c, const int ldc)
  {
    static const bool avx2 = __builtin_cpu_supports("avx2") && __builtin_cpu_supports("fma");
    (avx2 ? narrow_product_avx2<Real> : narrow_product_any<Real>)(ta, tb, m, n, k, alpha, a, lda,
                                                                 b, ldb, beta, c, ldc);
  }

  /// c (m x n) = alpha op(A) op(B) + beta c; with n = 1 by gemv, with a few
  /// columns by narrow_product().
  template <typename Real>
  void
  gemm(const char *name, const char *transa, const char *transb, const int *m, const int *n,
       const int *k, const Real *alpha, const Real *a, const int *lda, const Real *b,
       const int *ldb, const Real *beta, Real *c, const int *ldc)
  {
    if (*n < 1 || *n > widest_narrow || *m <= 0 || *k <= 0 ||
        !forwarding.load(std::memory_order_relaxed))
      {
        blas_gemm<Real>(name)(transa, transb, m, n, k, alpha, a, lda, b, ldb, beta, c, ldc);
        return;
      }
    // op(B)'s trailing columns that are zero (a second right-hand side
    // that is zero off the interface: in a forward elimination always, in a
    // backward substitution in the steps that have no load for it) only
    // scale C's: the product has the leading columns alone.
    const bool tb         = transposed(transb);
    const auto zero_entry = [&](const int j, const int r) {
      return (tb ? b[r + std::size_t(j) * *ldb] : b[j + std::size_t(r) * *ldb]) == Real(0);
    };
    int width = *n;
    while (width > 1)
      {
        int j = 0;
        while (j < *k && zero_entry(j, width - 1))
          ++j;
        if (j < *k)
          break;
        Real *cr = c + std::size_t(width - 1) * *ldc;
        for (int i = 0; i < *m; ++i)
          cr[i] = *beta == Real(0) ? Real(0) : *beta * cr[i];
        --width;
      }
    if (width > 1)
      {
        narrow_product_of(transposed(transa), tb, *m, width, *k, *alpha, a, *lda, b, *ldb, *beta,
                          c, *ldc);
        forwarded.fetch_add(1, std::memory_order_relaxed);
        return;
      }
    // op(B) is k x 1, a column of B (stride 1) or, transposed, a row of B
    // (stride ldb).
    const int one  = 1;
    const int incx = transposed(transb) ? *ldb : 1;
    if (transposed(transa)) // A is k x m
      gemv("T", k, m, alpha, a, lda, b, &incx, beta, c, &one);
    else // A is m x k
      gemv("N", m, k, alpha, a, lda, b, &incx, beta, c, &one);
    forwarded.fetch_add(1, std::memory_order_relaxed);
  }
} // namespace

extern "C" void
dgemm_(const char *transa, const char *transb, const int *m, const int *n, const int *k,
       const double *alpha, const double *a, const int *lda, const double *b, const int *ldb,
       const double *beta, double *c, const int *ldc)
{
  gemm("dgemm_", transa, transb, m, n, k, alpha, a, lda, b, ldb, beta, c, ldc);
}

// The solves of a single-precision factor (Time integration/Factor precision).
extern "C" void
sgemm_(const char *transa, const char *transb, const int *m, const int *n, const int *k,
       const float *alpha, const float *a, const int *lda, const float *b, const int *ldb,
       const float *beta, float *c, const int *ldc)
{
  gemm("sgemm_", transa, transb, m, n, k, alpha, a, lda, b, ldb, beta, c, ldc);
}

namespace archdam::time
{
  std::uint64_t
  single_column_products_forwarded()
  {
    return forwarded.load(std::memory_order_relaxed);
  }

  void
  forward_single_column_products(const bool forward)
  {
    forwarding.store(forward, std::memory_order_relaxed);
  }
} // namespace archdam::time
