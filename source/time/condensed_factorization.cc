#include <archdam/base/petsc_check.h>
#include <archdam/time/condensed_factorization.h>
#include <archdam/time/fill_reducing_order.h>

#include <deal.II/base/mpi.h>
#include <deal.II/lac/exceptions.h>

#include <dmumps_c.h>
#include <smumps_c.h>

#include <algorithm>
#include <cmath>
#include <string>

namespace archdam::time
{
  using namespace dealii;

  namespace
  {
    /// MUMPS's C interface in the arithmetic of the factor.
    template <typename Real>
    struct MumpsInterface;

    template <>
    struct MumpsInterface<double>
    {
      using Struc = DMUMPS_STRUC_C;
      static void
      call(Struc &id)
      {
        dmumps_c(&id);
      }
    };

    template <>
    struct MumpsInterface<float>
    {
      using Struc = SMUMPS_STRUC_C;
      static void
      call(Struc &id)
      {
        smumps_c(&id);
      }
    };
  } // namespace

  /// One MUMPS instance whose factor, right-hand sides and Schur complement
  /// are of type Real (double, or float for a single-precision factor: the
  /// values are rounded on the way in and widened on the way out).
  template <typename Real>
  struct CondensedFactorization::Mumps
  {
    typename MumpsInterface<Real>::Struc id{};
    MPI_Comm       comm = MPI_COMM_NULL;
    /// Gathers a distributed vector on rank 0 and scatters it back (a
    /// second vector on rank 0 for the second right-hand side's solution).
    VecScatter to_zero = nullptr;
    Vec        on_zero = nullptr, second_on_zero = nullptr;
    std::vector<MUMPS_INT> irn, jcn, schur_list, perm;
    std::vector<Real>      values, schur, rhs, reduced;
    /// The right-hand sides of the last condensation: 1, or 2 with the
    /// interface load's column.
    MUMPS_INT columns = 1;
    /// The symmetric scaling D = diag(|a_ii|^(-1/2)) of every unknown (on
    /// every rank): MUMPS factorizes D A D, whose diagonal entries are ±1.
    std::vector<double> scaling;
    MUMPS_INT &
    icntl(const unsigned int k)
    {
      return id.icntl[k - 1];
    }

    /// One MUMPS call; a failure names the phase and MUMPS's codes.
    void
    run(const int job, const char *phase)
    {
      id.job = job;
      MumpsInterface<Real>::call(id);
      AssertThrow(id.infog[0] >= 0,
                  ExcMessage(std::string("MUMPS failed in the ") + phase +
                             " of the condensed factorization: INFOG(1) = " +
                             std::to_string(id.infog[0]) +
                             ", INFOG(2) = " + std::to_string(id.infog[1])));
    }

    ~Mumps()
    {
      if (id.job != 0)
        {
          id.job = -2;
          MumpsInterface<Real>::call(id);
        }
      if (to_zero != nullptr)
        VecScatterDestroy(&to_zero);
      if (on_zero != nullptr)
        VecDestroy(&on_zero);
      if (second_on_zero != nullptr)
        VecDestroy(&second_on_zero);
    }
  };

  CondensedFactorization::CondensedFactorization(
    const SparseMatrix &A, const bool positive_definite,
    const std::vector<dealii::types::global_dof_index> &interface, const Ordering ordering,
    const double low_rank_tolerance, const Precision precision)
    : gamma(interface)
  {
    // The interface (NodePairs::interface()): sorted, unique, rows of A.
    AssertThrow(std::is_sorted(gamma.begin(), gamma.end()) &&
                  std::adjacent_find(gamma.begin(), gamma.end()) == gamma.end() &&
                  (gamma.empty() || gamma.back() < A.m()),
                ExcMessage("The condensed interface must be sorted, unique DOFs of the matrix."));
    AssertThrow(low_rank_tolerance >= 0.,
                ExcMessage("The low-rank tolerance of a factorization must not be negative."));
    if (precision == Precision::single_precision)
      factorize(*mumps.emplace<std::unique_ptr<Mumps<float>>>(std::make_unique<Mumps<float>>()),
                A, positive_definite, ordering, low_rank_tolerance);
    else
      factorize(*mumps.emplace<std::unique_ptr<Mumps<double>>>(std::make_unique<Mumps<double>>()),
                A, positive_definite, ordering, low_rank_tolerance);
  }

