#include <archdam/joints/joint_solver.h>

#include <chrono>
#include <cmath>

namespace archdam::joints
{
  using namespace dealii;

  namespace
  {
    void
    check(const PetscErrorCode ierr)
    {
      AssertThrow(ierr == 0, ExcPETScError(ierr));
    }

    /// Entries of row k of B for pair i: (global DOF, value) over free DOFs;
    /// w_k = sum value * u[DOF] (side 2 minus side 1, projected on frame k).
    template <typename F>
    void
    for_row_of_B(const NodePair &pair, const unsigned int k, F &&action)
    {
      for (unsigned int c = 0; c < dim; ++c)
        {
          if (pair.free_2[c])
            action(pair.dofs_2[c], pair.frame[k][c]);
          if (pair.free_1[c])
            action(pair.dofs_1[c], -pair.frame[k][c]);
        }
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
        check(MatCreateDense(comm, n_local, PETSC_DECIDE, layout.size(), nb, nullptr, &rhs));
        PetscScalar *a;
        check(MatDenseGetArray(rhs, &a));
        std::fill(a, a + n_local * nb, 0.);
        for (unsigned int j = 0; j < nb; ++j)
          for_row_of_B(pairs[(start + j) / dim], (start + j) % dim,
                       [&](const types::global_dof_index d, const double v) {
                         if (is_owned(d))
                           a[j * n_local + (d - range.first)] += v;
                       });
        check(MatDenseRestoreArray(rhs, &a));
        check(MatAssemblyBegin(rhs, MAT_FINAL_ASSEMBLY));
        check(MatAssemblyEnd(rhs, MAT_FINAL_ASSEMBLY));
        check(MatDuplicate(rhs, MAT_DO_NOT_COPY_VALUES, &solution));
        A_factor.solve(solution, rhs);

        // Columns of C: B A^{-1} B^T e_j, the owners' parts summed over ranks.
        std::vector<double> block(static_cast<std::size_t>(m) * nb, 0.);
        const PetscScalar  *x;
        check(MatDenseGetArrayRead(solution, &x));
        for (unsigned int j = 0; j < nb; ++j)
          for (unsigned int i = 0; i < pairs.size(); ++i)
            for (unsigned int k = 0; k < dim; ++k)
              for_row_of_B(pairs[i], k, [&](const types::global_dof_index d, const double v) {
                if (is_owned(d))
                  block[j * m + dim * i + k] += v * x[j * n_local + (d - range.first)];
              });
        check(MatDenseRestoreArrayRead(solution, &x));
        check(MatDestroy(&rhs));
        check(MatDestroy(&solution));
        Utilities::MPI::sum(block, comm, block);
        std::copy(block.begin(), block.end(), C.begin() + static_cast<std::size_t>(start) * m);
      }

    if (neighbours_only)
      for (unsigned int j = 0; j < m; ++j)
        for (unsigned int i = 0; i < m; ++i)
          if (std::abs(static_cast<int>(pairs[i / dim].joint) -
                       static_cast<int>(pairs[j / dim].joint)) > 1)
            C[static_cast<std::size_t>(j) * m + i] = 0.;
    return C;
  }

  MixedJointSolver::MixedJointSolver(const JointParameters &p, const NodePairs &pairs,
                                     const double h, const time::FactorizedOperator &A_factor)
    : JointSolver(p, pairs, h)
    , A_factor(A_factor)
  {}

  ContactStep
  MixedJointSolver::solve(const Vector &r, const std::vector<double> &w_base, Vector &x)
  {
    const unsigned int m = dim * pairs.size();
    if (rhs.size() != r.size())
      {
        rhs.reinit(r);
        correction.reinit(r);
      }
    if (C.empty() && m > 0)
      {
        // C is built once, with the first right-hand side's layout
        // (multi-column solves, 64 columns at a time).
        const auto start = std::chrono::steady_clock::now();
        C = flexibility_matrix(pairs, A_factor, r, 64, p.coupling == "neighbouring joints");
        build_time =
          std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
      }

    // 1. predictor: the pair forces held at their committed values.
    rhs = r;
    pairs.add_transpose(force_committed, -1., rhs);
    A_factor.solve(x, rhs);
    pairs.relative_displacement(x, w);
    for (unsigned int j = 0; j < m; ++j)
      w[j] = w_base[j] + h * w[j];
    force = force_committed;

    // 2. the contact problem on the pairs: w = w_bar - h C (f - f_n), projected
    //    block Gauss-Seidel, each pair solving its own law with the others frozen.
    ContactStep         step;
    std::vector<double> before;
    while (step.iterations < p.max_iterations)
      {
        ++step.iterations;
        before = force;
        for (unsigned int i = 0; i < pairs.size(); ++i)
          {
            Tensor<2, dim> A_ii;
            Tensor<1, dim> s, w_prev, f;
            for (unsigned int a = 0; a < dim; ++a)
              {
                for (unsigned int b = 0; b < dim; ++b)
                  A_ii[a][b] = h * C[static_cast<std::size_t>(dim * i + b) * m + dim * i + a];
                w_prev[a] = w_committed[dim * i + a];
              }
            for (unsigned int a = 0; a < dim; ++a)
              {
                s[a] = w[dim * i + a];
                for (unsigned int b = 0; b < dim; ++b)
                  s[a] += A_ii[a][b] * force[dim * i + b];
              }
            state[i] = solve_pair(A_ii, s, w_prev, laws[i].initial_gap, strength(i), f);
            for (unsigned int b = 0; b < dim; ++b)
              {
                const double df = f[b] - force[dim * i + b];
                if (df == 0.)
                  continue;
                const double *column = &C[static_cast<std::size_t>(dim * i + b) * m];
                for (unsigned int j = 0; j < m; ++j)
                  w[j] -= h * column[j] * df;
                force[dim * i + b] = f[b];
              }
          }
        step.force_change = relative_change(before);
        step.gap_residual = gap_residual(step.worst_pair);
        if (step.force_change <= p.force_tolerance && step.gap_residual <= p.gap_tolerance)
          {
            step.converged = true;
            break;
          }
      }

    // 3. corrector: x += A^{-1} (-B^T (f - f_n)).
    std::vector<double> df(m);
    bool                changed = false;
    for (unsigned int j = 0; j < m; ++j)
      {
        df[j]   = force[j] - force_committed[j];
        changed = changed || df[j] != 0.;
      }
    if (changed)
      {
        rhs = 0.;
        pairs.add_transpose(df, -1., rhs);
        A_factor.solve(correction, rhs);
        x += correction;
      }
    return step;
  }
} // namespace archdam::joints
