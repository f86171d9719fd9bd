#include <archdam/base/wall_time.h>
#include <archdam/joints/joint_solver.h>

#include <deal.II/lac/lapack_full_matrix.h>
#include <deal.II/lac/vector.h>

#include <algorithm>
#include <array>
#include <map>
#include <numeric>
#include <cmath>

namespace archdam::joints
{
  using namespace dealii;

  MixedJointSolver::MixedJointSolver(const JointParameters &p, const NodePairs &pairs,
                                     const double h, const time::FactorizedOperator &A_factor)
    : JointSolver(p, pairs, h)
    , A_factor(A_factor)
    , all_pairs([&] {
      std::vector<unsigned int> all(pairs.size());
      std::iota(all.begin(), all.end(), 0u);
      return all;
    }())
  {
    if (p.contact_problem != ContactProblem::joint_by_joint)
      return;
    std::vector<std::vector<unsigned int>> of_joint;
    for (unsigned int i = 0; i < pairs.size(); ++i)
      {
        if (pairs[i].joint >= of_joint.size())
          of_joint.resize(pairs[i].joint + 1);
        of_joint[pairs[i].joint].push_back(i);
      }
    std::vector<unsigned int> joint_of_system;
    for (unsigned int J = 0; J < of_joint.size(); ++J)
      if (!of_joint[J].empty())
        {
          by_joint.emplace_back(of_joint[J]);
          joint_of_system.push_back(J);
        }
    // a joint's change moves its own and its neighbouring joints' pairs
    // within a sweep (doc/theory/joints.md §12)
    reach.resize(by_joint.size());
    for (unsigned int a = 0; a < by_joint.size(); ++a)
      for (unsigned int b = 0; b < by_joint.size(); ++b)
        if (std::abs(static_cast<int>(joint_of_system[a]) -
                     static_cast<int>(joint_of_system[b])) <= 1)
          reach[a].push_back(b);
  }

  std::size_t
  MixedJointSolver::memory() const
  {
    std::size_t bytes = sizeof(double) * (C.size() + C_rows.size() + G.m() * G.n());
    bytes += all_pairs.memory();
    for (const PairSystem &system : by_joint)
      bytes += system.memory();
    return bytes;
  }

  void
  MixedJointSolver::add_flexibility_times(const double factor, const std::vector<double> &f,
                                          std::vector<double> &out) const
  {
    const unsigned int m = dim * pairs.size();
    for (unsigned int j = 0; j < m; ++j)
      if (f[j] != 0.)
        for (unsigned int k = 0; k < m; ++k)
          out[k] += factor * C[static_cast<std::size_t>(j) * m + k] * f[j];
  }

  void
  MixedJointSolver::set_relative_displacement()
  {
    w = s;
    add_flexibility_times(-contact_h(), force, w);
  }

