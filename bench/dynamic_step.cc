// Benchmark: cost of one dynamic step against one back-substitution with the
// factor of Kbar (doc/performance.md §2: target step / back-substitution <= 3), plus
// the one-time set-up (assembly, factorization) and peak memory, all in ONE
// process run on the box "dam on rock" model (bench_common.h).
//
//   bench_dynamic_step [--size tiny|small|large|cx,cy,cz,h] [--steps N]
//                      [--rounds R] [--record FILE.AT2] [--dofs-only]
//
// Defaults: --size large (110,835 DOFs), --rounds 5, --steps 8 (steps per
// round); --size small (27,747 DOFs) runs in a few seconds. Step and back-substitution are timed in alternating rounds (R
// rounds of N steps, then N back-substitutions) so that load from other users
// of this shared machine hits both alike.
//
// What is timed:
//  - "step": what the dynamic stage does per step (Simulation::run_dynamic_stage
//    without monitors/output): the load F(t) = F_grav - a_g(t) M iota (one
//    copy + up to 3 axpy) and time::NewmarkIntegrator::advance.
//  - "back-substitution": time::FactorizedOperator::solve with a second
//    FactorizedOperator that factorizes the identical Kbar (the integrator's own
//    factor is private); the PETSc log at the end shows that the
//    back-substitution inside advance() (MatSolve event) costs the same.
//  - the pieces of advance() (the two matrix-vector products, the constraint
//    zeroing, the vector updates), timed alone with the same calls, to show
//    what dominates a step.
//  - the set-up: mesh and DOFs, assembly of M and K (and, for comparison, one
//    FESpace::reinit of a matrix), the Newmark constructor (Kbar + MUMPS Cholesky factorization),
//    and Kbar built again as the constructor does it.
//
// Peak memory is VmHWM of /proc/self/status. It is printed after the steps,
// before the second factorization (the figure of a real run), and at the end.

#include "bench_common.h"

#include <archdam/geometry/ids.h>
#include <archdam/loads/ground_motion.h>
#include <archdam/time/factorized_operator.h>
#include <archdam/time/newmark.h>

#include <deal.II/fe/fe_values.h>
#include <deal.II/hp/fe_values.h>
#include <deal.II/lac/full_matrix.h>

#include <petsclog.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <map>

using namespace archdam;
using dealii::Tensor;
using dealii::Timer;
namespace Utilities = dealii::Utilities;

namespace
{
  // Time of fn() in seconds per call, over n calls.
  template <typename F>
  double
  per_call(const unsigned int n, F &&fn)
  {
    Timer t;
    for (unsigned int i = 0; i < n; ++i)
      fn();
    return t.wall_time() / n;
  }

  double
  median(std::vector<double> v)
  {
    std::sort(v.begin(), v.end());
    const std::size_t n = v.size();
    return n % 2 ? v[n / 2] : 0.5 * (v[n / 2 - 1] + v[n / 2]);
  }

  // Cumulative time and count of a PETSc log event (0 if it does not exist).
  std::pair<double, int>
  petsc_event(const char *name)
  {
    PetscLogEvent      id;
    PetscEventPerfInfo info;
    PetscPushErrorHandler(PetscReturnErrorHandler, nullptr);
    const PetscErrorCode ierr = PetscLogEventGetId(name, &id);
    PetscPopErrorHandler();
    if (ierr != 0)
      return {0., 0};
    PetscLogEventGetPerfInfo(0 /* main stage */, id, &info);
    return {info.time, info.count};
  }
} // namespace