  template <typename Real>
  void
  CondensedFactorization::factorize(Mumps<Real> &m, const SparseMatrix &A,
                                    const bool positive_definite, const Ordering ordering,
                                    const double low_rank_tolerance)
  {
    m.comm          = A.get_mpi_communicator();
    const bool host = Utilities::MPI::this_mpi_process(m.comm) == 0;
    const auto k    = static_cast<MUMPS_INT>(gamma.size());

    m.id.sym          = positive_definite ? 1 : 2;
    m.id.par          = 1;
    m.id.comm_fortran = static_cast<MUMPS_INT>(MPI_Comm_c2f(m.comm));
    m.run(-1, "initialization");
    m.icntl(1) = -1; // no messages: failures are reported through INFOG
    m.icntl(2) = -1;
    m.icntl(3) = -1;
    m.icntl(4) = 0;
    m.icntl(18) = 3; // the matrix distributed by the owners of its rows
    m.icntl(20) = 0; // dense right-hand side on rank 0
    m.icntl(21) = 0; // and the solution there

    // The locally owned rows, one triangle (MUMPS sums symmetric duplicates).
    const Mat mat = static_cast<const Mat &>(A);
    PetscInt  first, last;
    petsc_check(MatGetOwnershipRange(mat, &first, &last));
    std::vector<double> owned_scaling, values; // the values scaled and rounded below
    for (PetscInt row = first; row < last; ++row)
      {
        PetscInt           n_cols;
        const PetscInt    *cols;
        const PetscScalar *vals;
        petsc_check(MatGetRow(mat, row, &n_cols, &cols, &vals));
        double diagonal = 0.;
        for (PetscInt c = 0; c < n_cols; ++c)
          if (cols[c] >= row)
            {
              m.irn.push_back(static_cast<MUMPS_INT>(row + 1));
              m.jcn.push_back(static_cast<MUMPS_INT>(cols[c] + 1));
              values.push_back(vals[c]);
              if (cols[c] == row)
                diagonal = std::abs(vals[c]);
            }
        owned_scaling.push_back(diagonal > 0. ? 1. / std::sqrt(diagonal) : 1.);
        petsc_check(MatRestoreRow(mat, row, &n_cols, &cols, &vals));
      }
    // The symmetric scaling D A D (doc/performance.md §8): the coupled
    // matrix's water rows are some 1e19 times smaller than the solid's, and
    // a factorization unaware of it loses digits (and block low-rank
    // compression, whose dropping tolerance is absolute, drops the water
    // whole). The ranks own consecutive rows, in rank order.
    for (const auto &part : Utilities::MPI::all_gather(m.comm, owned_scaling))
      m.scaling.insert(m.scaling.end(), part.begin(), part.end());
    AssertThrow(m.scaling.size() == A.m(), ExcInternalError());
    m.values.resize(values.size());
    for (std::size_t e = 0; e < values.size(); ++e)
      m.values[e] =
        static_cast<Real>(values[e] * m.scaling[m.irn[e] - 1] * m.scaling[m.jcn[e] - 1]);
    std::vector<double>().swap(values);
    m.id.n       = static_cast<MUMPS_INT>(A.m());
    m.id.nnz_loc = static_cast<MUMPS_INT8>(m.values.size());
    m.id.irn_loc = m.irn.data();
    m.id.jcn_loc = m.jcn.data();
    m.id.a_loc   = m.values.data();

    // The ordering: with a Schur complement MUMPS orders by AMD alone, which
    // on these meshes gives 3-4 times the operations of PORD. So the whole
    // matrix is ordered first, by METIS's or SCOTCH's nested dissection of
    // the node graph (computed here: Debian's MUMPS has no METIS) or by
    // PORD, and the order with the interface moved last is given to MUMPS.
    std::vector<MUMPS_INT> by_position; // 1-based unknowns in elimination order
    if (ordering == Ordering::pord)
      {
        m.icntl(7)  = 4; // PORD
        m.icntl(19) = 0;
        m.run(1, "ordering");
        if (host)
          {
            by_position.resize(m.id.n);
            for (MUMPS_INT i = 0; i < m.id.n; ++i)
              by_position[m.id.sym_perm[i] - 1] = i + 1;
          }
      }
    else
      {
        const auto rows = Utilities::MPI::gather(m.comm, m.irn, 0);
        const auto cols = Utilities::MPI::gather(m.comm, m.jcn, 0);
        if (host)
          {
            std::vector<MUMPS_INT> all_rows, all_cols;
            for (unsigned int r = 0; r < rows.size(); ++r)
              {
                all_rows.insert(all_rows.end(), rows[r].begin(), rows[r].end());
                all_cols.insert(all_cols.end(), cols[r].begin(), cols[r].end());
              }
            by_position = nested_dissection_order(m.id.n, all_rows, all_cols,
                                                  ordering == Ordering::scotch ?
                                                    Dissector::scotch :
                                                    Dissector::metis);
            for (auto &i : by_position)
              ++i;
          }
      }
    if (host)
      {
        std::vector<bool> on_interface(m.id.n, false);
        for (const auto g : gamma)
          on_interface[g] = true;
        m.perm.clear();
        m.perm.resize(m.id.n);
        MUMPS_INT position = 0;
        for (const MUMPS_INT i : by_position)
          if (!on_interface[i - 1])
            m.perm[i - 1] = ++position;
        for (const auto g : gamma)
          {
            m.perm[g] = ++position;
            m.schur_list.push_back(static_cast<MUMPS_INT>(g + 1));
          }
        m.schur.resize(static_cast<std::size_t>(k) * k);
        m.id.perm_in       = m.perm.data();
        m.id.size_schur    = k;
        m.id.listvar_schur = m.schur_list.data();
        m.id.schur         = m.schur.data();
        m.id.schur_lld     = k;
      }
    m.icntl(7)  = 1; // the order above
    m.icntl(19) = 1; // the Schur complement centralized on rank 0
    if (low_rank_tolerance > 0.)
      {
        m.icntl(35)  = 2;                  // block low-rank factors, kept compressed for the solves
        m.id.cntl[6] = static_cast<Real>(low_rank_tolerance); // CNTL(7): the blocks' dropping tolerance
      }
    m.run(1, "analysis");
    m.run(2, "factorization");
    // The solves need the factors only: MUMPS's copy of the matrix goes.
    m.id.irn_loc = m.id.jcn_loc = nullptr;
    m.id.a_loc                  = nullptr;
    std::vector<MUMPS_INT>().swap(m.irn);
    std::vector<MUMPS_INT>().swap(m.jcn);
    std::vector<Real>().swap(m.values);
    // INFOG(29) < 0 counts millions (MUMPS's convention for large factors);
    // with low-rank factors INFOG(35) counts the entries they keep.
    const int entries = m.id.infog[low_rank_tolerance > 0. ? 34 : 28];
    stats.entries     = entries < 0 ? -1e6 * entries : double(entries);
    stats.operations  = m.id.rinfog[2];
    stats.memory      = 1e6 * m.id.infog[21]; // INFOG(22): MB used, all processes

    // S on every rank: MUMPS returns the lower triangle by rows (for a
    // symmetric matrix; the rest of the array is workspace), completed by
    // symmetry, then factorized.
    m.schur.resize(static_cast<std::size_t>(k) * k);
    Utilities::MPI::broadcast(m.comm, m.schur, 0).swap(m.schur);
    schur.reinit(k, k);
    for (MUMPS_INT i = 0; i < k; ++i)
      for (MUMPS_INT j = 0; j <= i; ++j)
        schur(i, j) = schur(j, i) = m.schur[static_cast<std::size_t>(i) * k + j];
    if (positive_definite)
      {
        schur.set_property(LAPACKSupport::symmetric);
        schur.compute_cholesky_factorization();
      }
    else
      schur.compute_lu_factorization();
    std::vector<Real>().swap(m.schur);
    m.id.schur = nullptr; // read by the factorization only

    m.reduced.resize(k);
    gamma_scaling.resize(k);
    for (MUMPS_INT i = 0; i < k; ++i)
      gamma_scaling[i] = m.scaling[gamma[i]];
    elimination.reset(); // (a deal.II timer starts when made)
    substitution.reset();
  }

