#pragma once

#include <archdam/fe/fe_space.h>
#include <archdam/joints/joint_solver.h>
#include <archdam/output/recorder.h>
#include <archdam/physics/foundation/reference_motion.h>
#include <archdam/physics/foundation/viscous_boundary.h>
#include <archdam/physics/reservoir/fluid_operators.h>
#include <archdam/time/newmark.h>

#include <deal.II/base/tensor.h>

#include <array>
#include <iosfwd>
#include <memory>
#include <string>
#include <vector>

namespace archdam::analysis
{
  /// The terms of the energy balance of a dynamic stage [J] (doc/theory/results.md §7).
  struct EnergyTerms
  {
    /// Work put into the model: the ground motion's inertia loads (relative
    /// formulation), the free-field forces of the viscous boundary, or the net
    /// work of the reactions on a prescribed outer boundary (MTF: input minus
    /// radiated).
    double input = 0.;
    /// 1/2 v^T M v at the end.
    double kinetic = 0.;
    /// 1/2 w^T K w - f_s^T (B w) with w = u - u_static: the elastic energy
    /// from the static state, and the work against the static joint forces.
    double strain = 0.;
    /// What the Rayleigh damping dissipated: int v^T D v dt, with the
    /// dam's mass term relative to the ground int (v - w)^T D_dam (v - w)
    /// dt in the dam (w = iota v_r; doc/theory/solid.md §4) instead,
    double damping = 0.;
    /// of which in the dam (the rest is the rock's: the water's damping is
    /// its radiation),
    double damping_dam = 0.;
    /// and the work the dam's mass term relative to the ground hands to
    /// the reference motion, int w^T D_dam (v - w) dt: zero when the dam
    /// moves rigidly with it, of either sign otherwise.
    double damping_reference = 0.;
    /// int v^T c v dt in the dashpots of the viscous boundary.
    double radiated = 0.;
    /// int f . dw at the joints (f the total pair forces): friction, and
    /// the normal forces' work on the gaps,
    double contact = 0.;
    /// of which the normal part int f_xi dw_xi: zero in the continuous law
    /// (a pair is closed or free of force), in the scheme the work of the
    /// trapezoidal mean force over the steps where pairs open (released,
    /// negative) or close (impact, positive).
    double contact_normal = 0.;
    /// The water's acoustic energy at the end: 1/(2 rho_w) (p^T G p + P^T Q P),
    /// P = int p dt (potential, free-surface waves and kinetic).
    double water = 0.;
    /// 1/rho_w int p^T H p dt: radiated at the upstream truncation and
    /// absorbed at the bottom.
    double water_radiated = 0.;
    /// The scheme's own (algorithmic) dissipation of the solid's inertia,
    /// the sum over the steps of [u]^T M <a> - [1/2 v^T M v]
    ///   = dt^2 (Beta2 - Beta1/2) [a]^T M <a> - dt (Beta1 - 1/2) <v>^T M [a]
    /// ([x] = x_{n+1} - x_n, <x> = (x_n + x_{n+1}) / 2;
    /// doc/theory/time-integration.md §7): exactly 0 for the average
    /// acceleration rule, and the energy Beta1 > 1/2 takes out of the high
    /// frequencies otherwise.
    double algorithmic = 0.;
    /// The energy the joints' position correction put into the model
    /// (Contraction joints/Position correction, doc/theory/joints.md §11):
    /// the change of the strain energy (with the static loads' potential)
    /// that the displacements it moved hold, which no force of the model
    /// did; the work of the other terms is taken without those
    /// displacements. Zero without the correction.
    double correction = 0.;

    /// What the model holds or lost: everything but the input.
    double
    sum() const
    {
      return kinetic + strain + damping + damping_reference + radiated + contact + water +
             water_radiated + algorithmic;
    }
    /// |input + correction - sum| / max(|input|, sum of the magnitudes of
    /// the terms): what no term accounts for.
    double
    balance_error() const;

    /// A balance error above this is reported as a warning (the run's log
    /// and summary.json): the results hold work that no term explains
    /// (doc/user-guide.md, "Energy balance").
    static constexpr double warning_threshold = 0.01;
  };

