#include <archdam/base/binary_io.h>
#include <archdam/base/petsc_check.h>
#include <archdam/analysis/energy_balance.h>

#include <algorithm>
#include <cmath>
#include <iomanip>
#include <sstream>

namespace archdam::analysis
{
  using namespace dealii;

  double
  EnergyTerms::balance_error() const
  {
    const double magnitudes = std::abs(kinetic) + std::abs(strain) + std::abs(damping) +
                              std::abs(radiated) + std::abs(contact) + std::abs(water) +
                              std::abs(water_radiated) + std::abs(algorithmic) +
                              std::abs(correction) + std::abs(damping_reference);
    const double scale = std::max(std::abs(input), magnitudes);
    return scale > 0. ? std::abs(input + correction - sum()) / scale : 0.;
  }

  /**
   * The prescribed columns' rows at the prescribed DOFs b, R = A_col(b, :)
   * for M, K (and D), and the water's rows of M's columns at the free
   * pressures p, W = M_col(p, b). The columns matrices hold every row of the
   * cells that touch b (with quadratic cells about three times the rows of
   * b), which the integrator needs; the balance needs only
   *   (A_col x)_b = R x,  (A_col x_b)_f = (R^T x_b)_f,  q . M_col du_b = q_p . W du_b,
   * the second because the solid blocks of M, D and K are symmetric.
   */
  struct EnergyBalance::BoundaryRows
  {
    IS  b = nullptr, pressures = nullptr;
    Mat mass = nullptr, stiffness = nullptr, damping = nullptr, water = nullptr;
    Vec at_b = nullptr, at_p = nullptr;

    /// @p free_pressures: the locally owned ones, empty without water.
    BoundaryRows(const time::PrescribedDofs &prescribed, const IndexSet &owned,
                 const IndexSet &free_pressures, const bool general, MPI_Comm comm)
    {
      const auto index_set = [&](const auto &dofs, IS &is) {
        std::vector<PetscInt> mine;
        for (const auto i : dofs)
          if (owned.is_element(i))
            mine.push_back(static_cast<PetscInt>(i));
        std::sort(mine.begin(), mine.end());
        petsc_check(ISCreateGeneral(comm, static_cast<PetscInt>(mine.size()), mine.data(),
                                    PETSC_COPY_VALUES, &is));
      };
      index_set(prescribed.dofs, b);
      IS columns;
      petsc_check(ISCreateStride(comm, static_cast<PetscInt>(owned.n_elements()),
                                 static_cast<PetscInt>(owned.nth_index_in_set(0)), 1, &columns));
      const auto rows_of = [&](const SparseMatrix &A, Mat &R) {
        petsc_check(MatCreateSubMatrix(static_cast<Mat>(A), b, columns, MAT_INITIAL_MATRIX, &R));
      };
      rows_of(prescribed.mass_columns, mass);
      rows_of(prescribed.stiffness_columns, stiffness);
      if (general)
        {
          AssertThrow(prescribed.damping_columns.m() == prescribed.mass_columns.m(),
                      ExcMessage("The energy balance with a general damping matrix and "
                                 "prescribed DOFs needs that matrix's columns."));
          rows_of(prescribed.damping_columns, damping);
        }
      petsc_check(ISDestroy(&columns));
      petsc_check(MatCreateVecs(mass, nullptr, &at_b));
      if (Utilities::MPI::max(free_pressures.n_elements(), comm) > 0)
        {
          index_set(free_pressures, pressures);
          petsc_check(MatCreateSubMatrix(static_cast<Mat>(prescribed.mass_columns), pressures, b,
                                         MAT_INITIAL_MATRIX, &water));
          petsc_check(MatCreateVecs(water, nullptr, &at_p));
        }
    }

    ~BoundaryRows()
    {
      for (Mat *A : {&mass, &stiffness, &damping, &water})
        if (*A != nullptr)
          MatDestroy(A);
      for (Vec *v : {&at_b, &at_p})
        if (*v != nullptr)
          VecDestroy(v);
      for (IS *is : {&b, &pressures})
        if (*is != nullptr)
          ISDestroy(is);
    }

    Mat
    of(const Operator which) const
    {
      return which == Operator::mass ? mass : which == Operator::stiffness ? stiffness : damping;
    }

