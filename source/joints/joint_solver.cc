#include <archdam/joints/joint_solver.h>

#include <cmath>
#include <sstream>

namespace archdam::joints
{
  using namespace dealii;

  JointSolver::JointSolver(const JointParameters &p, const NodePairs &pairs, const double h)
    : pairs(pairs)
    , force(dim * pairs.size(), 0.)
    , force_committed(dim * pairs.size(), 0.)
    , w(dim * pairs.size(), 0.)
    , w_committed(dim * pairs.size(), 0.)
    , state(pairs.size(), PairState::stick)
    , damaged(pairs.size(), false)
    , p(p)
    , h(h)
  {
    for (unsigned int i = 0; i < pairs.size(); ++i)
      laws.push_back(p.law_of(pairs[i].joint));
  }

  void
  JointSolver::accept()
  {
    for (unsigned int i = 0; i < pairs.size(); ++i)
      damaged[i] = damaged[i] || state[i] != PairState::stick;
    force_committed = force;
    w_committed     = w;
  }

  void
  JointSolver::set_state(const JointSolver &other)
  {
    force           = other.force;
    force_committed = other.force_committed;
    w               = other.w;
    w_committed     = other.w_committed;
    state           = other.state;
    damaged         = other.damaged;
  }

  double
  JointSolver::slip(const unsigned int i) const
  {
    return std::hypot(w[dim * i + 1], w[dim * i + 2]);
  }

  double
  JointSolver::gap_residual(unsigned int &worst) const
  {
    double largest = 0.;
    worst          = 0;
    for (unsigned int i = 0; i < pairs.size(); ++i)
      {
        double r = state[i] == PairState::separation ? std::max(0., -gap(i)) : std::abs(gap(i));
        if (state[i] == PairState::stick)
          r = std::max(r, std::hypot(w[dim * i + 1] - w_committed[dim * i + 1],
                                     w[dim * i + 2] - w_committed[dim * i + 2]));
        if (r > largest)
          {
            largest = r;
            worst   = i;
          }
      }
    return largest;
  }

  double
  JointSolver::relative_change(const std::vector<double> &before) const
  {
    double change = 0., scale = 0.;
    for (unsigned int i = 0; i < pairs.size(); ++i)
      {
        double d2 = 0., f2 = 0.;
        for (unsigned int k = 0; k < dim; ++k)
          {
            d2 += std::pow(force[dim * i + k] - before[dim * i + k], 2);
            f2 += std::pow(force[dim * i + k], 2);
          }
        change = std::max(change, std::sqrt(d2));
        scale  = std::max(scale, std::sqrt(f2));
      }
    return change == 0. ? 0. : change / scale;
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

  ContactStep
  advance_with_contact(time::NewmarkIntegrator &newmark, JointSolver &solver,
                       const Vector &load_next, time::NewmarkState &s)
  {
    Vector rhs, da;
    rhs.reinit(load_next);
    da.reinit(load_next);
    newmark.effective_load(load_next, s, rhs);
    std::vector<double> w_base;
    solver.pairs.relative_displacement(newmark.predicted_displacement(), w_base);
    const ContactStep step = solver.solve(rhs, w_base, da);
    solver.accept();
    newmark.update(da, s);
    return step;
  }

  std::unique_ptr<JointSolver>
  make_joint_solver(const JointParameters &p, const NodePairs &pairs, const double h,
                    const SparseMatrix &A, const time::FactorizedOperator &A_factor)
  {
    if (p.solver == "monolithic")
      return std::make_unique<MonolithicJointSolver>(p, pairs, h, A);
    return std::make_unique<MixedJointSolver>(p, pairs, h, A_factor);
  }
} // namespace archdam::joints
