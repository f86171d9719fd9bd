#include <archdam/base/number_text.h>
#include <archdam/loads/fft.h>
#include <archdam/loads/record_io.h>
#include <archdam/loads/record_processing.h>

#include <deal.II/base/exceptions.h>
#include <deal.II/lac/full_matrix.h>
#include <deal.II/lac/vector.h>

#include <algorithm>
#include <cmath>
#include <iomanip>
#include <complex>
#include <sstream>

namespace archdam::loads
{
  namespace
  {
    void
    check_samples(const AccelerationRecord &record, const std::string &what)
    {
      if (record.times.size() < 2 || record.values.size() != record.times.size())
        throw InputError(what + ": the record needs at least 2 samples.");
    }

    /// Samples at t_0 + k dt of the piecewise-linear record, up to its end.
    AccelerationRecord
    linear_resample(const AccelerationRecord &record, const double dt)
    {
      const double      t0 = record.times.front();
      const std::size_t n  = static_cast<std::size_t>(
        std::floor((record.times.back() - t0) / dt + 1e-9));
      std::vector<double> values(n + 1);
      for (std::size_t k = 0; k <= n; ++k)
        values[k] = record.value(std::min(t0 + k * dt, record.times.back()));
      return uniform_record(values, dt, record.source, t0);
    }
  } // namespace



  MotionHistories
  integrate(const AccelerationRecord &record)
  {
    check_samples(record, "Integration");
    MotionHistories h;
    h.times        = record.times;
    h.acceleration = record.values;
    const std::size_t n = record.times.size();
    h.velocity.assign(n, 0.);
    h.displacement.assign(n, 0.);
    for (std::size_t k = 0; k + 1 < n; ++k)
      {
        const double dt = record.times[k + 1] - record.times[k];
        const double a0 = record.values[k], a1 = record.values[k + 1];
        h.velocity[k + 1] = h.velocity[k] + dt * 0.5 * (a0 + a1);
        h.displacement[k + 1] =
          h.displacement[k] + dt * h.velocity[k] + dt * dt * (a0 / 3. + a1 / 6.);
      }
    return h;
  }



  AccelerationRecord
  scale_to_pga(const AccelerationRecord &record, const double pga)
  {
    if (!(pga > 0) || !std::isfinite(pga))
      throw InputError("Scaling: the target PGA must be positive, it is " +
                       number_text(pga / standard_gravity) + " g.");
    const double peak = record.peak();
    if (!(peak > 0))
      throw InputError("Scaling: the record is zero everywhere; it cannot be "
                       "scaled to a PGA.");
    AccelerationRecord scaled = record;
    const double       factor = pga / peak;
    for (double &a : scaled.values)
      a *= factor;
    return scaled;
  }



  AccelerationRecord
  time_window(const AccelerationRecord &record,
              const double              start,
              const double              end_in,
              const double              taper)
  {
    check_samples(record, "Time window");
    const double record_end = record.times.back();
    const double end        = (end_in == 0.) ? record_end : end_in;
    if (!(start >= 0) || !std::isfinite(start))
      throw InputError("Time window: Start time must be at least 0, it is " +
                       number_text(start) + " s.");
    if (end > record_end * (1 + 1e-12))
      throw InputError("Time window: End time " + number_text(end) +
                       " s is after the end of the record (" + number_text(record_end) +
                       " s).");
    if (!(end > start))
      throw InputError("Time window: End time (" + number_text(end) +
                       " s) must be after Start time (" + number_text(start) + " s).");
    if (!(taper >= 0) || 2. * taper > end - start)
      throw InputError("Time window: Taper length " + number_text(taper) +
                       " s must be between 0 and half the window (" +
                       number_text(0.5 * (end - start)) + " s).");

    AccelerationRecord window;
    window.source = record.source;
    double dt     = 0.;
    if (record.is_uniform(&dt))
      {
        const std::size_t n =
          static_cast<std::size_t>(std::floor((end - start) / dt + 1e-9));
        for (std::size_t k = 0; k <= n; ++k)
          {
            window.times.push_back(k * dt);
            window.values.push_back(
              record.value(std::min(start + k * dt, record_end)));
          }
      }
    else
      {
        window.times.push_back(0.);
        window.values.push_back(record.value(start));
        for (std::size_t k = 0; k < record.times.size(); ++k)
          if (record.times[k] > start && record.times[k] < end)
            {
              window.times.push_back(record.times[k] - start);
              window.values.push_back(record.values[k]);
            }
        window.times.push_back(end - start);
        window.values.push_back(record.value(std::min(end, record_end)));
      }
    if (window.times.size() < 2)
      throw InputError("Time window: the window from " + number_text(start) + " s to " +
                       number_text(end) + " s holds fewer than 2 samples.");

    if (taper > 0)
      {
        const double length = window.times.back();
        for (std::size_t k = 0; k < window.times.size(); ++k)
          {
            const double tau = std::min(window.times[k], length - window.times[k]);
            if (tau < taper)
              window.values[k] *= 0.5 * (1. - std::cos(M_PI * tau / taper));
          }
      }
    return window;
  }