    /// out_b += (R x)_b; out's other entries unchanged.
    void
    add_rows_times(const Mat R, const Vector &x, Vector &out) const
    {
      petsc_check(MatMult(R, static_cast<const Vec &>(x), at_b));
      Vec out_b;
      petsc_check(VecGetSubVector(static_cast<const Vec &>(out), b, &out_b));
      petsc_check(VecAXPY(out_b, 1., at_b));
      petsc_check(VecRestoreSubVector(static_cast<const Vec &>(out), b, &out_b));
    }

    /// out = R^T x_b (every entry).
    void
    transpose_times(const Mat R, const Vector &x, Vector &out) const
    {
      Vec x_b;
      Vec x_all = static_cast<const Vec &>(x);
      petsc_check(VecGetSubVector(x_all, b, &x_b));
      petsc_check(MatMultTranspose(R, x_b, static_cast<const Vec &>(out)));
      petsc_check(VecRestoreSubVector(x_all, b, &x_b));
    }

    /// q . M_col du for du zero off b.
    double
    water_work(const Vector &q, const Vector &du) const
    {
      if (water == nullptr)
        return 0.;
      Vec du_all = static_cast<const Vec &>(du), q_all = static_cast<const Vec &>(q), du_b, q_p;
      petsc_check(VecGetSubVector(du_all, b, &du_b));
      petsc_check(MatMult(water, du_b, at_p));
      petsc_check(VecRestoreSubVector(du_all, b, &du_b));
      PetscScalar work;
      petsc_check(VecGetSubVector(q_all, pressures, &q_p));
      petsc_check(VecDot(at_p, q_p, &work));
      petsc_check(VecRestoreSubVector(q_all, pressures, &q_p));
      return work;
    }
  };

  EnergyBalance::~EnergyBalance() = default;

  EnergyBalance::EnergyBalance(const Model &model)
    : m(model)
    , has_water(model.fluid != nullptr)
  {
    AssertThrow(m.space && m.mass && m.stiffness,
                ExcMessage("The energy balance needs the FE space, M and K."));
    for (Vector *v : {&free_mask, &kept_mask, &pressure_mask, &solid_mask, &prescribed_mask, &u_static,
                      &u_prev, &v_prev, &damping_prev, &p_prev, &impulse, &boundary_prev,
                      &boundary_static, &free_field_prev, &free_field_static, &radiation_prev,
                      &dashpot_prev, &ub_prev, &tmp, &tmp2, &du, &work, &scratch,
                      &a_prev, &inertia_prev, &mean, &jump, &solid_part,
                      &correction_residual, &dam_prev, &du_last})
      m.space->reinit(*v);
    if (has_water)
      {
        for (const auto i : physics::reservoir::free_pressure_dofs(*m.space))
          pressure_mask(i) = 1.;
        pressure_mask.compress(VectorOperation::insert);
      }
    // 1 at every DOF but the free pressures (the constrained ones are zero
    // in free_part()'s vectors and rows).
    solid_mask = 1.;
    solid_mask -= pressure_mask;
    if (m.prescribed)
      {
        const IndexSet owned = prescribed_mask.locally_owned_elements();
        for (const auto i : m.prescribed->dofs)
          if (owned.is_element(i))
            prescribed_mask(i) = 1.;
        prescribed_mask.compress(VectorOperation::insert);
      }
    for (unsigned int d = 0; d < dim && m.reference; ++d)
      reference_mass[d] = (*m.reference_loads)[d].mean_value() * (*m.reference_loads)[d].size();
    // Setting constrained entries to zero one by one costs a PETSc call per
    // entry; a pointwise product with a mask is one pass.
    free_mask = 1.;
    m.space->constraints.set_zero(free_mask);
    kept_mask = free_mask;
    kept_mask += prescribed_mask;
    if (m.prescribed)
      rows = std::make_unique<BoundaryRows>(
        *m.prescribed, free_mask.locally_owned_elements(),
        has_water ? physics::reservoir::free_pressure_dofs(*m.space) : IndexSet(),
        m.damping != nullptr, free_mask.get_mpi_communicator());
  }

  void
  EnergyBalance::free_part(const Vector &x, Vector &out) const
  {
    // The free entries, and with a prescribed boundary its entries too: the
    // balance is that of the whole model, the boundary nodes included.
    out = x;
    out.scale(kept_mask);
  }

