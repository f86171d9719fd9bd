#include <archdam/base/input_error.h>
#include <archdam/base/petsc_check.h>
#include <archdam/joints/joint_solver.h>

#include <cmath>
#include <sstream>

namespace archdam::joints
{
  using namespace dealii;

  MonolithicJointSolver::MonolithicJointSolver(const JointParameters &p, const NodePairs &pairs,
                                               const double h, const SparseMatrix &A,
                                               const time::FactorizedOperator &A_factor)
    : JointSolver(p, pairs, h)
    , A(A)
    , A_factor(A_factor)
  {
    // kappa h = Penalty factor x the largest diagonal entry of A.
    Vector diagonal;
    diagonal.reinit(A.locally_owned_range_indices(), A.get_mpi_communicator());
    petsc_check(MatGetDiagonal(static_cast<Mat>(A), static_cast<const Vec &>(diagonal)));
    kappa = p.penalty_factor * diagonal.linfty_norm() / h;

    // A with zero entries coupling the two sides of every pair, once.
    petsc_check(MatDuplicate(static_cast<Mat>(A), MAT_COPY_VALUES, &pattern));
    petsc_check(MatSetOption(pattern, MAT_NEW_NONZERO_ALLOCATION_ERR, PETSC_FALSE));
    const IndexSet owned = A.locally_owned_range_indices();
    for (unsigned int i = 0; i < pairs.size(); ++i)
      {
        std::vector<PetscInt> dofs;
        for (const auto &[d, v] : pairs[i].B_row(0))
          dofs.push_back(d);
        for (const auto &[d, v] : pairs[i].B_row(1))
          dofs.push_back(d);
        std::sort(dofs.begin(), dofs.end());
        dofs.erase(std::unique(dofs.begin(), dofs.end()), dofs.end());
        const std::vector<PetscScalar> zeros(dofs.size(), 0.);
        for (const PetscInt row : dofs)
          if (owned.is_element(row))
            petsc_check(MatSetValues(pattern, 1, &row, dofs.size(), dofs.data(),
                                     zeros.data(), ADD_VALUES));
      }
    petsc_check(MatAssemblyBegin(pattern, MAT_FINAL_ASSEMBLY));
    petsc_check(MatAssemblyEnd(pattern, MAT_FINAL_ASSEMBLY));
  }

  MonolithicJointSolver::~MonolithicJointSolver()
  {
    if (pattern != nullptr)
      MatDestroy(&pattern);
  }

  ContactStep
  MonolithicJointSolver::solve(const Vector &r, const std::vector<double> &w_base, Vector &x)
  {
    const IndexSet owned = A.locally_owned_range_indices();
    const unsigned int n = pairs.size();
    if (augmentation.empty())
      augmentation = augmentation_of(flexibility_matrix(pairs, A_factor, r, 64, false), h);
    start_solve();
    force = force_committed;
    Vector rhs;
    rhs.reinit(r);

    ContactStep         step;
    std::vector<double> before;
    while (step.iterations < p.max_iterations)
      {
        ++step.iterations;
        before = force;
        // The penalized system for the current states:
        //   (A + kappa h sum b b^T) x = r - kappa sum (w_base - w*) b - B^T f_slip.
        Mat matrix;
        petsc_check(MatDuplicate(pattern, MAT_COPY_VALUES, &matrix));
        rhs = r;
        std::vector<types::global_dof_index> rhs_index;
        std::vector<double>                  rhs_value;
        for (unsigned int i = 0; i < n; ++i)
          {
            if (state[i] == PairState::separation)
              continue;
            const unsigned int n_constrained = state[i] == PairState::stick ? dim : 1;
            for (unsigned int k = 0; k < n_constrained; ++k)
              {
                const double w_target = target[dim * i + k];
                const auto b = pairs[i].B_row(k);
                for (const auto &[row, v_row] : b)
                  if (owned.is_element(row))
                    {
                      for (const auto &[col, v_col] : b)
                        {
                          const PetscInt    ir = row, ic = col;
                          const PetscScalar value = kappa * h * v_row * v_col;
                          petsc_check(MatSetValues(matrix, 1, &ir, 1, &ic, &value, ADD_VALUES));
                        }
                      rhs_index.push_back(row);
                      rhs_value.push_back(-kappa * (w_base[dim * i + k] - w_target) * v_row);
                    }
              }
            if (state[i] == PairState::slip)
              {
                const double tau = strength(i).shear_capacity(force[dim * i]);
                for (const unsigned int k : {1u, 2u})
                  for (const auto &[row, v_row] : pairs[i].B_row(k))
                    if (owned.is_element(row))
                      {
                        rhs_index.push_back(row);
                        rhs_value.push_back(-tau * direction[i][k] * v_row);
                      }
              }
          }
        petsc_check(MatAssemblyBegin(matrix, MAT_FINAL_ASSEMBLY));
        petsc_check(MatAssemblyEnd(matrix, MAT_FINAL_ASSEMBLY));
        rhs.add(rhs_index, rhs_value);
        rhs.compress(VectorOperation::add);
        {
          time::FactorizedOperator factor;
          factor.factorize(matrix, true);
          petsc_check(MatDestroy(&matrix)); // the factorization keeps its own reference
          factor.solve(x, rhs);
        }
        // A non-finite solution of a finite load is the penalty's doing; a
        // non-finite load (a run that diverged) is left to the step checks,
        // which report the time and place.
        if (std::isfinite(r.linfty_norm()) && !std::isfinite(x.linfty_norm()))
          {
            std::ostringstream message;
            message << "Contraction joints: the monolithic solver's penalized matrix could "
                       "not be solved (the solution is not finite): Penalty factor = "
                    << p.penalty_factor
                    << " makes it too ill-conditioned for this model; use a smaller one "
                       "(1e4 ... 1e6).";
            throw InputError(message.str());
          }

        // Forces from the springs and the friction loads; new states.
        pairs.relative_displacement(x, w);
        for (unsigned int j = 0; j < dim * n; ++j)
          w[j] = w_base[j] + h * w[j];
        bool states_changed = false;
        for (unsigned int i = 0; i < n; ++i)
          {
            double *f = &force[dim * i];
            if (state[i] == PairState::separation)
              std::fill(f, f + dim, 0.);
            else
              {
                f[0] = kappa * closure(i);
                if (state[i] == PairState::stick)
                  for (const unsigned int k : {1u, 2u})
                    f[k] = kappa * (w[dim * i + k] - target[dim * i + k]);
                else
                  for (const unsigned int k : {1u, 2u})
                    f[k] = strength(i).shear_capacity(f[0]) * direction[i][k];
              }
            states_changed = update_state(i) || states_changed;
          }
        step.force_change = relative_change(before);
        step.gap_residual = gap_residual(step.worst_pair);
        if (!states_changed && step.iterations > 1 && step.force_change <= p.force_tolerance)
          {
            step.converged = true;
            break;
          }
      }
    set_load();
    return step;
  }
} // namespace archdam::joints
