#include <archdam/base/binary_io.h>
#include <archdam/base/input_error.h>
#include <archdam/joints/joint_solver.h>

#include <algorithm>
#include <cmath>
#include <sstream>

namespace archdam::joints
{
  using namespace dealii;

  JointSolver::JointSolver(const JointParameters &p, const NodePairs &pairs, const double h)
    : pairs(pairs)
    , force(dim * pairs.size(), 0.)
    , force_committed(dim * pairs.size(), 0.)
    , pair_load(dim * pairs.size(), 0.)
    , load_committed(dim * pairs.size(), 0.)
    , w(dim * pairs.size(), 0.)
    , w_committed(dim * pairs.size(), 0.)
    , state(pairs.size(), PairState::stick)
    , damaged(pairs.size(), false)
    , largest_opening(pairs.size(), 0.)
    , w_grouted(dim * pairs.size(), 0.)
    , p(p)
    , h(h)
    , law(make_joint_law(p.strength_law))
  {
    for (unsigned int i = 0; i < pairs.size(); ++i)
      laws.push_back(p.law_of(pairs[i].joint));
    set_initial_states();
  }

  void
  JointSolver::set_initial_states()
  {
    for (unsigned int i = 0; i < pairs.size(); ++i)
      state[i] = laws[i].initial_gap > 0. ? PairState::separation : PairState::stick;
  }

  void
  JointSolver::accept()
  {
    for (unsigned int i = 0; i < pairs.size(); ++i)
      {
        damaged[i] = damaged[i] || state[i] != PairState::stick;
        if (state[i] == PairState::separation)
          largest_opening[i] = std::max(largest_opening[i], gap(i));
      }
    force_committed = force;
    load_committed  = pair_load;
    w_committed     = w;
  }

  void
  JointSolver::set_state(const JointSolver &other)
  {
    force           = other.force;
    force_committed = other.force_committed;
    pair_load       = other.pair_load;
    load_committed  = other.load_committed;
    w               = other.w;
    w_committed     = other.w_committed;
    state           = other.state;
    damaged         = other.damaged;
    largest_opening = other.largest_opening;
    w_grouted       = other.w_grouted;
  }

  void
  JointSolver::grout(const Vector &u)
  {
    pairs.relative_displacement(u, w_grouted);
    for (auto *v : {&force, &force_committed, &pair_load, &load_committed, &w, &w_committed})
      std::fill(v->begin(), v->end(), 0.);
    set_initial_states();
    std::fill(damaged.begin(), damaged.end(), false);
    std::fill(largest_opening.begin(), largest_opening.end(), 0.);
  }

  void
  JointSolver::joint_displacement(const Vector &u, std::vector<double> &w_u) const
  {
    pairs.relative_displacement(u, w_u);
    for (unsigned int j = 0; j < w_u.size(); ++j)
      w_u[j] -= w_grouted[j];
  }

  std::vector<double>
  JointSolver::unloaded() const
  {
    std::vector<double> w_0(w_grouted.size());
    for (unsigned int j = 0; j < w_0.size(); ++j)
      w_0[j] = -w_grouted[j];
    return w_0;
  }

  double
  JointSolver::slip(const unsigned int i) const
  {
    return std::hypot(w[dim * i + 1], w[dim * i + 2]);
  }

  double
  JointSolver::law_residual(const unsigned int i) const
  {
    const double r =
      state[i] == PairState::separation ? std::max(0., -approach(i)) : std::abs(closure(i));
    if (state[i] != PairState::stick)
      return r;
    return std::max(r, std::hypot(w[dim * i + 1] - target[dim * i + 1],
                                  w[dim * i + 2] - target[dim * i + 2]));
  }

  double
  JointSolver::gap_residual(unsigned int &worst) const
  {
    double largest = 0.;
    worst          = 0;
    for (unsigned int i = 0; i < pairs.size(); ++i)
      if (const double r = law_residual(i); r > largest)
        {
          largest = r;
          worst   = i;
        }
    return largest;
  }

  double
  JointSolver::largest_pair_force() const
  {
    double largest = 0.;
    for (unsigned int i = 0; i < pairs.size(); ++i)
      largest = std::max(largest, std::sqrt(force[dim * i] * force[dim * i] +
                                            force[dim * i + 1] * force[dim * i + 1] +
                                            force[dim * i + 2] * force[dim * i + 2]));
    return largest;
  }

