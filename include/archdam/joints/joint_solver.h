#pragma once

#include <archdam/joints/contact_law.h>
#include <archdam/joints/joint_parameters.h>
#include <archdam/joints/node_pairs.h>
#include <archdam/joints/pair_system.h>
#include <archdam/time/factorized_operator.h>
#include <archdam/time/newmark.h>

#include <deal.II/lac/lapack_full_matrix.h>
#include <deal.II/lac/vector.h>

#include <algorithm>
#include <iosfwd>
#include <limits>
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
   * One implicit solve with joint forces (doc/theory/joints.md §3):
   *   A x = r - B^T f,   w = w_base + h B x,   the law at every pair,
   * where f (3 per pair, local frame) is the force on side 1 (-f on side 2).
   * The dynamic step has A = Kbar, x = da, w_base = B u^p - w_g, h = beta2 dt^2;
   * the static stage A = K, x = u, w_base = -w_g, h = 1, where w_g = B u_g
   * is the relative displacement at grouting (joint_displacement(): the law
   * sees the joints' movement since they were grouted). The solver keeps the
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

    /// Commit the solved step: the openings and slips it made weaken the
    /// pairs for good (doc/theory/joints.md §2).
    void
    accept();

    /// Start from a committed state (e.g. the static stage's), keeping the
    /// damage and the grouted state.
    void
    set_state(const JointSolver &other);

    /// Grout the joints in the state @p u (doc/theory/loading-sequence.md
    /// §1): its relative displacements become the joints' zero, and the
    /// joints are intact, closed and unloaded.
    void
    grout(const Vector &u);

    /// The relative displacement the law sees at @p u (3 per pair, local
    /// frame): B u less its value at grouting.
    void
    joint_displacement(const Vector &u, std::vector<double> &w_u) const;
    /// The same at u = 0, the static stage's w_base.
    std::vector<double>
    unloaded() const;

    /// The committed state of every pair (forces, relative displacements,
    /// states, damage), for a checkpoint (output/checkpoint.h); solve()
    /// starts from it alone.
    void
    save(std::ostream &out) const;
    void
    load(std::istream &in);
    /// The next solve() factorizes what it keeps between solves anew, as a
    /// solver loaded from a checkpoint does: called when a checkpoint is
    /// written, so that the run and one resumed from the checkpoint take
    /// the same arithmetic.
    virtual void
    forget_factorization()
    {}
    /// Whether solve() uses the matrix A itself, not only its factor (the
    /// monolithic reference refactorizes A with its springs).
    virtual bool
    uses_matrix() const
    {
      return false;
    }

    /// A message for a step that did not converge: joint, place, residual.
    std::string
    describe(const ContactStep &step) const;

    /**
     * Set up the dynamic step that @p newmark is about to solve with
     * Contraction joints/Contact in time = step impulse
     * (doc/theory/joints.md §10): the step's force f acts over the whole
     * step, so the model is loaded with g = omega f - (omega - 1) g_n,
     * omega = dt / (beta1 dt), and the closed pairs hold the relative
     * velocity at the step's end at zero, w = B (u^p - beta2 dt / beta1 v^p).
     * Nothing to do with the trapezoidal forces.
     */
    void
    prepare_step(const time::NewmarkIntegrator &newmark);

    /**
     * With Contraction joints/Position correction, after the Newmark step
     * that solve() made: u_{n+1} += beta2 dt^2 Kbar^{-1} (-B^T nu), the
     * correction that solve() found to bring every closed pair back to
     * touching (doc/theory/joints.md §11), v and a kept. solve() solved it
     * too: with the factorization condensed on the pairs, its load lies on
     * the interface, and its response comes from the step's own backward
     * substitution as a second column (CondensedFactorization::expand).
     * Nothing when the step needed none.
     */
    void
    correct_position(time::NewmarkIntegrator &newmark, time::NewmarkState &s);
    /// What the last step's position correction moved (dw empty when it
    /// made none): the displacements and the pairs' relative displacements,
    /// for the energy balance's term of its own (analysis/energy_balance.h,
    /// EnergyTerms::correction).
    struct PositionCorrection
    {
      Vector              du;
      std::vector<double> dw;
    };
    const PositionCorrection &
    last_correction() const
    {
      return moved;
    }
    /// The steps that made a position correction, and the largest change of
    /// a pair's normal relative displacement one of them made [m] (this
    /// solver's run, as the time below; not kept in a checkpoint).
    unsigned long corrections        = 0;
    double        largest_correction = 0.;
    /// The wall time spent solving for the corrections' displacements [s].
    double correction_time = 0.;

    const NodePairs &pairs;
    /// Pair values, 3 per pair in the local frame (xi, eta, zeta): the
    /// forces the law holds (what the joints carry), the forces the model is
    /// loaded with (the same with the trapezoidal forces, §10) and the
    /// relative displacements.
    std::vector<double>    force, force_committed, pair_load, load_committed, w, w_committed;
    std::vector<PairState> state;
    /// The pairs' histories (PairHistory), only ever weakening them: the
    /// damage at once within a solve (so that the iteration cannot cycle
    /// between a broken and an intact pair), the largest opening from the
    /// committed gaps.
    std::vector<bool>   damaged;
    std::vector<double> largest_opening;
    /// B u_g: the relative displacements at grouting (zero unless grouted).
    std::vector<double> w_grouted;

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
    /// The contact problem's h: h for the trapezoidal forces, omega h with
    /// the step impulse (w = s - omega h C f).
    double
    contact_h() const
    {
      return omega * h;
    }
    /// w_xi - its target for a closed pair: the gap with the trapezoidal
    /// forces, the change from the velocity target with the step impulse.
    double
    closure(unsigned int i) const
    {
      return w[dim * i] - target[dim * i];
    }
    /// How far an open pair is from having to close; negative: it must.
    /// With the trapezoidal forces its gap; with the step impulse its
    /// closure if it may close in this step (it touches at the start of the
    /// solve, or was closed), else never (doc/theory/joints.md §10).
    double
    approach(unsigned int i) const
    {
      if (velocity_target.empty())
        return gap(i);
      return may_close[i] ? closure(i) : std::numeric_limits<double>::infinity();
    }
    /// The targets of the closed pairs for this solve (target), and the slip
    /// directions from the committed tangential forces.
    void
    start_solve();
    /// Every pair closed (stick), but open where its joint has an initial
    /// gap: a closed pair must touch, because with the step impulse it holds
    /// only its velocity (doc/theory/joints.md §10).
    void
    set_initial_states();
    /// pair_load = omega force - (omega - 1) load_committed.
    void
    set_load();

    /// The position correction's pair forces nu (3 per pair, normal only;
    /// empty when the last step needed none) and Kbar^{-1} (-B^T nu), which
    /// solve() finds with them.
    std::vector<double> correction_force;
    Vector              corrected_displacement;
    /// What correct_position() moved in the last step.
    PositionCorrection moved;

    /// Pair i's strength from the joint law at its history.
    PairStrength
    strength(unsigned int i) const
    {
      return law->strength(laws[i], pairs[i].area, {damaged[i], largest_opening[i]});
    }
    /// The violation of the law in w at pair i [m].
    double
    law_residual(unsigned int i) const;
    /// Largest violation of the law in w over all pairs, and where.
    double
    gap_residual(unsigned int &worst) const;
    /// Largest change of a pair force relative to the largest force.
    double
    relative_change(const std::vector<double> &before) const;
    /// Largest pair force |f_i| [N].
    double
    largest_pair_force() const;

    /**
     * The active-set update of pair i (doc/theory/joints.md §6) from its force (for
     * the current state) and relative displacement: separation -> stick when
     * the gap closes by more than Gap tolerance; stick/slip -> separation
     * when f_xi exceeds sigma_t A (or the shear capacity becomes negative);
     * stick -> slip when |f_t| exceeds the capacity by more than Force
     * tolerance (relative), the slip direction then along f_t; slip -> stick
     * when the augmented tangential force q = f_t + r dw_t (Alart-Curnier,
     * r = augmentation, dw_t the slip increment) falls inside the capacity,
     * else the slip direction becomes q / |q| and slip_ratio tau / |q| (0
     * with |q| at the capacity itself, where d is then held fixed). The
     * tolerance bands keep a pair exactly at the stick/slip limit from
     * switching back and forth. Returns whether the state changed or, in
     * slip, the slip increment is not along the direction (by more than Gap
     * tolerance, in m).
     */
    bool
    update_state(unsigned int i);

    /// Augmentation r of every pair [N/m], ~ its own stiffness 1 / (h C_tt,ii).
    std::vector<double> augmentation;
    /// Unit tangential slip direction of every slipping pair (local frame).
    std::vector<dealii::Tensor<1, dim>> direction;
    /// kappa = tau / |q| of every slipping pair at its last update (0 when it
    /// has just started to slip): the weight of the direction's own change
    /// in the semi-smooth Newton step of a slipping pair (MixedJointSolver).
    std::vector<double> slip_ratio;
    /// The load weight omega (1: trapezoidal forces) and the step's velocity
    /// targets B (u^p - beta2 dt / beta1 v^p) (empty: trapezoidal forces).
    double              omega = 1.;
    std::vector<double> velocity_target;
    /// What a closed pair holds in this solve, 3 per pair: w_xi = target_xi
    /// (-delta_0 with the trapezoidal forces), and, sticking, w_t = target_t
    /// (its committed value); a slipping pair slips along w_t - target_t.
    std::vector<double> target;
    /// With the step impulse, the pairs that may be closed in this solve: closed
    /// at the start of the step or touching at the committed forces (fixed for
    /// the solve, so that the contact problem keeps one index set).
    std::vector<bool> may_close;

    /// A copy: a solver may be made for settings that differ from the
    /// case's (the static stage's relaxation uses the trapezoidal forces).
    const JointParameters      p;
    const double               h;
    std::unique_ptr<JointLaw>  law;
    std::vector<LawParameters> laws;
  };

  /**
   * The mixed method (doc/theory/joints.md §3-§6, paper eq. 2.5-2.8): A is factorized
   * once; the flexibility matrix C = B A^{-1} B^T on the pair DOFs is built
   * once; each solve is a predictor (one back-substitution), the contact
   * problem on the pairs alone, and a corrector (a second back-substitution,
   * only if a force changed). When A's factorization is condensed on the
   * pairs' DOFs, C comes from its Schur complement, and a solve is the
   * forward elimination, the contact problem and the backward substitution:
   * one back-substitution in all.
   * The contact problem w = s - h C f with the law at every pair is solved
   * by an active-set (semi-smooth Newton) iteration: with the states and
   * slip directions linearized, the law is linear in f (stick: w = w_target
   * in all three directions; slip: w_xi = -delta_0 and the Newton step of
   * f_t = (c A - mu f_xi) q / |q|, see solve_with_fixed_states(); separation:
   * f = 0), a dense system on the forces of the closed pairs
   * solved by LU; then update_state() on every pair; repeat until no state
   * or direction changes. A joint's pairs are coupled through C at once, so
   * a rigid block on several pairs stops or slides as a whole (a pair-by-pair
   * Gauss-Seidel sweep cycles there between stick and slip). With Contact
   * problem = joint by joint the joints are solved one after the other
   * (block Gauss-Seidel, doc/theory/joints.md §12), each by that iteration on
   * its own system, until the law holds with the exact C at every pair;
   * otherwise, and for a step that does not settle so, all pairs at once.
   */
  class MixedJointSolver : public JointSolver
  {
  public:
    MixedJointSolver(const JointParameters &p, const NodePairs &pairs, double h,
                     const time::FactorizedOperator &A_factor);

    ContactStep
    solve(const Vector &r, const std::vector<double> &w_base, Vector &x) override;

    void
    forget_factorization() override;

    /// Dense C (3 n_pairs squared, column major).
    const std::vector<double> &
    flexibility() const
    {
      return C;
    }
    /// Wall time of building C [s].
    double build_time = 0.;
    /// What the contact problem holds: C (by columns and by rows), G and
    /// the pair systems' LUs [bytes].
    std::size_t
    memory() const;
    /// Pair systems' bases factorized (once per stage and system, and after
    /// a checkpoint), and fixed-state systems solved with the kept LU
    /// updated by the rows that differ from the base (all systems: the
    /// joints' own too).
    unsigned long factorizations = 0, updated_solves = 0;
    /// Steps that joint by joint handed to all pairs at once.
    unsigned long handed_over = 0;

  private:
    /// Active-set iterations before projected Gauss-Seidel takes over, and
    /// allowed for each try of the states Gauss-Seidel reaches once they have
    /// held for polish_after sweeps. The reference case's static stage on
    /// its former production mesh needs 9 active-set iterations, and
    /// thousands of sweeps when they are cut short. An iteration that
    /// comes back from other states to the same states (with the same
    /// damage) for the cycle_visits-th time cycles, and hands over at once
    /// (doc/theory/joints.md §6).
    static constexpr unsigned int active_set_limit = 100, active_set_polish = 10,
                                  polish_after = 5, cycle_visits = 3;
    /// Sweeps over the joints before a step is handed to all pairs at once.
    static constexpr unsigned int sweep_limit = 100;

    /// @p out += @p factor C @p f.
    void
    add_flexibility_times(double factor, const std::vector<double> &f,
                          std::vector<double> &out) const;
    /// w = s - omega h C f.
    void
    set_relative_displacement();
    /// The forces of @p system's pairs from the law with the states and
    /// slip directions fixed, where their relative displacement at zero
    /// forces of their own is @p s_of; then their w.
    void
    solve_with_fixed_states(PairSystem &system, const std::vector<double> &s_of);
    /// update_state() on the pairs @p among; true if it changed none and
    /// every slipping one's force is on the slip law to Force tolerance
    /// (relative to the largest pair force).
    bool
    settle(const std::vector<unsigned int> &among);
    /// Up to @p limit active-set iterations on @p system; true if they
    /// converged.
    bool
    active_set_iteration(ContactStep &step, unsigned int limit, PairSystem &system,
                         const std::vector<double> &s_of);
    /// Block Gauss-Seidel over the joints, each joint's problem solved
    /// exactly by the active set (doc/theory/joints.md §12); true if it
    /// converged to the exact problem's tolerances.
    bool
    joint_by_joint(ContactStep &step);
    /// Projected Gauss-Seidel sweeps from the committed forces until the law
    /// holds to the tolerances or the iterations run out.
    void
    projected_gauss_seidel(ContactStep &step);

    /// The position correction of the step just solved (doc/theory/joints.md
    /// §11): the normal forces nu that bring the closed pairs off touch
    /// and the open pairs that penetrate to touching, h C_PP nu_P = gap_P
    /// on the set P of those pairs (grown while the correction moves
    /// others off touch or into penetration), w moved by -h C nu.
    void
    find_position_correction();

    /// With A factorized condensed on the pairs' DOFs (Contraction
    /// joints/Mixed method solves): G = S^{-1} B^T on the interface and
    /// C = B G from its Schur complement S, the interface's B.
    void
    build_from_schur_complement(const time::CondensedFactorization &condensed);

    const time::FactorizedOperator &A_factor;
    std::vector<double>             C;
    /// C by rows (its transpose by columns): the fixed-state system's rows
    /// are rows of C, read contiguously from here (by columns of C they
    /// would touch a cache line per entry); the same values as C.
    std::vector<double> C_rows;
    dealii::LAPACKFullMatrix<double> G;
    /// B on the interface: for every pair unknown its (interface index, value).
    std::vector<std::vector<std::pair<unsigned int, double>>> B_interface;
    dealii::Vector<double>                                    interface_x;
    /// Relative displacement of the pairs at zero pair forces.
    std::vector<double> s;
    /// The fixed-state system of all pairs at once, and of every joint
    /// alone (Contraction joints/Contact problem = joint by joint).
    PairSystem              all_pairs;
    std::vector<PairSystem> by_joint;
    /// Of every joint, the indices of the joints whose pairs a change of its
    /// forces moves within a sweep: itself and its neighbours
    /// (doc/theory/joints.md §12).
    std::vector<std::vector<unsigned int>> reach;
    /// s with the forces of the other joints: what a joint's own system sees.
    std::vector<double> s_joint;
    Vector              rhs, correction;
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

  /// The augmentation of every pair from C: r_i = 1 / (h C_tt,ii), the mean
  /// of its two tangential diagonal entries (the pair's own stiffness
  /// including everything it moves, e.g. a whole block).
  std::vector<double>
  augmentation_of(const std::vector<double> &C, double h);

  /**
   * The monolithic reference (doc/theory/joints.md §7): the same law enforced on the
   * full system by penalty springs between the two sides of every closed pair
   * (all three directions when it sticks, the normal only when it slips, with
   * the friction force as a load), the penalized matrix refactorized at every
   * iteration of the contact states. The penalty stiffness is Penalty factor
   * times the largest diagonal entry of A (over h), so the law holds to
   * |f| / kappa in w. The stick/slip decision uses the augmentation of the
   * mixed method (from the diagonal of C, built once at the first solve), so
   * both iterate on the same criterion.
   */
  class MonolithicJointSolver : public JointSolver
  {
  public:
    MonolithicJointSolver(const JointParameters &p, const NodePairs &pairs, double h,
                          const SparseMatrix &A, const time::FactorizedOperator &A_factor);
    ~MonolithicJointSolver() override;

    ContactStep
    solve(const Vector &r, const std::vector<double> &w_base, Vector &x) override;
    bool
    uses_matrix() const override
    {
      return true;
    }

  private:
    const SparseMatrix             &A;
    const time::FactorizedOperator &A_factor;
    Mat                                      pattern = nullptr; ///< A with room for the springs
    double                                   kappa   = 0.;
  };

  /**
   * The solve of one Newmark step with joint forces (doc/theory/joints.md §5), for
   * NewmarkIntegrator::advance(): @p solver's predictor, contact problem and
   * corrector with w_base = B u^p - w_g; the pair state is committed and how the
   * contact problem went is left in @p step (the caller decides what a step
   * that did not converge means).
   */
  time::NewmarkIntegrator::StepSolver
  contact_step_solver(const time::NewmarkIntegrator &newmark, JointSolver &solver,
                      ContactStep &step);

  /// One Newmark step with joint forces: advance() with contact_step_solver(),
  /// then the solver's position correction, if any.
  ContactStep
  advance_with_contact(time::NewmarkIntegrator &newmark, JointSolver &solver,
                       const Vector &load_next, time::NewmarkState &s);

  /// The solver the parameters choose (Contraction joints/Solver).
  std::unique_ptr<JointSolver>
  make_joint_solver(const JointParameters &p, const NodePairs &pairs, double h,
                    const SparseMatrix &A, const time::FactorizedOperator &A_factor);
} // namespace archdam::joints
