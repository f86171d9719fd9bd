// Independent references for the ground-motion tests.
//
// rk4_peak: the peak relative displacement of a damped SDOF oscillator under a
// piecewise-linear ground acceleration, by classical fourth-order Runge-Kutta
// with steps of T / steps_per_period (a method entirely different from the
// library's exact Nigam-Jennings recurrence), including the free vibration
// after the record.
#pragma once

#include <archdam/loads/acceleration_record.h>

#include <algorithm>
#include <cmath>

namespace archdam::testing
{
  /// Peak |u| of u'' + 2 zeta w u' + w^2 u = -a_g(t), w = 2 pi / T, from rest;
  /// after the record, 2 * steps_per_period further steps of free vibration.
  inline double
  rk4_peak(const loads::AccelerationRecord &r, const double T, const double zeta,
           const unsigned int steps_per_period)
  {
    const double w = 2 * M_PI / T;
    double       u = 0, v = 0, peak = 0;
    const auto   step = [&](const double h, const double a0, const double a1) {
      // State derivative at load a: (v, -a - 2 zeta w v - w^2 u).
      const auto f = [&](double uu, double vv, double a, double &du, double &dv) {
        du = vv;
        dv = -a - 2 * zeta * w * vv - w * w * uu;
      };
      const double am = 0.5 * (a0 + a1);
      double       k1u, k1v, k2u, k2v, k3u, k3v, k4u, k4v;
      f(u, v, a0, k1u, k1v);
      f(u + 0.5 * h * k1u, v + 0.5 * h * k1v, am, k2u, k2v);
      f(u + 0.5 * h * k2u, v + 0.5 * h * k2v, am, k3u, k3v);
      f(u + h * k3u, v + h * k3v, a1, k4u, k4v);
      u += h / 6 * (k1u + 2 * k2u + 2 * k3u + k4u);
      v += h / 6 * (k1v + 2 * k2v + 2 * k3v + k4v);
      peak = std::max(peak, std::abs(u));
    };
    const double h_max = T / steps_per_period;
    for (std::size_t k = 0; k + 1 < r.times.size(); ++k)
      {
        const double       interval = r.times[k + 1] - r.times[k];
        const unsigned int m        = static_cast<unsigned int>(std::ceil(interval / h_max));
        for (unsigned int j = 0; j < m; ++j)
          step(interval / m,
               r.values[k] + (r.values[k + 1] - r.values[k]) * j / m,
               r.values[k] + (r.values[k + 1] - r.values[k]) * (j + 1.) / m);
      }
    for (unsigned int j = 0; j < 2 * steps_per_period; ++j)
      step(h_max, 0., 0.);
    return peak;
  }

  /// End and peak values of velocity and displacement.
  struct Ends
  {
    double v_end = 0, d_end = 0, v_peak = 0, d_peak = 0;
  };

  /// Velocity and displacement of the piecewise-linear acceleration,
  /// integrated exactly interval by interval (trapezoid for v, the cubic
  /// term for d), independently of the library's integration.
  inline Ends
  ends(const loads::AccelerationRecord &r)
  {
    Ends   e;
    double v = 0, d = 0;
    for (std::size_t k = 0; k + 1 < r.times.size(); ++k)
      {
        const double h = r.times[k + 1] - r.times[k];
        d += h * v + h * h * (r.values[k] / 3 + r.values[k + 1] / 6);
        v += h * (r.values[k] + r.values[k + 1]) / 2;
        e.v_peak = std::max(e.v_peak, std::abs(v));
        e.d_peak = std::max(e.d_peak, std::abs(d));
      }
    e.v_end = v;
    e.d_end = d;
    return e;
  }
} // namespace archdam::testing
