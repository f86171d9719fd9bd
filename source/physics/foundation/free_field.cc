#include <archdam/base/input_error.h>
#include <archdam/loads/fft.h>
#include <archdam/loads/record_processing.h>
#include <archdam/physics/foundation/foundation.h>
#include <archdam/physics/foundation/free_field.h>

#include <algorithm>
#include <cmath>
#include <complex>

namespace archdam::physics::foundation
{
  using namespace dealii;

  ControlMotion::ControlMotion(const loads::AccelerationRecord &record)
  {
    const auto h = loads::integrate(record);
    t            = h.times;
    a            = h.acceleration;
    v            = h.velocity;
    d            = h.displacement;
  }

  unsigned int
  ControlMotion::interval(const double time) const
  {
    const auto it = std::upper_bound(t.begin(), t.end(), time);
    return std::min<unsigned int>(it - t.begin() - 1, t.size() - 2);
  }

  // Between samples a is linear (slope j), so over h = t - t_k
  //   a = a_k + j h,  v = v_k + a_k h + j h^2/2,  d = d_k + v_k h + a_k h^2/2 + j h^3/6.
  double
  ControlMotion::acceleration(const double time) const
  {
    if (t.size() < 2 || time < t.front() || time >= t.back())
      return 0.;
    const unsigned int k = interval(time);
    const double       j = (a[k + 1] - a[k]) / (t[k + 1] - t[k]);
    return a[k] + j * (time - t[k]);
  }

  double
  ControlMotion::velocity(const double time) const
  {
    if (t.size() < 2 || time < t.front())
      return 0.;
    if (time >= t.back())
      return v.back();
    const unsigned int k = interval(time);
    const double       j = (a[k + 1] - a[k]) / (t[k + 1] - t[k]);
    const double       h = time - t[k];
    return v[k] + a[k] * h + j * h * h / 2;
  }

  double
  ControlMotion::displacement(const double time) const
  {
    if (t.size() < 2 || time < t.front())
      return 0.;
    if (time >= t.back())
      return d.back() + v.back() * (time - t.back());
    const unsigned int k = interval(time);
    const double       j = (a[k + 1] - a[k]) / (t[k + 1] - t[k]);
    const double       h = time - t[k];
    return d[k] + v[k] * h + a[k] * h * h / 2 + j * h * h * h / 6;
  }

  namespace
  {
    /// Cubic Lagrange interpolation on the levels j h (n + 1 of them, n >= 3):
    /// the first of the four levels used, their weights at depth s, and the
    /// weights' derivatives in s.
    struct Stencil
    {
      unsigned int          first;
      std::array<double, 4> w, dw;
    };

    Stencil
    stencil(const double s, const double h, const unsigned int n)
    {
      const double x = s / h;
      const int    j = std::clamp(static_cast<int>(std::floor(x)), 1, static_cast<int>(n) - 2);
      const double q = x - j; // the levels at q = -1, 0, 1, 2
      Stencil      st;
      st.first = j - 1;
      st.w     = {{-q * (q - 1) * (q - 2) / 6, (q + 1) * (q - 1) * (q - 2) / 2,
                   -(q + 1) * q * (q - 2) / 2, (q + 1) * q * (q - 1) / 6}};
      st.dw    = {{-(3 * q * q - 6 * q + 2) / (6 * h), (3 * q * q - 4 * q - 1) / (2 * h),
                   -(3 * q * q - 2 * q - 2) / (2 * h), (3 * q * q - 1) / (6 * h)}};
      return st;
    }

    /// 1 up to the band limit f_b, 0 from 2 f_b, and between them the
    /// smooth step 1/(1 + exp(1/(1 - x) - 1/x)), x = (f - f_b)/f_b, whose
    /// every derivative is continuous: its ringing in time decays faster
    /// than any power, so that the deconvolved waves have no precursor
    /// beyond a few 1/f_b (a cosine taper's, decaying as t^-3, feeds the
    /// MTF's drift; doc/theory/foundation.md §4).
    double
    band_taper(const double f, const double f_b)
    {
      if (f <= f_b)
        return 1.;
      if (f >= 2 * f_b)
        return 0.;
      const double x = (f - f_b) / f_b;
      return 1. / (1. + std::exp(1. / (1. - x) - 1. / x));
    }

