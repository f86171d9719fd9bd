#include <archdam/analysis/modal_analysis.h>
#include <archdam/base/input_error.h>
#include <archdam/physics/reservoir/coupled_system.h>

#include <algorithm>
#include <cmath>
#include <numeric>
#include <slepceps.h>
#include <string>

namespace archdam::analysis
{
  using namespace dealii;

  namespace
  {
    void
    check(const PetscErrorCode ierr, const char *what)
    {
      AssertThrow(ierr == 0, ExcMessage(std::string("SLEPc/PETSc error in ") + what));
    }

    /// RAII for the PETSc/SLEPc objects of one solve.
    struct Objects
    {
      Mat K = nullptr, M = nullptr, Ms = nullptr;
      Vec x = nullptr, y = nullptr, d = nullptr;
      EPS eps = nullptr;
      ~Objects()
      {
        if (eps)
          EPSDestroy(&eps);
        for (Vec *v : {&x, &y, &d})
          if (*v)
            VecDestroy(v);
        for (Mat *m : {&K, &M, &Ms})
          if (*m)
            MatDestroy(m);
      }
    };

    /**
     * The lowest eigenpairs of K x = lambda M x (shift-and-invert about 0),
     * each normalized by @p solid_mass (x^T M_s x = 1): Hermitian (M_s = M,
     * Cholesky) without @p water_rows, else non-Hermitian (LU), with
     * @p water_rows 1 on the rows of the water's pressure and 0 elsewhere.
     * The constrained rows of M and M_s and the rows without stiffness lose
     * their mass, see compute_natural_modes(). The residual is taken relative
     * to |K x| over the solid's rows and over the water's rows separately:
     * displacements [m] and pressures [Pa] differ by orders of magnitude, and
     * one norm over both would measure only the water.
     */
    NaturalModes
    lowest_modes(const SparseMatrix              &stiffness,
                 const SparseMatrix              &mass,
                 const SparseMatrix              &solid_mass,
                 const Vector                    *water_rows,
                 const AffineConstraints<double> &constraints,
                 const ModalParameters           &p)
    {
      const bool hermitian = water_rows == nullptr;
      Objects o;
      check(MatDuplicate(static_cast<Mat>(stiffness), MAT_COPY_VALUES, &o.K), "MatDuplicate");
      check(MatDuplicate(static_cast<Mat>(mass), MAT_COPY_VALUES, &o.M), "MatDuplicate");
      if (!hermitian)
        check(MatDuplicate(static_cast<Mat>(solid_mass), MAT_COPY_VALUES, &o.Ms),
              "MatDuplicate");
      const Mat normalization = hermitian ? o.M : o.Ms;
      // A symmetric K factorized in the static stage carries PETSc's symmetry
      // flag, which the coupled matrices would inherit.
      if (!hermitian)
        for (Mat A : {o.K, o.M})
          check(MatSetOption(A, MAT_SYMMETRIC, PETSC_FALSE), "MatSetOption");
      check(MatCreateVecs(o.K, &o.x, &o.y), "MatCreateVecs");
      check(VecDuplicate(o.x, &o.d), "VecDuplicate");

      // Constrained rows hold only their diagonal (the constraints were applied
      // while assembling): remove their mass. Rows without stiffness belong to
      // no solid element: unit stiffness, no mass.
      PetscInt first, last;
      check(MatGetOwnershipRange(o.K, &first, &last), "MatGetOwnershipRange");
      check(MatGetDiagonal(o.K, o.d), "MatGetDiagonal");
      {
        const PetscScalar *diag;
        check(VecGetArrayRead(o.d, &diag), "VecGetArrayRead");
        const PetscScalar zero = 0., one = 1.;
        for (PetscInt i = first; i < last; ++i)
          {
            const bool no_stiffness = diag[i - first] == 0.;
            if (no_stiffness || constraints.is_constrained(i))
              for (Mat A : {o.M, o.Ms})
                if (A)
                  check(MatSetValues(A, 1, &i, 1, &i, &zero, INSERT_VALUES), "MatSetValues");
            if (no_stiffness)
              check(MatSetValues(o.K, 1, &i, 1, &i, &one, INSERT_VALUES), "MatSetValues");
          }
        check(VecRestoreArrayRead(o.d, &diag), "VecRestoreArrayRead");
      }
      for (Mat A : {o.K, o.M, o.Ms})
        if (A)
        {
          check(MatAssemblyBegin(A, MAT_FINAL_ASSEMBLY), "MatAssemblyBegin");
          check(MatAssemblyEnd(A, MAT_FINAL_ASSEMBLY), "MatAssemblyEnd");
        }

      // Krylov-Schur on the generalized problem with shift-and-invert about 0:
      // the eigenvalues nearest 0 are the lowest omega^2.
      const MPI_Comm comm = stiffness.get_mpi_communicator();
      check(EPSCreate(comm, &o.eps), "EPSCreate");
      check(EPSSetOperators(o.eps, o.K, o.M), "EPSSetOperators");
      check(EPSSetProblemType(o.eps, hermitian ? EPS_GHEP : EPS_GNHEP), "EPSSetProblemType");
      check(EPSSetType(o.eps, EPSKRYLOVSCHUR), "EPSSetType");
      check(EPSSetDimensions(o.eps, p.n_modes, PETSC_DEFAULT, PETSC_DEFAULT), "EPSSetDimensions");
      check(EPSSetTolerances(o.eps, p.tolerance, 1000), "EPSSetTolerances");
      check(EPSSetWhichEigenpairs(o.eps, EPS_TARGET_MAGNITUDE), "EPSSetWhichEigenpairs");
      check(EPSSetTarget(o.eps, 0.), "EPSSetTarget");
      ST  st;
      KSP ksp;
      PC  pc;
      check(EPSGetST(o.eps, &st), "EPSGetST");
      check(STSetType(st, STSINVERT), "STSetType");
      check(STGetKSP(st, &ksp), "STGetKSP");
      check(KSPSetType(ksp, KSPPREONLY), "KSPSetType");
      check(KSPGetPC(ksp, &pc), "KSPGetPC");
      check(PCSetType(pc, hermitian ? PCCHOLESKY : PCLU), "PCSetType");
      check(PCFactorSetMatSolverType(pc, MATSOLVERMUMPS), "PCFactorSetMatSolverType");
      check(EPSSolve(o.eps), "EPSSolve");

      PetscInt n_converged;
      check(EPSGetConverged(o.eps, &n_converged), "EPSGetConverged");
      if (n_converged < static_cast<PetscInt>(p.n_modes))
        throw InputError("Modal analysis: only " + std::to_string(n_converged) + " of " +
                         std::to_string(p.n_modes) +
                         " modes converged (is the model supported? try fewer modes or a "
                         "looser Tolerance).");

      IndexSet owned(stiffness.m());
      owned.add_range(first, last);
      std::vector<std::pair<double, Vector>> pairs;
      for (unsigned int k = 0; k < p.n_modes; ++k)
        {
          PetscScalar lambda, lambda_imag;
          check(EPSGetEigenpair(o.eps, k, &lambda, &lambda_imag, o.x, nullptr),
                "EPSGetEigenpair");
          if (!(lambda > 0.))
            throw InputError("Modal analysis: eigenvalue " + std::to_string(lambda) +
                             " <= 0: the model has a rigid-body mode (is it supported?).");
          // The coupled pencil's eigenvalues are real in exact arithmetic.
          AssertThrow(std::abs(lambda_imag) <= 1e-6 * lambda,
                      ExcMessage("Modal analysis: complex eigenvalue of the coupled system."));
          // Purification: SLEPc purifies only in the Hermitian case. A Ritz
          // vector keeps components of the starting vector in the null space
          // of M (constrained rows, massless rock, the water's rows without
          // G), which belong to the infinite eigenvalues; K^-1 M annihilates
          // them (twice for the incompressible water, whose infinite
          // eigenvalues come in 2x2 Jordan blocks) and maps the eigenvector
          // to itself times 1/lambda.
          if (!hermitian)
            for (unsigned int twice = 0; twice < 2; ++twice)
              {
                check(STApply(st, o.x, o.y), "STApply");
                check(VecCopy(o.y, o.x), "VecCopy");
              }
          // Mass-normalize with the condensed (solid) mass matrix, and fix the
          // sign so that the largest component is positive (the same on any
          // number of processes).
          PetscScalar mass_norm, max_value, min_value;
          check(MatMult(normalization, o.x, o.y), "MatMult");
          check(VecDot(o.x, o.y, &mass_norm), "VecDot");
          check(VecMax(o.x, nullptr, &max_value), "VecMax");
          check(VecMin(o.x, nullptr, &min_value), "VecMin");
          const double sign = max_value >= -min_value ? 1. : -1.;
          check(VecScale(o.x, sign / std::sqrt(mass_norm)), "VecScale");

          Vector shape(owned, comm);
          check(VecCopy(o.x, static_cast<const Vec &>(shape)), "VecCopy");
          pairs.emplace_back(lambda, std::move(shape));
        }
      std::sort(pairs.begin(), pairs.end(),
                [](const auto &a, const auto &b) { return a.first < b.first; });

      NaturalModes modes;
      for (auto &[lambda, shape] : pairs)
        {
          // Residual of K x = lambda M x, relative to |K x|, per block.
          check(VecCopy(static_cast<const Vec &>(shape), o.x), "VecCopy");
          check(MatMult(o.K, o.x, o.y), "MatMult");
          check(MatMult(o.M, o.x, o.d), "MatMult");
          check(VecAYPX(o.d, -lambda, o.y), "VecAYPX"); // d = K x - lambda M x
          for (const double block : {0., 1.})
            {
              if (hermitian && block == 1.)
                break;
              PetscReal r, k_norm;
              if (!hermitian) // keep the rows of this block only
                {
                  Vector in_block(*water_rows);
                  if (block == 0.)
                    {
                      in_block *= -1.;
                      in_block.add(1.);
                    }
                  const Vec mask = static_cast<const Vec &>(in_block);
                  check(VecPointwiseMult(o.x, o.y, mask), "VecPointwiseMult");
                  check(VecNorm(o.x, NORM_2, &k_norm), "VecNorm");
                  check(VecPointwiseMult(o.x, o.d, mask), "VecPointwiseMult");
                  check(VecNorm(o.x, NORM_2, &r), "VecNorm");
                }
              else
                {
                  check(VecNorm(o.y, NORM_2, &k_norm), "VecNorm");
                  check(VecNorm(o.d, NORM_2, &r), "VecNorm");
                }
              if (k_norm > 0.)
                modes.max_residual = std::max(modes.max_residual, r / k_norm);
            }

          modes.omega.push_back(std::sqrt(lambda));
          modes.shapes.push_back(std::move(shape));
        }
      return modes;
    }
  } // namespace

