#include <archdam/joints/joint_solver.h>

#include <deal.II/lac/lapack_full_matrix.h>
#include <deal.II/lac/vector.h>

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
        augmentation = augmentation_of(C, h);
      }

    // 1. predictor: the pair forces held at their committed values.
    rhs = r;
    pairs.add_transpose(force_committed, -1., rhs);
    A_factor.solve(x, rhs);
    pairs.relative_displacement(x, w);
    for (unsigned int j = 0; j < m; ++j)
      w[j] = w_base[j] + h * w[j];
    force = force_committed;

    // 2. the contact problem on the pairs: w = s - h C f with s = w + h C f_n
    //    the relative displacement at zero pair forces; active-set iteration.
    std::vector<double> s(w);
    for (unsigned int j = 0; j < m; ++j)
      if (force_committed[j] != 0.)
        for (unsigned int k = 0; k < m; ++k)
          s[k] += h * C[static_cast<std::size_t>(j) * m + k] * force_committed[j];
    start_directions();

    ContactStep         step;
    std::vector<double> before;
    std::vector<unsigned int> closed;
    while (step.iterations < p.max_iterations)
      {
        ++step.iterations;
        before = force;
        // The law with the states and directions fixed, on the closed pairs.
        closed.clear();
        for (unsigned int i = 0; i < pairs.size(); ++i)
          if (state[i] != PairState::separation)
            closed.push_back(i);
        const unsigned int        n = dim * closed.size();
        LAPACKFullMatrix<double>  L(n, n);
        dealii::Vector<double>    f(n);
        for (unsigned int a = 0; a < closed.size(); ++a)
          {
            const unsigned int i = closed[a];
            for (unsigned int k = 0; k < dim; ++k)
              {
                const unsigned int row = dim * a + k;
                if (k > 0 && state[i] == PairState::slip)
                  {
                    // f_k - (c A - mu f_xi) d_k = 0
                    const auto strength_i = strength(i);
                    L(row, row)       = 1.;
                    L(row, dim * a)   = strength_i.friction * direction[i][k];
                    f(row)            = strength_i.cohesion_force * direction[i][k];
                    continue;
                  }
                // (h C f)_ik = s_ik - w_target,k
                for (unsigned int b = 0; b < closed.size(); ++b)
                  for (unsigned int l = 0; l < dim; ++l)
                    L(row, dim * b + l) =
                      h * C[static_cast<std::size_t>(dim * closed[b] + l) * m + dim * i + k];
                f(row) = s[dim * i + k] - (k == 0 ? -laws[i].initial_gap : w_committed[dim * i + k]);
              }
          }
        if (n > 0)
          {
            L.compute_lu_factorization();
            L.solve(f);
          }
        std::fill(force.begin(), force.end(), 0.);
        for (unsigned int a = 0; a < closed.size(); ++a)
          for (unsigned int k = 0; k < dim; ++k)
            force[dim * closed[a] + k] = f(dim * a + k);
        w = s;
        for (unsigned int j = 0; j < m; ++j)
          if (force[j] != 0.)
            for (unsigned int k = 0; k < m; ++k)
              w[k] -= h * C[static_cast<std::size_t>(j) * m + k] * force[j];

        bool changed = false;
        for (unsigned int i = 0; i < pairs.size(); ++i)
          changed = update_state(i) || changed;
        step.force_change = relative_change(before);
        step.gap_residual = gap_residual(step.worst_pair);
        if (!changed && step.gap_residual <= p.gap_tolerance)
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
