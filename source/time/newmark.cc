#include <archdam/base/input_error.h>
#include <archdam/time/newmark.h>

#include <cmath>
#include <sstream>

namespace archdam::time
{
  using namespace dealii;

  void
  NewmarkParameters::add_parameters(ParameterHandler &prm)
  {
    prm.add_parameter("Time step", time_step, "Time step dt [s], fixed for the run.",
                      Patterns::Double(0., Patterns::Double::max_double_value));
    prm.add_parameter("End time", end_time,
                      "End of the dynamic stage [s]; 0 = the duration of the "
                      "ground motion (on massed rock plus the time its wave "
                      "takes to reach the free surface).",
                      Patterns::Double(0.));
    prm.add_parameter("Beta1", beta1,
                      "Newmark's gamma (paper eq. 2.2): 0.5 = no numerical "
                      "damping; > 0.5 damps high frequencies.",
                      Patterns::Double(0., 1.));
    prm.add_parameter("Beta2", beta2,
                      "Newmark's beta (paper eq. 2.2): 0.25 with Beta1 = 0.5 is "
                      "the average acceleration rule.",
                      Patterns::Double(0., 1.));
    prm.add_parameter("Low-rank tolerance", low_rank_tolerance,
                      "Dropping tolerance of the block low-rank compression of the "
                      "factor of the effective matrix (MUMPS's BLR, relative to the "
                      "scaled matrix's entries); 0 = the full-rank factor. The steps' "
                      "substitutions then cost less and are exact to about this "
                      "tolerance (doc/performance.md §8). For frictional joints with the "
                      "mixed solver, whose factor is condensed on the node pairs.",
                      Patterns::Double(0., 1e-3));
    add_selection(prm, "Factor precision", factor_precision, precision_names(),
                  "The arithmetic of the factor of the effective matrix: double, or single "
                  "(the factor's bytes halved, and the steps' substitutions about 0.6 of "
                  "their time in double; each solve then exact to about 1e-5 of the "
                  "solution in the unknowns' own scale, doc/performance.md §8). For "
                  "frictional joints with the mixed solver, whose factor is condensed on the "
                  "node pairs.");
    add_selection(prm, "Product precision", product_precision, precision_names(),
                  "The arithmetic of the entries of M and D, and of the prescribed outer "
                  "boundary's columns, in each step's effective load: double, or single (one "
                  "pass over their entries, each read in single precision: these products then "
                  "take about half their time in double, each row exact to 6e-8 of the sum of "
                  "its terms' magnitudes; K's product, which carries the static state's "
                  "forces, stays in double; doc/performance.md §11).");
  }

  void
  NewmarkParameters::check() const
  {
    if (!(time_step > 0.))
      throw InputError("Time integration: Time step must be positive (it is " +
                       std::to_string(time_step) + " s).");
    if (beta1 < 0.5 || beta2 < 0.25 * (beta1 + 0.5) * (beta1 + 0.5) - 1e-12)
      throw InputError("Time integration: Beta1 = " + std::to_string(beta1) +
                       ", Beta2 = " + std::to_string(beta2) +
                       " is not unconditionally stable; need Beta1 >= 0.5 and "
                       "Beta2 >= (Beta1 + 0.5)^2 / 4 (doc/theory/time-integration.md §6).");
    if (end_time > 0)
      n_steps(end_time);
  }

  unsigned int
  NewmarkParameters::n_steps(const double end) const
  {
    const double steps = end / time_step;
    const auto   both  = [&] {
      std::ostringstream s;
      s << "End time = " << end << " s with Time step = " << time_step << " s";
      return s.str();
    };
    if (!(steps < max_steps + 0.5))
      {
        std::ostringstream s;
        s << "Time integration: " << both() << " gives " << steps << " steps, more than the "
          << max_steps << " one run can take; check the units of both.";
        throw InputError(s.str());
      }
    if (!(steps >= 0.5))
      throw InputError("Time integration: " + both() +
                       " is shorter than one time step.");
    return static_cast<unsigned int>(std::lround(steps));
  }

  NewmarkIntegrator::NewmarkIntegrator(const NewmarkParameters         &p,
                                       const SparseMatrix              &mass,
                                       const SparseMatrix              &stiffness,
                                       const SparseMatrix              *damping,
                                       const std::pair<double, double>  rayleigh,
                                       const AffineConstraints<double> &constraints,
                                       const Vector                    *boundary_dashpots)
    : p(p)
    , dt(p.time_step)
    , M(mass)
    , K(stiffness)
    , D(damping)
    , alpha(rayleigh.first)
    , beta(rayleigh.second)
    , constraints(constraints)
    , dashpots(boundary_dashpots)
  {}