  NaturalModes
  compute_natural_modes(const SparseMatrix              &mass,
                        const SparseMatrix              &stiffness,
                        const AffineConstraints<double> &constraints,
                        const ModalParameters           &p)
  {
    return lowest_modes(stiffness, mass, mass, nullptr, constraints, p);
  }

  NaturalModes
  compute_coupled_modes(const SparseMatrix                       &mass,
                        const SparseMatrix                       &stiffness,
                        const physics::reservoir::FluidOperators &water,
                        const double                              water_density,
                        const double                              pressure_scale,
                        const AffineConstraints<double>          &constraints,
                        const ModalParameters                    &p)
  {
    namespace reservoir = physics::reservoir;
    SparseMatrix A, B;
    reservoir::linear_combination(A, {{1., &stiffness},
                                      {-1. / water_density, &water.S_transpose},
                                      {1., &water.Q}});
    reservoir::linear_combination(B, {{1., &mass}, {1., &water.S}, {1., &water.G}});
    // The water's rows: those of Q (the Laplacian has a positive diagonal on
    // every pressure DOF, and nothing on the solid's).
    const auto &owned = water.Q.locally_owned_range_indices();
    const auto  comm  = water.Q.get_mpi_communicator();
    Vector      water_rows(owned, comm);
    double      solid_diagonal = 0., water_diagonal = 0.;
    for (const auto i : owned)
      {
        const double q = water.Q.diag_element(i);
        water_rows(i)  = q != 0. ? 1. : 0.;
        (q != 0. ? water_diagonal : solid_diagonal) += std::abs(A.diag_element(i));
      }
    water_rows.compress(VectorOperation::insert);
    const double n_water = water_rows.l1_norm(); // collective: every rank's rows
    const double n_all   = static_cast<double>(A.m());
    solid_diagonal       = Utilities::MPI::sum(solid_diagonal, comm) / (n_all - n_water);
    water_diagonal       = Utilities::MPI::sum(water_diagonal, comm) / n_water;

    // Balance the pencil: p = s p~ with s = @p pressure_scale makes the
    // eigenvector's pressures comparable with its displacements (else they
    // are ~1e8 times larger and the Krylov solve and its convergence test
    // see the water only), and the water's rows are scaled by t so that
    // their diagonal matches the solid's (else the LU factorization's and
    // SLEPc's errors, relative to the largest entries, swamp the water's
    // equations). Row scaling leaves the eigenpairs unchanged, the column
    // scaling the eigenvalues; the shapes are scaled back.
    const double t = solid_diagonal / (water_diagonal * pressure_scale);
    Vector       rows(water_rows), columns(water_rows);
    rows *= t - 1.;
    rows.add(1.);
    columns *= pressure_scale - 1.;
    columns.add(1.);
    for (SparseMatrix *matrix : {&A, &B})
      check(MatDiagonalScale(matrix->petsc_matrix(), static_cast<const Vec &>(rows),
                             static_cast<const Vec &>(columns)),
            "MatDiagonalScale");
    NaturalModes modes = lowest_modes(A, B, mass, &water_rows, constraints, p);
    for (auto &shape : modes.shapes)
      shape.scale(columns);
    return modes;
  }


  std::array<double, dim>
  participation_factors(const Vector &shape, const std::array<Vector, dim> &mass_times_iota)
  {
    std::array<double, dim> gamma;
    for (unsigned int d = 0; d < dim; ++d)
      gamma[d] = shape * mass_times_iota[d];
    return gamma;
  }
} // namespace archdam::analysis
