// Benchmark: the measurement behind the choice of direct solver
// (doc/performance.md §5). On the effective matrix Kbar = (1 + alpha beta1 dt) M +
// (beta beta1 dt + beta2 dt^2) K of the box "dam on rock" model (bench_common.h,
// built as time::NewmarkIntegrator builds it), time the factorization and one
// solve of
//   (a) MUMPS Cholesky through PETSc: time::FactorizedOperator (the library's choice)
//   (b) MUMPS LU through PETSc (KSPPREONLY + PCLU + MATSOLVERMUMPS)
//   (c) Trilinos Amesos through TrilinosWrappers::SolverDirect (initialize()
//       factorizes, solve(x, b) reuses the factor): Amesos_Mumps, and
//       Amesos_Klu (by default only below 60,000 DOFs: it is slow)
//   (d) UMFPACK (SparseDirectUMFPACK on a deal.II SparseMatrix copy; by
//       default only below 60,000 DOFs)
// and check that all give the same solution as (a): max |x - x_a| / max |x_a|.
// The relative residual of (a) is printed too.
//
// Then the cost model of the joint flexibility matrix: N right-hand sides
// (unit loads at N unconstrained DOFs spread over the model) solved one after
// another with KSPSolve, against one multi-column solve with KSPMatSolve (dense
// B and X, MATDENSE), both with the same MUMPS Cholesky factor (a KSP set up
// exactly as FactorizedOperator does it), alternated twice; the columns are
// compared.
//
//   bench_direct_solvers [--size tiny|small|large|cx,cy,cz,h] [--solves N]
//                        [--rounds R] [--nrhs N] [--klu] [--umfpack] [--no-klu] [--no-umfpack]
//
// Defaults: --size small (27,747 DOFs), --rounds 3 --solves 3 (interleaved
// rounds of 3 solves per solver), --nrhs 100. Serial only.
//
// "heap held" is the heap in use (glibc mallinfo2) after the factorization
// minus before it: the memory the factor keeps (MUMPS, KLU, UMFPACK all
// allocate with malloc).

#include "bench_common.h"

#include <archdam/time/factorized_operator.h>

#include <deal.II/lac/dynamic_sparsity_pattern.h>
#include <deal.II/lac/solver_control.h>
#include <deal.II/lac/sparse_direct.h>
#include <deal.II/lac/sparse_matrix.h>
#include <deal.II/lac/sparsity_pattern.h>
#include <deal.II/lac/trilinos_solver.h>
#include <deal.II/lac/trilinos_sparse_matrix.h>
#include <deal.II/lac/trilinos_vector.h>
#include <deal.II/lac/vector.h>

#include <petscksp.h>

#include <malloc.h>

#include <algorithm>
#include <cmath>
#include <functional>

using namespace archdam;
using dealii::Timer;

namespace
{
  void
  check(const PetscErrorCode ierr)
  {
    AssertThrow(ierr == 0, dealii::ExcMessage("PETSc error " + std::to_string(ierr)));
  }

  /// Heap in use in GB (malloc'ed, including mmapped blocks).
  double
  heap_gb()
  {
    const struct mallinfo2 mi = mallinfo2();
    return (mi.uordblks + mi.hblkhd) / 1073741824.;
  }

  // PETSc vector <-> deal.II vector (serial: all entries are local)
  void
  to_dealii(const Vector &v, dealii::Vector<double> &d)
  {
    const PetscScalar *a;
    PetscInt           n;
    check(VecGetLocalSize(v, &n));
    d.reinit(n);
    check(VecGetArrayRead(v, &a));
    std::copy(a, a + n, d.begin());
    check(VecRestoreArrayRead(v, &a));
  }

  /// max |x - ref| / max |ref|
  double
  max_rel_diff(const dealii::Vector<double> &x, const dealii::Vector<double> &ref)
  {
    double d = 0, r = 0;
    for (unsigned int i = 0; i < ref.size(); ++i)
      {
        d = std::max(d, std::abs(x[i] - ref[i]));
        r = std::max(r, std::abs(ref[i]));
      }
    return d / r;
  }