  AccelerationRecord
  resample(const AccelerationRecord &record, const double dt)
  {
    check_samples(record, "Resampling");
    if (!(dt > 0) || !std::isfinite(dt))
      throw InputError("Resampling: the time step must be positive, it is " +
                       number_text(dt) + " s.");
    if (dt > record.times.back() - record.times.front())
      throw InputError("Resampling: the time step " + number_text(dt) +
                       " s is longer than the record (" +
                       number_text(record.times.back() - record.times.front()) + " s).");

    double old_dt  = 0.;
    const bool uniform = record.is_uniform(&old_dt);
    if (!uniform)
      {
        old_dt = record.times[1] - record.times[0];
        for (std::size_t k = 1; k + 1 < record.times.size(); ++k)
          old_dt = std::min(old_dt, record.times[k + 1] - record.times[k]);
      }
    if (dt <= old_dt * (1. + 1e-9))
      return linear_resample(record, dt);

    // Coarser: anti-alias first, on an equally spaced copy.
    const AccelerationRecord fine = uniform ? record : linear_resample(record, old_dt);
    const double new_nyquist = 0.5 / dt;
    return linear_resample(bandpass_filter(fine, 0., 0.8 * new_nyquist, 8), dt);
  }



  AccelerationRecord
  bandpass_filter(const AccelerationRecord &record,
                  const double              high_pass,
                  const double              low_pass,
                  const unsigned int        order)
  {
    check_samples(record, "Filter");
    double dt = 0.;
    if (!record.is_uniform(&dt))
      throw InputError("Filter: the record's samples are not equally spaced; "
                       "resample it first (Resample time step).");
    const double nyquist = 0.5 / dt;
    if (!(high_pass >= 0) || !(low_pass >= 0))
      throw InputError("Filter: corner frequencies must be at least 0 (0 = no "
                       "filter).");
    if (low_pass >= nyquist)
      throw InputError("Filter: the low-pass corner " + number_text(low_pass) +
                       " Hz must be below the Nyquist frequency 1/(2 dt) = " +
                       number_text(nyquist) + " Hz.");
    if (high_pass >= nyquist)
      throw InputError("Filter: the high-pass corner " + number_text(high_pass) +
                       " Hz must be below the Nyquist frequency 1/(2 dt) = " +
                       number_text(nyquist) + " Hz.");
    if (low_pass > 0 && high_pass >= low_pass)
      throw InputError("Filter: the high-pass corner " + number_text(high_pass) +
                       " Hz must be below the low-pass corner " + number_text(low_pass) +
                       " Hz.");
    if (order < 1 || order > 10)
      throw InputError("Filter: the order must be from 1 to 10, it is " +
                       std::to_string(order) + ".");
    if (high_pass == 0. && low_pass == 0.)
      return record;

    // Zero pads of 1.5 n / f_c on each side (Converse & Brady 1992): the
    // filter's impulse response, spread over both sides by the zero-phase
    // form, stays inside them, so the transform's periodic wrap-around does
    // not fold the end of the record onto its start.
    double pad_time = 0.;
    if (high_pass > 0)
      pad_time = std::max(pad_time, 1.5 * order / high_pass);
    if (low_pass > 0)
      pad_time = std::max(pad_time, 1.5 * order / low_pass);
    const std::size_t n   = record.values.size();
    const std::size_t pad = static_cast<std::size_t>(std::ceil(pad_time / dt));
    const std::size_t m   = next_power_of_two(n + 2 * pad);

    std::vector<std::complex<double>> x(m, 0.);
    for (std::size_t k = 0; k < n; ++k)
      x[pad + k] = record.values[k];
    fft(x);
    for (std::size_t j = 0; j < m; ++j)
      {
        const double f = std::min(j, m - j) / (m * dt);
        double       gain = 1.;
        if (high_pass > 0)
          gain *= (f == 0.) ? 0. : 1. / (1. + std::pow(high_pass / f, 2. * order));
        if (low_pass > 0)
          gain *= 1. / (1. + std::pow(f / low_pass, 2. * order));
        x[j] *= gain;
      }
    fft(x, true);

    AccelerationRecord filtered = record;
    for (std::size_t k = 0; k < n; ++k)
      filtered.values[k] = x[pad + k].real();
    return filtered;
  }



