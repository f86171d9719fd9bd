#include <archdam/loads/fft.h>

#include <deal.II/base/exceptions.h>

#include <cmath>
#include <utility>

namespace archdam::loads
{
  std::size_t
  next_power_of_two(const std::size_t n)
  {
    std::size_t m = 1;
    while (m < n)
      m *= 2;
    return m;
  }



  void
  fft(std::vector<std::complex<double>> &x, const bool inverse)
  {
    const std::size_t n = x.size();
    Assert(n > 0 && (n & (n - 1)) == 0,
           dealii::ExcMessage("The FFT length must be a power of two."));
    if (n == 1)
      return;

    // Bit-reversal permutation.
    for (std::size_t i = 1, j = 0; i < n; ++i)
      {
        std::size_t bit = n >> 1;
        for (; j & bit; bit >>= 1)
          j ^= bit;
        j ^= bit;
        if (i < j)
          std::swap(x[i], x[j]);
      }

    // Twiddle factors w_k = exp(-+2 pi i k / n), k < n/2, each from its own
    // angle; a stage of length len uses every (n/len)-th of them.
    const double                      sign = inverse ? 1. : -1.;
    std::vector<std::complex<double>> w(n / 2);
    for (std::size_t k = 0; k < n / 2; ++k)
      {
        const double angle = sign * 2. * M_PI * static_cast<double>(k) / n;
        w[k]               = {std::cos(angle), std::sin(angle)};
      }

    for (std::size_t len = 2; len <= n; len *= 2)
      {
        const std::size_t half   = len / 2;
        const std::size_t stride = n / len;
        for (std::size_t start = 0; start < n; start += len)
          for (std::size_t k = 0; k < half; ++k)
            {
              const std::complex<double> t = w[k * stride] * x[start + k + half];
              x[start + k + half]          = x[start + k] - t;
              x[start + k] += t;
            }
      }

    if (inverse)
      for (auto &v : x)
        v /= static_cast<double>(n);
  }
} // namespace archdam::loads
