#pragma once

#include <archdam/base/selection.h>
#include <archdam/base/types.h>
#include <archdam/time/factorized_operator.h>
#include <archdam/time/single_precision_products.h>

#include <deal.II/base/parameter_handler.h>
#include <deal.II/lac/affine_constraints.h>

#include <functional>
#include <memory>
#include <vector>

namespace archdam::time
{
  /// The names of Precision in the case file (`Time integration/Factor
  /// precision` and `Product precision`).
  inline const SelectionNames<Precision> &
  precision_names()
  {
    static const SelectionNames<Precision> names{
      {"double", Precision::double_precision},
      {"single", Precision::single_precision}};
    return names;
  }

  /// The `Time integration` subsection (doc/theory/time-integration.md §2).
  struct NewmarkParameters
  {
    double time_step = 0.01;
    double end_time  = 0.;
    double beta1     = 0.5;
    double beta2     = 0.25;
    /// The dropping tolerance of the effective matrix's block low-rank
    /// factor (0: full rank; doc/performance.md §8).
    double low_rank_tolerance = 0.;
    /// The arithmetic of that factor (doc/performance.md §8).
    Precision factor_precision = Precision::double_precision;
    /// The arithmetic of M's and D's entries (and the prescribed boundary's
    /// columns') in the steps' effective load (doc/performance.md §11).
    Precision product_precision = Precision::double_precision;

    void
    add_parameters(dealii::ParameterHandler &prm);
    /// Throws InputError unless the scheme is unconditionally stable:
    /// beta1 >= 1/2 and beta2 >= (beta1 + 1/2)^2 / 4.
    void
    check() const;

    /// The number of steps of Time step that reach @p end (s), rounded; an
    /// InputError naming both values when that is less than one step or more
    /// than max_steps (a unit mistake, and beyond what a step counter holds).
    unsigned int
    n_steps(double end) const;

    static constexpr double max_steps = 1e7;
  };

  /// Displacement, velocity and acceleration at the current time.
  struct NewmarkState
  {
    Vector       u, v, a;
    double       time = 0.;
    unsigned int step = 0;
  };

  /**
   * Prescribed motion on constrained DOFs (doc/theory/foundation.md §7: the outer boundary
   * of a massed foundation). The DOFs are constrained (homogeneously) in the
   * model's M, D and K, so Kbar keeps them fixed and stays factorized once;
   * their coupling to the free DOFs is carried by the full (unconstrained)
   * columns of M, D and K at these DOFs, assembled apart
   * (solid::assemble_mass_and_stiffness_columns; for the coupled dam-water
   * system reservoir::form_coupled_columns adds the water's rows).
   */
  struct PrescribedDofs
  {
    /// The prescribed DOFs, the same list on every rank.
    std::vector<dealii::types::global_dof_index> dofs;
    /// Columns of the full M and K at `dofs` (rows at other DOFs are used).
    SparseMatrix mass_columns, stiffness_columns;
    /// Columns of the full D at `dofs`, for the integrator with a general
    /// damping matrix only (with Rayleigh damping they are alpha M + beta K
    /// of the columns above, and this matrix is not used).
    SparseMatrix damping_columns;
  };

  /**
   * The generalized Newmark scheme of the paper's eq. 2.1-2.4 (doc/theory/time-integration.md §2-§3)
   * for M a + D v + K u = F with Rayleigh damping D = alpha M + beta K. With
   * the predictors
   *   u^p = u_n + dt v_n + dt^2/2 a_n,  v^p = v_n + dt a_n
   * each step solves
   *   Kbar da = F_{n+1} - M (a_n + alpha v^p) - K (u^p + beta v^p),
   *   Kbar = (1 + alpha beta1 dt) M + (beta beta1 dt + beta2 dt^2) K,
   * and updates u = u^p + beta2 dt^2 da, v = v^p + beta1 dt da, a = a_n + da.
   * Kbar is constant: it is assembled and factorized once in the constructor,
   * and a step costs two matrix-vector products and one back-substitution.
   * With `Product precision = single` the products with M (and D, and the
   * prescribed boundary's columns) take their entries in single precision
   * (SinglePrecisionProducts); K's product, which carries the static
   * state's forces, stays in double (doc/performance.md §11).
   * Optional @p boundary_dashpots c (a diagonal damping, the viscous boundary
   * of the foundation) add beta1 dt diag(c) to Kbar and c v^p to the load.
   * With a @p factor_interface (the joints' pair DOFs) Kbar's factorization
   * is condensed on it (FactorizedOperator::factorize()).
   */
  class NewmarkIntegrator
  {
  public:
    NewmarkIntegrator(const NewmarkParameters                 &p,
                      const SparseMatrix                      &mass,
                      const SparseMatrix                      &stiffness,
                      std::pair<double, double>                rayleigh,
                      const dealii::AffineConstraints<double> &constraints,
                      const Vector *boundary_dashpots = nullptr,
                      const std::vector<dealii::types::global_dof_index> &factor_interface = {});