  /// KSPPREONLY with a MUMPS factorization (PCCHOLESKY or PCLU) of A.
  struct PetscDirect
  {
    PetscDirect(Mat A, const PCType type)
    {
      check(KSPCreate(PETSC_COMM_WORLD, &ksp));
      check(KSPSetOperators(ksp, A, A));
      check(KSPSetType(ksp, KSPPREONLY));
      PC pc;
      check(KSPGetPC(ksp, &pc));
      check(PCSetType(pc, type));
      check(PCFactorSetMatSolverType(pc, MATSOLVERMUMPS));
      check(KSPSetUp(ksp)); // factorization
    }
    ~PetscDirect()
    {
      KSPDestroy(&ksp);
    }
    /// MUMPS statistics: entries in the factor, its memory [MB], the flops.
    std::string
    info() const
    {
      PC  pc;
      Mat F;
      check(KSPGetPC(ksp, &pc));
      check(PCFactorGetMatrix(pc, &F));
      PetscInt  entries, mem_mb;
      PetscReal flops;
      check(MatMumpsGetInfog(F, 29, &entries)); // < 0 means -entries in millions
      check(MatMumpsGetInfog(F, 22, &mem_mb));  // total memory of the factorization
      check(MatMumpsGetRinfog(F, 3, &flops));
      std::ostringstream o;
      o << "MUMPS factor entries "
        << (entries < 0 ? -1e6 * entries : static_cast<double>(entries)) << ", memory "
        << mem_mb << " MB, " << flops << " flops";
      return o.str();
    }
    KSP ksp = nullptr;
  };

  template <typename F>
  double
  per_call(const unsigned int n, F &&fn)
  {
    Timer t;
    for (unsigned int i = 0; i < n; ++i)
      fn();
    return t.wall_time() / n;
  }
} // namespace