  /**
   * The energy balance of the dynamic stage (doc/theory/time-integration.md §7 and doc/theory/results.md §7): every step adds
   * the work of each force group over the step, with the trapezoidal rule in
   * the displacement, W += (x_{n+1} - x_n) . (F_n + F_{n+1}) / 2, the rule
   * the Newmark scheme itself applies (with Beta1 = 1/2, Beta2 = 1/4,
   * x_{n+1} - x_n = dt (v_n + v_{n+1}) / 2, and the equation of motion
   * averaged over t_n, t_{n+1} multiplied by that increment is the balance
   * of the step exactly: the sum closes to round-off for any linear model and
   * any contact history; Beta1 > 1/2 shows its numerical dissipation as the
   * balance error). Everything is measured from the static state the stage
   * starts from. The water's balance uses the fluid equation integrated in
   * time, G p_t + H p + Q P + S (u_t + iota v_g) = 0 (P = int p dt,
   * trapezoidal), times p: its coupling work with the dam cancels the dam's.
   * With a prescribed outer boundary (MTF) the balance is that of the whole
   * model, the boundary nodes included (full operators from the prescribed
   * columns), and the input is the work of the reactions there: input minus
   * radiated, which the MTF does not separate.
   * Cost per step: D v (damping: formed in the integrator's own pass with
   * the products in single precision, Model::integrator, else one product
   * with the coupled system's D, else M v and K v), H p (water), and
   * vector operations; with a
   * prescribed boundary, products with the rows of the prescribed columns
   * at the prescribed DOFs only (BoundaryRows): the reactions, the
   * boundary's part of D v, and the water's rows at those columns.
   */
  class EnergyBalance : public output::Recorder
  {
  public:
    /// What the model is made of; pointers are null where a part is absent.
    /// M, K (and D) are the operators the integrator steps: the solid's, or
    /// the coupled dam-water system's, whose solid rows are the solid's M, D
    /// and K (with -(1/rho_w) S^T in the pressure columns of K, which the
    /// balance leaves out).
    struct Model
    {
      const fe::FESpace                         *space = nullptr;
      const SparseMatrix                        *mass = nullptr, *stiffness = nullptr;
      /// The damping matrix whose solid block is the solid's D (the coupled
      /// system's, or the solid's assembled per material; with a prescribed
      /// boundary its columns are PrescribedDofs::damping_columns): one
      /// product a step. Null: the two products alpha M v + beta K v with
      /// `rayleigh`.
      const SparseMatrix                        *damping = nullptr;
      /// With `damping`: its products from the integrator's copy in single
      /// precision (matrix 1, Time integration/Product precision = single);
      /// `damping` itself is then not multiplied (the dynamic stage releases
      /// its entries).
      const time::SinglePrecisionProducts       *damping_products = nullptr;
      /// With `damping_products`: the integrator whose step forms D v_n in
      /// its own pass (NewmarkIntegrator::damping_force_at_start()); the
      /// balance takes D v_{n+1} from the next step's pass and adds a
      /// step's damping work one step late (its last step's in terms()).
      const time::NewmarkIntegrator             *integrator = nullptr;
      std::pair<double, double>                  rayleigh{0., 0.};
      time::NewmarkParameters                    newmark;
      /// M iota_d of the relative formulation (massless or rigid foundation).
      const std::array<Vector, dim>             *influence = nullptr;
      /// The dam's own damping matrix D_dam (Model::dam_damping()): the
      /// damping in the dam itemized; null: not itemized.
      const SparseMatrix                        *dam_damping = nullptr;
      /// The dam's mass term relative to the ground: v_r and the loads
      /// D_dam iota_d = alpha_d M_dam iota_d it multiplies (Model).
      const physics::foundation::ReferenceMotion *reference = nullptr;
      const std::array<Vector, dim>             *reference_loads = nullptr;
      /// The water (compressible and incompressible models) and its density.
      const physics::reservoir::FluidOperators *fluid   = nullptr;
      double                                     density = 1000.;
      /// Massed foundation: the viscous boundary, or the prescribed boundary.
      const physics::foundation::ViscousSpringBoundary *viscous    = nullptr;
      const time::PrescribedDofs                       *prescribed = nullptr;
    };

    explicit EnergyBalance(const Model &model);
    ~EnergyBalance() override;
    EnergyBalance(const EnergyBalance &) = delete;
    EnergyBalance &
    operator=(const EnergyBalance &) = delete;

    /// Start from the state @p s (the static state, at rest) and the joint
    /// forces of @p joints (if any).
    void
    start(const time::NewmarkState &s, const joints::JointSolver *joints);

    /// Add the step to @p s, with the ground acceleration @p ag at its end
    /// (relative formulation) and the joint state after it.
    void
    add_step(const time::NewmarkState   &s,
             const dealii::Tensor<1, dim> &ag,
             const joints::JointSolver  *joints);

    /// The terms after the last step.
    EnergyTerms
    terms() const;

    /// One line for the run log.
    std::string
    line() const;

