// The fixed-state system of the contact problem by its low-rank update
// (joints::PairSystem, doc/theory/joints.md §6) against a direct LU of the
// same system assembled row by row (the second method). The flexibility is
// a synthetic one with the structure of the joints' W: symmetric positive
// definite, coupling decaying with distance (exp(-r / 8 m) / (1 + r / 8 m)
// plus the pair's own 3 x 3 block) over 150 pairs on three joint planes.
// A sequence of 40 solves with random states (stick, slip with its Newton
// rows kappa P hC and own entries, separation), each state drawn anew, so
// that rows enter and leave the update and the kept columns of Z are reused:
//  1. every solution equals the direct one to 1e-10 of its largest entry;
//  2. the first solve builds the base's LU, an all-stick system keeps it
//     as it is, every other solve updates it; a new h builds the base anew
//     (and its solution again equals the direct one);
//  3. a system with every pair separated (every row replaced, the largest
//     update) gives each row's rhs over its own entry, and one on a joint's
//     pairs alone (the joint-by-joint systems) equals its own direct solve.
#include <archdam/joints/pair_system.h>

#include <deal.II/lac/lapack_full_matrix.h>

#include <numeric>
#include <random>

#include "archdam_tests.h"

using namespace archdam;
using joints::PairSystem;
using joints::SystemRow;

namespace
{
  enum class State
  {
    stick,
    slip,
    separation
  };

  /// The law's rows as the mixed solver writes them (stick: the flexibility
  /// row; slip: the normal flexibility row and two Newton rows; separation:
  /// an own entry), with random directions, kappa and right-hand sides.
  struct Rows
  {
    std::vector<State>     state;
    std::vector<SystemRow> rows; // dim per pair

    Rows(const unsigned int n_pairs, const std::vector<double> &C, const double hc,
         std::mt19937 &random, const double p_slip, const double p_open)
      : state(n_pairs)
      , rows(dim * n_pairs)
    {
      std::uniform_real_distribution<double> u(0., 1.), s(-1., 1.);
      const unsigned int                     m = dim * n_pairs;
      for (unsigned int i = 0; i < n_pairs; ++i)
        {
          const double x = u(random);
          state[i]       = x < p_open ? State::separation :
                           x < p_open + p_slip ? State::slip :
                                                 State::stick;
          const double angle = 2 * M_PI * u(random), kappa = u(random) < 0.3 ? 0. : u(random);
          const double d[dim] = {0., std::cos(angle), std::sin(angle)};
          const double r      = 1. / (hc * C[(dim * i + 1) * m + dim * i + 1]);
          for (unsigned int k = 0; k < dim; ++k)
            {
              SystemRow &row = rows[dim * i + k];
              row.rhs        = 1e-3 * s(random);
              if (state[i] == State::separation)
                row.own[k] = hc * C[(dim * i + k) * m + dim * i + k];
              else if (state[i] == State::slip && k > 0)
                {
                  for (const unsigned int l : {1u, 2u})
                    {
                      const double P = (k == l ? 1. : 0.) - d[k] * d[l];
                      row.flex[l]    = kappa * P;
                      row.own[l]     = ((k == l ? 1. : 0.) - kappa * P) / r;
                    }
                  row.own[0] = 0.7 * d[k] / r;
                }
              else
                row.flex[k] = 1.;
            }
        }
    }
  };

  /// The system on @p pairs assembled densely and solved by LU.
  dealii::Vector<double>
  direct(const Rows &r, const std::vector<unsigned int> &pairs, const std::vector<double> &C,
         const unsigned int m, const double hc)
  {
    const unsigned int               n = dim * pairs.size();
    dealii::LAPACKFullMatrix<double> A(n, n);
    dealii::Vector<double>           x(n);
    for (unsigned int p = 0; p < pairs.size(); ++p)
      for (unsigned int k = 0; k < dim; ++k)
        {
          const SystemRow &row = r.rows[dim * pairs[p] + k];
          for (unsigned int l = 0; l < dim; ++l)
            {
              for (unsigned int q = 0; q < pairs.size(); ++q)
                for (unsigned int c = 0; c < dim; ++c)
                  A(dim * p + k, dim * q + c) +=
                    row.flex[l] * hc * C[(dim * pairs[p] + l) * m + dim * pairs[q] + c];
              A(dim * p + k, dim * p + l) += row.own[l];
            }
          x(dim * p + k) = row.rhs;
        }
    A.compute_lu_factorization();
    A.solve(x);
    return x;
  }

  double
  relative_difference(const dealii::Vector<double> &x, const dealii::Vector<double> &ref)
  {
    double diff = 0.;
    for (unsigned int j = 0; j < x.size(); ++j)
      diff = std::max(diff, std::abs(x(j) - ref(j)));
    return diff / ref.linfty_norm();
  }
} // namespace