  void
  EnergyBalance::full_product(const Operator which, const Vector &x, Vector &out,
                              const Vector *condensed) const
  {
    // A x for the full (unconstrained) solid operator, x from free_part():
    // the condensed A on the free entries, and with a prescribed boundary b
    // its columns (time::PrescribedDofs, all rows of the cells touching b),
    // of which the rows at b suffice (BoundaryRows):
    //   (A x)_f = A_cond x_f + (A_col x_b)_f = A_cond x_f + (R^T x_b)_f,
    //   (A x)_b = (A_col x)_b = R x.
    // The water's rows (Phi S in the coupled columns) are left out, and so
    // are its columns (the coupled K's -(1/rho_w) S^T: the pressure's work
    // on the dam is counted in the water's balance).
    const Vector *solid = &x;
    if (has_water)
      {
        solid_part = x;
        solid_part.scale(solid_mask);
        solid = &solid_part;
      }
    // (A condensed product formed elsewhere on all of x agrees on the solid
    // free rows: the condensed operators have no entries in the constrained
    // columns, the solid's rows none in the water's columns.)
    if (condensed != nullptr)
      out = *condensed;
    else if (which == Operator::damping && m.damping_products != nullptr)
      m.damping_products->vmult(1, *solid, out);
    else
      (which == Operator::mass ? *m.mass : which == Operator::stiffness ? *m.stiffness : *m.damping)
        .vmult(out, *solid);
    out.scale(free_mask);
    if (rows)
      {
        const Mat R = rows->of(which);
        rows->transpose_times(R, *solid, scratch);
        scratch.scale(free_mask);
        out += scratch;
        rows->add_rows_times(R, *solid, out); // out is 0 at b (constrained)
      }
    if (has_water)
      out.scale(solid_mask);
  }

  void
  EnergyBalance::damping_force(const Vector &v, Vector &out, const Vector *condensed) const
  {
    // D = alpha M + beta K (doc/theory/solid.md §4); for the coupled system this is
    // the solid's block of D_c, the water's radiation being counted apart.
    if (m.damping)
      {
        full_product(Operator::damping, v, out, condensed);
        return;
      }
    full_product(Operator::mass, v, out);
    out *= m.rayleigh.first;
    if (m.rayleigh.second != 0.)
      {
        full_product(Operator::stiffness, v, tmp2);
        out.add(m.rayleigh.second, tmp2);
      }
  }

  double
  EnergyBalance::last_step_damping(const Vector &force) const
  {
    return 0.5 * (du_last * damping_prev + du_last * force);
  }

  void
  EnergyBalance::boundary_reaction(const time::NewmarkState &s, Vector &out)
  {
    // The force the exterior applies to the prescribed DOFs b to move them:
    // (M a + D v + K u)_b of the full operators (the water's pressure on b
    // is counted with the water's balance below). D is alpha M + beta K, or
    // a general damping matrix with its own columns.
    const auto [alpha, beta] = m.damping ? std::pair<double, double>{0., 0.} : m.rayleigh;
    out = 0.;
    free_part(s.a, work);
    free_part(s.v, tmp2);
    work.add(alpha, tmp2);
    rows->add_rows_times(rows->mass, work, out);
    free_part(s.u, work);
    work.add(beta, tmp2);
    rows->add_rows_times(rows->stiffness, work, out);
    if (m.damping)
      {
        free_part(s.v, work);
        rows->add_rows_times(rows->damping, work, out);
      }
  }