    // As the dynamic stage's recorder: start() and add_step() with the
    // step's state, joints and ground acceleration.
    std::string
    name() const override
    {
      return "energy balance";
    }
    void
    start(const output::StepRecord &s) override;
    void
    record(const output::StepRecord &s) override;
    /// The terms into summary.json under "energy balance", line() on
    /// screen, and a warning when the balance error exceeds
    /// EnergyTerms::warning_threshold.
    void
    finish(output::Summary &summary, const dealii::ConditionalOStream &screen) override;

    /// The path integrals and the last step's state, for a checkpoint
    /// (output/checkpoint.h).
    void
    save(std::ostream &out) const override;
    void
    load(std::istream &in) override;

  private:
    /// x with its constrained entries zero (the condensed matrices act on it
    /// as the full ones on the constrained field), its prescribed entries kept.
    void
    free_part(const Vector &x, Vector &out) const;
    /// Which of the model's operators.
    enum class Operator
    {
      mass,
      stiffness,
      damping
    };
    /// The full solid operator @p which (condensed, plus its prescribed
    /// columns, if any) times the solid part of x from free_part();
    /// solid rows only. @p condensed: the condensed operator's product
    /// with x, if formed already (its solid free rows are used).
    void
    full_product(Operator which, const Vector &x, Vector &out,
                 const Vector *condensed = nullptr) const;
    /// D v = alpha M v + beta K v (full operators; Model::damping if given,
    /// with @p condensed as in full_product()).
    void
    damping_force(const Vector &v, Vector &out, const Vector *condensed = nullptr) const;
    /// The damping's work over the last step, du_last . (D v_n + D v_{n+1}) / 2,
    /// with D v_n in damping_prev and @p force = D v_{n+1}.
    double
    last_step_damping(const Vector &force) const;
    /// Itemize the step's damping (EnergyTerms::damping_dam,
    /// damping_reference) for the new state @p s and the increment du.
    void
    add_dam_damping(const time::NewmarkState &s);
    /// The reaction on the prescribed DOFs at the state @p s.
    void
    boundary_reaction(const time::NewmarkState &s, Vector &out);
    /// Add the step's algorithmic dissipation (EnergyTerms::algorithmic) for
    /// the new state @p s, the velocity @p v_old before the step and v_prev
    /// after it.
    void
    add_algorithmic_dissipation(const time::NewmarkState &s, const Vector &v_old, double dt);
    /// Whether the scheme dissipates (not the average acceleration rule).
    bool
    dissipative() const
    {
      return m.newmark.beta1 != 0.5 || m.newmark.beta2 != 0.25;
    }

    const Model m;
    /// The prescribed columns' rows at the prescribed DOFs (null without a
    /// prescribed boundary).
    struct BoundaryRows;
    std::unique_ptr<BoundaryRows> rows;
    const bool  has_water;
    /// 1 at the unconstrained DOFs; at those and the prescribed ones; at the
    /// free pressure DOFs; everywhere else; at the prescribed DOFs.
    Vector free_mask, kept_mask, pressure_mask, solid_mask, prescribed_mask;

    /// The state after the last step (free and prescribed entries), the
    /// static state, and each force group at the last step.
    Vector u_static, u_prev, v_prev, damping_prev, p_prev, impulse, boundary_prev,
      boundary_static, free_field_prev, free_field_static, radiation_prev, dashpot_prev, ub_prev,
      tmp, du, work;
    /// The acceleration after the last step and M times it (algorithmic
    /// dissipation); scratch for its means and jumps.
    Vector a_prev, inertia_prev, mean, jump;
    /// K du_c of the last step's position correction (zero when it made
    /// none): the out-of-balance force it leaves at the step's end, whose
    /// work over the next step is the correction's too.
    Vector correction_residual;
    /// The last step's increment, whose damping work is added with the next
    /// step (Model::integrator), and whether there is one.
    Vector du_last;
    bool   damping_pending = false;
    dealii::Tensor<1, dim> ag_prev, vg;
    /// D_dam v, (D_dam iota_d) . v, v_r and d_r after the last step, and
    /// iota_d . D_dam iota_d (alpha_d times the dam's mass).
    Vector                 dam_prev;
    dealii::Tensor<1, dim> reference_work_prev, vr_prev, dr_prev, reference_mass;
    std::vector<double>    f_static, w_static, f_prev, w_prev;
    double                 t_prev = 0.;

    EnergyTerms sums; ///< the path integrals (input, damping, radiated, contact, water radiated)
    mutable Vector scratch, tmp2, solid_part;
  };
} // namespace archdam::analysis