  void
  MixedJointSolver::solve_with_fixed_states(PairSystem &system, const std::vector<double> &s_of)
  {
    // The law with the states fixed and the slip directions linearized is
    // linear in the pair forces (doc/theory/joints.md §6): stick: w =
    // w_target in all three directions; slip: w_xi = -delta_0 and the
    // semi-smooth Newton step of f_t = tau(f_xi) q / |q|, q = f_t + r dw_t
    // (Alart-Curnier; Hueber, Stadler and Wohlmuth 2008): about the last
    // iterate, with d = q / |q|, P = I - d d^T (tangent plane) and
    // kappa = tau / |q|,
    //   (I - kappa P) f_t - kappa r P dw_t(f) + mu d f_xi = c A d;
    // separation: f = 0. With kappa = 0 (a pair that has just started to
    // slip) this is the fixed-direction law f_t = (c A - mu f_xi) d; with
    // kappa > 0 the direction converges with the forces instead of by a
    // damped fixed-point iteration, which needed hundreds of iterations when
    // the slip increment is small against tau / r. One row per pair unknown
    // (the open pairs' rows f = 0): a sticking pair's rows are those of the
    // base that PairSystem keeps factorized, the others enter by low rank.
    const unsigned int m = dim * pairs.size();
    const auto        &own = system.pairs();
    if (own.empty())
      return;
    const double hc       = contact_h();
    const auto   row_of   = [&](const unsigned int i, const unsigned int k) {
      const unsigned int r_ik = dim * i + k;
      SystemRow          parts;
      if (state[i] == PairState::separation)
        {
          // f = 0, scaled like the flexibility rows (metres) for the pivoting
          parts.own[k] = hc * C_rows[static_cast<std::size_t>(r_ik) * m + r_ik];
          return parts;
        }
      if (k > 0 && state[i] == PairState::slip)
        {
          const auto   strength_i = strength(i);
          const double kappa      = slip_ratio[i], r = augmentation[i];
          const auto  &d          = direction[i];
          const auto   P          = [&](const unsigned int k1, const unsigned int k2) {
            return (k1 == k2 ? 1. : 0.) - d[k1] * d[k2];
          };
          // The row divided by r: in metres like the other rows, so that
          // the LU's pivoting sees rows of one scale.
          // -kappa r P dw_t(f), dw_t = s_t - h (C f)_t - target_t
          parts.rhs = strength_i.cohesion_force * d[k] / r;
          for (const unsigned int l : {1u, 2u})
            {
              parts.flex[l] = kappa * P(k, l);
              parts.own[l]  = ((k == l ? 1. : 0.) - kappa * P(k, l)) / r;
              parts.rhs += kappa * P(k, l) * (s_of[dim * i + l] - target[dim * i + l]);
            }
          parts.own[0] = strength_i.friction * d[k] / r;
          return parts;
        }
      // (h C f)_ik = s_ik - w_target,k
      parts.flex[k] = 1.;
      parts.rhs     = s_of[r_ik] - target[r_ik];
      return parts;
    };
    dealii::Vector<double> x;
    switch (system.solve(C_rows, m, hc, row_of, x))
      {
        case PairSystem::Solve::factorized:
          ++factorizations;
          break;
        case PairSystem::Solve::updated:
          ++updated_solves;
          break;
        case PairSystem::Solve::kept:
          break;
      }
    for (unsigned int a = 0; a < own.size(); ++a)
      for (unsigned int k = 0; k < dim; ++k) // an open pair's exactly 0, not round-off
        force[dim * own[a] + k] =
          state[own[a]] == PairState::separation ? 0. : x(dim * a + k);
    if (&system == &all_pairs)
      {
        // w = s - h C f with h C f = A0 x from the update (PairSystem; the
        // open pairs' x is round-off): the exact product, a pass over C,
        // once the states have settled (active_set_iteration()).
        const auto &hCf = system.base_times_solution();
        for (unsigned int j = 0; j < m; ++j)
          w[j] = s_of[j] - hCf(j);
        return;
      }
    // the system's own w = s_of - h C f on its pairs
    for (const unsigned int i : own)
      for (unsigned int k = 0; k < dim; ++k)
        {
          const double *row = &C_rows[static_cast<std::size_t>(dim * i + k) * m];
          double        v   = s_of[dim * i + k];
          for (const unsigned int j : own)
            for (unsigned int l = 0; l < dim; ++l)
              v -= hc * row[dim * j + l] * force[dim * j + l];
          w[dim * i + k] = v;
        }
  }

  void
  MixedJointSolver::forget_factorization()
  {
    all_pairs.forget();
    for (PairSystem &system : by_joint)
      system.forget();
  }