  void
  EnergyBalance::start(const time::NewmarkState &s, const joints::JointSolver *joints)
  {
    free_part(s.u, u_static);
    u_prev = u_static;
    free_part(s.v, v_prev);
    damping_force(v_prev, damping_prev);
    if (m.dam_damping)
      m.dam_damping->vmult(dam_prev, v_prev);
    for (unsigned int d = 0; d < dim && m.reference; ++d)
      reference_work_prev[d] = (*m.reference_loads)[d] * v_prev;
    if (m.reference)
      {
        vr_prev = m.reference->velocity(s.time);
        dr_prev = m.reference->displacement(s.time);
      }
    if (dissipative())
      {
        free_part(s.a, a_prev);
        full_product(Operator::mass, a_prev, inertia_prev);
      }
    correction_residual = 0.;
    damping_pending     = false;
    p_prev  = 0.;
    impulse = 0.;
    if (has_water)
      {
        // The hydrodynamic pressure is measured from the start (the
        // hydrostatic pressure is a static load).
        p_prev = u_static;
        p_prev.scale(pressure_mask);
        radiation_prev = 0.;
      }
    if (m.prescribed)
      {
        boundary_reaction(s, boundary_static);
        boundary_prev = boundary_static;
        ub_prev       = s.u;
        ub_prev.scale(prescribed_mask);
      }
    if (m.viscous)
      {
        dashpot_prev = v_prev;
        dashpot_prev.scale(m.viscous->dashpots());
        free_field_prev = 0.;
        m.viscous->add_free_field_load(s.time, free_field_prev);
        free_field_static = free_field_prev;
      }
    t_prev  = s.time;
    ag_prev = Tensor<1, dim>();
    vg      = Tensor<1, dim>();
    f_static.clear();
    w_static.clear();
    if (joints)
      {
        f_static = f_prev = joints->pair_load;
        w_static = w_prev = joints->w;
      }
    sums = EnergyTerms();
  }

