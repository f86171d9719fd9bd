// Benchmark (issue 19; doc/performance.md §7): the fill-reducing order of the
// condensed factorization on a real case, by default the reference case on
// its production mesh (prm/paper_235m_dam.prm: Q2 2 x 2 x 9, 291,114 DOFs,
// 1,170 node pairs; the measurements of bench/RESULTS.md before 2026-11-29
// were made on the former 2 x 2 x 6, 245,706 DOFs, 780 node pairs). On the dynamic stage's effective matrix (the coupled dam-water
// system with the foundation's dashpots, made by
// Simulation::make_integrator()) with the node pairs' DOFs last:
//   nested dissection: METIS on the node graph (time/fill_reducing_order.h,
//                      the library's order)
//   PORD:              MUMPS's own order (the library's order before)
//   SCOTCH:            SCOTCH's nested dissection of the same node graph
// For each: the wall time of the factorization (order, analysis and
// factorization), the factor's entries, the elimination's operations and the
// memory MUMPS used (INFOG(29), RINFOG(3), INFOG(22)), and the mean wall
// time of the forward elimination and the backward substitution of one
// solve. The solves are checked against a manufactured solution: b = Kbar x
// for a known x, and the relative error of each factor's solution, both in
// the unknowns' own scale: x_i = r_i / sqrt|Kbar_ii| with r_i random in
// [-1, 1], the error max_i sqrt|Kbar_ii| |x_i - x*_i| / max_i |r_i|. (A
// vector of ones in every unknown put the water's potentials, whose entries
// are about 1e-9 of the displacements', eight orders off their scale: its
// error measured the conditioning of that vector, not the factor.)
// Then, on one factor of the library's order, the solves with MUMPS's
// products of one column made by dgemv (time/single_column_products.h, the
// library's way) and by the BLAS's dgemm, alternating, N solves each per
// round, and the largest difference of the two solutions.
// Then MUMPS's block low-rank factorization (ICNTL(35) = 2: compressed
// factors used in the solves) at each dropping tolerance CNTL(7) of
// --low-rank (default 1e-10, 1e-8, 1e-6, 1e-4) against the full-rank factor
// of the library's order, one factorization alive at a time: the same
// columns as the orders' table, the resident memory of the process with the
// factor alive, and the largest difference of the solution from the
// full-rank factor's, in the same scale as the error (the accuracy a step
// would lose).
//
// Then the factor in single precision against double (time::Precision,
// `Time integration/Factor precision`) at each dropping tolerance of
// --single (default 0, 1e-8, 1e-6; 0 is full rank): the same columns, the
// error of each, and that of the single-precision factor after one step of
// iterative refinement in double.
//
//   bench_factor_orders [CASE.prm] [--set "Section/Parameter=value"]...
//                       [--rounds R] [--solves N] [--low-rank TOL,TOL,...]
//                       [--single TOL,TOL,...] [--precision-only TOL,TOL,...]
//
// --precision-only measures the precisions alone, at the tolerances given.
//
// Defaults: the reference case, --rounds 1 (each factorization takes about
// a minute there), --solves 5. Rounds alternate the orders, one
// factorization alive at a time. The integrator's own factorization, made
// first, is released before the rounds.

#include <archdam/analysis/simulation.h>
#include <archdam/parameters/parameters.h>
#include <archdam/time/condensed_factorization.h>
#include <archdam/time/single_column_products.h>

#include <deal.II/base/timer.h>

#include <cmath>
#include <iomanip>
#include <tuple>
#include <iostream>
#include <random>

#include "bench_common.h"

using namespace archdam;
using Ordering = time::CondensedFactorization::Ordering;

namespace
{
  struct Result
  {
    double factorization = 0., elimination = 0., substitution = 0., error = 0.;
    double resident = 0.; ///< the process's resident memory with the factor alive [GB]
    double refined  = 0.; ///< the error after one step of iterative refinement
    time::CondensedFactorization::Statistics statistics;
  };

  /// max_i sqrt|A_ii| |x_i - x*_i| / max_i sqrt|A_ii| |x*_i|: the error in
  /// the unknowns' own scale.
  double
  scaled_error(const SparseMatrix &A, const Vector &x, const Vector &x_exact)
  {
    double error = 0., size = 0.;
    for (const auto i : x.locally_owned_elements())
      {
        const double scale = std::sqrt(std::abs(A.diag_element(i)));
        error              = std::max(error, scale * std::abs(x(i) - x_exact(i)));
        size               = std::max(size, scale * std::abs(x_exact(i)));
      }
    return dealii::Utilities::MPI::max(error, MPI_COMM_WORLD) /
           dealii::Utilities::MPI::max(size, MPI_COMM_WORLD);
  }

