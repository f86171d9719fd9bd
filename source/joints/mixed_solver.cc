#include <archdam/base/petsc_check.h>
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

  namespace
  {
    /// The paper's sparse approximation of C: the coupling of pairs on
    /// joints more than one apart dropped.
    void
    keep_neighbouring_joints(const NodePairs &pairs, std::vector<double> &C)
    {
      const unsigned int m = dim * pairs.size();
      for (unsigned int j = 0; j < m; ++j)
        for (unsigned int i = 0; i < m; ++i)
          if (std::abs(static_cast<int>(pairs[i / dim].joint) -
                       static_cast<int>(pairs[j / dim].joint)) > 1)
            C[static_cast<std::size_t>(j) * m + i] = 0.;
    }
  } // namespace

  std::vector<double>
  flexibility_matrix(const NodePairs &pairs, const time::FactorizedOperator &A_factor,
                     const Vector &layout, const unsigned int block_size,
                     const bool neighbours_only)
  {
    const unsigned int m        = dim * pairs.size();
    const auto         range    = layout.local_range();
    const auto         n_local  = range.second - range.first;
    const auto         is_owned = [&](const types::global_dof_index d) {
      return d >= range.first && d < range.second;
    };
    MPI_Comm comm = pairs.communicator();
    std::vector<double> C(static_cast<std::size_t>(m) * m, 0.);

    for (unsigned int start = 0; start < m; start += block_size)
      {
        const unsigned int nb = std::min(block_size, m - start);
        // Right-hand sides B^T e_j, j = start ... start + nb - 1.
        Mat rhs, solution;
        petsc_check(MatCreateDense(comm, n_local, PETSC_DECIDE, layout.size(), nb, nullptr, &rhs));
        PetscScalar *a;
        petsc_check(MatDenseGetArray(rhs, &a));
        std::fill(a, a + n_local * nb, 0.);
        for (unsigned int j = 0; j < nb; ++j)
          pairs[(start + j) / dim].for_each_B_entry((start + j) % dim,
                       [&](const types::global_dof_index d, const double v) {
                         if (is_owned(d))
                           a[j * n_local + (d - range.first)] += v;
                       });
        petsc_check(MatDenseRestoreArray(rhs, &a));
        petsc_check(MatAssemblyBegin(rhs, MAT_FINAL_ASSEMBLY));
        petsc_check(MatAssemblyEnd(rhs, MAT_FINAL_ASSEMBLY));
        petsc_check(MatDuplicate(rhs, MAT_DO_NOT_COPY_VALUES, &solution));
        A_factor.solve(solution, rhs);

        // Columns of C: B A^{-1} B^T e_j, the owners' parts summed over ranks.
        std::vector<double> block(static_cast<std::size_t>(m) * nb, 0.);
        const PetscScalar  *x;
        petsc_check(MatDenseGetArrayRead(solution, &x));
        for (unsigned int j = 0; j < nb; ++j)
          for (unsigned int i = 0; i < pairs.size(); ++i)
            for (unsigned int k = 0; k < dim; ++k)
              pairs[i].for_each_B_entry(k, [&](const types::global_dof_index d, const double v) {
                if (is_owned(d))
                  block[j * m + dim * i + k] += v * x[j * n_local + (d - range.first)];
              });
        petsc_check(MatDenseRestoreArrayRead(solution, &x));
        petsc_check(MatDestroy(&rhs));
        petsc_check(MatDestroy(&solution));
        Utilities::MPI::sum(block, comm, block);
        std::copy(block.begin(), block.end(), C.begin() + static_cast<std::size_t>(start) * m);
      }

    if (neighbours_only)
      keep_neighbouring_joints(pairs, C);
    return C;
  }

  std::vector<double>
  augmentation_of(const std::vector<double> &C, const double h)
  {
    const unsigned int  m = std::lround(std::sqrt(static_cast<double>(C.size())));
    std::vector<double> r(m / dim);
    for (unsigned int i = 0; i < r.size(); ++i)
      {
        const auto diagonal = [&](const unsigned int k) {
          return C[static_cast<std::size_t>(dim * i + k) * m + dim * i + k];
        };
        r[i] = 2. / (h * (diagonal(1) + diagonal(2)));
      }
    return r;
  }

  MixedJointSolver::MixedJointSolver(const JointParameters &p, const NodePairs &pairs,
                                     const double h, const time::FactorizedOperator &A_factor)
    : JointSolver(p, pairs, h)
    , A_factor(A_factor)
  {}

  void
  MixedJointSolver::build_from_schur_complement(const time::CondensedFactorization &condensed)
  {
    const unsigned int m     = dim * pairs.size();
    const auto        &gamma = condensed.interface();
    B_interface.assign(m, {});
    for (unsigned int j = 0; j < m; ++j)
      pairs[j / dim].for_each_B_entry(j % dim, [&](const types::global_dof_index d,
                                                   const double v) {
        const auto g = std::lower_bound(gamma.begin(), gamma.end(), d) - gamma.begin();
        AssertThrow(g < static_cast<long>(gamma.size()) && gamma[g] == d,
                    ExcMessage("The factorization is condensed on other DOFs than the "
                               "node pairs'."));
        B_interface[j].emplace_back(static_cast<unsigned int>(g), v);
      });

    // G = S^{-1} B^T, C = B G (doc/theory/joints.md §4: C = B A^{-1} B^T, since the
    // load B^T f lies on the interface).
    const unsigned int k = gamma.size();
    G.reinit(k, m);
    for (unsigned int j = 0; j < m; ++j)
      for (const auto &[g, v] : B_interface[j])
        G(g, j) += v;
    condensed.solve_interface(G);
    C.assign(static_cast<std::size_t>(m) * m, 0.);
    for (unsigned int j = 0; j < m; ++j)
      for (unsigned int i = 0; i < m; ++i)
        for (const auto &[g, v] : B_interface[i])
          C[static_cast<std::size_t>(j) * m + i] += v * G(g, j);
    if (p.coupling == Coupling::neighbouring_joints)
      keep_neighbouring_joints(pairs, C);
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
  MixedJointSolver::solve_with_fixed_states()
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
    // the slip increment is small against tau / r.
    //
    // One row per pair unknown (3 n_pairs, the open pairs' rows f = 0), so
    // that a change of a few pairs' states or slip directions changes a few
    // rows: the LU of the system as it was at its last factorization (the
    // base A0) is kept, and the rows R that changed since are taken in by
    // the Sherman-Morrison-Woodbury formula (doc/theory/joints.md §6):
    //   A = A0 + E_R dR,  Z = A0^{-1} E_R (kept per row while A0 is),
    //   x = y - Z T^{-1} t,  y = A0^{-1} b,  T = I + dR Z = A_R Z,
    //   t = dR y = A_R y - b_R
    // (A_R the new rows; A0_R Z = I and A0_R y = b_R). A0 is refactorized
    // when R grows beyond max_update_rows.
    const unsigned int m = dim * pairs.size();
    if (m == 0)
      return;
    // (h C)(row, j), from C by rows.
    const double hc          = contact_h();
    const auto   flexibility = [&](const unsigned int j, const unsigned int row) {
      return hc * C_rows[static_cast<std::size_t>(row) * m + j];
    };
    // Row dim i + k of the system from the pair's current state, in parts:
    //   row = sum_l flex[l] (h C)(dim i + l, .) + sum_l own[l] e_{dim i + l},
    // rows of h C with coefficients plus entries on the pair's own unknowns,
    // and its right-hand side.
    struct RowParts
    {
      std::array<double, dim> flex{}, own{};
      double                  rhs = 0.;
    };
    const auto row_parts = [&](const unsigned int i, const unsigned int k) {
      const unsigned int r_ik = dim * i + k;
      RowParts           parts;
      if (state[i] == PairState::separation)
        {
          // f = 0, scaled like the flexibility rows (metres) for the pivoting
          parts.own[k] = flexibility(r_ik, r_ik);
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
              parts.rhs += kappa * P(k, l) * (s[dim * i + l] - target[dim * i + l]);
            }
          parts.own[0] = strength_i.friction * d[k] / r;
          return parts;
        }
      // (h C f)_ik = s_ik - w_target,k
      parts.flex[k] = 1.;
      parts.rhs     = s[r_ik] - target[r_ik];
      return parts;
    };
    const auto system_row = [&](const unsigned int i, const RowParts &parts, double *row) {
      std::fill(row, row + m, 0.);
      for (unsigned int l = 0; l < dim; ++l)
        if (parts.flex[l] != 0.)
          for (unsigned int j = 0; j < m; ++j)
            row[j] += parts.flex[l] * flexibility(j, dim * i + l);
      for (unsigned int l = 0; l < dim; ++l)
        row[dim * i + l] += parts.own[l];
    };
    // What a pair's rows depend on besides C, h and r.
    const auto rows_of = [&](const unsigned int i) {
      RowsOfPair rows{state[i], {}, 0., 0.};
      if (state[i] == PairState::slip)
        {
          rows.direction = direction[i];
          rows.kappa     = slip_ratio[i];
          rows.friction  = strength(i).friction;
        }
      return rows;
    };

    // The rows that changed, ascending: the normal row is the flexibility
    // row in stick and slip alike, and changes only with a separation.
    std::vector<unsigned int> changed;
    if (base_rows.size() == pairs.size())
      for (unsigned int i = 0; i < pairs.size(); ++i)
        if (!(rows_of(i) == base_rows[i]))
          for (unsigned int k = 0; k < dim; ++k)
            if (k > 0 || (state[i] == PairState::separation) !=
                           (base_rows[i].state == PairState::separation))
              changed.push_back(dim * i + k);
    if (base_rows.size() != pairs.size() || changed.size() > max_update_rows(m))
      {
        base.reinit(m, m);
        std::vector<double> row(m);
        base_rows.resize(pairs.size());
        for (unsigned int i = 0; i < pairs.size(); ++i)
          {
            for (unsigned int k = 0; k < dim; ++k)
              {
                system_row(i, row_parts(i, k), row.data());
                for (unsigned int j = 0; j < m; ++j)
                  base(dim * i + k, j) = row[j];
              }
            base_rows[i] = rows_of(i);
          }
        base.compute_lu_factorization();
        ++factorizations;
        update_columns.assign(m, {});
        changed.clear();
      }

    const unsigned int     n_changed = changed.size();
    dealii::Vector<double> b(m);
    std::vector<RowParts>  changed_parts(n_changed);
    for (unsigned int i = 0, a = 0; i < pairs.size(); ++i)
      for (unsigned int k = 0; k < dim; ++k)
        {
          const unsigned int r_ik  = dim * i + k;
          const RowParts     parts = row_parts(i, k);
          b(r_ik)                  = parts.rhs;
          if (a < n_changed && changed[a] == r_ik)
            changed_parts[a++] = parts;
        }
    dealii::Vector<double> x(b);
    base.solve(x); // y
    if (n_changed > 0)
      {
        ++updated_solves;
        // Z's missing columns, in one multi-column solve.
        std::vector<unsigned int> missing;
        for (const unsigned int j : changed)
          if (update_columns[j].size() == 0)
            missing.push_back(j);
        if (!missing.empty())
          {
            dealii::LAPACKFullMatrix<double> Z(m, missing.size());
            for (unsigned int c = 0; c < missing.size(); ++c)
              Z(missing[c], c) = 1.;
            base.solve(Z);
            for (unsigned int c = 0; c < missing.size(); ++c)
              {
                update_columns[missing[c]].reinit(m);
                for (unsigned int j = 0; j < m; ++j)
                  update_columns[missing[c]](j) = Z(j, c);
              }
          }
        // T = A_R Z and t = A_R y - b_R. Where a new row's rows of h C are
        // rows of the base (a pair that the base has in stick, or a normal
        // row), A0_r Z = (E_R)_r and A0_r y = b_r give those parts without a
        // product: such a row (a slipping pair that the base has stuck, a
        // separated pair, a pair slipping with kappa = 0) costs its own few
        // entries of Z and y; the other rows are built and multiplied by Z.
        const auto base_row_is_flexibility = [&](const unsigned int i, const unsigned int l) {
          return base_rows[i].state == PairState::stick ||
                 (base_rows[i].state == PairState::slip && l == 0);
        };
        std::vector<int> position(m, -1);
        for (unsigned int a = 0; a < n_changed; ++a)
          position[changed[a]] = a;
        const auto Z_entry = [&](const unsigned int j, const unsigned int c) {
          return update_columns[changed[c]](j);
        };
        dealii::LAPACKFullMatrix<double> T(n_changed, n_changed);
        dealii::Vector<double>           t(n_changed);
        std::vector<unsigned int>        products; // rows of R multiplied by Z
        for (unsigned int a = 0; a < n_changed; ++a)
          {
            const unsigned int i     = changed[a] / dim;
            const RowParts    &parts = changed_parts[a];
            bool               cheap = true;
            for (unsigned int l = 0; l < dim; ++l)
              cheap = cheap && (parts.flex[l] == 0. || base_row_is_flexibility(i, l));
            if (!cheap)
              {
                products.push_back(a);
                continue;
              }
            t(a) = -b(changed[a]);
            for (unsigned int l = 0; l < dim; ++l)
              {
                const unsigned int r_il = dim * i + l;
                if (parts.flex[l] != 0.)
                  {
                    t(a) += parts.flex[l] * b(r_il);
                    if (position[r_il] >= 0)
                      T(a, position[r_il]) += parts.flex[l];
                  }
                if (parts.own[l] != 0.)
                  {
                    t(a) += parts.own[l] * x(r_il);
                    for (unsigned int c = 0; c < n_changed; ++c)
                      T(a, c) += parts.own[l] * Z_entry(r_il, c);
                  }
              }
          }
        if (!products.empty())
          {
            const unsigned int               n_products = products.size();
            dealii::LAPACKFullMatrix<double> A_P(n_products, m), Z(m, n_changed),
              T_P(n_products, n_changed);
            std::vector<double> row(m);
            for (unsigned int p = 0; p < n_products; ++p)
              {
                const unsigned int a = products[p];
                system_row(changed[a] / dim, changed_parts[a], row.data());
                double y_a = 0.;
                for (unsigned int j = 0; j < m; ++j)
                  {
                    A_P(p, j) = row[j];
                    y_a += row[j] * x(j);
                  }
                t(a) = y_a - b(changed[a]);
              }
            for (unsigned int c = 0; c < n_changed; ++c)
              for (unsigned int j = 0; j < m; ++j)
                Z(j, c) = Z_entry(j, c);
            A_P.mmult(T_P, Z);
            for (unsigned int p = 0; p < n_products; ++p)
              for (unsigned int c = 0; c < n_changed; ++c)
                T(products[p], c) = T_P(p, c);
          }
        T.compute_lu_factorization();
        T.solve(t);
        for (unsigned int a = 0; a < n_changed; ++a)
          x.add(-t(a), update_columns[changed[a]]);
      }
    for (unsigned int j = 0; j < m; ++j)
      force[j] = x(j);
    for (unsigned int i = 0; i < pairs.size(); ++i)
      if (state[i] == PairState::separation) // exactly 0, not round-off
        std::fill(&force[dim * i], &force[dim * i] + dim, 0.);
    set_relative_displacement();
  }

  void
  MixedJointSolver::forget_factorization()
  {
    base_rows.clear();
    update_columns.clear();
  }

  bool
  MixedJointSolver::active_set_iteration(ContactStep &step, const unsigned int limit)
  {
    std::vector<double> before;
    // How often the iteration has come to each set of states (with the
    // damage) from another: one come to for the cycle_visits-th time means
    // the iteration cycles, typically one pair opening and closing in turn
    // while the slipping pairs' directions move (doc/theory/joints.md §6).
    // Iterations that keep the states and only turn slip directions are not
    // visits.
    const auto states_now = [&] {
      std::vector<unsigned char> s(pairs.size());
      for (unsigned int i = 0; i < pairs.size(); ++i)
        s[i] = 2 * static_cast<unsigned char>(state[i]) + (damaged[i] ? 1 : 0);
      return s;
    };
    std::map<std::vector<unsigned char>, unsigned int> visits;
    std::vector<unsigned char>                         previous = states_now();
    for (unsigned int k = 0; k < limit; ++k)
      {
        ++step.iterations;
        before = force;
        solve_with_fixed_states();
        bool changed = false;
        for (unsigned int i = 0; i < pairs.size(); ++i)
          changed = update_state(i) || changed;
        // The Newton step meets the slip law f_t = tau q / |q| only at
        // convergence: a slipping pair whose force is off it by more than
        // Force tolerance, relative to the largest pair force (the scale of
        // the force change below, and of the round-off of the dense solve:
        // relative to a weakly loaded pair's own force the test asked for
        // more digits than the solve has), is not converged.
        const double force_scale = largest_pair_force();
        for (unsigned int i = 0; i < pairs.size() && !changed; ++i)
          if (state[i] == PairState::slip)
            {
              const double *f   = &force[dim * i];
              const double  tau = strength(i).shear_capacity(f[0]);
              changed = std::hypot(f[1] - tau * direction[i][1], f[2] - tau * direction[i][2]) >
                        p.force_tolerance * force_scale;
            }
        step.force_change = relative_change(before);
        step.gap_residual = gap_residual(step.worst_pair);
        if (!changed && step.gap_residual <= p.gap_tolerance)
          return step.converged = true;
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
        if (active_set_iteration(step, active_set_polish))
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
        condensed->condense(r, interface_x);
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

    // The active-set iteration first (exact and fast when the states settle);
    // if it does not, projected Gauss-Seidel from the committed forces, which
    // converges, with the active set tried again on the states it reaches.
    ContactStep                  step;
    const std::vector<bool>      damage_at_start  = damaged;
    const std::vector<double>    opening_at_start = largest_opening;
    const std::vector<PairState> states_at_start  = state;
    if (!active_set_iteration(step, std::min(p.max_iterations, active_set_limit)))
      {
        damaged         = damage_at_start;
        largest_opening = opening_at_start;
        state           = states_at_start;
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
        condensed->expand(interface_x, x);
        if (!correction_force.empty())
          {
            // the position correction's load -B^T nu lies on the interface
            correction_time += seconds_of([&] {
              dealii::Vector<double> q(interface_x.size());
              for (unsigned int j = 0; j < m; ++j)
                for (const auto &[g, v] : B_interface[j])
                  q[g] -= v * correction_force[j];
              condensed->solve_interface_load(q, corrected_displacement);
            });
          }
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