  bool
  MixedJointSolver::settle(const std::vector<unsigned int> &among)
  {
    bool changed = false;
    for (const unsigned int i : among)
      changed = update_state(i) || changed;
    // The Newton step meets the slip law f_t = tau q / |q| only at
    // convergence: a slipping pair whose force is off it by more than Force
    // tolerance, relative to the largest pair force (the scale of the force
    // change, and of the round-off of the dense solve: relative to a weakly
    // loaded pair's own force the test asked for more digits than the solve
    // has), is not converged.
    const double force_scale = largest_pair_force();
    for (auto i = among.begin(); i != among.end() && !changed; ++i)
      if (state[*i] == PairState::slip)
        {
          const double *f   = &force[dim * *i];
          const double  tau = strength(*i).shear_capacity(f[0]);
          changed = std::hypot(f[1] - tau * direction[*i][1], f[2] - tau * direction[*i][2]) >
                    p.force_tolerance * force_scale;
        }
    return !changed;
  }

  bool
  MixedJointSolver::active_set_iteration(ContactStep &step, const unsigned int limit,
                                         PairSystem &system, const std::vector<double> &s_of)
  {
    const auto         &among = system.pairs();
    std::vector<double> before;
    // How often the iteration has come to each set of states (with the
    // damage) from another: one come to for the cycle_visits-th time means
    // the iteration cycles, typically one pair opening and closing in turn
    // while the slipping pairs' directions move (doc/theory/joints.md §6).
    // Iterations that keep the states and only turn slip directions are not
    // visits.
    const auto states_now = [&] {
      std::vector<unsigned char> s(among.size());
      for (unsigned int a = 0; a < among.size(); ++a)
        s[a] = 2 * static_cast<unsigned char>(state[among[a]]) + (damaged[among[a]] ? 1 : 0);
      return s;
    };
    std::map<std::vector<unsigned char>, unsigned int> visits;
    std::vector<unsigned char>                         previous = states_now();
    for (unsigned int k = 0; k < limit; ++k)
      {
        ++step.iterations;
        before = force;
        solve_with_fixed_states(system, s_of);
        const bool settled = settle(among);
        step.force_change  = relative_change(before);
        const auto residual = [&] {
          step.gap_residual = 0.;
          step.worst_pair   = among.front();
          for (const unsigned int i : among)
            if (const double r = law_residual(i); r > step.gap_residual)
              {
                step.gap_residual = r;
                step.worst_pair   = i;
              }
          return step.gap_residual;
        };
        if (settled && residual() <= p.gap_tolerance)
          {
            // all pairs: w from the update's A0 x so far, now from C itself
            if (&system != &all_pairs)
              return step.converged = true;
            set_relative_displacement();
            if (residual() <= p.gap_tolerance)
              return step.converged = true;
          }
        const auto states = states_now();
        if (states != previous && ++visits[states] == cycle_visits)
          return false;
        previous = states;
      }
    return false;
  }