  /// @p solves solves of A x = b with @p factor; their mean elimination and
  /// substitution times into @p r.
  void
  solve(const time::CondensedFactorization &factor, const Vector &b, const unsigned int solves,
        Vector &x, Result &r)
  {
    const auto             before = factor.solve_times();
    dealii::Vector<double> x_gamma;
    for (unsigned int k = 0; k < solves; ++k)
      {
        factor.condense(b, x_gamma);
        factor.solve_interface(x_gamma);
        factor.expand(x_gamma, x);
      }
    const auto after = factor.solve_times();
    r.elimination    = (after.elimination - before.elimination) / solves;
    r.substitution   = (after.substitution - before.substitution) / solves;
  }

  /// Factorize A in @p ordering and @p precision (block low-rank if @p
  /// low_rank > 0), solve @p solves times; the solution into @p x, and the
  /// error after one step of iterative refinement in double, x + A~^{-1}
  /// (b - A x), into r.refined.
  Result
  measure(const SparseMatrix &A, const std::vector<dealii::types::global_dof_index> &interface,
          const Ordering ordering, const Vector &b, const Vector &x_exact,
          const unsigned int solves, Vector &x, const double low_rank = 0.,
          const time::Precision precision = time::Precision::double_precision)
  {
    Result        r;
    dealii::Timer timer;
    // The effective matrix of the coupled system is indefinite: LDL^T, as
    // the integrator factorizes it.
    const time::CondensedFactorization factor(A, false, interface, ordering, low_rank,
                                              precision);
    r.factorization = timer.wall_time();
    r.statistics    = factor.statistics();
    r.resident      = bench::memory_gb("VmRSS");
    solve(factor, b, solves, x, r);
    r.error = scaled_error(A, x, x_exact);
    Vector residual(b), refined(b);
    A.vmult(residual, x);
    residual.sadd(-1., 1., b);
    Result once;
    solve(factor, residual, 1, refined, once);
    refined += x;
    r.refined = scaled_error(A, refined, x_exact);
    return r;
  }

  void
  table_header(std::ostream &out, const std::string &first)
  {
    out << std::left << std::setw(28) << first << std::right << std::setw(12) << "factor [s]"
        << std::setw(14) << "entries" << std::setw(14) << "operations" << std::setw(13)
        << "memory [GB]" << std::setw(14) << "resident [GB]" << std::setw(16)
        << "elimination [s]" << std::setw(17) << "substitution [s]" << std::setw(12) << "error"
        << "\n";
  }

  void
  table_row(std::ostream &out, const std::string &first, const Result &m)
  {
    out << std::left << std::setw(28) << first << std::right << std::setprecision(3)
        << std::setw(12) << m.factorization << std::setw(14) << m.statistics.entries
        << std::setw(14) << m.statistics.operations << std::setw(13)
        << 1e-9 * m.statistics.memory << std::setw(14) << m.resident << std::setw(16)
        << m.elimination << std::setw(17) << m.substitution << std::setw(12) << m.error << "\n";
  }

  /// "LABEL, quantity: a / b" for each column of the tables.
  void
  ratios(std::ostream &out, const std::string &label, const Result &a, const Result &b)
  {
    out << "\n";
    for (const auto &[name, x, y] : std::vector<std::tuple<std::string, double, double>>{
           {"factorization time", a.factorization, b.factorization},
           {"factor entries", a.statistics.entries, b.statistics.entries},
           {"operations", a.statistics.operations, b.statistics.operations},
           {"MUMPS memory", a.statistics.memory, b.statistics.memory},
           {"resident memory", a.resident, b.resident},
           {"elimination", a.elimination, b.elimination},
           {"substitution", a.substitution, b.substitution}})
      bench::figure(out, label + ", " + name) << std::setprecision(3) << x / y << "\n";
  }

  std::vector<double>
  tolerances(const std::string &list)
  {
    std::vector<double> t;
    std::istringstream  in(list);
    for (std::string item; std::getline(in, item, ',');)
      t.push_back(std::stod(item));
    return t;
  }
} // namespace

