#include <archdam/time/single_column_products.h>

#include <dlfcn.h>

#include <atomic>
#include <cstdio>
#include <cstdlib>

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

  /// c (m x n) = alpha op(A) op(B) + beta c; with n = 1 by gemv.
  template <typename Real>
  void
  gemm(const char *name, const char *transa, const char *transb, const int *m, const int *n,
       const int *k, const Real *alpha, const Real *a, const int *lda, const Real *b,
       const int *ldb, const Real *beta, Real *c, const int *ldc)
  {
    if (*n != 1 || *m <= 0 || *k <= 0 || !forwarding.load(std::memory_order_relaxed))
      {
        blas_gemm<Real>(name)(transa, transb, m, n, k, alpha, a, lda, b, ldb, beta, c, ldc);
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