  void
  EnergyBalance::add_step(const time::NewmarkState &s,
                          const Tensor<1, dim>     &ag,
                          const joints::JointSolver *joints)
  {
    const double dt = s.time - t_prev;
    const double b1 = m.newmark.beta1, b2 = m.newmark.beta2;
    // Rayleigh damping, du . (D v_n + D v_{n+1}) / 2, is added one step
    // late: the step just made formed D v_n, the last step's D v_{n+1}, in
    // its pass over the integrator's copy of D (Model::integrator), else a
    // product forms it here (v_prev is still the last step's state).
    if (damping_pending)
      {
        damping_force(v_prev, tmp,
                      m.integrator ? m.integrator->damping_force_at_start() : nullptr);
        sums.damping += last_step_damping(tmp);
        damping_prev = tmp;
      }
    free_part(s.u, tmp);
    du = tmp;
    du -= u_prev;
    u_prev = tmp;
    // The position correction (doc/theory/joints.md §11) moves the
    // displacements by du_c after the step, without a force: its term is
    // the strain energy (with the static loads' potential, as terms()
    // measures it) that du_c adds, and the work of the out-of-balance force
    // K du_c it leaves at the step's end over the next step (the next
    // step's trapezoidal rule takes half of it); every path term below
    // works on the step's own increment.
    const std::vector<double> *corrected_w = nullptr;
    if (joints && !joints->last_correction().dw.empty())
      {
        corrected_w = &joints->last_correction().dw;
        free_part(joints->last_correction().du, tmp);
        du -= tmp;
      }
    sums.correction += 0.5 * (du * correction_residual);
    correction_residual = 0.;
    if (corrected_w)
      {
        full_product(Operator::stiffness, tmp, correction_residual);
        Vector w(u_prev);
        w -= u_static;
        sums.correction += correction_residual * w - 0.5 * (correction_residual * tmp);
        for (unsigned int k = 0; k < f_static.size(); ++k)
          sums.correction -= f_static[k] * (*corrected_w)[k];
      }
    if (dissipative())
      {
        tmp = v_prev; // v_n
        free_part(s.v, v_prev);
        add_algorithmic_dissipation(s, tmp, dt);
      }
    else
      free_part(s.v, v_prev);

    du_last         = du; // its damping work with the next step (above)
    damping_pending = true;
    add_dam_damping(s);

    // Relative formulation: F = -sum_d a_g,d M iota_d (doc/theory/foundation.md §2), and
    // the ground's own motion, integrated by the same Newmark rule, for the
    // water.
    Tensor<1, dim> dug;
    for (unsigned int d = 0; d < dim; ++d)
      {
        dug[d] = dt * vg[d] + dt * dt * ((0.5 - b2) * ag_prev[d] + b2 * ag[d]);
        vg[d] += dt * ((1. - b1) * ag_prev[d] + b1 * ag[d]);
        if (m.influence && (ag[d] != 0. || ag_prev[d] != 0.))
          sums.input -= 0.5 * (ag_prev[d] + ag[d]) * (du * (*m.influence)[d]);
      }
    ag_prev = ag;

    if (m.viscous)
      {
        // Viscous boundary (doc/theory/foundation.md §8): the free-field forces put the
        // wave in, the dashpots take c (v_n + v_{n+1}) / 2 . du out.
        tmp = 0.;
        m.viscous->add_free_field_load(s.time, tmp);
        sums.input += 0.5 * (du * free_field_prev + du * tmp) - du * free_field_static;
        free_field_prev = tmp;
        tmp             = v_prev;
        tmp.scale(m.viscous->dashpots());
        sums.radiated += 0.5 * (du * dashpot_prev + du * tmp);
        dashpot_prev = tmp;
      }

    if (m.prescribed)
      {
        // Work of the reactions on the prescribed boundary (MTF: input minus
        // radiated), from the static state.
        boundary_reaction(s, tmp);
        sums.input += 0.5 * (du * boundary_prev + du * tmp) - du * boundary_static;
        boundary_prev = tmp;
      }

    if (has_water)
      {
        // The water's balance (the integrated fluid equation times p):
        //   dE_w + (1/rho) dP . H p_mid = -(1/rho) p_mid . S (du + iota du_g),
        // dP = dt p_mid (trapezoidal); the part with du cancels the work of
        // -(1/rho) S^T p on the dam, so only the ground's part is input.
        const double rho = m.density;
        tmp              = s.u;
        tmp -= u_static;
        tmp.scale(pressure_mask); // p_{n+1}
        tmp2 = p_prev;
        tmp2 += tmp; // p_n + p_{n+1} = 2 p_mid
        impulse.add(0.5 * dt, tmp2);
        m.fluid->H.vmult(work, tmp);
        sums.water_radiated += 0.25 * dt / rho * (tmp2 * radiation_prev + tmp2 * work);
        radiation_prev = work;
        p_prev         = tmp;
        if (m.influence)
          for (unsigned int d = 0; d < dim; ++d)
            if (dug[d] != 0.)
              sums.input -= 0.5 / rho * dug[d] * (tmp2 * m.fluid->influence[d]);
        if (m.prescribed)
          {
            // The boundary moves the wetted rock under the water (the
            // constrained S has no columns at b): the fluid rows of the
            // prescribed mass columns are Phi S(:, b), Phi = -beta2 dt^2 / rho
            // (reservoir/coupled_system.h), so
            // -(1/rho) p_mid . S_b du_b = p_mid . (Mcol du_b) / (beta2 dt^2).
            tmp = s.u;
            tmp.scale(prescribed_mask);
            du = tmp;
            du -= ub_prev;
            ub_prev = tmp;
            sums.input += 0.5 / (b2 * dt * dt) * rows->water_work(tmp2, du);
          }
      }

    if (joints)
      {
        // The joints absorb g . dw with the load g on the dam (-B^T g,
        // doc/theory/joints.md §1), whose trapezoidal mean is the step's
        // force with the step impulse (§10) and f's mean with the
        // trapezoidal forces (g = f).
        for (unsigned int k = 0; k < f_prev.size(); ++k)
          {
            const double dw_k = joints->w[k] - w_prev[k] - (corrected_w ? (*corrected_w)[k] : 0.);
            const double work_k = 0.5 * (joints->pair_load[k] + f_prev[k]) * dw_k;
            sums.contact += work_k;
            if (k % dim == 0) // xi, the normal of the pair's frame
              sums.contact_normal += work_k;
          }
        f_prev = joints->pair_load;
        w_prev = joints->w;
      }
    t_prev = s.time;
  }