  double
  JointSolver::relative_change(const std::vector<double> &before) const
  {
    double change = 0.;
    for (unsigned int i = 0; i < pairs.size(); ++i)
      {
        double d2 = 0.;
        for (unsigned int k = 0; k < dim; ++k)
          d2 += std::pow(force[dim * i + k] - before[dim * i + k], 2);
        change = std::max(change, std::sqrt(d2));
      }
    return change == 0. ? 0. : change / largest_pair_force();
  }

  void
  JointSolver::prepare_step(const time::NewmarkIntegrator &newmark)
  {
    if (p.contact_in_time != ContactInTime::step_impulse)
      return;
    // the monolithic reference holds positions only (parameters::check
    // refuses it with the step impulse in a dynamic stage)
    AssertThrow(p.solver == Solver::mixed,
                ExcMessage("The step impulse needs the mixed joint solver."));
    omega = newmark.time_step() / newmark.velocity_factor();
    Vector x(newmark.predicted_displacement());
    x.add(-newmark.displacement_factor() / newmark.velocity_factor(),
          newmark.predicted_velocity());
    joint_displacement(x, velocity_target);
  }

  void
  JointSolver::correct_position(time::NewmarkIntegrator &newmark, time::NewmarkState &s)
  {
    if (correction_force.empty())
      {
        moved.dw.clear();
        return;
      }
    moved.du = s.u;
    newmark.correct_displacement(corrected_displacement, s);
    moved.du.sadd(-1., 1., s.u);
  }

  void
  JointSolver::set_load()
  {
    for (unsigned int j = 0; j < pair_load.size(); ++j)
      pair_load[j] = omega * force[j] - (omega - 1.) * load_committed[j];
  }

  void
  JointSolver::start_solve()
  {
    if (velocity_target.empty())
      {
        target = w_committed;
        for (unsigned int i = 0; i < pairs.size(); ++i)
          target[dim * i] = -laws[i].initial_gap;
      }
    else
      {
        target = velocity_target;
        if (p.closure == Closure::dissipative)
          // doc/theory/joints.md §11: a closed pair does not move apart in
          // the step (its normal target at most its gap at the step's
          // start), a sticking pair holds its tangential position and a
          // slipping pair slips along its step's increment, so that the
          // joints' work f . (w - w_n) is zero or a loss.
          for (unsigned int i = 0; i < pairs.size(); ++i)
            {
              target[dim * i] = std::min(w_committed[dim * i], target[dim * i]);
              for (const unsigned int k : {1u, 2u})
                target[dim * i + k] = w_committed[dim * i + k];
            }
        may_close.resize(pairs.size());
        for (unsigned int i = 0; i < pairs.size(); ++i)
          may_close[i] = state[i] != PairState::separation || gap(i) <= 0.;
      }

    direction.assign(pairs.size(), Tensor<1, dim>());
    slip_ratio.assign(pairs.size(), 0.);
    for (unsigned int i = 0; i < pairs.size(); ++i)
      {
        const double t = std::hypot(force_committed[dim * i + 1], force_committed[dim * i + 2]);
        if (t > 0)
          for (const unsigned int k : {1u, 2u})
            direction[i][k] = force_committed[dim * i + k] / t;
      }
  }