  CondensedFactorization::~CondensedFactorization() = default;

  // The factorized Schur complement is that of D A D, D_Γ S D_Γ:
  // S^{-1} = D_Γ (D_Γ S D_Γ)^{-1} D_Γ.
  void
  CondensedFactorization::solve_interface(dealii::Vector<double> &v) const
  {
    for (unsigned int i = 0; i < v.size(); ++i)
      v[i] *= gamma_scaling[i];
    schur.solve(v);
    for (unsigned int i = 0; i < v.size(); ++i)
      v[i] *= gamma_scaling[i];
  }

  void
  CondensedFactorization::solve_interface(LAPACKFullMatrix<double> &V) const
  {
    const auto scale_rows = [&] {
      for (unsigned int i = 0; i < V.m(); ++i)
        for (unsigned int j = 0; j < V.n(); ++j)
          V(i, j) *= gamma_scaling[i];
    };
    scale_rows();
    schur.solve(V);
    scale_rows();
  }

  void
  CondensedFactorization::condense(const archdam::Vector &b, dealii::Vector<double> &y,
                                   const bool with_interface_load) const
  {
    std::visit(
      [&](auto &owner) {
        auto &m = *owner;
        const Vec &vec  = static_cast<const Vec &>(b);
        const bool host = Utilities::MPI::this_mpi_process(m.comm) == 0;
        if (m.to_zero == nullptr)
          petsc_check(VecScatterCreateToZero(vec, &m.to_zero, &m.on_zero));
        petsc_check(VecScatterBegin(m.to_zero, vec, m.on_zero, INSERT_VALUES, SCATTER_FORWARD));
        petsc_check(VecScatterEnd(m.to_zero, vec, m.on_zero, INSERT_VALUES, SCATTER_FORWARD));
        // The interface load's column is zero: its forward elimination off
        // the interface, eliminated last, is zero whatever the load on it.
        m.columns = with_interface_load ? 2 : 1;
        m.reduced.resize(m.columns * gamma.size());
        if (host)
          {
            const PetscScalar *a;
            petsc_check(VecGetArrayRead(m.on_zero, &a));
            m.rhs.assign(m.columns * b.size(), 0.);
            for (std::size_t i = 0; i < b.size(); ++i)
              m.rhs[i] = a[i] * m.scaling[i];
            petsc_check(VecRestoreArrayRead(m.on_zero, &a));
            m.id.rhs     = m.rhs.data();
            m.id.nrhs    = m.columns;
            m.id.lrhs    = static_cast<MUMPS_INT>(b.size());
            m.id.redrhs  = m.reduced.data();
            m.id.lredrhs = static_cast<MUMPS_INT>(gamma.size());
          }
        m.icntl(26) = 1; // condensation: forward elimination, reduced right-hand side
        elimination.start();
        m.run(3, "condensation");
        elimination.stop();
        const auto reduced = Utilities::MPI::broadcast(m.comm, m.reduced, 0);
        y.reinit(gamma.size(), true);
        for (unsigned int i = 0; i < y.size(); ++i)
          y[i] = reduced[i] / gamma_scaling[i];
      },
      mumps);
  }