    /**
     * The same scheme for M a + D v + K u = F with a general damping matrix D
     * (e.g. the coupled dam-water system, doc/theory/reservoir.md §5, whose D holds the
     * Rayleigh damping of the solid and the radiation of the water):
     *   Kbar = M + beta1 dt D + beta2 dt^2 K,
     *   Kbar da = F_{n+1} - M a_n - D v^p - K u^p.
     * M, D and K share one sparsity pattern; Kbar must be symmetric, and is
     * factorized once as Cholesky if @p positive_definite, else as LDL^T.
     * Optional @p boundary_dashpots as in the constructor above.
     */
    NewmarkIntegrator(const NewmarkParameters                 &p,
                      const SparseMatrix                      &mass,
                      const SparseMatrix                      &damping,
                      const SparseMatrix                      &stiffness,
                      const dealii::AffineConstraints<double> &constraints,
                      bool                                     positive_definite,
                      const Vector *boundary_dashpots = nullptr,
                      const std::vector<dealii::types::global_dof_index> &factor_interface = {});

    /**
     * Solver of one step's Kbar da = rhs. The default is the back-substitution
     * with the factorized Kbar; a joint solver puts its predictor, contact
     * problem and corrector here (doc/theory/joints.md §5), reading u^p of the step
     * from predicted_displacement().
     */
    using StepSolver = std::function<void(const Vector &rhs, Vector &da)>;

    /// Advance @p s from t_n to t_{n+1} = t_n + dt under the load F_{n+1}.
    void
    advance(const Vector &load_next, NewmarkState &s, const StepSolver &solve = {});

    /**
     * Advance with the displacements @p u_next (one per entry of
     * @p prescribed.dofs) prescribed at t_{n+1}. Their acceleration increment
     * follows from u_{n+1} = u^p + beta2 dt^2 da:
     *   da_b = (u_next - u^p_b) / (beta2 dt^2),
     * and with their state at t_{n+1} known, the free DOFs take the load
     *   F_{n+1} - M_fb (a_b + alpha v_b) - K_fb (u_b + beta v_b)   (at t_{n+1})
     * from the prescribed columns (F_{n+1} - M_fb a_b - D_fb v_b - K_fb u_b
     * with a general damping matrix), which equals the full effective load
     * minus Kbar_fb da_b. The solve itself is advance() with the DOFs fixed,
     * so Kbar is not touched.
     */
    void
    advance(const Vector              &load_next,
            NewmarkState              &s,
            const PrescribedDofs      &prescribed,
            const std::vector<double> &u_next,
            const StepSolver          &solve = {});

    /**
     * With Product precision = single: copy M and D, and @p prescribed's
     * columns if given, into single precision now (advance() does it at its
     * first step otherwise). From then on advance() reads only the copies
     * (and K): the copied matrices may be released. Called once Kbar is
     * released, the copies do not add to the memory Kbar held.
     */
    void
    hold_in_single_precision(const PrescribedDofs *prescribed);

    /// With Product precision = single, the products of M (matrix 0) and of
    /// a general damping matrix D (matrix 1) in single precision; null
    /// otherwise.
    const SinglePrecisionProducts *
    single_precision_products() const
    {
      return load_products.get();
    }
    /// D v_n of the state the last advance() started from, formed in the
    /// same pass over the copies' entries as the effective load (Product
    /// precision = single with a general damping matrix; null otherwise or
    /// before the first step): the energy balance's D v, one step late
    /// (doc/performance.md §11).
    const Vector *
    damping_force_at_start() const
    {
      return damping_at_start.size() > 0 ? &damping_at_start : nullptr;
    }
    /// What the products in single precision hold on this rank [bytes].
    std::size_t
    single_precision_memory() const
    {
      return (load_products ? load_products->memory() : 0) +
             (column_products ? column_products->memory() : 0);
    }