  bool
  JointSolver::update_state(const unsigned int i)
  {
    double      *f  = &force[dim * i];
    Tensor<1, dim> &d = direction[i];
    const auto   strength_i = strength(i);
    const double f_norm     = std::sqrt(f[0] * f[0] + f[1] * f[1] + f[2] * f[2]);
    const double t          = std::hypot(f[1], f[2]);
    const double tau        = strength_i.shear_capacity(f[0]);
    // A pair that opens or slips is weakened at once, also within the
    // iteration (doc/theory/joints.md §2): strength only decreases, so the
    // iteration cannot cycle between a weaker and a stronger pair.
    const auto separate = [&] {
      state[i]   = PairState::separation;
      damaged[i] = true;
      std::fill(f, f + dim, 0.);
      return true;
    };
    switch (state[i])
      {
        case PairState::separation:
          if (approach(i) < -p.gap_tolerance)
            {
              state[i] = PairState::stick;
              return true;
            }
          return false;
        case PairState::stick:
          if (f[0] > strength_i.tensile_force + p.force_tolerance * f_norm)
            return separate();
          if (t > tau + p.force_tolerance * f_norm)
            {
              state[i]   = PairState::slip;
              damaged[i] = true;
              d[1]          = f[1] / t;
              d[2]          = f[2] / t;
              slip_ratio[i] = 0.;
              return true;
            }
          return false;
        case PairState::slip:
          {
            if (f[0] > strength_i.tensile_force + p.force_tolerance * f_norm || tau < 0)
              return separate();
            // the augmented tangential force q = f_t + r dw_t (Alart-Curnier):
            // stick when it falls inside the capacity, else the new direction
            const double s1 = w[dim * i + 1] - target[dim * i + 1],
                         s2 = w[dim * i + 2] - target[dim * i + 2];
            const double q1 = f[1] + augmentation[i] * s1, q2 = f[2] + augmentation[i] * s2;
            const double q  = std::hypot(q1, q2);
            if (q < tau - p.force_tolerance * f_norm)
              {
                state[i] = PairState::stick;
                return true;
              }
            // the part of the slip increment not along the friction force [m]
            const double along  = s1 * d[1] + s2 * d[2];
            const double misfit = std::hypot(s1 - along * d[1], s2 - along * d[2]);
            if (q > 0)
              {
                d[1]          = q1 / q;
                d[2]          = q2 / q;
                // at the capacity itself (|q| = tau within the tolerance) the
                // Newton row would leave f_t free across d: keep d fixed there
                slip_ratio[i] = q > tau ? tau / q : 0.;
              }
            return misfit > p.gap_tolerance || along < -p.gap_tolerance;
          }
      }
    return false;
  }

  std::string
  JointSolver::describe(const ContactStep &step) const
  {
    const auto        &pair = pairs[step.worst_pair];
    std::ostringstream s;
    s << "joint " << pair.joint << ", node pair at (" << pair.position[0] << ", "
      << pair.position[1] << ", " << pair.position[2] << "): the contact problem did not "
      << "converge in " << step.iterations << " iterations (law residual "
      << step.gap_residual << " m, last relative force change " << step.force_change
      << "; tolerances " << p.gap_tolerance << " m and " << p.force_tolerance << ")";
    return s.str();
  }

  time::NewmarkIntegrator::StepSolver
  contact_step_solver(const time::NewmarkIntegrator &newmark, JointSolver &solver,
                      ContactStep &step)
  {
    return [&newmark, &solver, &step](const Vector &rhs, Vector &da) {
      std::vector<double> w_base;
      solver.joint_displacement(newmark.predicted_displacement(), w_base);
      solver.prepare_step(newmark);
      step = solver.solve(rhs, w_base, da);
      solver.accept();
    };
  }

  ContactStep
  advance_with_contact(time::NewmarkIntegrator &newmark, JointSolver &solver,
                       const Vector &load_next, time::NewmarkState &s)
  {
    ContactStep step;
    newmark.advance(load_next, s, contact_step_solver(newmark, solver, step));
    solver.correct_position(newmark, s);
    return step;
  }

  std::unique_ptr<JointSolver>
  make_joint_solver(const JointParameters &p, const NodePairs &pairs, const double h,
                    const SparseMatrix &A, const time::FactorizedOperator &A_factor)
  {
    if (p.solver == Solver::monolithic)
      return std::make_unique<MonolithicJointSolver>(p, pairs, h, A, A_factor);
    return std::make_unique<MixedJointSolver>(p, pairs, h, A_factor);
  }

  void
  JointSolver::save(std::ostream &out) const
  {
    binary::write_all(out, force, force_committed, pair_load, load_committed, w, w_committed, state,
                      damaged, largest_opening, w_grouted);
  }

  void
  JointSolver::load(std::istream &in)
  {
    binary::read_all(in, force, force_committed, pair_load, load_committed, w, w_committed, state,
                     damaged, largest_opening, w_grouted);
    if (state.size() != pairs.size() || force.size() != dim * pairs.size())
      throw InputError("Checkpoint: the saved joint state has " + std::to_string(state.size()) +
                       " node pairs, the model " + std::to_string(pairs.size()) + ".");
  }
} // namespace archdam::joints