int
main(int argc, char **argv)
{
  dealii::Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  auto                                    &log = testing::log();

  // 150 pairs, 50 on each of three parallel joint planes 20 m apart, on a
  // 5 x 10 grid of 5 m.
  const unsigned int                  n_pairs = 150, m = dim * n_pairs;
  std::vector<std::array<double, 3>> at(n_pairs);
  for (unsigned int i = 0; i < n_pairs; ++i)
    at[i] = {{20. * (i / 50), 5. * (i % 5), 5. * ((i % 50) / 5)}};
  std::vector<double> C(m * m);
  std::mt19937        random(2026);
  for (unsigned int i = 0; i < n_pairs; ++i)
    for (unsigned int j = 0; j < n_pairs; ++j)
      {
        const double r = std::hypot(at[i][0] - at[j][0], at[i][1] - at[j][1], at[i][2] - at[j][2]);
        const double c = 1e-9 * std::exp(-r / 8.) / (1. + r / 8.);
        for (unsigned int k = 0; k < dim; ++k)
          C[(dim * i + k) * m + dim * j + k] = c * (k == 0 ? 1. : 0.6);
      }
  for (unsigned int i = 0; i < n_pairs; ++i) // the pair's own block: more normal than tangential
    C[(dim * i + 1) * m + dim * i + 2] = C[(dim * i + 2) * m + dim * i + 1] = 0.1e-9;
  const double hc = 2.5e-6;

  std::vector<unsigned int> all(n_pairs);
  std::iota(all.begin(), all.end(), 0u);
  PairSystem             system(all);
  dealii::Vector<double> x;
  double                 worst = 0.;
  bool                   outcomes_as_expected = true;
  for (unsigned int solve = 0; solve < 40; ++solve)
    {
      // the first and every tenth all stick; the others a share of slipping
      // and separated pairs from a few per cent to all of them
      const double p_slip = solve % 10 == 0 ? 0. : 0.6 * (solve % 7) / 6.;
      const double p_open = solve % 10 == 0 ? 0. : 0.4 * (solve % 5) / 4.;
      const Rows   r(n_pairs, C, hc, random, p_slip, p_open);
      const auto   how = system.solve(
        C, m, hc, [&](const unsigned int i, const unsigned int k) { return r.rows[dim * i + k]; },
        x);
      worst                             = std::max(worst, relative_difference(x, direct(r, all, C, m, hc)));
      const bool all_stick              = std::count(r.state.begin(), r.state.end(), State::stick) ==
                             static_cast<long>(n_pairs);
      const PairSystem::Solve expected = solve == 0 ? PairSystem::Solve::factorized :
                                         all_stick  ? PairSystem::Solve::kept :
                                                      PairSystem::Solve::updated;
      outcomes_as_expected = outcomes_as_expected && how == expected;
    }
  log << "40 solves with random states against a direct LU of the same system:" << std::endl;
  testing::check_below("  largest difference / largest entry", worst, 1e-10);
  log << "  the base factorized at the first solve, kept when all pairs stick, updated "
         "otherwise: "
      << testing::yes(outcomes_as_expected) << std::endl;

  {
    const Rows r(n_pairs, C, 2. * hc, random, 0.3, 0.2);
    const auto how = system.solve(
      C, m, 2. * hc, [&](const unsigned int i, const unsigned int k) { return r.rows[dim * i + k]; },
      x);
    log << "another h: the base built anew: " << testing::yes(how == PairSystem::Solve::factorized)
        << std::endl;
    testing::check_below("  largest difference / largest entry",
                         relative_difference(x, direct(r, all, C, m, 2. * hc)), 1e-10);
  }
  {
    // every row replaced (k = n): A is the diagonal of the own entries
    const Rows r(n_pairs, C, 2. * hc, random, 0., 1.);
    system.solve(
      C, m, 2. * hc, [&](const unsigned int i, const unsigned int k) { return r.rows[dim * i + k]; },
      x);
    dealii::Vector<double> diagonal(m);
    for (unsigned int a = 0; a < m; ++a)
      diagonal(a) = r.rows[a].rhs / r.rows[a].own[a % dim];
    testing::check_below("every pair separated (every row replaced): largest difference from "
                         "rhs / own entry, relative",
                         relative_difference(x, diagonal), 1e-10);
  }
  {
    // the second joint's pairs alone
    std::vector<unsigned int> joint(50);
    std::iota(joint.begin(), joint.end(), 50u);
    PairSystem of_joint(joint);
    double     worst_joint = 0.;
    for (unsigned int solve = 0; solve < 10; ++solve)
      {
        const Rows r(n_pairs, C, hc, random, 0.4, 0.2);
        of_joint.solve(
          C, m, hc, [&](const unsigned int i, const unsigned int k) { return r.rows[dim * i + k]; },
          x);
        worst_joint = std::max(worst_joint, relative_difference(x, direct(r, joint, C, m, hc)));
      }
    testing::check_below("one joint's pairs alone, 10 solves: largest difference / largest entry",
                         worst_joint, 1e-10);
  }
}