  void
  MixedJointSolver::projected_gauss_seidel(ContactStep &step)
  {
    // Pair by pair, component by component: the normal force towards closing
    // the gap, then the tangential force towards no slip, each projected on
    // the law (doc/theory/joints.md §2) and scaled by the pair's own flexibility
    // (a projected coordinate / block-gradient step: for fixed friction
    // bounds this is descent on a convex quadratic, so it converges). A pair
    // whose trial force exceeds its strength opens or slips and is damaged.
    // Every few sweeps, the states reached are handed to the active set
    // (exact solution when they are right).
    const unsigned int m = dim * pairs.size();
    force                = force_committed;
    set_relative_displacement();
    const auto add_force = [&](const unsigned int j, const double df) {
      if (df == 0.)
        return;
      force[j] += df;
      const double *column = &C[static_cast<std::size_t>(j) * m];
      for (unsigned int k = 0; k < m; ++k)
        w[k] -= contact_h() * column[k] * df;
    };
    std::vector<double> before, previous_states, tried_states, pgs_force, pgs_w, pgs_opening;
    std::vector<bool>   pgs_damage;
    unsigned int        unchanged = 0; // sweeps in a row with the same states
    while (step.iterations < p.max_iterations)
      {
        ++step.iterations;
        before = force;
        for (unsigned int i = 0; i < pairs.size(); ++i)
          {
            const auto entry = [&](const unsigned int k, const unsigned int l) {
              return contact_h() * C[static_cast<std::size_t>(dim * i + l) * m + dim * i + k];
            };
            // normal: f_xi <= min(sigma_t A, c A / mu), else the pair opens
            auto   strength_i = strength(i);
            double f_xi       = force[dim * i] + approach(i) / entry(0, 0);
            if (f_xi > strength_i.normal_limit())
              {
                damaged[i] = true;
                strength_i = strength(i);
                f_xi       = 0.;
              }
            add_force(dim * i, f_xi - force[dim * i]);
            // tangential: f_t + (w_t - w_t,n) / lambda_max, into the disk of
            // radius c A - mu f_xi
            const double a = entry(1, 1), b = entry(1, 2), d = entry(2, 2);
            const double lambda =
              0.5 * (a + d) + std::sqrt(0.25 * (a - d) * (a - d) + b * b);
            double q1 = force[dim * i + 1] + (w[dim * i + 1] - target[dim * i + 1]) / lambda;
            double q2 = force[dim * i + 2] + (w[dim * i + 2] - target[dim * i + 2]) / lambda;
            double capacity = std::max(0., strength_i.shear_capacity(force[dim * i]));
            double q        = std::hypot(q1, q2);
            if (q > capacity && !damaged[i])
              {
                damaged[i] = true;
                strength_i = strength(i);
                capacity   = std::max(0., strength_i.shear_capacity(force[dim * i]));
              }
            if (q > capacity)
              {
                q1 *= capacity / q;
                q2 *= capacity / q;
              }
            add_force(dim * i + 1, q1 - force[dim * i + 1]);
            add_force(dim * i + 2, q2 - force[dim * i + 2]);
          }
        set_relative_displacement(); // no drift from the incremental updates

        // The states the forces show.
        std::vector<double> states(pairs.size());
        for (unsigned int i = 0; i < pairs.size(); ++i)
          {
            const double *f        = &force[dim * i];
            const double  t        = std::hypot(f[1], f[2]);
            const double  capacity = strength(i).shear_capacity(f[0]);
            state[i]               = f[0] == 0. && t == 0. ? PairState::separation :
                                     t >= capacity * (1. - 1e-6) ? PairState::slip :
                                                                 PairState::stick;
            if (state[i] == PairState::slip && t > 0.)
              for (const unsigned int k : {1u, 2u})
                direction[i][k] = f[k] / t;
            if (state[i] == PairState::slip)
              slip_ratio[i] = 0.; // the next active set starts with d held fixed
            states[i] = static_cast<double>(state[i]);
          }
        step.force_change = relative_change(before);
        step.gap_residual = gap_residual(step.worst_pair);
        if (step.force_change <= p.force_tolerance && step.gap_residual <= p.gap_tolerance)
          {
            step.converged = true;
            return;
          }
        // The active set from these states: once they have held for a few
        // sweeps (an LU per try), and once per set of states.
        unchanged       = states == previous_states ? unchanged + 1 : 0;
        previous_states = states;
        if (unchanged < polish_after || states == tried_states ||
            step.iterations + active_set_polish > p.max_iterations)
          continue;
        tried_states = states;
        pgs_force    = force;
        pgs_w        = w;
        pgs_damage   = damaged;
        pgs_opening  = largest_opening;
        if (active_set_iteration(step, active_set_polish, all_pairs, s))
          return;
        force           = pgs_force;
        w               = pgs_w;
        damaged         = pgs_damage;
        largest_opening = pgs_opening;
      }
  }

