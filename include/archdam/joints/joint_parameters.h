#pragma once

#include <archdam/base/selection.h>

#include <deal.II/base/parameter_handler.h>

#include <string>

namespace archdam::joints
{
  /// `Contraction joints/Model`: how the joints between dam blocks behave.
  enum class Model
  {
    glued,             ///< the faces tied together (the monolithic dam)
    frictional_contact ///< the joints open, close and slide
  };

  /// The names of Model in the case file.
  inline const SelectionNames<Model> &
  model_names()
  {
    static const SelectionNames<Model> names{{"glued", Model::glued},
                                             {"frictional contact", Model::frictional_contact}};
    return names;
  }

  /// `Contraction joints/Solver`: the solver of the frictional contact.
  enum class Solver
  {
    mixed,     ///< the mixed method on the node pairs (MixedJointSolver, joint_solver.h)
    monolithic ///< the penalty reference solver on the full system (MonolithicJointSolver)
  };

  /// The names of Solver in the case file.
  inline const SelectionNames<Solver> &
  solver_names()
  {
    static const SelectionNames<Solver> names{{"mixed", Solver::mixed},
                                              {"monolithic", Solver::monolithic}};
    return names;
  }

  /// `Contraction joints/Flexibility coupling`: which entries of the
  /// flexibility matrix the mixed method keeps.
  enum class Coupling
  {
    all_joints,         ///< the exact matrix
    neighbouring_joints ///< only pairs of the same or adjacent joints
  };

  /// The names of Coupling in the case file.
  inline const SelectionNames<Coupling> &
  coupling_names()
  {
    static const SelectionNames<Coupling> names{
      {"all joints", Coupling::all_joints},
      {"neighbouring joints", Coupling::neighbouring_joints}};
    return names;
  }

  /// `Contraction joints/Contact problem`: how the mixed method solves the
  /// contact problem on the pairs (doc/theory/joints.md §6 and §12).
  enum class ContactProblem
  {
    joint_by_joint,   ///< block Gauss-Seidel over the joints, each joint exact
    all_pairs_at_once ///< one active set on every pair
  };

  /// The names of ContactProblem in the case file.
  inline const SelectionNames<ContactProblem> &
  contact_problem_names()
  {
    static const SelectionNames<ContactProblem> names{
      {"joint by joint", ContactProblem::joint_by_joint},
      {"all pairs at once", ContactProblem::all_pairs_at_once}};
    return names;
  }

  /// `Contraction joints/Mixed method solves`: how a solve of the mixed
  /// method reaches the pairs (doc/theory/joints.md §4).
  enum class MixedSolves
  {
    condensed_on_the_pairs, ///< the pairs' unknowns last, C from their Schur complement
    predictor_and_corrector ///< a plain factorization, two back-substitutions per solve
  };

  /// The names of MixedSolves in the case file.
  inline const SelectionNames<MixedSolves> &
  mixed_solves_names()
  {
    static const SelectionNames<MixedSolves> names{
      {"condensed on the pairs", MixedSolves::condensed_on_the_pairs},
      {"predictor and corrector", MixedSolves::predictor_and_corrector}};
    return names;
  }

  /// `Contraction joints/On non-convergence`: what a step whose contact
  /// problem does not converge does.
  enum class OnNonConvergence
  {
    stop, ///< end the run with a message naming the joint
    go_on ///< go on and flag the step in the summary
  };

  /// The names of OnNonConvergence in the case file.
  inline const SelectionNames<OnNonConvergence> &
  on_non_convergence_names()
  {
    static const SelectionNames<OnNonConvergence> names{
      {"stop", OnNonConvergence::stop}, {"continue", OnNonConvergence::go_on}};
    return names;
  }

  /// `Contraction joints/Law`: how a pair's strength evolves (contact_law.h).
  enum class Law
  {
    mohr_coulomb,       ///< intact strength until the pair opens or slips, then residual
    softening_shear_key ///< strength softening with the largest opening reached
  };

  /// The names of Law in the case file.
  inline const SelectionNames<Law> &
  law_names()
  {
    static const SelectionNames<Law> names{{"Mohr-Coulomb", Law::mohr_coulomb},
                                           {"softening shear key", Law::softening_shear_key}};
    return names;
  }

  /// `Contraction joints/Contact in time`: how the dynamic step's pair forces
  /// act in time (doc/theory/joints.md §10).
  enum class ContactInTime
  {
    trapezoidal, ///< the forces at the step's ends, averaged by the Newmark rule; positions held
    step_impulse ///< one force over the whole step; closed pairs as Closure says
  };

  /// The names of ContactInTime in the case file.
  inline const SelectionNames<ContactInTime> &
  contact_in_time_names()
  {
    static const SelectionNames<ContactInTime> names{
      {"trapezoidal", ContactInTime::trapezoidal}, {"step impulse", ContactInTime::step_impulse}};
    return names;
  }

  /// `Contraction joints/Closure`: what a closed pair holds in a step with
  /// the step impulse (doc/theory/joints.md §10-§11).
  enum class Closure
  {
    dissipative, ///< velocities, no motion apart while pressed, tangential positions held
    velocities   ///< the relative velocity at the step's end at zero in all three directions
  };

