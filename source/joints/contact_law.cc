#include <archdam/joints/contact_law.h>

#include <cmath>

namespace archdam::joints
{
  using namespace dealii;

  PairStrength
  strength_of(const JointLaw &law, const double area, const bool damaged)
  {
    // numerics.md §3: sigma_t and c drop to their residual values once a pair
    // has opened or slipped.
    return {law.friction_coefficient,
            area * (damaged ? law.residual_cohesion : law.cohesion),
            area * (damaged ? law.residual_tensile_strength : law.tensile_strength)};
  }

  PairState
  solve_pair(const Tensor<2, dim> &A, const Tensor<1, dim> &s, const Tensor<1, dim> &w_previous,
             const double initial_gap, const PairStrength &strength, Tensor<1, dim> &f)
  {
    const auto tangential_norm = [](const Tensor<1, dim> &v) {
      return std::sqrt(v[1] * v[1] + v[2] * v[2]);
    };

    // Stick: w = (-delta_0, w_previous_eta, w_previous_zeta), f = A^{-1}(s - w).
    Tensor<1, dim> w_stick = w_previous;
    w_stick[0]             = -initial_gap;
    const Tensor<2, dim> A_inv = invert(A);
    f                          = A_inv * (s - w_stick);
    if (f[0] <= strength.tensile_force &&
        tangential_norm(f) <= strength.shear_capacity(f[0]))
      return PairState::stick;

    // Slip: delta = 0 and f_t = tau(f_xi) d with d the unit slip increment,
    // a fixed point on d started from the stick force's direction (exact in
    // one step when A is isotropic in the tangent plane).
    // (The stick trial may need tension only because it holds the tangential
    // displacement: try slip whatever its normal force was.)
    {
      Tensor<1, dim> d;
      if (tangential_norm(f) > 0)
        {
          d[1] = f[1] / tangential_norm(f);
          d[2] = f[2] / tangential_norm(f);
        }
        Tensor<1, dim> g;
        bool           consistent = false;
        for (unsigned int it = 0; it < 50; ++it)
          {
            // normal row: A_00 f_0 + (A_0t . d) tau(f_0) = s_0 + delta_0
            const double a_d = A[0][1] * d[1] + A[0][2] * d[2];
            g[0] = (s[0] + initial_gap - a_d * strength.cohesion_force) /
                   (A[0][0] - strength.friction * a_d);
            const double tau = strength.shear_capacity(g[0]);
            g[1]             = tau * d[1];
            g[2]             = tau * d[2];
            const Tensor<1, dim> slip = s - A * g - w_previous;
            const double         n    = tangential_norm(slip);
            consistent = tau >= 0 && g[0] <= strength.tensile_force;
            if (!consistent || n == 0)
              break;
            const double change = std::hypot(slip[1] / n - d[1], slip[2] / n - d[2]);
            d[1]                = slip[1] / n;
            d[2]                = slip[2] / n;
            if (change < 1e-13)
              break;
          }
        if (consistent)
          {
            f = g;
            return PairState::slip;
          }
      }

    f = 0.;
    return PairState::separation;
  }
} // namespace archdam::joints