  NewmarkIntegrator::NewmarkIntegrator(const NewmarkParameters         &p,
                                       const SparseMatrix              &mass,
                                       const SparseMatrix              &stiffness,
                                       const std::pair<double, double>  rayleigh,
                                       const AffineConstraints<double> &constraints,
                                       const Vector                    *boundary_dashpots,
                                       const std::vector<types::global_dof_index> &factor_interface)
    : NewmarkIntegrator(p, mass, stiffness, nullptr, rayleigh, constraints, boundary_dashpots)
  {
    // Kbar = (1 + alpha beta1 dt) M + (beta beta1 dt + beta2 dt^2) K  (eq. 2.4).
    // M and K share one sparsity pattern (solid_operators.cc), so PETSc can
    // add them entry by entry; deal.II's add() assumes different patterns and
    // is ~30x slower.
    AssertThrow(M.n_nonzero_elements() == K.n_nonzero_elements(),
                ExcMessage("M and K must share their sparsity pattern."));
    build_effective_operator(beta * p.beta1 * dt + p.beta2 * dt * dt,
                             {{1. + alpha * p.beta1 * dt, &M}}, true, factor_interface);
  }

  void
  NewmarkIntegrator::build_effective_operator(
    const double                                              k_factor,
    const std::vector<std::pair<double, const SparseMatrix *>> &terms,
    const bool                                                positive_definite,
    const std::vector<types::global_dof_index>               &factor_interface)
  {
    effective_matrix.reinit(K);
    effective_matrix.copy_from(K);
    effective_matrix *= k_factor;
    for (const auto &[c, A] : terms)
      AssertThrow(MatAXPY(effective_matrix.petsc_matrix(), c, static_cast<Mat>(*A),
                          SAME_NONZERO_PATTERN) == 0,
                  ExcMessage("PETSc MatAXPY failed."));
    add_dashpots_to_effective_matrix();
    effective_operator.factorize(effective_matrix, positive_definite, factor_interface,
                                 p.low_rank_tolerance, p.factor_precision);

    const IndexSet owned = M.locally_owned_range_indices();
    for (Vector *v : {&up, &vp, &rhs, &tmp, &da, &prescribed_a, &prescribed_v, &prescribed_u,
                      &reduced_load})
      v->reinit(owned, M.get_mpi_communicator());
  }

  void
  NewmarkIntegrator::hold_in_single_precision(const PrescribedDofs *prescribed)
  {
    if (p.product_precision != Precision::single_precision)
      return;
    if (!load_products)
      load_products = std::make_unique<SinglePrecisionProducts>(
        D != nullptr ? std::vector<const SparseMatrix *>{&M, D} :
                       std::vector<const SparseMatrix *>{&M});
    if (prescribed != nullptr && columns_of != prescribed)
      {
        column_products =
          std::make_unique<SinglePrecisionProducts>(columns_of_matrices(*prescribed));
        columns_of = prescribed;
      }
  }

  void
  NewmarkIntegrator::add_dashpots_to_effective_matrix()
  {
    if (!dashpots)
      return;
    tmp.reinit(*dashpots);
    tmp.equ(p.beta1 * dt, *dashpots);
    AssertThrow(MatDiagonalSet(effective_matrix.petsc_matrix(), tmp, ADD_VALUES) == 0,
                ExcMessage("PETSc MatDiagonalSet failed."));
  }

  NewmarkIntegrator::NewmarkIntegrator(const NewmarkParameters         &p,
                                       const SparseMatrix              &mass,
                                       const SparseMatrix              &damping,
                                       const SparseMatrix              &stiffness,
                                       const AffineConstraints<double> &constraints,
                                       const bool                       positive_definite,
                                       const Vector                    *boundary_dashpots,
                                       const std::vector<types::global_dof_index> &factor_interface)
    : NewmarkIntegrator(p, mass, stiffness, &damping, {0., 0.}, constraints, boundary_dashpots)
  {
    // Kbar = M + beta1 dt D + beta2 dt^2 K on the common pattern.
    build_effective_operator(p.beta2 * dt * dt, {{1., &M}, {p.beta1 * dt, D}},
                             positive_definite, factor_interface);
  }

