#pragma once

#include <archdam/joints/contact_law.h>
#include <archdam/joints/joint_parameters.h>
#include <archdam/joints/node_pairs.h>
#include <archdam/time/factorized_operator.h>
#include <archdam/time/newmark.h>

#include <memory>
#include <string>
#include <vector>

namespace archdam::joints
{
  /// How the contact problem of one solve went.
  struct ContactStep
  {
    unsigned int iterations   = 0;
    bool         converged    = false;
    double       force_change = 0.; ///< last iteration, relative to the largest force
    double       gap_residual = 0.; ///< largest violation of the law in w [m]
    unsigned int worst_pair   = 0;  ///< where the law is violated most
  };

  /**
   * One implicit solve with joint forces (numerics.md §3):
   *   A x = r - B^T f,   w = w_base + h B x,   the law at every pair,
   * where f (3 per pair, local frame) is the force on side 1 (-f on side 2).
   * The dynamic step has A = Kbar, x = da, w_base = B u^p, h = beta2 dt^2;
   * the static stage A = K, x = u, w_base = 0, h = 1. The solver keeps the
   * committed state of every pair (force, relative displacement, state, and
   * whether its intact strength is lost); solve() starts from it and accept()
   * commits the new one.
   */
  class JointSolver
  {
  public:
    JointSolver(const JointParameters &p, const NodePairs &pairs, double h);
    virtual ~JointSolver() = default;

    virtual ContactStep
    solve(const Vector &r, const std::vector<double> &w_base, Vector &x) = 0;

    /// Commit the solved step: pairs that opened or slipped lose their
    /// intact strength for good (numerics.md §3).
    void
    accept();

    /// Start from a committed state (e.g. the static stage's), keeping the damage.
    void
    set_state(const JointSolver &other);

    /// A message for a step that did not converge: joint, place, residual.
    std::string
    describe(const ContactStep &step) const;

    const NodePairs &pairs;
    /// Pair values, 3 per pair in the local frame (xi, eta, zeta).
    std::vector<double>    force, force_committed, w, w_committed;
    std::vector<PairState> state;
    std::vector<bool>      damaged;

    /// delta = delta_0 + w_xi of pair i (positive = open).
    double
    gap(unsigned int i) const
    {
      return laws[i].initial_gap + w[dim * i];
    }
    /// |w_t - w_t,0|: the tangential relative displacement since the start.
    double
    slip(unsigned int i) const;

  protected:
    PairStrength
    strength(unsigned int i) const
    {
      return strength_of(laws[i], pairs[i].area, damaged[i]);
    }
    /// Largest violation of the law in w over all pairs, and where.
    double
    gap_residual(unsigned int &worst) const;
    /// Largest change of a pair force relative to the largest force.
    double
    relative_change(const std::vector<double> &before) const;

    const JointParameters &p;
    const double           h;
    std::vector<JointLaw>  laws;
    std::vector<double>    w_initial;
  };

  /**
   * The mixed method (numerics.md §3, paper eq. 2.5-2.8): A is factorized
   * once; the flexibility matrix C = B A^{-1} B^T on the pair DOFs is built
   * once; each solve is a predictor (one back-substitution), the contact
   * problem on the pairs alone (projected block Gauss-Seidel over pairs), and a
   * corrector (a second back-substitution, only if a force changed).
   */
  class MixedJointSolver : public JointSolver
  {
  public:
    MixedJointSolver(const JointParameters &p, const NodePairs &pairs, double h,
                     const time::FactorizedOperator &A_factor);

    ContactStep
    solve(const Vector &r, const std::vector<double> &w_base, Vector &x) override;

    /// Dense C (3 n_pairs squared, column major).
    const std::vector<double> &
    flexibility() const
    {
      return C;
    }
    /// Wall time of building C [s].
    double build_time = 0.;

  private:
    const time::FactorizedOperator &A_factor;
    std::vector<double>             C;
    Vector                          rhs, correction;
  };

  /**
   * C = B A^{-1} B^T, dense, column major, on every rank: the columns
   * A^{-1} B^T e_j are solved @p block_size at a time (block_size = 1: one
   * back-substitution per column). With @p neighbours_only the coupling of
   * pairs on joints more than one apart is dropped (the paper's sparse
   * approximation).
   */
  std::vector<double>
  flexibility_matrix(const NodePairs &pairs, const time::FactorizedOperator &A_factor,
                     const Vector &layout, unsigned int block_size, bool neighbours_only);

  /**
   * The monolithic reference (numerics.md §3): the same law enforced on the
   * full system by penalty springs between the two sides of every closed pair
   * (all three directions when it sticks, the normal only when it slips, with
   * the friction force as a load), the penalized matrix refactorized at every
   * iteration of the contact states. The penalty stiffness is Penalty factor
   * times the largest diagonal entry of A (over h), so the law holds to
   * |f| / kappa in w.
   */
  class MonolithicJointSolver : public JointSolver
  {
  public:
    MonolithicJointSolver(const JointParameters &p, const NodePairs &pairs, double h,
                          const SparseMatrix &A);
    ~MonolithicJointSolver() override;

    ContactStep
    solve(const Vector &r, const std::vector<double> &w_base, Vector &x) override;

  private:
    const SparseMatrix &A;
    Mat                                      pattern = nullptr; ///< A with room for the springs
    double                                   kappa   = 0.;
  };

  /**
   * One Newmark step with joint forces (numerics.md §3): the effective load,
   * then @p solver's predictor, contact problem and corrector with
   * w_base = B u^p, then the Newmark correctors; the pair state is committed.
   * Returns how the contact problem went (the caller decides what a step that
   * did not converge means).
   */
  ContactStep
  advance_with_contact(time::NewmarkIntegrator &newmark, JointSolver &solver,
                       const Vector &load_next, time::NewmarkState &s);

  /// The solver the parameters choose (Contraction joints/Solver).
  std::unique_ptr<JointSolver>
  make_joint_solver(const JointParameters &p, const NodePairs &pairs, double h,
                    const SparseMatrix &A, const time::FactorizedOperator &A_factor);
} // namespace archdam::joints