  void
  EnergyBalance::add_dam_damping(const time::NewmarkState &s)
  {
    // With the dam's mass term on v - w, w = iota v_r (doc/theory/solid.md
    // §4), the damping forces are -D v + D_dam w, D_dam w = sum_d v_r,d g_d
    // (g_d = D_dam iota_d = alpha_d M_dam iota_d, the loads of the
    // integrator). Their work over the step, with r = v - w, du_r the
    // reference's own increment iota dd_r and <x> the step's mean, is
    //   du . D <v> - du . D_dam <w>
    //     = du . (D - D_dam) <v>             (the rock)
    //     + (du - du_r) . D_dam <r>          (the dam: zero when it moves
    //                                         rigidly with w, ~ dt <r> D_dam <r>)
    //     + du_r . D_dam <r>,                (handed to the reference motion)
    // with du_r . D_dam <r> = sum_d dd_r,d (<g_d . v> - m_d <v_r,d>), m_d =
    // iota_d . g_d = alpha_d times the dam's mass.
    // (EnergyTerms::damping itself, du . D <v>, is added in add_step().)
    if (!m.dam_damping)
      return;
    m.dam_damping->vmult(tmp2, v_prev);
    const double dam_total = 0.5 * (du * dam_prev + du * tmp2);
    dam_prev               = tmp2;
    double relative_load = 0., handed = 0.;
    if (m.reference)
      {
        const Tensor<1, dim> vr = m.reference->velocity(s.time);
        const Tensor<1, dim> dr = m.reference->displacement(s.time);
        for (unsigned int d = 0; d < dim; ++d)
          {
            const Vector &g    = (*m.reference_loads)[d];
            const double  gv   = g * v_prev;
            const double  md   = reference_mass[d];
            const double  vr_m = 0.5 * (vr[d] + vr_prev[d]);
            relative_load += vr_m * (du * g);
            handed += (dr[d] - dr_prev[d]) * (0.5 * (gv + reference_work_prev[d]) - md * vr_m);
            reference_work_prev[d] = gv;
          }
        vr_prev = vr;
        dr_prev = dr;
      }
    sums.damping -= relative_load + handed;
    sums.damping_dam += dam_total - relative_load - handed;
    sums.damping_reference += handed;
  }

  void
  EnergyBalance::add_algorithmic_dissipation(const time::NewmarkState &s, const Vector &v_old,
                                             const double dt)
  {
    // [u] = dt <v> + dt^2 (Beta2 - Beta1/2) [a] and [v] = dt <a> +
    // dt (Beta1 - 1/2) [a] (eq. 2.3), so the inertia's work over the step,
    // [u]^T M <a>, exceeds the change of 1/2 v^T M v by
    // dt^2 (Beta2 - Beta1/2) [a]^T M <a> - dt (Beta1 - 1/2) <v>^T M [a]:
    // one product M a_{n+1} a step, M a_n kept from the step before.
    const double b1 = m.newmark.beta1, b2 = m.newmark.beta2;
    free_part(s.a, mean);
    full_product(Operator::mass, mean, jump); // M a_{n+1}
    mean += a_prev;
    mean *= 0.5;                                         // <a>
    a_prev.sadd(-1., 2., mean);                          // a_{n+1}
    tmp2 = jump;
    jump -= inertia_prev;                                // M [a]
    inertia_prev = tmp2;
    sums.algorithmic += dt * dt * (b2 - 0.5 * b1) * (mean * jump);
    mean = v_old;
    mean += v_prev;
    mean *= 0.5;                                         // <v>
    sums.algorithmic -= dt * (b1 - 0.5) * (mean * jump);
  }

  EnergyTerms
  EnergyBalance::terms() const
  {
    EnergyTerms e = sums;
    Vector      w(u_prev), Ax(u_prev);
    if (damping_pending) // the last step's damping work (add_step())
      {
        damping_force(v_prev, Ax);
        e.damping += last_step_damping(Ax);
      }
    full_product(Operator::mass, v_prev, Ax);
    e.kinetic = 0.5 * (Ax * v_prev);
    w -= u_static;
    full_product(Operator::stiffness, w, Ax);
    e.strain = 0.5 * (Ax * w);
    for (unsigned int k = 0; k < f_static.size(); ++k)
      e.strain -= f_static[k] * (w_prev[k] - w_static[k]);
    if (has_water)
      {
        m.fluid->G.vmult(Ax, p_prev);
        e.water = 0.5 / m.density * (Ax * p_prev);
        m.fluid->Q.vmult(Ax, impulse);
        e.water += 0.5 / m.density * (Ax * impulse);
      }
    return e;
  }

  void
  EnergyBalance::start(const output::StepRecord &s)
  {
    start(s.state, s.joints);
  }

  void
  EnergyBalance::record(const output::StepRecord &s)
  {
    add_step(s.state, s.ground_acceleration, s.joints);
  }