int
main(int argc, char **argv)
{
  dealii::Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  std::ostream &out = bench::screen();
  AssertThrow(dealii::Utilities::MPI::n_mpi_processes(MPI_COMM_WORLD) == 1,
              dealii::ExcMessage("bench_direct_solvers runs serially"));

  std::string  size_name = "small";
  unsigned int n_solves = 3, n_rounds = 3, n_rhs = 100;
  int          klu = -1, umfpack = -1; // -1: only below 60k DOFs
  for (int i = 1; i < argc; ++i)
    {
      const std::string a = argv[i];
      const auto next = [&]() -> std::string {
        AssertThrow(i + 1 < argc, dealii::ExcMessage("missing value after " + a));
        return argv[++i];
      };
      if (a == "--size")
        size_name = next();
      else if (a == "--solves")
        n_solves = std::stoi(next());
      else if (a == "--rounds")
        n_rounds = std::stoi(next());
      else if (a == "--nrhs")
        n_rhs = std::stoi(next());
      else if (a == "--klu" || a == "--no-klu")
        klu = (a == "--klu");
      else if (a == "--umfpack" || a == "--no-umfpack")
        umfpack = (a == "--umfpack");
      else
        {
          out << "usage: bench_direct_solvers [--size tiny|small|large|cx,cy,cz,h] "
                 "[--solves N] [--rounds R] [--nrhs N] [--klu|--no-klu] [--umfpack|--no-umfpack]"
              << std::endl;
          return 1;
        }
    }

  bench::Model m(bench::parse_size(size_name));
  m.build();
  const auto  n    = m.n_dofs();
  const auto &b    = m.p.mesh.box;
  const auto  nd   = ", DOFs " + std::to_string(n);
  if (klu < 0)
    klu = n < 60000;
  if (umfpack < 0)
    umfpack = n < 60000;
  SparseMatrix kbar;
  bench::effective_matrix(m, kbar);
  out << "model: box dam on rock, Q2, dam cells " << b.cells_x << "x" << b.cells_y << "x"
      << b.cells_z << ", rock cell size " << b.rock_cell_size << " m, "
      << m.triangulation.n_active_cells() << " cells, " << n << " DOFs, nnz(Kbar) = "
      << kbar.n_nonzero_elements() << std::endl;

  // the right-hand side: one step's kind of load (gravity and 0.3 g in x)
  Vector rhs, x;
  m.space->reinit(rhs);
  m.space->reinit(x);
  rhs = m.gravity;
  rhs.add(-0.3 * 9.81, m.influence[0]);
  m.space->constraints.set_zero(rhs);
  dealii::Vector<double> rhs_d, x_ref, x_d;
  to_dealii(rhs, rhs_d);

  out << std::defaultfloat << std::setprecision(4);

  // Each solver is factorized (timed) and kept; the solves are timed afterwards
  // in interleaved rounds (a, b, c, ..., a, b, c, ...), so that load from
  // other users of this machine falls on all of them alike.
  struct Entry
  {
    std::string                                 name;
    double                                      t_factor = 0, heap = 0;
    std::string                                 extra;
    std::function<void()>                       solve;
    std::function<void(dealii::Vector<double> &)> solution;
    std::vector<double>                         t_solve;
  };
  std::vector<Entry> entries;
  const auto factorize = [&](Entry &e, const std::function<void()> &f) {
    const double h0 = heap_gb();
    Timer        t;
    f();
    e.t_factor = t.wall_time();
    e.heap     = heap_gb() - h0;
    bench::figure(out, "factorized: " + e.name) << e.t_factor << " s" << std::endl;
  };

  // --------------------------------------------------- (a) FactorizedOperator
  time::FactorizedOperator op;
  {
    Entry e;
    e.name = "(a) MUMPS Cholesky, PETSc (FactorizedOperator)";
    factorize(e, [&] { op.factorize(kbar, true); });
    e.solve    = [&] { op.solve(x, rhs); };
    e.solution = [&](dealii::Vector<double> &v) { to_dealii(x, v); };
    entries.push_back(std::move(e));
  }

  // ---------------------------------------------------- (b) MUMPS LU, PETSc
  Mat                          kbar_lu;
  std::unique_ptr<PetscDirect> lu;
  {
    check(MatDuplicate(kbar, MAT_COPY_VALUES, &kbar_lu));
    Entry e;
    e.name = "(b) MUMPS LU, PETSc (PCLU)";
    factorize(e, [&] { lu = std::make_unique<PetscDirect>(kbar_lu, PCLU); });
    e.extra    = "; " + lu->info();
    e.solve    = [&] { check(KSPSolve(lu->ksp, rhs, x)); };
    e.solution = [&](dealii::Vector<double> &v) { to_dealii(x, v); };
    entries.push_back(std::move(e));
  }

  // ---------------- deal.II SparseMatrix copy of Kbar (for UMFPACK and Trilinos)
  dealii::SparsityPattern      sp;
  dealii::SparseMatrix<double> kd;
  {
    dealii::DynamicSparsityPattern dsp(n, n);
    for (PetscInt i = 0; i < static_cast<PetscInt>(n); ++i)
      {
        PetscInt        nc;
        const PetscInt *cols;
        check(MatGetRow(kbar, i, &nc, &cols, nullptr));
        for (PetscInt k = 0; k < nc; ++k)
          dsp.add(i, cols[k]);
        check(MatRestoreRow(kbar, i, &nc, &cols, nullptr));
      }
    sp.copy_from(dsp);
    kd.reinit(sp);
    for (PetscInt i = 0; i < static_cast<PetscInt>(n); ++i)
      {
        PetscInt           nc;
        const PetscInt    *cols;
        const PetscScalar *vals;
        check(MatGetRow(kbar, i, &nc, &cols, &vals));
        for (PetscInt k = 0; k < nc; ++k)
          kd.set(i, cols[k], vals[k]);
        check(MatRestoreRow(kbar, i, &nc, &cols, &vals));
      }
  }

  // -------------------------------------------------- (c) Trilinos Amesos
  dealii::TrilinosWrappers::SparseMatrix kt;
  kt.reinit(kd, 0.); // drops only exact zeros
  const dealii::IndexSet                all = dealii::complete_index_set(n);
  dealii::TrilinosWrappers::MPI::Vector bt(all, MPI_COMM_WORLD), xt(all, MPI_COMM_WORLD);
  for (unsigned int i = 0; i < n; ++i)
    bt[i] = rhs_d[i];
  bt.compress(dealii::VectorOperation::insert);
  dealii::SolverControl                                               sc;
  std::vector<std::unique_ptr<dealii::TrilinosWrappers::SolverDirect>> amesos;
  std::vector<std::string> types = {"Amesos_Mumps"};
  if (klu)
    types.push_back("Amesos_Klu");
  for (const auto &type : types)
    {
      Entry e;
      e.name = "(c) Trilinos " + type + " (SolverDirect)";
      amesos.push_back(std::make_unique<dealii::TrilinosWrappers::SolverDirect>(
        sc, dealii::TrilinosWrappers::SolverDirect::AdditionalData(false, type)));
      auto &solver = *amesos.back();
      factorize(e, [&] { solver.initialize(kt); });
      e.solve    = [&solver, &xt, &bt] { solver.solve(xt, bt); };
      e.solution = [&](dealii::Vector<double> &v) {
        v.reinit(n);
        for (unsigned int i = 0; i < n; ++i)
          v[i] = xt[i];
      };
      entries.push_back(std::move(e));
    }
  if (!klu)
    out << "(c) Trilinos Amesos_Klu: skipped at this size (--klu to force)" << std::endl;

  // ------------------------------------------------------------- (d) UMFPACK
  auto umf = std::make_unique<dealii::SparseDirectUMFPACK>();
  if (umfpack)
    {
      Entry e;
      e.name = "(d) UMFPACK (SparseDirectUMFPACK)";
      factorize(e, [&] { umf->initialize(kd); });
      e.solve = [&] {
        x_d = rhs_d;
        umf->solve(x_d);
      };
      e.solution = [&](dealii::Vector<double> &v) { v = x_d; };
      entries.push_back(std::move(e));
    }
  else
    out << "(d) UMFPACK: skipped at this size (--umfpack to force)" << std::endl;

  // ------------------------------------------- solves: warm-up and check
  for (auto &e : entries)
    {
      e.solve(); // warm-up (the first solve may allocate)
      if (&e == &entries.front())
        {
          e.solution(x_ref);
          Vector r;
          m.space->reinit(r);
          kbar.vmult(r, x); // residual, independent of every solver
          r -= rhs;
          std::ostringstream res;
          res << ", residual |Kbar x - b| / |b| = " << std::setprecision(3)
              << r.l2_norm() / rhs.l2_norm();
          e.extra = res.str();
        }
      dealii::Vector<double> v;
      e.solution(v);
      std::ostringstream d;
      d << ", max rel diff vs (a) " << std::setprecision(3) << max_rel_diff(v, x_ref);
      e.extra = d.str() + e.extra;
    }
  // -------------------------------------------- solves: interleaved rounds
  for (unsigned int r = 0; r < n_rounds; ++r)
    for (auto &e : entries)
      e.t_solve.push_back(per_call(n_solves, e.solve));
  for (const auto &e : entries)
    {
      double sum = 0;
      for (const double t : e.t_solve)
        sum += t;
      bench::figure(out, e.name)
        << "factor " << e.t_factor << " s, one solve " << sum / n_rounds << " s (best round "
        << *std::min_element(e.t_solve.begin(), e.t_solve.end()) << " s), heap held "
        << e.heap << " GB" << e.extra << nd << std::endl;
    }
  out << "  (one solve: mean of " << n_rounds << " interleaved rounds of " << n_solves
      << " solves each, after one warm-up solve)" << std::endl;

  // free all but (a) before the multi-rhs part
  umf.reset();
  amesos.clear();
  kt.clear();
  kd.clear();
  lu.reset();
  MatDestroy(&kbar_lu);

  // ------------- N right-hand sides: one after another vs one KSPMatSolve
  if (n_rhs > 0)
    {
      Mat A;
      check(MatDuplicate(kbar, MAT_COPY_VALUES, &A));
      check(MatSetOption(A, MAT_SYMMETRIC, PETSC_TRUE));
      check(MatSetOption(A, MAT_SPD, PETSC_TRUE));
      Timer              t;
      PetscDirect        chol(A, PCCHOLESKY);
      const double       t_f = t.wall_time();
      bench::figure(out, "multi-rhs: MUMPS Cholesky factor (own KSP)")
        << t_f << " s; " << chol.info() << nd << std::endl;

      // unit loads at n_rhs unconstrained DOFs spread evenly over the numbering
      std::vector<PetscInt> at;
      PetscInt              next_free = 0;
      for (unsigned int k = 0; k < n_rhs; ++k)
        {
          PetscInt i = std::max<PetscInt>(next_free, (k + 0.5) * n / n_rhs);
          while (i < static_cast<PetscInt>(n) && m.space->constraints.is_constrained(i))
            ++i;
          if (i >= static_cast<PetscInt>(n))
            break;
          at.push_back(i);
          next_free = i + 1;
        }
      const PetscInt nr = at.size();

      Mat B, X, Xseq;
      check(MatCreateDense(PETSC_COMM_WORLD, PETSC_DECIDE, PETSC_DECIDE, n, nr, nullptr, &B));
      check(MatCreateDense(PETSC_COMM_WORLD, PETSC_DECIDE, PETSC_DECIDE, n, nr, nullptr, &X));
      check(MatCreateDense(PETSC_COMM_WORLD, PETSC_DECIDE, PETSC_DECIDE, n, nr, nullptr,
                           &Xseq));
      check(MatZeroEntries(B));
      for (PetscInt k = 0; k < nr; ++k)
        check(MatSetValue(B, at[k], k, 1.0, INSERT_VALUES));
      check(MatAssemblyBegin(B, MAT_FINAL_ASSEMBLY));
      check(MatAssemblyEnd(B, MAT_FINAL_ASSEMBLY));
      check(MatAssemblyBegin(Xseq, MAT_FINAL_ASSEMBLY));
      check(MatAssemblyEnd(Xseq, MAT_FINAL_ASSEMBLY));

      Vec bk, xk;
      check(VecDuplicate(rhs, &bk));
      check(VecDuplicate(rhs, &xk));
      check(KSPSolve(chol.ksp, rhs, xk)); // warm-up

      // one after another, as FactorizedOperator::solve would do it
      const auto sequential = [&] {
        for (PetscInt k = 0; k < nr; ++k)
          {
            Vec col;
            check(VecSet(bk, 0.));
            check(VecSetValue(bk, at[k], 1.0, INSERT_VALUES));
            check(VecAssemblyBegin(bk));
            check(VecAssemblyEnd(bk));
            check(KSPSolve(chol.ksp, bk, xk));
            check(MatDenseGetColumnVecWrite(Xseq, k, &col));
            check(VecCopy(xk, col));
            check(MatDenseRestoreColumnVecWrite(Xseq, k, &col));
          }
      };
      const auto multi = [&] { check(KSPMatSolve(chol.ksp, B, X)); };

      // alternate to share the noise of this machine: seq, multi, seq, multi;
      // the figures are the means of the two
      const unsigned int reps = 2;
      double             t_seq = 0, t_multi = 0;
      for (unsigned int r = 0; r < reps; ++r)
        {
          t_seq += per_call(1, sequential) / reps;
          t_multi += per_call(1, multi) / reps;
        }
      // same columns?
      check(MatAXPY(Xseq, -1., X, SAME_NONZERO_PATTERN));
      PetscReal diff, ref;
      check(MatNorm(Xseq, NORM_MAX, &diff));
      check(MatNorm(X, NORM_MAX, &ref));

      bench::figure(out, "multi-rhs: " + std::to_string(nr) + " solves one by one (KSPSolve)")
        << t_seq << " s (" << t_seq / nr << " s each)" << nd << std::endl;
      bench::figure(out, "multi-rhs: one KSPMatSolve with " + std::to_string(nr) + " columns")
        << t_multi << " s (" << t_multi / nr << " s per column), max rel diff of columns "
        << diff / ref << nd << std::endl;
      bench::figure(out, "multi-rhs: ratio one-by-one / KSPMatSolve")
        << std::setprecision(3) << t_seq / t_multi << nd << std::endl;

      VecDestroy(&bk);
      VecDestroy(&xk);
      MatDestroy(&B);
      MatDestroy(&X);
      MatDestroy(&Xseq);
      MatDestroy(&A);
    }

  bench::figure(out, "peak memory (VmHWM) [GB]") << bench::memory_gb("VmHWM") << nd
                                                 << std::endl;
  return 0;
}