  AccelerationRecord
  subtract_fitted_baseline(const AccelerationRecord               &record,
                           const std::vector<std::vector<double>> &basis_a)
  {
    check_samples(record, "Baseline correction");
    const std::vector<double> &t  = record.times;
    const std::size_t          n  = t.size();
    const double               L  = t.back() - t.front();
    const unsigned int         nb = basis_a.size();
    Assert(nb >= 2, dealii::ExcMessage("The baseline needs at least 2 functions."));
    const MotionHistories h = integrate(record);

    // Velocity and displacement of every basis acceleration, by the same
    // exact rule as the record's.
    std::vector<MotionHistories> basis(nb);
    for (unsigned int b = 0; b < nb; ++b)
      {
        Assert(basis_a[b].size() == n, dealii::ExcMessage("One value per sample."));
        AccelerationRecord phi;
        phi.times  = t;
        phi.values = basis_a[b];
        basis[b]   = integrate(phi);
      }

    // Trapezoidal weights (equal inside an equally spaced record), divided by
    // L so that the matrix entries are of the size of the displacements.
    std::vector<double> w(n, 0.);
    for (std::size_t i = 0; i + 1 < n; ++i)
      {
        w[i] += 0.5 * (t[i + 1] - t[i]) / L;
        w[i + 1] += 0.5 * (t[i + 1] - t[i]) / L;
      }

    // KKT system of the constrained least-squares fit:
    //   [G  C^T] [c     ]   [r]
    //   [C  0  ] [lambda] = [e],
    // G_jk = sum_i w_i D_j D_k, r_j = sum_i w_i D_j d; C = end velocity
    // (times L, a displacement) and end displacement of each basis function,
    // e = the record's end velocity (times L) and displacement. With only 2
    // functions G drops out: the constraints alone fix c.
    const unsigned int         size = nb + 2;
    dealii::FullMatrix<double> K(size, size);
    dealii::Vector<double>     rhs(size);
    for (unsigned int j = 0; j < nb; ++j)
      {
        for (unsigned int k = 0; k < nb; ++k)
          {
            double g = 0.;
            for (std::size_t i = 0; i < n; ++i)
              g += w[i] * basis[j].displacement[i] * basis[k].displacement[i];
            K(j, k) = g;
          }
        double r = 0.;
        for (std::size_t i = 0; i < n; ++i)
          r += w[i] * basis[j].displacement[i] * h.displacement[i];
        rhs(j) = r;
        K(nb, j) = K(j, nb) = L * basis[j].velocity.back();
        K(nb + 1, j) = K(j, nb + 1) = basis[j].displacement.back();
      }
    rhs(nb)     = L * h.velocity.back();
    rhs(nb + 1) = h.displacement.back();
    K.gauss_jordan();
    dealii::Vector<double> c(size);
    K.vmult(c, rhs);

    AccelerationRecord corrected = record;
    for (unsigned int b = 0; b < nb; ++b)
      for (std::size_t i = 0; i < n; ++i)
        corrected.values[i] -= c(b) * basis_a[b][i];
    return corrected;
  }



  AccelerationRecord
  baseline_correction(const AccelerationRecord &record, const unsigned int degree)
  {
    check_samples(record, "Baseline correction");
    if (degree < 3 || degree > 10)
      throw InputError("Baseline correction: the polynomial degree must be "
                       "from 3 to 10, it is " +
                       std::to_string(degree) + ".");
    // Basis p_k = tau^k, k = 2 ... degree: second derivatives
    // k (k-1) tau^(k-2) / L^2 at the samples.
    const std::vector<double> &t  = record.times;
    const double               L  = t.back() - t.front();
    std::vector<std::vector<double>> basis_a(degree - 1, std::vector<double>(t.size()));
    for (unsigned int k = 2; k <= degree; ++k)
      for (std::size_t i = 0; i < t.size(); ++i)
        basis_a[k - 2][i] = k * (k - 1.) * std::pow((t[i] - t.front()) / L, int(k) - 2) / (L * L);
    return subtract_fitted_baseline(record, basis_a);
  }