  /// The names of Closure in the case file.
  inline const SelectionNames<Closure> &
  closure_names()
  {
    static const SelectionNames<Closure> names{{"dissipative", Closure::dissipative},
                                               {"velocities", Closure::velocities}};
    return names;
  }

  /// `Contraction joints/Grouting`: when the static stage grouts the joints
  /// (doc/theory/loading-sequence.md §1).
  enum class Grouting
  {
    after_self_weight, ///< self-weight on the independent cantilevers, then grouted, then the rest
    before_self_weight ///< the whole static load on the grouted dam
  };

  /// The names of Grouting in the case file.
  inline const SelectionNames<Grouting> &
  grouting_names()
  {
    static const SelectionNames<Grouting> names{{"after self-weight", Grouting::after_self_weight},
                                                {"before self-weight", Grouting::before_self_weight}};
    return names;
  }

  /// `Contraction joints/Static solution`: how the static stage solves the
  /// contact problem (doc/theory/loading-sequence.md §1).
  enum class StaticSolution
  {
    one_solve,         ///< the mixed method with K, the whole load at once
    dynamic_relaxation ///< the load ramped in a damped transient until the dam is at rest
  };

  /// The names of StaticSolution in the case file.
  inline const SelectionNames<StaticSolution> &
  static_solution_names()
  {
    static const SelectionNames<StaticSolution> names{
      {"one solve", StaticSolution::one_solve},
      {"dynamic relaxation", StaticSolution::dynamic_relaxation}};
    return names;
  }

  /// `Contraction joints/Dynamic relaxation` (doc/theory/loading-sequence.md
  /// §1): the fictitious transient that brings the static load onto the
  /// joints.
  struct RelaxationParameters
  {
    double       time_step    = 0.01;  ///< s
    double       frequency    = 1.5;   ///< Hz: the damping is critical at this frequency
    double       loading_time = 1.;    ///< s: the load's smooth ramp
    double       tolerance    = 1e-6;  ///< out-of-balance force relative to the largest load
    unsigned int max_steps    = 4000;
  };

  /// The values of the law of one joint (doc/theory/joints.md §2, the
  /// paper's Table 1). Stresses in Pa, lengths in m.
  struct LawParameters
  {
    double friction_coefficient      = 1.0;
    double cohesion                  = 0.;
    double tensile_strength          = 0.;
    double residual_cohesion         = 0.;
    double residual_tensile_strength = 0.;
    double initial_gap               = 0.;
    /// The opening at which the softening shear key is down to its
    /// residual strength.
    double softening_opening = 1e-3;
  };

  /// The `Contraction joints` subsection (doc/theory/joints.md).
  struct JointParameters
  {
    Model       model        = Model::glued;
    Solver      solver       = Solver::mixed;
    Coupling    coupling     = Coupling::all_joints;
    ContactProblem contact_problem = ContactProblem::all_pairs_at_once;
    MixedSolves mixed_solves = MixedSolves::condensed_on_the_pairs;
    Law           strength_law = Law::mohr_coulomb;
    ContactInTime contact_in_time = ContactInTime::step_impulse;
    /// With the step impulse: what a closed pair holds in a step
    /// (doc/theory/joints.md §10-§11).
    Closure closure = Closure::dissipative;
    /// With the step impulse: after each dynamic step, move the closed
    /// pairs that do not touch back to touching by a correction of the
    /// displacements alone (doc/theory/joints.md §11). The trapezoidal
    /// forces hold the closed pairs at their positions themselves.
    bool position_correction = true;
    /// A step corrects when a pair is off touch by more than this [m]; it
    /// then brings every pair to within Gap tolerance.
    double position_tolerance = 1e-5;
    Grouting      grouting        = Grouting::before_self_weight;
    StaticSolution       static_solution = StaticSolution::one_solve;
    RelaxationParameters relaxation;
    LawParameters law;
    /// "k: name = value, ...; ..." overrides of the law for single joints
    std::string per_joint;
    double       force_tolerance = 1e-8;
    double       gap_tolerance   = 1e-9;
    unsigned int max_iterations  = 50000;
    double       penalty_factor  = 1e8;
    OnNonConvergence on_non_convergence = OnNonConvergence::stop;
    /// "name: x, y, z; ..." points whose nearest node pair is recorded
    std::string monitor_points;

    void
    add_parameters(dealii::ParameterHandler &prm);

    bool
    frictional() const
    {
      return model == Model::frictional_contact;
    }

    /// Whether a dynamic step corrects the closed pairs' positions: the
    /// step impulse with its position correction (doc/theory/joints.md §11).
    bool
    corrects_positions() const
    {
      return position_correction && contact_in_time == ContactInTime::step_impulse;
    }

    /// The law of joint @p k: the global one with its per-joint overrides.
    /// Throws InputError for a malformed override or a value out of range.
    LawParameters
    law_of(unsigned int k) const;

    /// Throws InputError if `Per joint` is malformed or names a joint the
    /// model does not have (k >= @p n_joints).
    void
    check_per_joint(unsigned int n_joints) const;
  };
} // namespace archdam::joints
