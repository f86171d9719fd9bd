// Independent numerical tools shared by the arch dam tests: quadrature of the
// documented geometry's formulas, the area of a bilinear face, and the scaled
// Jacobian of a hexahedron. None of them uses the mesh generator.
#pragma once

#include <deal.II/base/point.h>
#include <deal.II/base/quadrature_lib.h>
#include <deal.II/base/tensor.h>

#include <algorithm>
#include <array>
#include <functional>

namespace archdam::testing
{
  /// Composite Gauss-Legendre rule on [a, b]: 16 panels of 20 points.
  inline double
  integrate(const std::function<double(double)> &f, const double a, const double b)
  {
    const dealii::QGauss<1> q(20);
    const int               panels = 16;
    double                  sum    = 0;
    for (int p = 0; p < panels; ++p)
      {
        const double lo = a + (b - a) * p / panels, h = (b - a) / panels;
        for (unsigned int i = 0; i < q.size(); ++i)
          sum += q.weight(i) * h * f(lo + h * q.point(i)[0]);
      }
    return sum;
  }

  /// Area of the bilinear quadrilateral with vertices in deal.II's order.
  inline double
  bilinear_area(const std::array<dealii::Point<3>, 4> &v)
  {
    const dealii::QGauss<2> q(4);
    double                  area = 0;
    for (unsigned int i = 0; i < q.size(); ++i)
      {
        const double               a = q.point(i)[0], b = q.point(i)[1];
        const dealii::Tensor<1, 3> xa = (1 - b) * (v[1] - v[0]) + b * (v[3] - v[2]);
        const dealii::Tensor<1, 3> xb = (1 - a) * (v[2] - v[0]) + a * (v[3] - v[1]);
        area += q.weight(i) * dealii::cross_product_3d(xa, xb).norm();
      }
    return area;
  }

  /// Scaled Jacobian of a hexahedron (Verdict's definition: the 8 corners and
  /// the principal axes), vertices in deal.II's lexicographic order.
  inline double
  scaled_jacobian(const std::array<dealii::Point<3>, 8> &x)
  {
    using dealii::Tensor;
    double worst = 1;
    for (unsigned int v = 0; v < 8; ++v)
      {
        Tensor<1, 3> e[3];
        for (unsigned int d = 0; d < 3; ++d)
          {
            const unsigned int w = v ^ (1u << d);
            e[d]                 = x[std::max(v, w)] - x[std::min(v, w)];
            e[d] /= e[d].norm();
          }
        worst = std::min(worst, scalar_product(e[0], cross_product_3d(e[1], e[2])));
      }
    Tensor<1, 3> a[3]; // principal axes: mean of the four edges in each direction
    for (unsigned int v = 0; v < 8; ++v)
      for (unsigned int d = 0; d < 3; ++d)
        if (!(v & (1u << d)))
          a[d] += x[v | (1u << d)] - x[v];
    for (auto &t : a)
      t /= t.norm();
    return std::min(worst, scalar_product(a[0], cross_product_3d(a[1], a[2])));
  }
} // namespace archdam::testing