int
main(int argc, char **argv)
{
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  std::ostream &out = bench::screen();

  std::string  size_name = "large";
  unsigned int n_steps = 8, n_rounds = 5;
  bool         dofs_only = false;
  std::string  record = "ground_motions/RSN6_IMPVALL.I_I-ELC180.AT2";
  for (int i = 1; i < argc; ++i)
    {
      const std::string a = argv[i];
      const auto next = [&]() -> std::string {
        AssertThrow(i + 1 < argc, dealii::ExcMessage("missing value after " + a));
        return argv[++i];
      };
      if (a == "--size")
        size_name = next();
      else if (a == "--steps")
        n_steps = std::stoi(next());
      else if (a == "--rounds")
        n_rounds = std::stoi(next());
      else if (a == "--record")
        record = next();
      else if (a == "--dofs-only")
        dofs_only = true;
      else
        {
          out << "usage: bench_dynamic_step [--size tiny|small|large|cx,cy,cz,h] "
                 "[--steps N] [--rounds R] [--record FILE.AT2] [--dofs-only]"
              << std::endl;
          return 1;
        }
    }

  // ---------------------------------------------------------------- set-up
  bench::Model m(bench::parse_size(size_name));
  m.build();
  const auto dofs = m.n_dofs();
  const auto &b   = m.p.mesh.box;
  out << "model: box dam on rock, Q2, dam cells " << b.cells_x << "x" << b.cells_y << "x"
      << b.cells_z << ", rock cell size " << b.rock_cell_size << " m, "
      << m.triangulation.n_active_cells() << " cells, " << dofs << " DOFs, "
      << m.space->constraints.n_constraints() << " constrained, nnz(K) = " << m.nnz()
      << ", MPI processes " << Utilities::MPI::n_mpi_processes(MPI_COMM_WORLD) << std::endl;
  if (dofs_only)
    return 0;

  const std::string nd = ", DOFs " + std::to_string(dofs);
  out << std::fixed << std::setprecision(3);
  bench::figure(out, "setup: mesh + DOFs + constraints [s]") << m.time_mesh_and_dofs << nd
                                                             << std::endl;
  bench::figure(out, "setup: assembly of M and K [s]") << m.time_assembly << nd << std::endl;
  {
    SparseMatrix scratch;
    Timer        t;
    m.space->reinit(scratch);
    bench::figure(out, "setup: one FESpace::reinit(SparseMatrix) [s]")
      << t.wall_time() << " (sparsity pattern + PETSc preallocation; assembly does it for M and K)"
      << nd << std::endl;
  }
  bench::figure(out, "setup: gravity + 3 influence loads [s]") << m.time_loads << nd
                                                               << std::endl;

  const auto rayleigh = m.p.damping.rayleigh_coefficients();
  const double dt     = m.p.time_integration.time_step;
  Timer        timer;
  auto newmark = std::make_unique<time::NewmarkIntegrator>(
    m.p.time_integration, m.mass, m.stiffness, rayleigh, m.space->constraints);
  const double t_factor = timer.wall_time();
  bench::figure(out, "setup: Kbar + factorization (Newmark ctor) [s]") << t_factor << nd
                                                                       << std::endl;

  // ground motion: the El Centro record in x if present, else 0.3 g at 2 Hz
  std::unique_ptr<loads::GroundMotion> motion;
  if (std::filesystem::exists(record))
    {
      loads::GroundMotionParameters gp;
      gp.components[0].file = record;
      motion                = std::make_unique<loads::GroundMotion>(gp, "");
    }
  out << "ground motion: "
      << (motion ? record : std::string("synthetic 0.3 g sine at 2 Hz in x")) << std::endl;
  const auto ground = [&](const double t) {
    if (motion)
      return motion->acceleration(t);
    Tensor<1, dim> a;
    a[0] = 0.3 * 9.81 * std::sin(2 * M_PI * 2. * t);
    return a;
  };

  time::NewmarkState s;
  Vector             load;
  for (Vector *v : {&s.u, &s.v, &s.a, &load})
    m.space->reinit(*v);
  unsigned int n = 0;
  // one step as in Simulation::run_dynamic_stage (without monitors and output)
  const auto step = [&] {
    ++n;
    const double         t  = n * dt;
    const Tensor<1, dim> ag = ground(2. + t); // start inside the strong motion
    load                    = m.gravity;
    for (unsigned int d = 0; d < dim; ++d)
      if (ag[d] != 0.)
        load.add(-ag[d], m.influence[d]);
    newmark->advance(load, s);
  };

  for (unsigned int i = 0; i < 2; ++i) // warm-up (first MUMPS solve allocates)
    step();
  const double peak_model = bench::memory_gb("VmHWM");

  // ---------------------------------------- the same Kbar, factorized again
  // built as NewmarkIntegrator does it (M and K share one sparsity pattern)
  const auto  &ti = m.p.time_integration;
  const double ck = rayleigh.second * ti.beta1 * dt + ti.beta2 * dt * dt;
  const double cm = 1. + rayleigh.first * ti.beta1 * dt;
  SparseMatrix kbar;
  timer.restart();
  kbar.reinit(m.stiffness);
  kbar.copy_from(m.stiffness);
  kbar *= ck;
  MatAXPY(kbar.petsc_matrix(), cm, m.mass, SAME_NONZERO_PATTERN);
  const double t_kbar = timer.wall_time();
  timer.restart();
  time::FactorizedOperator op;
  op.factorize(kbar, true);
  const double t_factor2 = timer.wall_time();
  Vector x, rhs;
  m.space->reinit(x);
  m.space->reinit(rhs);
  rhs = load;
  op.solve(x, rhs); // warm-up

  // ------------------------------------------------ alternating rounds
  std::vector<double> t_step, t_solve;
  for (unsigned int r = 0; r < n_rounds; ++r)
    {
      t_step.push_back(per_call(n_steps, step));
      t_solve.push_back(per_call(n_steps, [&] { op.solve(x, rhs); }));
    }
  double sum_step = 0, sum_solve = 0;
  for (unsigned int r = 0; r < n_rounds; ++r)
    {
      sum_step += t_step[r];
      sum_solve += t_solve[r];
    }
  const double mean_step = sum_step / n_rounds, mean_solve = sum_solve / n_rounds;

  // ------------------------------------- the pieces of advance(), alone
  const unsigned int n_pieces = std::max(4u, n_steps);
  Vector             tmp, tmp2;
  m.space->reinit(tmp);
  m.space->reinit(tmp2);
  tmp              = s.v;
  const double t_mv_m = per_call(n_pieces, [&] { m.mass.vmult(tmp2, tmp); });
  const double t_mv_k = per_call(n_pieces, [&] { m.stiffness.vmult(tmp2, tmp); });
  const double t_zero = per_call(n_pieces, [&] { m.space->constraints.set_zero(tmp2); });
  // the vector work of advance(): 7 assignments (copies), 6 add/axpy, 2 -=, 1 +=
  Vector       up, vp;
  m.space->reinit(up);
  m.space->reinit(vp);
  const double t_vec = per_call(n_pieces, [&] {
    up = s.u;
    up.add(dt, s.v, 0.5 * dt * dt, s.a);
    vp = s.v;
    vp.add(dt, s.a);
    tmp2 = load;
    tmp  = s.a;
    tmp.add(0.1, vp);
    tmp2 -= x;
    tmp = up;
    tmp.add(0.1, vp);
    tmp2 -= x;
    x = up;
    x.add(1e-9, rhs);
    x = vp;
    x.add(1e-9, rhs);
    x += rhs;
  });
  const double t_load = per_call(n_pieces, [&] {
    load = m.gravity;
    load.add(-0.1, m.influence[0]);
  });

  // --------------------- PETSc log of a few more steps (the in-step MatSolve)
  PetscLogDefaultBegin();
  const char *events[] = {"MatSolve", "MatMult", "VecSetValues", "VecAssemblyBegin",
                          "VecAssemblyEnd", "VecCopy", "VecAXPY", "VecAXPBYCZ", "VecAYPX"};
  std::map<std::string, std::pair<double, int>> before;
  for (const char *e : events)
    before[e] = petsc_event(e);
  const double t_logged = per_call(n_steps, step);

  // ------------------------------------------------------------ report
  const double ratio = mean_step / mean_solve;
  out << std::defaultfloat;
  bench::figure(out, "setup: Kbar again, as the Newmark ctor [s]") << t_kbar << nd << std::endl;
  bench::figure(out, "setup: factorization again (FactorizedOperator) [s]")
    << t_factor2 << nd << std::endl;
  bench::figure(out, "peak memory after factorization + steps [GB]")
    << peak_model << nd << std::endl;
  out << std::setprecision(4);
  bench::figure(out, "step (load + advance) [s]")
    << mean_step << " mean, " << median(t_step) << " median of " << n_rounds << " rounds x "
    << n_steps << " steps" << nd << std::endl;
  bench::figure(out, "back-substitution (FactorizedOperator::solve) [s]")
    << mean_solve << " mean, " << median(t_solve) << " median of " << n_rounds
    << " rounds x " << n_steps << nd << std::endl;
  bench::figure(out, "ratio step / back-substitution")
    << std::setprecision(2) << ratio << " (median " << median(t_step) / median(t_solve)
    << "), target <= 3: " << (ratio <= 3 ? "met" : "NOT met") << nd << std::endl;
  out << std::setprecision(4);
  out << "  rounds step [s]:";
  for (const double t : t_step)
    out << " " << t;
  out << "\n  rounds back-substitution [s]:";
  for (const double t : t_solve)
    out << " " << t;
  out << std::endl;
  bench::figure(out, "piece: M.vmult [s]") << t_mv_m << nd << std::endl;
  bench::figure(out, "piece: K.vmult [s]") << t_mv_k << nd << std::endl;
  bench::figure(out, "piece: constraints.set_zero [s]")
    << t_zero << " (" << m.space->constraints.n_constraints() << " entries)" << nd
    << std::endl;
  bench::figure(out, "piece: vector updates of advance [s]") << t_vec << nd << std::endl;
  bench::figure(out, "piece: load F(t) [s]") << t_load << nd << std::endl;
  bench::figure(out, "pieces sum + back-substitution [s]")
    << t_mv_m + t_mv_k + t_zero + t_vec + t_load + mean_solve << " (vs step " << mean_step
    << ")" << nd << std::endl;

  bench::figure(out, "step with PETSc logging on [s]") << t_logged << nd << std::endl;
  for (const char *e : events)
    {
      const auto after = petsc_event(e);
      const int  calls = after.second - before[e].second;
      if (calls == 0)
        continue;
      bench::figure(out, std::string("  in-step PETSc event ") + e + " [s/step]")
        << (after.first - before[e].first) / n_steps << " (" << calls / n_steps
        << " calls/step)" << std::endl;
    }

  bench::figure(out, "peak memory at the end (2 factors) [GB]")
    << bench::memory_gb("VmHWM") << nd << std::endl;
  return 0;
}