int
main(int argc, char **argv)
{
  dealii::Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  unsigned int        rounds = 1, solves = 5;
  std::vector<double> low_rank = {1e-10, 1e-8, 1e-6, 1e-4}, single = {0., 1e-8, 1e-6};
  bool                orders = true; // the orders' and the products' tables
  const auto [file, overrides] = bench::case_arguments(
    argc, argv, "prm/paper_235m_dam.prm", [&](const std::string &a, int &i) {
      if (a == "--rounds")
        rounds = std::stoi(argv[++i]);
      else if (a == "--solves")
        solves = std::stoi(argv[++i]);
      else if (a == "--low-rank")
        low_rank = tolerances(argv[++i]);
      else if (a == "--single")
        single = tolerances(argv[++i]);
      else if (a == "--precision-only")
        {
          orders = false;
          low_rank.clear();
          single = tolerances(argv[++i]);
        }
      else
        return false;
      return true;
    });
  auto &out = bench::screen();

  const Parameters     p = read_parameters(file, overrides);
  std::ostringstream   quiet;
  analysis::Simulation sim(p, MPI_COMM_WORLD, quiet);
  dealii::Timer        setup;
  const auto          &model = sim.setup_model();
  AssertThrow(model.joint_pairs(), dealii::ExcMessage("The case has no joints in contact."));
  const auto interface = model.joint_pairs()->interface();
  out << file << ": " << model.space().dof_handler.n_dofs() << " DOFs, "
      << model.joint_pairs()->size() << " node pairs (" << interface.size()
      << " interface DOFs), " << dealii::Utilities::MPI::n_mpi_processes(MPI_COMM_WORLD)
      << " MPI process(es); setup " << std::setprecision(3) << setup.wall_time() << " s\n";

  // The effective matrix, copied; the integrator and its factorization
  // released before the rounds.
  SparseMatrix A;
  {
    const auto integrator = sim.make_integrator();
    A.reinit(integrator->effective());
    A.copy_from(integrator->effective());
  }
  Vector x_exact, b;
  model.space().reinit(x_exact);
  model.space().reinit(b);
  std::mt19937                           random(42);
  std::uniform_real_distribution<double> uniform(-1., 1.);
  for (const auto i : x_exact.locally_owned_elements())
    {
      const double diagonal = std::abs(A.diag_element(i));
      x_exact(i)            = diagonal > 0. ? uniform(random) / std::sqrt(diagonal) : 0.;
    }
  x_exact.compress(dealii::VectorOperation::insert);
  model.space().constraints.set_zero(x_exact);
  A.vmult(b, x_exact);

  if (orders)
    {
      const std::vector<std::pair<Ordering, std::string>> by_order = {
        {Ordering::nested_dissection, "nested dissection (METIS)"},
        {Ordering::pord, "PORD"},
        {Ordering::scotch, "nested dissection (SCOTCH)"}};
      std::vector<std::vector<Result>> results(by_order.size());
      Vector                           x(b);
      for (unsigned int r = 0; r < rounds; ++r)
        for (unsigned int o = 0; o < by_order.size(); ++o)
          results[o].push_back(measure(A, interface, by_order[o].first, b, x_exact, solves, x));

      out << "\nper order, means over " << rounds << " round(s), " << solves
          << " solves each; peak resident memory of the process " << std::setprecision(3)
          << bench::memory_gb("VmHWM") << " GB\n";
      table_header(out, "order");
      std::vector<Result> mean(by_order.size());
      for (unsigned int o = 0; o < by_order.size(); ++o)
        {
          for (const auto &r : results[o])
            {
              mean[o].factorization += r.factorization / rounds;
              mean[o].elimination += r.elimination / rounds;
              mean[o].substitution += r.substitution / rounds;
              mean[o].error = std::max(mean[o].error, r.error);
            }
          mean[o].statistics = results[o].front().statistics;
          mean[o].resident   = results[o].front().resident;
          table_row(out, by_order[o].second, mean[o]);
        }
      ratios(out, "nested dissection / PORD", mean[0], mean[1]);
      ratios(out, "SCOTCH / METIS", mean[2], mean[0]);

      // The products of one column: dgemv against the BLAS's dgemm, on one
      // factor, alternating.
      {
        const time::CondensedFactorization factor(A, false, interface, Ordering::nested_dissection);
        Vector                             x_gemv(b), x_gemm(b);
        Result                             gemv, gemm;
        for (unsigned int r = 0; r < rounds; ++r)
          for (const bool forward : {true, false})
            {
              Result one;
              time::forward_single_column_products(forward);
              solve(factor, b, solves, forward ? x_gemv : x_gemm, one);
              auto &sum = forward ? gemv : gemm;
              sum.elimination += one.elimination / rounds;
              sum.substitution += one.substitution / rounds;
            }
        time::forward_single_column_products(true);
        x_gemm -= x_gemv;
        out << "\nsolves with MUMPS's products of one column by dgemv and by dgemm (" << rounds
            << " round(s) of " << solves << " solves each, alternating)\n"
            << std::left << std::setw(28) << "products of one column" << std::right
            << std::setw(16) << "elimination [s]" << std::setw(17) << "substitution [s]" << "\n";
        for (const auto &[name, m] : {std::pair<std::string, Result>{"dgemv", gemv}, {"dgemm", gemm}})
          out << std::left << std::setw(28) << name << std::right << std::setprecision(3)
              << std::setw(16) << m.elimination << std::setw(17) << m.substitution << "\n";
        out << "\n";
        bench::figure(out, "dgemv / dgemm, elimination") << gemv.elimination / gemm.elimination << "\n";
        bench::figure(out, "dgemv / dgemm, substitution")
          << gemv.substitution / gemm.substitution << "\n";
        bench::figure(out, "largest difference of the two solutions / largest entry")
          << x_gemm.linfty_norm() / x_gemv.linfty_norm() << "\n";
      }
    }

  // Block low-rank factors against the full-rank one, one alive at a time.
  if (!low_rank.empty())
    {
      Vector       x_full(b), x_low(b);
      const Result full =
        measure(A, interface, Ordering::nested_dissection, b, x_exact, solves, x_full);
      out << "\nblock low-rank factorization (ICNTL(35) = 2, nested dissection), " << solves
          << " solves each; \"change\" is the largest difference of the solution from the "
             "full-rank factor's, in the unknowns' own scale (as the error)\n";
      table_header(out, "factor");
      table_row(out, "full rank", full);
      std::vector<std::pair<double, Result>> compressed;
      std::vector<double>                    change;
      for (const double tolerance : low_rank)
        {
          compressed.emplace_back(tolerance, measure(A, interface, Ordering::nested_dissection,
                                                     b, x_exact, solves, x_low, tolerance));
          change.push_back(scaled_error(A, x_low, x_full));
          std::ostringstream name;
          name << "low rank, CNTL(7) = " << tolerance;
          table_row(out, name.str(), compressed.back().second);
        }
      for (unsigned int k = 0; k < compressed.size(); ++k)
        {
          std::ostringstream label;
          label << "low rank " << compressed[k].first << " / full rank";
          ratios(out, label.str(), compressed[k].second, full);
          bench::figure(out, label.str() + ", change of the solution") << change[k] << "\n";
        }
    }

  // Single against double precision (time::Precision) at each
  // tolerance of --single (0: full rank), one factor alive at a time.
  if (!single.empty())
    {
      out << "\nsingle against double precision (nested dissection), " << solves
          << " solves each; \"refined\" is the error after one step of iterative refinement "
             "in double (one product with A and one more solve)\n";
      table_header(out, "factor");
      std::vector<std::pair<Result, Result>> pairs;
      for (const double tolerance : single)
        {
          std::pair<Result, Result> pair;
          for (const auto precision :
               {time::Precision::double_precision, time::Precision::single_precision})
            {
              Vector       x_p(b);
              const Result r = measure(A, interface, Ordering::nested_dissection, b, x_exact,
                                       solves, x_p, tolerance, precision);
              const bool   in_single = precision == time::Precision::single_precision;
              (in_single ? pair.second : pair.first) = r;
              std::ostringstream name;
              name << (in_single ? "single" : "double") << ", CNTL(7) = " << tolerance;
              table_row(out, name.str(), r);
            }
          pairs.push_back(pair);
        }
      for (unsigned int k = 0; k < pairs.size(); ++k)
        {
          std::ostringstream label;
          label << "single / double at CNTL(7) = " << single[k];
          ratios(out, label.str(), pairs[k].second, pairs[k].first);
          bench::figure(out, label.str() + ", error in single, refined once")
            << pairs[k].second.error << ", " << pairs[k].second.refined << "\n";
        }
      std::ostringstream label;
      label << "single at CNTL(7) = " << single.back() << " / double at " << single.front();
      ratios(out, label.str(), pairs.back().second, pairs.front().first);
    }
  return 0;
}