  void
  MixedJointSolver::find_position_correction()
  {
    // doc/theory/joints.md §11: when a pair is off touch by more than
    // Position tolerance, the closed pairs off touch (|gap| above Gap
    // tolerance) and the open pairs that penetrate (an open pair closes only
    // in a step it starts touching, §10) take normal forces nu with
    // h C_PP nu_P = gap_P, which move w by -h C nu (the displacements by
    // h Kbar^{-1} (-B^T nu)) and bring them to touching; the pairs that this
    // moves off touch or into penetration join P.
    const unsigned int m = dim * pairs.size();
    correction_force.clear();
    const auto off_touch = [&](const unsigned int i, const double g) {
      return state[i] == PairState::separation ? -g : std::abs(g);
    };
    bool needed = false;
    for (unsigned int i = 0; i < pairs.size() && !needed; ++i)
      needed = off_touch(i, gap(i)) > p.position_tolerance;
    if (!needed)
      return;
    std::vector<double>       dw(m, 0.), nu(m, 0.);
    std::vector<unsigned int> P;
    std::vector<bool>         in_P(pairs.size(), false);
    for (unsigned int round = 0; round < pairs.size(); ++round)
      {
        bool grown = false;
        for (unsigned int i = 0; i < pairs.size(); ++i)
          if (!in_P[i] && off_touch(i, gap(i) + dw[dim * i]) > p.gap_tolerance)
            {
              P.push_back(i);
              in_P[i] = grown = true;
            }
        if (!grown)
          break;
        const unsigned int       n = P.size();
        LAPACKFullMatrix<double> S(n, n);
        dealii::Vector<double>   gaps(n);
        for (unsigned int b = 0; b < n; ++b)
          {
            const double *column = &C[static_cast<std::size_t>(dim * P[b]) * m];
            for (unsigned int a = 0; a < n; ++a)
              S(a, b) = h * column[dim * P[a]];
            gaps(b) = gap(P[b]);
          }
        S.compute_lu_factorization();
        S.solve(gaps);
        for (unsigned int a = 0; a < n; ++a)
          nu[dim * P[a]] = gaps(a);
        std::fill(dw.begin(), dw.end(), 0.);
        add_flexibility_times(-h, nu, dw);
      }
    if (P.empty())
      return;
    for (unsigned int j = 0; j < m; ++j)
      w[j] += dw[j];
    moved.dw = dw;
    ++corrections;
    for (const unsigned int i : P)
      largest_correction = std::max(largest_correction, std::abs(dw[dim * i]));
    correction_force = std::move(nu);
  }

