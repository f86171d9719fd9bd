#include <archdam/base/input_error.h>
#include <archdam/joints/joint_parameters.h>

#include <deal.II/base/utilities.h>

#include <map>
#include <vector>

namespace archdam::joints
{
  using namespace dealii;

  void
  JointParameters::add_parameters(ParameterHandler &prm)
  {
    add_selection(prm, "Model", model, model_names(),
                  "How the contraction joints between dam blocks behave: glued = "
                  "the two faces of every joint are tied together (the monolithic "
                  "dam); frictional contact = the joints open, close and slide "
                  "(Mohr-Coulomb with tension cut-off, doc/theory/joints.md §2).");
    add_selection(prm, "Solver", solver, solver_names(),
                  "Frictional contact solver: mixed = the mixed method (the "
                  "effective matrix factorized once, the contact problem on the "
                  "node pairs only); monolithic = the reference solver on the "
                  "full system (penalty, refactorized as the contact states "
                  "change), for verification and benchmarks.");
    add_selection(prm, "Flexibility coupling", coupling, coupling_names(),
                  "Which entries of the flexibility matrix C the mixed method "
                  "keeps: all joints = the exact C; neighbouring joints = only "
                  "the coupling between pairs of the same or adjacent joints "
                  "(the paper's sparse approximation).");
    add_selection(prm, "Contact problem", contact_problem, contact_problem_names(),
                  "How the mixed method solves the contact problem of a dynamic "
                  "step on the node pairs (doc/theory/joints.md §6 and §12): all pairs at "
                  "once = one active set on the system of every pair (a dense LU of "
                  "three unknowns per pair, kept between solves; the default); joint by "
                  "joint = block Gauss-Seidel over the joints, red-black, each joint's "
                  "pairs solved together by the active set on their own small system, "
                  "until the law holds at every pair with the exact flexibility (the "
                  "joints of a colour shared among the MPI processes; a step that does "
                  "not settle so is solved all pairs at once). Joint by joint converges "
                  "slowly on the reference case (about 0.6 per sweep: a joint's load "
                  "moves its blocks as a whole) and is slower there; it is the base of "
                  "a two-level solver. The static stage solves all pairs at once.");
    add_selection(prm, "Mixed method solves", mixed_solves, mixed_solves_names(),
                  "How a solve of the mixed method reaches the pairs (doc/theory/joints.md "
                  "§4): condensed on the pairs = the stage's matrix factorized by "
                  "MUMPS with the pairs' unknowns eliminated last, C from the Schur "
                  "complement of those unknowns, and one back-substitution per solve "
                  "split around the contact problem (forward elimination, contact "
                  "problem, backward substitution); predictor and corrector = a "
                  "plain factorization, C from one back-substitution per pair "
                  "unknown, and two back-substitutions per solve (the pair forces "
                  "held, then their change), for comparison.");
    add_selection(prm, "Law", strength_law, law_names(),
                  "How the strength of a node pair evolves (doc/theory/joints.md §2): "
                  "Mohr-Coulomb = the intact cohesion and tensile strength until the "
                  "pair first opens or slips, the residual values from then on (the "
                  "paper's law); softening shear key = cohesion and tensile strength "
                  "falling linearly from the intact to the residual values as the "
                  "largest opening the pair has reached grows to Softening opening "
                  "(keys that crack progressively as the joint opens). Friction is "
                  "the same in both.");
    add_selection(prm, "Contact in time", contact_in_time, contact_in_time_names(),
                  "How the pair forces of a dynamic step act in time (doc/theory/joints.md "
                  "§10): trapezoidal = the forces at the two ends of the step, averaged "
                  "by the Newmark rule, with the closed pairs held at their positions "
                  "(the paper's scheme; a pair that opens works against the opening "
                  "with half its last force and puts energy into the dam); step "
                  "impulse = one force over the whole step, the closed pairs holding "
                  "their relative velocity at the step's end at zero (the default): a "
                  "step cannot create energy at the joints, and persistent contact "
                  "does not chatter; it needs the mixed solver, and with it use the "
                  "average acceleration rule (Beta1 = 0.5, Beta2 = 0.25).");
    add_selection(prm, "Closure", closure, closure_names(),
                  "With Contact in time = step impulse: what a closed pair holds in a "
                  "dynamic step (doc/theory/joints.md §10-§11). dissipative (the default) "
                  "= a closed pair holds its relative velocity at zero at the step's end "
                  "as far as it does not move apart while pressed, a sticking pair holds "
                  "its position and a slipping pair slips along its step's increment: the "
                  "joints' work in every step is zero or a loss, so no step creates energy "
                  "at the joints, damped or not; velocities = the closed pairs hold their "
                  "relative velocity at the step's end at zero in all three directions "
                  "(the scheme before 2026-12-02: on an undamped model a pair can do work "
                  "against its motion at the start of a step, and a block hops). Either "
                  "way a pair that closes in a step penetrates by up to dt/2 times its "
                  "approach velocity, which Position correction removes.");
    prm.add_parameter("Position correction", position_correction,
                      "With Contact in time = step impulse: after every dynamic step, the "
                      "closed pairs that penetrate or stand apart by more than Position "
                      "tolerance are moved back to touching by a correction of the "
                      "displacements alone, the velocities kept (doc/theory/joints.md §11). "
                      "It costs a second column of the step's backward substitution in the "
                      "steps that correct (one more substitution without the condensed "
                      "factorization). "
                      "No force does its work: the energy balance reports it as the "
                      "position correction's energy. With the trapezoidal forces there is "
                      "nothing to correct: they hold the closed pairs at their positions "
                      "themselves.");
    prm.add_parameter("Position tolerance", position_tolerance,
                      "With Position correction: a step corrects when a closed pair stands "
                      "apart or penetrates, or an open pair penetrates, by more than this "
                      "[m]; the correction then brings every such pair to touching (within "
                      "Gap tolerance).",
                      Patterns::Double(0.));
    add_selection(prm, "Grouting", grouting, grouting_names(),
                  "When the static stage grouts the joints (doc/theory/loading-sequence.md "
                  "§1): before self-weight = the whole static load on the grouted dam at "
                  "once, the weight carried across the joints too (the blocks of the "
                  "parametric arch dam lean on each other: its joints fan out with the "
                  "canyon, doc/arch-dam-geometry.md §10); after self-weight = as a dam with "
                  "vertical joints is built: the self-weight acts on the independent "
                  "cantilevers (the joints carry nothing), the joints are grouted in that "
                  "deformed state (its relative displacements become the joints' zero: no "
                  "opening, slip or force from self-weight), then the hydrostatic load "
                  "acts on the grouted dam with the joints in contact.");
    add_selection(prm, "Static solution", static_solution, static_solution_names(),
                  "How the static stage solves the joints' contact problem "
                  "(doc/theory/loading-sequence.md §1): one solve = the mixed method "
                  "with K, the whole static load at once (fast; on meshes with many "
                  "cells over the height its active set can cycle without converging); "
                  "dynamic relaxation = the load ramped smoothly in a fictitious "
                  "transient with the dam's mass and a damping critical at Frequency, "
                  "stepped with the Newmark scheme (Beta1 = 3/4, the trapezoidal joint "
                  "forces, whatever Contact in time says) until the out-of-balance "
                  "force falls below Tolerance (subsection Dynamic relaxation): each "
                  "step's contact problem is the well-conditioned one of a dynamic "
                  "step, and friction sees the load grow as it does in the dam.");
    prm.enter_subsection("Dynamic relaxation");
    prm.add_parameter("Time step", relaxation.time_step,
                      "Step of the fictitious transient [s].", Patterns::Double(1e-12));
    prm.add_parameter("Frequency", relaxation.frequency,
                      "The mass-proportional damping is critical at this frequency "
                      "[Hz]: every mode above it dies out at the same rate, 2 pi "
                      "Frequency per second, a mode of frequency f well below it at "
                      "pi f^2 / Frequency per second. Fastest near the lowest frequency of "
                      "the dam with its joints: at or below the grouted dam's first "
                      "frequency without water, lower where joints open wide.",
                      Patterns::Double(1e-12));
    prm.add_parameter("Loading time", relaxation.loading_time,
                      "The static load grows from zero to its full value over this "
                      "time, along (1 - cos(pi t / Loading time)) / 2 [s].",
                      Patterns::Double(0.));
    prm.add_parameter("Tolerance", relaxation.tolerance,
                      "The transient ends, after the loading time, when the largest "
                      "out-of-balance nodal force |F - K u - B^T f| is at most this "
                      "times the largest nodal load.",
                      Patterns::Double(1e-15));
    prm.add_parameter("Maximum steps", relaxation.max_steps,
                      "The run stops with a message if the transient has not come to "
                      "rest within this many steps.",
                      Patterns::Integer(1));
    prm.leave_subsection();
    prm.add_parameter("Friction coefficient", law.friction_coefficient,
                      "Coulomb friction coefficient mu of the joint faces.",
                      Patterns::Double(0.));
    prm.add_parameter("Cohesion", law.cohesion,
                      "Cohesion c of the intact joint [Pa].", Patterns::Double(0.));
    prm.add_parameter("Tensile strength", law.tensile_strength,
                      "Tensile strength sigma_t of the intact joint [Pa].",
                      Patterns::Double(0.));
    prm.add_parameter("Residual cohesion", law.residual_cohesion,
                      "Cohesion of a pair after it has opened or slipped [Pa].",
                      Patterns::Double(0.));
    prm.add_parameter("Residual tensile strength", law.residual_tensile_strength,
                      "Tensile strength of a pair after it has opened or slipped [Pa].",
                      Patterns::Double(0.));
    prm.add_parameter("Initial gap", law.initial_gap,
                      "Initial normal gap delta_0 of the joints [m] (0 = closed, "
                      "grouted).",
                      Patterns::Double(0.));
    prm.add_parameter("Softening opening", law.softening_opening,
                      "Law = softening shear key: the largest opening at which the "
                      "cohesion and tensile strength have fallen to their residual "
                      "values [m].",
                      Patterns::Double(1e-12));
    prm.add_parameter("Per joint", per_joint,
                      "Values for single joints, overriding the ones above: "
                      "'k: Name = value, ...; ...' with k the joint number (0 = "
                      "between blocks 0 and 1) and Name one of Friction coefficient, "
                      "Cohesion, Tensile strength, Residual cohesion, Residual tensile "
                      "strength, Initial gap, Softening opening.",
                      Patterns::Anything());
    prm.add_parameter("Force tolerance", force_tolerance,
                      "Contact problem convergence: largest change of a pair force in "
                      "an iteration, relative to the largest pair force.",
                      Patterns::Double(0.));
    prm.add_parameter("Gap tolerance", gap_tolerance,
                      "Contact problem convergence: largest violation of the law in "
                      "the relative displacements (penetration, opening of a closed "
                      "pair, slip of a sticking pair) [m].",
                      Patterns::Double(0.));
    prm.add_parameter("Maximum iterations", max_iterations,
                      "Contact iterations allowed in one solve: active-set "
                      "iterations plus projected Gauss-Seidel sweeps (doc/theory/joints.md "
                      "§6; a sweep costs about as much as one matrix-vector product "
                      "with the flexibility matrix).",
                      Patterns::Integer(1));
    prm.add_parameter("Penalty factor", penalty_factor,
                      "Monolithic solver only: penalty stiffness of a closed pair as a "
                      "multiple of the largest diagonal entry of the matrix.",
                      Patterns::Double(1.));
    add_selection(prm, "On non-convergence", on_non_convergence, on_non_convergence_names(),
                  "A step whose contact problem does not converge: stop = end the "
                  "run with a message naming the joint, place, time and residual; "
                  "continue = go on and flag the step in the summary.");
    prm.add_parameter("Monitor points", monitor_points,
                      "Points whose nearest node pair's opening and slip are recorded "
                      "every step (joint_histories_static.csv, joint_histories_dynamic.csv): "
                      "'name: x, y, z; ...'.",
                      Patterns::Anything());
  }