    /**
     * Move the displacements of the step just advanced by @p x, the
     * response of the effective matrix to a load b that the caller solved
     * (x = Kbar^{-1} b): u_{n+1} += beta2 dt^2 x, leaving v and a as they
     * are, a correction of the positions alone (the joints' position
     * correction, doc/theory/joints.md §11). Constrained DOFs follow their
     * masters.
     */
    void
    correct_displacement(const Vector &x, NewmarkState &s);

    double
    time_step() const
    {
      return dt;
    }

    /// u^p of the step being advanced; u_{n+1} = u^p + beta2 dt^2 da.
    const Vector &
    predicted_displacement() const
    {
      return up;
    }
    /// The step's velocity predictor v^p = v_n + dt a_n.
    const Vector &
    predicted_velocity() const
    {
      return vp;
    }
    /// beta1 dt: the velocity per unit acceleration increment.
    double
    velocity_factor() const
    {
      return p.beta1 * dt;
    }
    /// beta2 dt^2: the displacement per unit acceleration increment.
    double
    displacement_factor() const
    {
      return p.beta2 * dt * dt;
    }
    /// Kbar and its factorization (constant for the run).
    const SparseMatrix &
    effective() const
    {
      return effective_matrix;
    }
    /// Free Kbar, keeping its factorization (the steps need only that):
    /// effective() is empty from then on.
    void
    release_effective_matrix()
    {
      effective_matrix.clear();
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
    const SparseMatrix                      *D = nullptr; // general damping, if any
    const double                             alpha, beta;
    const dealii::AffineConstraints<double> &constraints;
    SparseMatrix                             effective_matrix;
    FactorizedOperator                       effective_operator;
    const Vector                            *dashpots = nullptr; // boundary dashpots, if any
    Vector                                   up, vp, rhs, tmp, da;
    Vector prescribed_a, prescribed_v, prescribed_u, reduced_load;
    /// With Product precision = single: M and D in single precision, and
    /// the columns of the prescribed DOFs (hold_in_single_precision()).
    std::unique_ptr<SinglePrecisionProducts> load_products, column_products;
    const PrescribedDofs                    *columns_of = nullptr;
    /// D v_n of the last step's start (damping_force_at_start()).
    Vector damping_at_start;

    /// What both public constructors set (@p damping null: Rayleigh damping
    /// from @p rayleigh); each then builds its own effective operator.
    NewmarkIntegrator(const NewmarkParameters                 &p,
                      const SparseMatrix                      &mass,
                      const SparseMatrix                      &stiffness,
                      const SparseMatrix                      *damping,
                      std::pair<double, double>                rayleigh,
                      const dealii::AffineConstraints<double> &constraints,
                      const Vector                            *boundary_dashpots);

    /// The columns of M, K (and D) at the prescribed DOFs, in that order.
    std::vector<const SparseMatrix *>
    columns_of_matrices(const PrescribedDofs &prescribed) const;
    /// y -= sum_k A_k x_k: from @p copy in single precision if there is
    /// one, else PETSc's products with @p matrices() one at a time.
    void
    subtract_products(const SinglePrecisionProducts                          *copy,
                      const std::function<std::vector<const SparseMatrix *>()> &matrices,
                      const std::vector<const Vector *> &x, Vector &y);
    /// Add beta1 dt diag(dashpots) to Kbar (the viscous boundary).
    void
    add_dashpots_to_effective_matrix();
    /// Kbar = @p k_factor K + sum c A over @p terms (on K's pattern), plus
    /// the dashpots; factorize it, and size the work vectors.
    void
    build_effective_operator(double                                                     k_factor,
                             const std::vector<std::pair<double, const SparseMatrix *>> &terms,
                             bool positive_definite,
                             const std::vector<dealii::types::global_dof_index> &factor_interface);
  };
} // namespace archdam::time