  void
  CondensedFactorization::expand(const dealii::Vector<double> &x_gamma, archdam::Vector &x,
                                 const dealii::Vector<double> *q, archdam::Vector *x_q) const
  {
    std::visit(
      [&](auto &owner) {
        auto &m = *owner;
        const bool host = Utilities::MPI::this_mpi_process(m.comm) == 0;
        const auto k    = gamma.size();
        AssertThrow(q == nullptr || (m.columns == 2 && x_q != nullptr && q->size() == k),
                    ExcMessage("An interface load's response needs the condensation's room "
                               "for it."));
        // the second column's x_Γ = S^{-1} q (zero without a load)
        dealii::Vector<double> q_gamma(k);
        if (q != nullptr)
          {
            q_gamma = *q;
            solve_interface(q_gamma);
          }
        if (host)
          for (unsigned int g = 0; g < k; ++g)
            {
              m.reduced[g] = x_gamma[g] / gamma_scaling[g];
              if (m.columns == 2)
                m.reduced[k + g] = q_gamma[g] / gamma_scaling[g];
            }
        m.icntl(26) = 2; // expansion: backward substitution from x_Γ
        substitution.start();
        m.run(3, "expansion");
        substitution.stop();
        const auto solution_of = [&](const unsigned int column, Vec &on_zero, archdam::Vector &y) {
          const std::size_t n = y.size();
          if (host)
            {
              PetscScalar *a;
              petsc_check(VecGetArray(on_zero, &a));
              for (std::size_t i = 0; i < n; ++i)
                a[i] = m.rhs[column * n + i] * m.scaling[i];
              petsc_check(VecRestoreArray(on_zero, &a));
            }
          const Vec &vec = static_cast<const Vec &>(y);
          petsc_check(VecScatterBegin(m.to_zero, on_zero, vec, INSERT_VALUES, SCATTER_REVERSE));
          petsc_check(VecScatterEnd(m.to_zero, on_zero, vec, INSERT_VALUES, SCATTER_REVERSE));
        };
        solution_of(0, m.on_zero, x);
        if (q != nullptr)
          {
            if (m.second_on_zero == nullptr)
              petsc_check(VecDuplicate(m.on_zero, &m.second_on_zero));
            solution_of(1, m.second_on_zero, *x_q);
          }
      },
      mumps);
  }

  CondensedFactorization::SolveTimes
  CondensedFactorization::solve_times() const
  {
    return {elimination.wall_time(), substitution.wall_time()};
  }
} // namespace archdam::time
