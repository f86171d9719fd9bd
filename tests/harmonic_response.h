// Shared by the reservoir and modal tests: the steady-state response to a
// harmonic ground acceleration, solved directly in the frequency domain, the
// reference the eigenvalues and the time-domain results are compared with. It
// is built from the library's operators (solid and reservoir modules;
// doc/theory/reservoir.md §9).
#pragma once

#include <archdam/base/types.h>
#include <archdam/fe/fe_space.h>
#include <archdam/physics/reservoir/coupled_system.h>
#include <archdam/physics/reservoir/fluid_operators.h>
#include <archdam/time/factorized_operator.h>

#include <deal.II/base/index_set.h>
#include <deal.II/base/mpi.h>
#include <deal.II/lac/dynamic_sparsity_pattern.h>

#include <algorithm>
#include <utility>
#include <vector>

namespace archdam::testing
{
  /**
   * Solve the complex symmetric system (A + iB)(x_re + i x_im) = f_re + i f_im
   * on the DOFs in @p active (locally owned ones; x = 0 elsewhere) through its
   * real symmetric indefinite form
   *   [[A, -B], [-B, -A]] [x_re; x_im] = [f_re; -f_im],
   * factorized by MUMPS LDL^T (time/factorized_operator.h). A and B share one
   * sparsity pattern.
   */
  inline void
  solve_complex_symmetric(const SparseMatrix     &A,
                          const SparseMatrix     &B,
                          const dealii::IndexSet &active,
                          const Vector           &f_re,
                          const Vector           &f_im,
                          Vector                 &x_re,
                          Vector                 &x_im)
  {
    using namespace dealii;
    const MPI_Comm  comm  = A.get_mpi_communicator();
    const IndexSet  owned = A.locally_owned_range_indices();
    const auto      n     = A.m();
    // Whether a column is active must be known for columns owned elsewhere.
    IndexSet all_active(n);
    for (const auto &part : Utilities::MPI::all_gather(comm, active))
      all_active.add_indices(part);
    all_active.compress();

    // Unknown i becomes rows 2i (real part) and 2i + 1 (imaginary part), so
    // each rank keeps owning a contiguous range.
    IndexSet owned2(2 * n);
    for (const auto i : owned)
      owned2.add_range(2 * i, 2 * i + 2);
    owned2.compress();

    // Row i of A and B (one pattern, so the same columns in the same order),
    // restricted to active columns.
    struct Row
    {
      std::vector<types::global_dof_index> columns;
      std::vector<double>                  a, b;
    };
    std::vector<Row> rows(owned.n_elements());
    for (const auto i : owned)
      if (active.is_element(i))
        {
          Row &row = rows[owned.index_within_set(i)];
          auto it_b = B.begin(i);
          for (auto it = A.begin(i); it != A.end(i); ++it, ++it_b)
            {
              Assert(it_b->column() == it->column(), ExcInternalError());
              if (all_active.is_element(it->column()))
                {
                  row.columns.push_back(it->column());
                  row.a.push_back(it->value());
                  row.b.push_back(it_b->value());
                }
            }
        }

    DynamicSparsityPattern               dsp(2 * n, 2 * n, owned2);
    std::vector<types::global_dof_index> columns2;
    for (const auto i : owned)
      {
        const Row &row = rows[owned.index_within_set(i)];
        columns2.clear();
        for (const auto j : row.columns)
          {
            columns2.push_back(2 * j);
            columns2.push_back(2 * j + 1);
          }
        if (row.columns.empty()) // an inactive unknown: identity, kept symmetric
          columns2 = {2 * i, 2 * i + 1};
        std::sort(columns2.begin(), columns2.end());
        dsp.add_entries(2 * i, columns2.begin(), columns2.end(), true);
        dsp.add_entries(2 * i + 1, columns2.begin(), columns2.end(), true);
      }
    SparseMatrix Z;
    Z.reinit(owned2, owned2, dsp, comm);
    std::vector<double> real_row, imaginary_row;
    for (const auto i : owned)
      {
        const Row &row = rows[owned.index_within_set(i)];
        if (row.columns.empty())
          {
            Z.set(2 * i, 2 * i, 1.);
            Z.set(2 * i + 1, 2 * i + 1, -1.);
            continue;
          }
        columns2.clear();
        real_row.clear();
        imaginary_row.clear();
        for (unsigned int k = 0; k < row.columns.size(); ++k)
          {
            columns2.push_back(2 * row.columns[k]);
            columns2.push_back(2 * row.columns[k] + 1);
            real_row.push_back(row.a[k]); // [A, -B]
            real_row.push_back(-row.b[k]);
            imaginary_row.push_back(-row.b[k]); // [-B, -A]
            imaginary_row.push_back(-row.a[k]);
          }
        Z.set(2 * i, columns2.size(), columns2.data(), real_row.data(), false);
        Z.set(2 * i + 1, columns2.size(), columns2.data(), imaginary_row.data(), false);
      }
    Z.compress(VectorOperation::insert);

    Vector b(owned2, comm), x(owned2, comm);
    for (const auto i : active)
      {
        b(2 * i)     = f_re(i);
        b(2 * i + 1) = -f_im(i);
      }
    b.compress(VectorOperation::insert);

    time::FactorizedOperator solver;
    solver.factorize(Z, false);
    solver.solve(x, b);

    x_re.reinit(owned, comm);
    x_im.reinit(owned, comm);
    for (const auto i : active)
      {
        x_re(i) = x(2 * i);
        x_im(i) = x(2 * i + 1);
      }
    x_re.compress(VectorOperation::insert);
    x_im.compress(VectorOperation::insert);
  }

