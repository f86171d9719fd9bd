// The flexibility matrix C = B A^{-1} B^T of the mixed method
// (doc/theory/joints.md §4): column by column from the factor, or from the
// Schur complement of the pairs' unknowns.
#include <archdam/base/petsc_check.h>
#include <archdam/joints/joint_solver.h>

#include <algorithm>
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

} // namespace archdam::joints
