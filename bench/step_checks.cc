// Benchmark: what the reliability checks add to a dynamic step, against one
// back-substitution with the factor of Kbar (a step costs about two to three
// of those, bench_dynamic_step), on the box "dam on rock" model
// (bench_common.h):
//  - time::DivergenceCheck::check (one pass over the owned entries of u, v, a
//    and one all-reduce);
//  - output::HistoryWriter::append of a row of 13 columns (formatted, written
//    in one piece and flushed by rank 0, its success shared with all ranks).
// Alternating rounds, so that load from other users hits all alike.
//
//   bench_step_checks [--size tiny|small|large|cx,cy,cz,h] [--rounds R] [--calls N]

#include "bench_common.h"

#include <archdam/output/histories.h>
#include <archdam/time/divergence_check.h>
#include <archdam/time/factorized_operator.h>

#include <algorithm>
#include <filesystem>

using namespace archdam;

namespace
{
  template <typename F>
  double
  per_call(const unsigned int n, F &&fn)
  {
    dealii::Timer t;
    for (unsigned int i = 0; i < n; ++i)
      fn();
    return t.wall_time() / n;
  }

  double
  median(std::vector<double> v)
  {
    std::sort(v.begin(), v.end());
    return v[v.size() / 2];
  }
} // namespace

int
main(int argc, char **argv)
{
  dealii::Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  std::string  size   = "small";
  unsigned int rounds = 5, calls = 20;
  for (int i = 1; i + 1 < argc; i += 2)
    {
      const std::string a = argv[i];
      if (a == "--size")
        size = argv[i + 1];
      else if (a == "--rounds")
        rounds = std::stoi(argv[i + 1]);
      else if (a == "--calls")
        calls = std::stoi(argv[i + 1]);
    }
  bench::Model m(bench::parse_size(size));
  m.build();

  SparseMatrix kbar;
  kbar.reinit(m.stiffness);
  kbar.copy_from(m.stiffness);
  kbar *= 1e-4;
  MatAXPY(kbar.petsc_matrix(), 1., m.mass, SAME_NONZERO_PATTERN);
  time::FactorizedOperator op;
  op.factorize(kbar, true);

  time::NewmarkState s;
  for (Vector *v : {&s.u, &s.v, &s.a})
    m.space->reinit(*v);
  op.solve(s.u, m.gravity); // a displacement field with every entry set
  s.v = s.u;
  s.a = s.u;
  s.time = 0.01;

  const time::DivergenceCheck check(*m.space);
  if (dealii::Utilities::MPI::this_mpi_process(MPI_COMM_WORLD) == 0)
    std::filesystem::create_directories("bench_results");
  output::HistoryWriter history("bench_results",
                                std::vector<std::string>(13, "column"), MPI_COMM_WORLD);
  const std::vector<double> row(13, 1.2345678e-3);

  Vector x;
  m.space->reinit(x);
  std::vector<double> t_solve, t_check, t_append;
  for (unsigned int r = 0; r < rounds; ++r)
    {
      t_solve.push_back(per_call(calls, [&] { op.solve(x, m.gravity); }));
      t_check.push_back(per_call(calls, [&] { check.check(s, 1); }));
      t_append.push_back(per_call(calls, [&] { history.append(row); }));
    }
  auto &out = bench::screen();
  out << "box model '" << size << "', " << m.n_dofs() << " DOFs, "
      << dealii::Utilities::MPI::n_mpi_processes(MPI_COMM_WORLD)
      << " MPI process(es), medians of " << rounds << " rounds of " << calls << " calls\n";
  bench::figure(out, "back-substitution [s]") << median(t_solve) << "\n";
  bench::figure(out, "divergence check [s]")
    << median(t_check) << "  (" << 100 * median(t_check) / median(t_solve)
    << " % of a back-substitution)\n";
  bench::figure(out, "history row appended [s]")
    << median(t_append) << "  (" << 100 * median(t_append) / median(t_solve)
    << " % of a back-substitution)\n";
}