  /**
   * Steady-state pressure amplitude of the water alone (rigid, fixed solid)
   * under the harmonic ground acceleration a_g(t) = Re(e^{i omega t}) e_d:
   *   (Q - omega^2 G + i omega H) P = -S iota_d   (doc/theory/reservoir.md §9),
   * on the free pressure DOFs.
   */
  inline void
  harmonic_pressure(const fe::FESpace                        &space,
                    const physics::reservoir::FluidOperators &ops,
                    const double                              omega,
                    const unsigned int                        direction,
                    Vector                                   &p_re,
                    Vector                                   &p_im)
  {
    using physics::reservoir::linear_combination;
    SparseMatrix A, B;
    linear_combination(A, {{1., &ops.Q}, {-omega * omega, &ops.G}});
    linear_combination(B, {{omega, &ops.H}});
    Vector f = ops.influence[direction], zero;
    f *= -1.;
    space.reinit(zero);
    solve_complex_symmetric(A, B, physics::reservoir::free_pressure_dofs(space), f, zero, p_re,
                            p_im);
  }

  /**
   * Steady-state response (U, P) of the dam (with its water, if @p water is
   * given) to the harmonic ground acceleration a_g(t) = Re(e^{i omega t}) e_d,
   * relative formulation (doc/theory/reservoir.md §9, doc/theory/foundation.md §2):
   *   (K - omega^2 M + i omega D) U - (1/rho_w) S^T P = -M iota_d,
   *   -omega^2 S U + (Q - omega^2 G + i omega H) P = -S iota_d,
   * D = alpha M + beta K. The water rows are scaled by 1/(omega^2 rho_w),
   * which makes the system complex symmetric (the 2x2-block analogue of the
   * paper's eq. 3.2), and solved by solve_complex_symmetric() on all free
   * DOFs. Used to find the resonances of the dam-water system from a sweep.
   */
  inline void
  harmonic_response(const fe::FESpace                        &space,
                    const SparseMatrix                       &M,
                    const SparseMatrix                       &K,
                    const std::pair<double, double>           rayleigh,
                    const Vector                             &inertia_load, ///< M iota_d
                    const physics::reservoir::FluidOperators *water,
                    const double                              density,
                    const double                              omega,
                    const unsigned int                        direction,
                    Vector                                   &x_re,
                    Vector                                   &x_im)
  {
    using physics::reservoir::linear_combination;
    const auto [alpha, beta] = rayleigh;
    const double w2rho       = omega * omega * density;
    SparseMatrix A, B;
    Vector       f = inertia_load, zero;
    f *= -1.;
    if (water != nullptr)
      {
        linear_combination(A, {{1., &K},
                               {-omega * omega, &M},
                               {-1. / density, &water->S_transpose},
                               {-1. / density, &water->S},
                               {1. / w2rho, &water->Q},
                               {-1. / density, &water->G}});
        linear_combination(B, {{omega * alpha, &M},
                               {omega * beta, &K},
                               {omega / w2rho, &water->H}});
        f.add(-1. / w2rho, water->influence[direction]);
      }
    else
      {
        linear_combination(A, {{1., &K}, {-omega * omega, &M}});
        linear_combination(B, {{omega * alpha, &M}, {omega * beta, &K}});
      }
    dealii::IndexSet free = space.locally_owned;
    dealii::IndexSet constrained(free.size());
    for (const auto i : free)
      if (space.constraints.is_constrained(i))
        constrained.add_index(i);
    free.subtract_set(constrained);
    space.reinit(zero);
    solve_complex_symmetric(A, B, free, f, zero, x_re, x_im);
  }
} // namespace archdam::testing