    /**
     * The histories of the free field at the depths j h, j = 0..n, of a
     * component of speed @p c whose control acceleration is @p record, in
     * rock damped by @p damping, over a half-space surface @p depth above
     * the bottom (doc/theory/foundation.md §4): the FFT of the record,
     * times cos(k s), back, and delayed by @p shift samples. Returns the
     * levels; h and the shift in samples go to @p h and @p shift.
     */
    std::vector<ControlMotion>
    deconvolved_levels(const loads::AccelerationRecord &record, const double c,
                       const FreeFieldDamping &damping, const double depth, double &h,
                       unsigned int &shift)
    {
      using complex = std::complex<double>;
      double dt     = 0.;
      record.is_uniform(&dt);
      const std::size_t n = record.values.size();
      // The delay: the travel time with a tenth more, 4 / f_b for the
      // precursors of the taper and four samples, rounded up to whole
      // samples; the levels are kept to the record's end plus the latest
      // arrival (2 T) and a second for the damped tail; the FFT's length
      // leaves at least the delay beyond that, a quiet stretch in which
      // the periodic signal wraps around and each level starts.
      shift = static_cast<unsigned int>(
                std::ceil((1.1 * depth / c + 4 / damping.band_limit) / dt)) +
              4;
      const std::size_t keep = n + 2 * shift + static_cast<std::size_t>(std::ceil(1. / dt));
      const std::size_t N    = loads::next_power_of_two(keep + shift);
      std::vector<complex> A(N, 0.);
      for (std::size_t k = 0; k < n; ++k)
        A[k] = record.values[k];
      loads::fft(A);

      // Levels an eighth of the shortest wave apart, of the record's Nyquist
      // frequency or four times the band limit, whichever is lower (cubic
      // interpolation: 0.9 % at that wave, 4e-5 at a quarter of its frequency).
      const double       f_top = std::min(0.5 / dt, 4 * damping.band_limit);
      const unsigned int n_h =
        std::max(3u, static_cast<unsigned int>(std::ceil(depth / (c / (8 * f_top)))));
      h                      = depth / n_h;
      // Each level starts mid-way through the samples the window leaves
      // out, where the periodic signal is quietest, and is integrated from
      // rest there: its velocity and displacement when the analysis starts
      // are then those of the wave (tiny, not zero), and no level carries
      // the offset d0(s) + v0(s) t that integrating from rest at the start
      // would leave, which no damped column can follow (a drift).
      const std::size_t   pre = (N - keep) / 2;
      std::vector<double> times(pre + keep), values(pre + keep);
      for (std::size_t k = 0; k < pre + keep; ++k)
        times[k] = record.times.front() + (double(k) - double(pre)) * dt;

      // k(w) for every frequency of the FFT (signed: k(-w) = conj k(w)).
      std::vector<complex> wavenumber(N);
      for (std::size_t m = 0; m < N; ++m)
        {
          const double  f   = (m <= N / 2 ? double(m) : double(m) - double(N)) / (N * dt);
          const double  w   = 2 * M_PI * f, tau = band_taper(std::abs(f), damping.band_limit);
          const complex k2  = complex(w * w, -w * damping.alpha * tau) /
                             (c * c * complex(1., w * damping.beta * tau));
          wavenumber[m] = std::sqrt(k2);
        }

      std::vector<ControlMotion> levels;
      levels.reserve(n_h + 1);
      std::vector<complex> B(N);
      for (unsigned int j = 0; j <= n_h; ++j)
        {
          const double s = j * h;
          for (std::size_t m = 0; m < N; ++m)
            B[m] = A[m] * std::cos(wavenumber[m] * s);
          loads::fft(B, true);
          for (std::size_t k = 0; k < pre + keep; ++k)
            values[k] = std::real(B[(k + 2 * N - shift - pre) % N]);
          levels.emplace_back(loads::AccelerationRecord{record.source, times, values});
        }
      return levels;
    }
  } // namespace

  FreeField::FreeField(const std::array<ControlMotion, dim> &control,
                       const solid::ElasticMaterial         &rock,
                       const double                          z_surface,
                       const double                          z_bottom)
    : control(control)
    , rock(rock)
    , c{{shear_wave_speed(rock), shear_wave_speed(rock), pressure_wave_speed(rock)}}
    , z_s(z_surface)
    , z_b(z_bottom)
  {
    for (unsigned int d = 0; d < dim; ++d)
      T[d] = (z_s - z_b) / c[d];
  }