  namespace
  {
    /// One override of `Per joint`: joint k's member of the law.
    struct Override
    {
      unsigned int joint;
      double LawParameters::*member;
      double            value;
    };

    /// Parse "k: Name = value, ...; ..."; throw InputError for a malformed
    /// entry or a value out of range.
    std::vector<Override>
    parse_per_joint(const std::string &per_joint)
    {
      const std::map<std::string, double LawParameters::*> names{
        {"Friction coefficient", &LawParameters::friction_coefficient},
        {"Cohesion", &LawParameters::cohesion},
        {"Tensile strength", &LawParameters::tensile_strength},
        {"Residual cohesion", &LawParameters::residual_cohesion},
        {"Residual tensile strength", &LawParameters::residual_tensile_strength},
        {"Initial gap", &LawParameters::initial_gap},
        {"Softening opening", &LawParameters::softening_opening}};
      std::vector<Override> result;
      for (const auto &entry : Utilities::split_string_list(per_joint, ';'))
        {
          const auto colon = entry.find(':');
          const auto bad   = [&](const std::string &why) {
            return InputError("Contraction joints/Per joint: '" + entry + "': " + why + ".");
          };
          if (colon == std::string::npos)
            throw bad("expected 'k: Name = value, ...'");
          // The values are read as the main section's are (Patterns::Integer
          // and Patterns::Double: no 'inf', 'nan' or hexadecimal).
          const std::string number = Utilities::trim(entry.substr(0, colon));
          if (!Patterns::Integer().match(number))
            throw bad("the joint number is not an integer");
          const int joint = Utilities::string_to_int(number);
          if (joint < 0)
            throw bad("the joint number must be 0 or more");
          for (const auto &earlier : result)
            if (earlier.joint == static_cast<unsigned int>(joint))
              throw bad("joint " + number + " is given twice; give all its values in one entry, "
                        "'" + number + ": Name = value, Name = value'");
          for (const auto &assignment :
               Utilities::split_string_list(entry.substr(colon + 1), ','))
            {
              const auto eq = assignment.find('=');
              if (eq == std::string::npos)
                throw bad("expected 'Name = value' in '" + assignment + "'");
              const auto name = Utilities::trim(assignment.substr(0, eq));
              const auto it   = names.find(name);
              if (it == names.end())
                throw bad("unknown name '" + name + "'");
              const std::string text = Utilities::trim(assignment.substr(eq + 1));
              if (!Patterns::Double().match(text))
                throw bad("the value of '" + name + "' is not a number");
              const double value = Utilities::string_to_double(text);
              if (!(value >= 0.))
                throw bad("'" + name + "' must be >= 0");
              result.push_back({static_cast<unsigned int>(joint), it->second, value});
            }
        }
      return result;
    }
  } // namespace

  LawParameters
  JointParameters::law_of(const unsigned int k) const
  {
    LawParameters result = law;
    for (const auto &o : parse_per_joint(per_joint))
      if (o.joint == k)
        result.*(o.member) = o.value;
    return result;
  }

  void
  JointParameters::check_per_joint(const unsigned int n_joints) const
  {
    for (const auto &o : parse_per_joint(per_joint))
      if (o.joint >= n_joints)
        throw InputError(
          "Contraction joints/Per joint: there is no joint " + std::to_string(o.joint) +
          ": the model has " +
          (n_joints == 0 ? std::string("no joints") :
           n_joints == 1 ? std::string("one joint, number 0") :
                           std::to_string(n_joints) + " joints, numbered 0 to " +
                             std::to_string(n_joints - 1)) +
          " (joint k lies between blocks k and k + 1).");
  }
} // namespace archdam::joints