  void
  NewmarkIntegrator::advance(const Vector &load_next, NewmarkState &s, const StepSolver &solve)
  {
    // predictors (eq. 2.1)
    up = s.u;
    up.add(dt, s.v, 0.5 * dt * dt, s.a);
    vp = s.v;
    vp.add(dt, s.a);

    // effective load (eq. 2.3)
    rhs = load_next;
    tmp = s.a;
    tmp.add(alpha, vp);
    hold_in_single_precision(nullptr);
    if (load_products && D != nullptr)
      {
        // D v_n in the same pass, for the energy balance
        if (damping_at_start.size() == 0)
          damping_at_start.reinit(vp);
        load_products->subtract_from({&tmp, &vp}, rhs, 1, s.v, damping_at_start);
      }
    else
      subtract_products(
        load_products.get(),
        [&] {
          return D != nullptr ? std::vector<const SparseMatrix *>{&M, D} :
                                std::vector<const SparseMatrix *>{&M};
        },
        D != nullptr ? std::vector<const Vector *>{&tmp, &vp} : std::vector<const Vector *>{&tmp},
        rhs);
    tmp = up;
    tmp.add(beta, vp);
    K.vmult(da, tmp);
    rhs -= da;
    if (dashpots)
      {
        tmp = vp;
        tmp.scale(*dashpots);
        rhs -= tmp;
      }
    constraints.set_zero(rhs);

    if (solve)
      solve(rhs, da);
    else
      effective_operator.solve(da, rhs);
    constraints.distribute(da); // constrained DOFs follow their masters

    // correctors (eq. 2.2)
    s.u = up;
    s.u.add(p.beta2 * dt * dt, da);
    s.v = vp;
    s.v.add(p.beta1 * dt, da);
    s.a += da;
    s.time += dt;
    ++s.step;
  }

  void
  NewmarkIntegrator::correct_displacement(const Vector &x, NewmarkState &s)
  {
    tmp = x;
    constraints.distribute(tmp);
    s.u.add(p.beta2 * dt * dt, tmp);
  }

  void
  NewmarkIntegrator::subtract_products(
    const SinglePrecisionProducts                          *copy,
    const std::function<std::vector<const SparseMatrix *>()> &matrices,
    const std::vector<const Vector *>                       &x,
    Vector                                                  &y)
  {
    if (copy)
      {
        copy->subtract_from(x, y);
        return;
      }
    const auto A = matrices();
    for (unsigned int k = 0; k < A.size(); ++k)
      {
        A[k]->vmult(da, *x[k]);
        y -= da;
      }
  }

  std::vector<const SparseMatrix *>
  NewmarkIntegrator::columns_of_matrices(const PrescribedDofs &prescribed) const
  {
    if (D == nullptr)
      return {&prescribed.mass_columns, &prescribed.stiffness_columns};
    AssertThrow(prescribed.damping_columns.m() == M.m(),
                ExcMessage("Prescribed DOFs with a general damping matrix need the "
                           "columns of that matrix (PrescribedDofs::damping_columns)."));
    return {&prescribed.mass_columns, &prescribed.stiffness_columns, &prescribed.damping_columns};
  }

  void
  NewmarkIntegrator::advance(const Vector              &load_next,
                             NewmarkState              &s,
                             const PrescribedDofs      &prescribed,
                             const std::vector<double> &u_next,
                             const StepSolver          &solve)
  {
    AssertDimension(u_next.size(), prescribed.dofs.size());
    // State of the prescribed DOFs at t_{n+1} (eq. 2.1-2.2 with da_b fixed by u_next).
    const IndexSet      &owned = s.u.locally_owned_elements();
    std::vector<double> u1, v1, a1;
    std::vector<types::global_dof_index> mine;
    prescribed_a = 0.;
    prescribed_v = 0.;
    prescribed_u = 0.;
    for (unsigned int k = 0; k < prescribed.dofs.size(); ++k)
      {
        const auto i = prescribed.dofs[k];
        if (!owned.is_element(i))
          continue;
        const double up_i = s.u[i] + dt * s.v[i] + 0.5 * dt * dt * s.a[i];
        const double da_i = (u_next[k] - up_i) / (p.beta2 * dt * dt);
        mine.push_back(i);
        u1.push_back(u_next[k]);
        v1.push_back(s.v[i] + dt * s.a[i] + p.beta1 * dt * da_i);
        a1.push_back(s.a[i] + da_i);
        prescribed_a(i) = a1.back() + alpha * v1.back();
        prescribed_v(i) = v1.back();
        prescribed_u(i) = u1.back() + beta * v1.back();
      }
    for (Vector *v : {&prescribed_a, &prescribed_v, &prescribed_u})
      v->compress(VectorOperation::insert);

    // M's, K's and (a general damping matrix's own) D's columns
    std::vector<const Vector *> column_vectors{&prescribed_a, &prescribed_u};
    if (D != nullptr)
      column_vectors.push_back(&prescribed_v);
    reduced_load = load_next;
    hold_in_single_precision(&prescribed);
    subtract_products(
      column_products.get(), [&] { return columns_of_matrices(prescribed); }, column_vectors,
      reduced_load);
    advance(reduced_load, s, solve);

    // advance() left the constrained DOFs at their predictors: set them.
    for (Vector *v : {&s.u, &s.v, &s.a})
      {
        const std::vector<double> &values = v == &s.u ? u1 : v == &s.v ? v1 : a1;
        v->set(mine, values);
        v->compress(VectorOperation::insert);
      }
  }
} // namespace archdam::time
