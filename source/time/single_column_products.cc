#include <archdam/time/single_column_products.h>

#include <dlfcn.h>

#include <atomic>
#include <cstdio>
#include <cstdlib>

// The Fortran BLAS interface (hidden string lengths are not passed: the
// character arguments are single letters, as every BLAS caller does).
using Dgemm = void (*)(const char *, const char *, const int *, const int *, const int *,
                       const double *, const double *, const int *, const double *,
                       const int *, const double *, double *, const int *);

extern "C" void
dgemv_(const char *trans, const int *m, const int *n, const double *alpha, const double *a,
       const int *lda, const double *x, const int *incx, const double *beta, double *y,
       const int *incy);

namespace
{
  std::atomic<std::uint64_t> forwarded{0};
  std::atomic<bool>          forwarding{true};

  Dgemm
  blas_dgemm()
  {
    // The next dgemm_ in the search order after this library: the BLAS's.
    static const Dgemm next = [] {
      const auto f = reinterpret_cast<Dgemm>(dlsym(RTLD_NEXT, "dgemm_"));
      if (f == nullptr)
        {
          std::fprintf(stderr, "archdam: error: no BLAS library with dgemm_ is loaded "
                               "(time/single_column_products.h).\n");
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
} // namespace

extern "C" void
dgemm_(const char *transa, const char *transb, const int *m, const int *n, const int *k,
       const double *alpha, const double *a, const int *lda, const double *b, const int *ldb,
       const double *beta, double *c, const int *ldc)
{
  if (*n != 1 || *m <= 0 || *k <= 0 || !forwarding.load(std::memory_order_relaxed))
    {
      blas_dgemm()(transa, transb, m, n, k, alpha, a, lda, b, ldb, beta, c, ldc);
      return;
    }
  // c (m x 1) = alpha op(A) b + beta c: op(B) is k x 1, a column of B (stride
  // 1) or, transposed, a row of B (stride ldb).
  const int one  = 1;
  const int incx = transposed(transb) ? *ldb : 1;
  if (transposed(transa)) // A is k x m
    dgemv_("T", k, m, alpha, a, lda, b, &incx, beta, c, &one);
  else // A is m x k
    dgemv_("N", m, k, alpha, a, lda, b, &incx, beta, c, &one);
  forwarded.fetch_add(1, std::memory_order_relaxed);
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
