#pragma once

#include <archdam/base/types.h>
#include <archdam/time/factorized_operator.h>

#include <deal.II/base/parameter_handler.h>
#include <deal.II/lac/affine_constraints.h>

namespace archdam::time
{
  /// The `Time integration` subsection (numerics.md §2).
  struct NewmarkParameters
  {
    double time_step = 0.01;
    double end_time  = 0.;
    double beta1     = 0.5;
    double beta2     = 0.25;

    void
    add_parameters(dealii::ParameterHandler &prm);
    /// Throws InputError unless the scheme is unconditionally stable:
    /// beta1 >= 1/2 and beta2 >= (beta1 + 1/2)^2 / 4.
    void
    check() const;
  };

  /// Displacement, velocity and acceleration at the current time.
  struct NewmarkState
  {
    Vector       u, v, a;
    double       time = 0.;
    unsigned int step = 0;
  };

  /**
   * The generalized Newmark scheme of the paper's eq. 2.1-2.4 (numerics.md §2)
   * for M a + D v + K u = F with Rayleigh damping D = alpha M + beta K. With
   * the predictors
   *   u^p = u_n + dt v_n + dt^2/2 a_n,  v^p = v_n + dt a_n
   * each step solves
   *   Kbar da = F_{n+1} - M (a_n + alpha v^p) - K (u^p + beta v^p),
   *   Kbar = (1 + alpha beta1 dt) M + (beta beta1 dt + beta2 dt^2) K,
   * and updates u = u^p + beta2 dt^2 da, v = v^p + beta1 dt da, a = a_n + da.
   * Kbar is constant: it is assembled and factorized once in the constructor,
   * and a step costs two matrix-vector products and one back-substitution.
   */
  class NewmarkIntegrator
  {
  public:
    NewmarkIntegrator(const NewmarkParameters                 &p,
                      const SparseMatrix                      &mass,
                      const SparseMatrix                      &stiffness,
                      std::pair<double, double>                rayleigh,
                      const dealii::AffineConstraints<double> &constraints);

    /// Advance @p s from t_n to t_{n+1} = t_n + dt under the load F_{n+1}.
    void
    advance(const Vector &load_next, NewmarkState &s);

    double
    time_step() const
    {
      return dt;
    }

    // The step split for contact forces (numerics.md §3): advance() is
    // effective_load(), one back-substitution with Kbar, and update(); a joint
    // solver puts its predictor, contact problem and corrector in between.

    /// The predictors u^p, v^p of the step from @p s and the right-hand side
    /// of Kbar da = rhs (eq. 2.3), constrained rows zero.
    void
    effective_load(const Vector &load_next, const NewmarkState &s, Vector &rhs);
    /// u^p of the step prepared by effective_load(); u_{n+1} = u^p + beta2 dt^2 da.
    const Vector &
    predicted_displacement() const
    {
      return up;
    }
    /// beta2 dt^2: the displacement per unit acceleration increment.
    double
    displacement_factor() const
    {
      return p.beta2 * dt * dt;
    }
    /// Correctors (eq. 2.2) with the solved da (its constrained entries are
    /// set from the constraints first): t_n -> t_{n+1}.
    void
    update(Vector &da, NewmarkState &s);
    /// Kbar and its factorization (constant for the run).
    const SparseMatrix &
    effective() const
    {
      return effective_matrix;
    }
    const FactorizedOperator &
    effective_factor() const
    {
      return effective_operator;
    }

  private:
    const NewmarkParameters                  p;
    const double                             dt;
    const SparseMatrix                      &M;
    const SparseMatrix                      &K;
    const double                             alpha, beta;
    const dealii::AffineConstraints<double> &constraints;
    SparseMatrix                             effective_matrix;
    FactorizedOperator                       effective_operator;
    Vector                                   up, vp, rhs, tmp, da;
  };
} // namespace archdam::time