  FreeField::FreeField(const std::array<loads::AccelerationRecord, dim> &records,
                       const solid::ElasticMaterial                     &rock,
                       const FreeFieldDamping                           &damping,
                       const double                                      z_surface,
                       const double                                      z_bottom)
    : FreeField({}, rock, z_surface, z_bottom)
  {
    this->damping = damping;
    if (!(damping.band_limit > 0.))
      throw InputError("Foundation: the free field's Band limit must be positive.");
    for (unsigned int d = 0; d < dim; ++d)
      {
        if (records[d].times.empty())
          continue;
        if (damping.none())
          {
            control[d] = ControlMotion(records[d]);
            continue;
          }
        if (!records[d].is_uniform())
          throw InputError(
            "Foundation: the free field through the damped rock is deconvolved by the FFT "
            "and needs equally spaced samples; the ground motion's component " +
            std::string(1, "xyz"[d]) + " (" + records[d].source +
            ") has not: set its Processing/Resample time step.");
        unsigned int shift = 0;
        levels[d]          = deconvolved_levels(records[d], c[d], damping, z_s - z_b, h[d], shift);
        T[d]               = shift * (records[d].times[1] - records[d].times[0]);
      }
  }

  FreeField
  FreeField::of_ground_motion(const loads::GroundMotion    &motion,
                              const solid::ElasticMaterial &rock,
                              const FreeFieldDamping       &damping,
                              const double                  z_surface,
                              const double                  z_bottom)
  {
    std::array<loads::AccelerationRecord, dim> records;
    for (unsigned int d = 0; d < dim; ++d)
      if (motion.has_component(d))
        records[d] = motion.record(d);
    return FreeField(records, rock, damping, z_surface, z_bottom);
  }

  double
  FreeField::value(const unsigned int d, const double z, const double time,
                   double (ControlMotion::*of)(double) const, const bool slope) const
  {
    if (levels[d].empty())
      {
        // u_ff = 1/2 [u_c(t1) + u_c(t2)], t1,2 = t - T +- s/c (doc/theory/foundation.md §4).
        const double t0 = time - T[d], ds = (z_s - z) / c[d];
        Assert(!slope, ExcInternalError());
        return 0.5 * ((control[d].*of)(t0 + ds) + (control[d].*of)(t0 - ds));
      }
    const Stencil st = stencil(z_s - z, h[d], levels[d].size() - 1);
    double        q  = 0.;
    for (unsigned int i = 0; i < 4; ++i)
      q += (slope ? -st.dw[i] : st.w[i]) * (levels[d][st.first + i].*of)(time);
    return q;
  }

  Tensor<1, dim>
  FreeField::field(const double z, const double time,
                   double (ControlMotion::*of)(double) const) const
  {
    Tensor<1, dim> u;
    for (unsigned int d = 0; d < dim; ++d)
      u[d] = value(d, z, time, of);
    return u;
  }

  Tensor<1, dim>
  FreeField::displacement(const double z, const double time) const
  {
    return field(z, time, &ControlMotion::displacement);
  }

  Tensor<1, dim>
  FreeField::velocity(const double z, const double time) const
  {
    return field(z, time, &ControlMotion::velocity);
  }

  Tensor<1, dim>
  FreeField::acceleration(const double z, const double time) const
  {
    return field(z, time, &ControlMotion::acceleration);
  }

  SymmetricTensor<2, dim>
  FreeField::hooke(const double z, const double time,
                   double (ControlMotion::*of)(double) const) const
  {
    Tensor<1, dim> dudz;
    for (unsigned int d = 0; d < dim; ++d)
      if (levels[d].empty())
        {
          // d/dz of 1/2 [q(t0 + ds) + q(t0 - ds)], ds = (z_s - z)/c: 1/(2c) [q'(t0 - ds) - q'(t0 + ds)].
          const auto   rate = of == &ControlMotion::displacement ? &ControlMotion::velocity :
                                                                   &ControlMotion::acceleration;
          const double t0 = time - T[d], ds = (z_s - z) / c[d];
          dudz[d] = ((control[d].*rate)(t0 - ds) - (control[d].*rate)(t0 + ds)) / (2 * c[d]);
        }
      else
        dudz[d] = value(d, z, time, of, true);
    SymmetricTensor<2, dim> eps;
    eps[2][2] = dudz[2];
    eps[0][2] = dudz[0] / 2;
    eps[1][2] = dudz[1] / 2;
    return rock.stress(eps);
  }

  SymmetricTensor<2, dim>
  FreeField::stress(const double z, const double time) const
  {
    SymmetricTensor<2, dim> sigma = hooke(z, time, &ControlMotion::displacement);
    if (damped() && damping.beta != 0.)
      sigma += damping.beta * hooke(z, time, &ControlMotion::velocity);
    return sigma;
  }
} // namespace archdam::physics::foundation