  void
  EnergyBalance::finish(output::Summary &summary, const dealii::ConditionalOStream &screen)
  {
    const EnergyTerms e = terms();
    const std::string s = "energy balance/";
    summary.set(s + "input work [J]", e.input);
    summary.set(s + "kinetic energy [J]", e.kinetic);
    summary.set(s + "strain energy [J]", e.strain);
    summary.set(s + "damping dissipation [J]", e.damping);
    if (m.dam_damping)
      {
        summary.set(s + "damping dissipation in the dam [J]", e.damping_dam);
        summary.set(s + "damping dissipation in the rock [J]", e.damping - e.damping_dam);
      }
    if (m.reference)
      summary.set(s + "damping work handed to the reference motion [J]", e.damping_reference);
    summary.set(s + "radiated energy [J]", e.radiated);
    summary.set(s + "contact dissipation [J]", e.contact);
    if (!f_static.empty())
      summary.set(s + "contact dissipation, normal part [J]", e.contact_normal);
    if (has_water)
      {
        summary.set(s + "water energy [J]", e.water);
        summary.set(s + "water radiated energy [J]", e.water_radiated);
      }
    if (dissipative())
      summary.set(s + "algorithmic dissipation [J]", e.algorithmic);
    if (e.correction != 0.)
      summary.set(s + "position correction's energy [J]", e.correction);
    summary.set(s + "balance error", e.balance_error());
    if (m.prescribed)
      summary.set(s + "note", "the input work is the net work of the prescribed outer "
                              "boundary (MTF): input minus radiated");

    screen << line() << std::endl;
    // (Without input work, from rest, every term is round-off and so is
    // their ratio: nothing to say.)
    if (e.input != 0. && e.balance_error() > EnergyTerms::warning_threshold)
      {
        std::ostringstream text;
        text << std::setprecision(2) << "the energy balance closes only to "
             << e.balance_error() << ", more than " << EnergyTerms::warning_threshold
             << ": some work is accounted for by no term (doc/user-guide.md, \"Energy "
                "balance\").";
        output::warn(summary, screen, text.str());
      }
  }

  std::string
  EnergyBalance::line() const
  {
    const EnergyTerms  e = terms();
    std::ostringstream out;
    out << std::setprecision(4) << "Energy balance: input " << e.input << " J = kinetic "
        << e.kinetic << " + strain " << e.strain << " + damping " << e.damping;
    if (m.dam_damping)
      out << " (dam " << e.damping_dam << ", rock " << e.damping - e.damping_dam << ")";
    if (m.reference)
      out << " + to the reference motion " << e.damping_reference;
    if (m.viscous)
      out << " + radiated " << e.radiated;
    if (!f_static.empty())
      out << " + contact " << e.contact;
    if (has_water)
      out << " + water " << e.water << " + water radiated " << e.water_radiated;
    if (dissipative())
      out << " + algorithmic " << e.algorithmic;
    if (e.correction != 0.)
      out << " - position correction " << e.correction;
    // Round-off differs between runs on different numbers of processes: a
    // closed balance is printed as such.
    const double error = e.balance_error();
    if (error < 1e-9)
      out << " J; balance error below 1e-9";
    else
      out << " J; balance error " << std::setprecision(2) << error;
    return out.str();
  }

  void
  EnergyBalance::save(std::ostream &out) const
  {
    for (const Vector *v : {&u_static, &u_prev, &v_prev, &damping_prev, &p_prev, &impulse,
                            &boundary_prev, &boundary_static, &free_field_prev,
                            &free_field_static, &radiation_prev, &dashpot_prev, &ub_prev, &a_prev,
                            &inertia_prev, &correction_residual, &dam_prev, &du_last})
      binary::write(out, *v);
    binary::write_all(out, ag_prev, vg, f_static, w_static, f_prev, w_prev, t_prev, sums,
                      reference_work_prev, vr_prev, dr_prev, damping_pending);
  }

  void
  EnergyBalance::load(std::istream &in)
  {
    for (Vector *v : {&u_static, &u_prev, &v_prev, &damping_prev, &p_prev, &impulse,
                      &boundary_prev, &boundary_static, &free_field_prev, &free_field_static,
                      &radiation_prev, &dashpot_prev, &ub_prev, &a_prev, &inertia_prev,
                      &correction_residual, &dam_prev, &du_last})
      binary::read(in, *v);
    binary::read_all(in, ag_prev, vg, f_static, w_static, f_prev, w_prev, t_prev, sums,
                     reference_work_prev, vr_prev, dr_prev, damping_pending);
  }
} // namespace archdam::analysis
