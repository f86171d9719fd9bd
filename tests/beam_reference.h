// Independent references for a uniform square concrete cantilever (clamped
// base, free top), shared by the tests that measure its natural frequencies:
// the Euler-Bernoulli and Timoshenko bending frequencies (Huang's 1961
// frequency equation, and shooting on the Timoshenko ODEs as a second method)
// and the root finding they need.
#pragma once

#include <array>
#include <cmath>
#include <functional>

namespace archdam::testing
{
  /// Bisection for a sign change of f in [lo, hi].
  inline double
  bisect(const std::function<double(double)> &f, double lo, double hi)
  {
    double flo = f(lo);
    for (unsigned int i = 0; i < 200 && hi - lo > 1e-15 * std::abs(hi); ++i)
      {
        const double mid = 0.5 * (lo + hi), fm = f(mid);
        if ((fm > 0) == (flo > 0))
          {
            lo  = mid;
            flo = fm;
          }
        else
          hi = mid;
      }
    return 0.5 * (lo + hi);
  }

  /// The first root of f above lo, found by scanning in steps of (hi - lo)/n.
  inline double
  first_root(const std::function<double(double)> &f, const double lo, const double hi,
             const unsigned int n = 400)
  {
    double x0 = lo, f0 = f(lo);
    for (unsigned int i = 1; i <= n; ++i)
      {
        const double x1 = lo + (hi - lo) * i / n, f1 = f(x1);
        if ((f1 > 0) != (f0 > 0))
          return bisect(f, x0, x1);
        x0 = x1;
        f0 = f1;
      }
    return std::nan("");
  }

  /// A square cantilever of side h and length L (SI units); shear coefficient
  /// k = 10(1 + nu)/(12 + 11 nu) of a rectangle (Cowper), exact 5/6 for nu = 0.
  struct SquareCantilever
  {
    double E, rho, nu, h, length;

    double
    area() const
    {
      return h * h;
    }
    double
    inertia() const
    {
      return h * h * h * h / 12.;
    }
    double
    shear_modulus() const
    {
      return E / (2. * (1. + nu));
    }
    double
    k_shear() const
    {
      return 10. * (1. + nu) / (12. + 11. * nu);
    }
    /// Rotary inertia and shear parameters of Huang's equation.
    double
    r2() const
    {
      return inertia() / (area() * length * length);
    }
    double
    s2() const
    {
      return E * inertia() / (k_shear() * area() * shear_modulus() * length * length);
    }

    /// Euler-Bernoulli circular frequency for a root l of 1 + cosh(l) cos(l) = 0.
    double
    euler_bernoulli_omega(const double l) const
    {
      return l * l * std::sqrt(E * inertia() / (rho * area() * std::pow(length, 4)));
    }

    /// Huang's clamped-free Timoshenko frequency function of w [rad/s], with
    /// b^2 = rho A w^2 L^4/(E I):
    ///   2 + [b^2 (r^2 - s^2)^2 + 2] cosh(b alpha) cos(b beta)
    ///     - b (r^2 + s^2)/sqrt(1 - b^2 r^2 s^2) sinh(b alpha) sin(b beta),
    ///   alpha, beta = (1/sqrt2) sqrt(-/+ (r^2 + s^2) + sqrt((r^2 - s^2)^2 + 4/b^2)).
    double
    huang(const double w, const double r2, const double s2) const
    {
      const double b = std::sqrt(rho * area() * w * w * std::pow(length, 4) / (E * inertia()));
      const double q = std::sqrt((r2 - s2) * (r2 - s2) + 4. / (b * b));
      const double alpha = std::sqrt(0.5 * (-(r2 + s2) + q));
      const double beta  = std::sqrt(0.5 * ((r2 + s2) + q));
      return 2. + (b * b * (r2 - s2) * (r2 - s2) + 2.) * std::cosh(b * alpha) * std::cos(b * beta) -
             b * (r2 + s2) / std::sqrt(1. - b * b * r2 * s2) * std::sinh(b * alpha) *
               std::sin(b * beta);
    }

    /// Second method: shooting on the Timoshenko equations
    ///   w' = psi + Q/(k G A), psi' = M/(E I), Q' = -rho A w^2 w,
    ///   M' = -Q - rho I w^2 psi
    /// from the clamped end (w = psi = 0) with (Q, M) = (1, 0) and (0, 1);
    /// the free end needs Q = M = 0: the 2x2 determinant vanishes.
    double
    shooting(const double omega) const
    {
      using State    = std::array<double, 4>;
      const double A = area(), I = inertia(), kGA = k_shear() * shear_modulus() * A;
      const auto   rhs = [&](const State &y) {
        return State{{y[1] + y[2] / kGA, y[3] / (E * I), -rho * A * omega * omega * y[0],
                      -y[2] - rho * I * omega * omega * y[1]}};
      };
      const auto integrate = [&](State y) {
        const unsigned int n  = 2000;
        const double       dx = length / n;
        for (unsigned int i = 0; i < n; ++i)
          {
            State k1 = rhs(y), tmp;
            for (unsigned int j = 0; j < 4; ++j)
              tmp[j] = y[j] + 0.5 * dx * k1[j];
            State k2 = rhs(tmp);
            for (unsigned int j = 0; j < 4; ++j)
              tmp[j] = y[j] + 0.5 * dx * k2[j];
            State k3 = rhs(tmp);
            for (unsigned int j = 0; j < 4; ++j)
              tmp[j] = y[j] + dx * k3[j];
            State k4 = rhs(tmp);
            for (unsigned int j = 0; j < 4; ++j)
              y[j] += dx / 6. * (k1[j] + 2. * k2[j] + 2. * k3[j] + k4[j]);
          }
        return y;
      };
      const State a = integrate({{0., 0., 1., 0.}});
      const State c = integrate({{0., 0., 0., 1.}});
      return a[2] * c[3] - a[3] * c[2];
    }
  };
} // namespace archdam::testing
