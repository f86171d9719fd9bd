#include <archdam/base/input_error.h>
#include <archdam/time/newmark.h>

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
                      "ground motion.",
                      Patterns::Double(0.));
    prm.add_parameter("Beta1", beta1,
                      "Newmark's gamma (paper eq. 2.2): 0.5 = no numerical "
                      "damping; > 0.5 damps high frequencies.",
                      Patterns::Double(0., 1.));
    prm.add_parameter("Beta2", beta2,
                      "Newmark's beta (paper eq. 2.2): 0.25 with Beta1 = 0.5 is "
                      "the average acceleration rule.",
                      Patterns::Double(0., 1.));
  }

  void
  NewmarkParameters::check() const
  {
    if (beta1 < 0.5 || beta2 < 0.25 * (beta1 + 0.5) * (beta1 + 0.5) - 1e-12)
      throw InputError("Time integration: Beta1 = " + std::to_string(beta1) +
                       ", Beta2 = " + std::to_string(beta2) +
                       " is not unconditionally stable; need Beta1 >= 0.5 and "
                       "Beta2 >= (Beta1 + 0.5)^2 / 4 (numerics.md §2).");
  }

  NewmarkIntegrator::NewmarkIntegrator(const NewmarkParameters         &p,
                                       const SparseMatrix              &mass,
                                       const SparseMatrix              &stiffness,
                                       const std::pair<double, double>  rayleigh,
                                       const AffineConstraints<double> &constraints)
    : p(p)
    , dt(p.time_step)
    , M(mass)
    , K(stiffness)
    , alpha(rayleigh.first)
    , beta(rayleigh.second)
    , constraints(constraints)
  {
    // Kbar = (1 + alpha beta1 dt) M + (beta beta1 dt + beta2 dt^2) K  (eq. 2.4).
    // M and K share one sparsity pattern (solid_operators.cc), so PETSc can
    // add them entry by entry; deal.II's add() assumes different patterns and
    // is ~30x slower.
    AssertThrow(M.n_nonzero_elements() == K.n_nonzero_elements(),
                ExcMessage("M and K must share their sparsity pattern."));
    effective_matrix.reinit(K);
    effective_matrix.copy_from(K);
    effective_matrix *= beta * p.beta1 * dt + p.beta2 * dt * dt;
    AssertThrow(MatAXPY(effective_matrix.petsc_matrix(), 1. + alpha * p.beta1 * dt,
                        static_cast<Mat>(M), SAME_NONZERO_PATTERN) == 0,
                ExcMessage("PETSc MatAXPY failed."));
    effective_operator.factorize(effective_matrix, true);

    const IndexSet owned = M.locally_owned_range_indices();
    for (Vector *v : {&up, &vp, &rhs, &tmp, &da})
      v->reinit(owned, M.get_mpi_communicator());
  }

  void
  NewmarkIntegrator::advance(const Vector &load_next, NewmarkState &s)
  {
    effective_load(load_next, s, rhs);
    effective_operator.solve(da, rhs);
    update(da, s);
  }

  void
  NewmarkIntegrator::effective_load(const Vector &load_next, const NewmarkState &s,
                                    Vector &result)
  {
    // predictors (eq. 2.1)
    up = s.u;
    up.add(dt, s.v, 0.5 * dt * dt, s.a);
    vp = s.v;
    vp.add(dt, s.a);

    // effective load (eq. 2.3)
    result = load_next;
    tmp    = s.a;
    tmp.add(alpha, vp);
    M.vmult(da, tmp);
    result -= da;
    tmp = up;
    tmp.add(beta, vp);
    K.vmult(da, tmp);
    result -= da;
    constraints.set_zero(result);
  }

  void
  NewmarkIntegrator::update(Vector &acceleration_increment, NewmarkState &s)
  {
    constraints.distribute(acceleration_increment); // constrained DOFs follow their masters

    // correctors (eq. 2.2)
    s.u = up;
    s.u.add(p.beta2 * dt * dt, acceleration_increment);
    s.v = vp;
    s.v.add(p.beta1 * dt, acceleration_increment);
    s.a += acceleration_increment;
    s.time += dt;
    ++s.step;
  }
} // namespace archdam::time