  ContactStep
  MixedJointSolver::solve(const Vector &r, const std::vector<double> &w_base, Vector &x)
  {
    const unsigned int m = dim * pairs.size();
    if (rhs.size() != r.size())
      {
        rhs.reinit(r);
        correction.reinit(r);
        corrected_displacement.reinit(r);
      }
    if (C.empty() && m > 0)
      {
        // C is built once, with the first right-hand side's layout
        // (multi-column solves, 64 columns at a time, or from the Schur
        // complement).
        build_time = seconds_of([&] {
          if (const auto *condensed = A_factor.condensed())
            build_from_schur_complement(*condensed);
          else
            C = flexibility_matrix(pairs, A_factor, r, 64,
                                   p.coupling == Coupling::neighbouring_joints);
        });
        augmentation = augmentation_of(C, contact_h());
        C_rows.resize(C.size());
        for (unsigned int j = 0; j < m; ++j)
          for (unsigned int i = 0; i < m; ++i)
            C_rows[static_cast<std::size_t>(i) * m + j] = C[static_cast<std::size_t>(j) * m + i];
      }

    const auto *condensed = A_factor.condensed();
    if (condensed)
      {
        // 1. forward elimination: the interface's response to r at zero
        //    pair forces, z = S^{-1} y; s = w_base + h B z.
        // (room for the position correction's load in a dynamic step)
        condensed->condense(r, interface_x,
                            p.corrects_positions() && !velocity_target.empty());
        condensed->solve_interface(interface_x);
        s.assign(m, 0.);
        for (unsigned int j = 0; j < m; ++j)
          {
            double bz = 0.;
            for (const auto &[g, v] : B_interface[j])
              bz += v * interface_x[g];
            s[j] = w_base[j] + h * bz;
          }
        // the step impulse's load g = omega f - (omega - 1) g_n (§10):
        // s gains (omega - 1) h C g_n
        if (omega != 1.)
          add_flexibility_times((omega - 1.) * h, load_committed, s);
        force = force_committed;
        set_relative_displacement();
      }
    else
      {
        // 1. predictor: the pair loads held at their committed values.
        rhs = r;
        pairs.add_transpose(load_committed, -1., rhs);
        A_factor.solve(x, rhs);
        pairs.relative_displacement(x, w);
        for (unsigned int j = 0; j < m; ++j)
          w[j] = w_base[j] + h * w[j];

        // 2. the contact problem on the pairs: w = s - omega h C f with
        //    s = w + omega h C g_n (the relative displacement at zero pair
        //    forces when omega = 1).
        s = w;
        add_flexibility_times(contact_h(), load_committed, s);
        force = force_committed;
        set_relative_displacement();
      }
    start_solve();

    // Joint by joint, when chosen; if it does not settle, or all pairs at
    // once: the active-set iteration first (exact and fast when the states
    // settle); if it does not, projected Gauss-Seidel from the committed
    // forces, which converges, with the active set tried again on the states
    // it reaches.
    ContactStep                  step;
    const std::vector<bool>      damage_at_start  = damaged;
    const std::vector<double>    opening_at_start = largest_opening;
    const std::vector<PairState> states_at_start  = state;
    const auto                   start_again      = [&] {
      damaged         = damage_at_start;
      largest_opening = opening_at_start;
      state           = states_at_start;
    };
    const bool solved = !by_joint.empty() && joint_by_joint(step);
    if (!by_joint.empty() && !solved)
      {
        ++handed_over;
        start_again();
        force = force_committed;
        set_relative_displacement();
        start_solve();
      }
    if (!solved && !active_set_iteration(step, std::min(p.max_iterations, active_set_limit),
                                         all_pairs, s))
      {
        start_again();
        projected_gauss_seidel(step);
      }
    set_load();
    // (velocity targets: a dynamic step)
    if (p.corrects_positions() && !velocity_target.empty())
      find_position_correction();

    if (condensed)
      {
        // 3. backward substitution from x_Γ = z - G g.
        dealii::Vector<double> f(pair_load.begin(), pair_load.end()), Gf(interface_x.size());
        G.vmult(Gf, f);
        interface_x -= Gf;
        if (correction_force.empty())
          {
            condensed->expand(interface_x, x);
            return step;
          }
        // the position correction's load -B^T nu lies on the interface: its
        // response comes from the same backward substitution
        dealii::Vector<double> q(interface_x.size());
        for (unsigned int j = 0; j < m; ++j)
          for (const auto &[g, v] : B_interface[j])
            q[g] -= v * correction_force[j];
        condensed->expand(interface_x, x, &q, &corrected_displacement);
        return step;
      }

    // 3. corrector: x += A^{-1} (-B^T (g - g_n)).
    std::vector<double> df(m);
    bool                changed = false;
    for (unsigned int j = 0; j < m; ++j)
      {
        df[j]   = pair_load[j] - load_committed[j];
        changed = changed || df[j] != 0.;
      }
    if (changed)
      {
        rhs = 0.;
        pairs.add_transpose(df, -1., rhs);
        A_factor.solve(correction, rhs);
        x += correction;
      }
    if (!correction_force.empty())
      correction_time += seconds_of([&] {
        rhs = 0.;
        pairs.add_transpose(correction_force, -1., rhs);
        A_factor.solve(corrected_displacement, rhs);
      });
    return step;
  }
} // namespace archdam::joints