  bool
  ProcessingParameters::any() const
  {
    return start_time != 0. || end_time != 0. || taper != 0. ||
           time_step != 0. || high_pass != 0. || low_pass != 0. || baseline ||
           target_pga != 0.;
  }



  std::string
  ProcessingParameters::description() const
  {
    std::ostringstream out;
    out << std::setprecision(6);
    const auto next = [&out]() -> std::ostringstream & {
      if (out.tellp() > 0)
        out << ", ";
      return out;
    };
    if (start_time != 0. || end_time != 0. || taper != 0.)
      {
        next() << "window from " << start_time << " s to ";
        if (end_time > 0.)
          out << end_time << " s";
        else
          out << "the end";
        if (taper > 0.)
          out << " with " << taper << " s tapers";
      }
    if (time_step > 0.)
      next() << "resampled to " << time_step << " s";
    if (high_pass > 0.)
      next() << "high-pass " << high_pass << " Hz";
    if (low_pass > 0.)
      next() << "low-pass " << low_pass << " Hz";
    if (high_pass > 0. || low_pass > 0.)
      out << " (Butterworth, order " << filter_order << ", zero phase)";
    if (baseline)
      next() << "baseline corrected (polynomial of degree " << baseline_degree << ")";
    if (target_pga > 0.)
      next() << "scaled to PGA " << target_pga << " g";
    return out.tellp() > 0 ? out.str() : std::string("none");
  }

  void
  ProcessingParameters::add_parameters(dealii::ParameterHandler &prm)
  {
    using dealii::Patterns::Bool;
    using dealii::Patterns::Double;
    using dealii::Patterns::Integer;
    prm.add_parameter("Start time",
                      start_time,
                      "Start of the time window kept, s; the window is "
                      "shifted to start at t = 0.",
                      Double(0));
    prm.add_parameter("End time",
                      end_time,
                      "End of the time window kept, s; 0 means the end of the "
                      "record.",
                      Double(0));
    prm.add_parameter("Taper length",
                      taper,
                      "Length of the half-cosine ramps applied at both ends of "
                      "the window, s; 0 means none.",
                      Double(0));
    prm.add_parameter("Resample time step",
                      time_step,
                      "Resample the record to this time step, s (e.g. the "
                      "analysis time step); 0 keeps its samples. A coarser "
                      "step low-pass filters the record first (anti-aliasing).",
                      Double(0));
    prm.add_parameter("High-pass corner",
                      high_pass,
                      "Corner frequency of the zero-phase Butterworth "
                      "high-pass filter, Hz (gain 1/2 there); 0 means none.",
                      Double(0));
    prm.add_parameter("Low-pass corner",
                      low_pass,
                      "Corner frequency of the zero-phase Butterworth low-pass "
                      "filter, Hz (gain 1/2 there); 0 means none.",
                      Double(0));
    prm.add_parameter("Filter order",
                      filter_order,
                      "Order of each Butterworth pass (applied forward and "
                      "backward, so the roll-off doubles).",
                      Integer(1, 10));
    prm.add_parameter("Baseline correction",
                      baseline,
                      "Subtract the second derivative of a polynomial fitted "
                      "to the displacement, so that velocity and displacement "
                      "end at zero (no drift).",
                      Bool());
    prm.add_parameter("Baseline polynomial degree",
                      baseline_degree,
                      "Degree of the baseline polynomial (terms t^2 ... "
                      "t^degree).",
                      Integer(3, 10));
    prm.add_parameter("Target PGA",
                      target_pga,
                      "Scale the processed record so that its peak "
                      "acceleration is this, in g; 0 keeps the record's.",
                      Double(0));
  }



  AccelerationRecord
  process(const AccelerationRecord   &record,
          const ProcessingParameters &p,
          const std::string          &context)
  {
    try
      {
        AccelerationRecord r = record;
        if (p.start_time != 0. || p.end_time != 0. || p.taper != 0.)
          r = time_window(r, p.start_time, p.end_time, p.taper);
        if (p.time_step > 0.)
          r = resample(r, p.time_step);
        if (p.high_pass > 0. || p.low_pass > 0.)
          r = bandpass_filter(r, p.high_pass, p.low_pass, p.filter_order);
        if (p.baseline)
          r = baseline_correction(r, p.baseline_degree);
        if (p.target_pga > 0.)
          r = scale_to_pga(r, p.target_pga * standard_gravity);
        return r;
      }
    catch (const InputError &e)
      {
        throw InputError(context + e.what());
      }
  }
} // namespace archdam::loads
