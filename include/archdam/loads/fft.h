#pragma once

#include <complex>
#include <cstddef>
#include <vector>

namespace archdam::loads
{
  /**
   * In-place discrete Fourier transform of a sequence whose length is a power
   * of two (iterative radix-2 Cooley-Tukey):
   *   forward:  X_k = sum_n x_n exp(-2 pi i k n / N),
   *   inverse:  x_n = (1/N) sum_k X_k exp(+2 pi i k n / N).
   * The twiddle factors are computed directly from cos and sin of each angle
   * (not by a recurrence), so the round-off is that of a few operations per
   * stage, O(log N) eps overall. deal.II has no FFT; this is all the loads
   * module needs (filtering, artificial motions).
   */
  void
  fft(std::vector<std::complex<double>> &x, const bool inverse = false);

  /// The smallest power of two >= n (1 for n = 0).
  std::size_t
  next_power_of_two(const std::size_t n);
} // namespace archdam::loads
