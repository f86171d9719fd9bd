// Water on a massed foundation (doc/theory/reservoir.md §5 and doc/theory/foundation.md §7): the prescribed outer
// boundary of the rock drives the coupled dam-water system (paper eq. 3.2)
// through the full columns of its M_c, D_c and K_c at the prescribed DOFs
// (time::PrescribedDofs, reservoir::form_coupled_columns), the water's rows
// Phi S included. Rock box under a column of compressible water, split at
// the wetted face z = 0; rock bottom (id 1) and sides (id 2) prescribed, so
// the wetted face meets the prescribed boundary along its edges.
//
// A. Rigid base. One rock cell (Q1: every rock DOF lies on the outer
//    boundary and is prescribed) moves up as u_z = g(t), a sin^4 pulse,
//    under a water column of depth H = 30 m (rigid side walls, p = 0 at the
//    surface): the water sees the prescribed DOFs only through Phi S. The
//    exact pressure is the 1-D wave with the base velocity v = g' sent up
//    and reflected at the surface (p = 0, factor -1) and at the base (dp/dz
//    fixed, factor +1):
//      p(z, t) = rho c sum_n (-1)^n [v(t - (2nH + z)/c) - v(t - (2(n+1)H - z)/c)].
//    The FE pressure at the base and at mid-depth must follow it within 1 %
//    of its peak. At the pulse's upper frequency 2/T = 40 Hz, Q1 cells of
//    0.5 m with their consistent mass raise the phase speed by (kh)^2/24 =
//    0.04 % and the average acceleration rule with dt = 0.25 ms lowers it by
//    (omega dt)^2/12 = 0.03 %; over the 8 periods of the run either alone
//    shifts the phase by ~1.5 % of a period (they largely cancel here); the
//    base acceleration of the prescribed motion is the Newmark-consistent
//    one, within O(dt^2) of g''. (With 1 m cells the measured error is 2 %:
//    the spatial dispersion dominates.)
// B. Second method. A flexible rock box (4 x 3 x 3 Q1 cells) with Rayleigh
//    damping under water with a Sommerfeld truncation (x = 0), the boundary
//    moving with a pulse that varies in space and direction. Reference: the
//    same model with the boundary DOFs free (unconstrained M, K and S) and
//    held on the prescribed motion by penalty springs k, k u_target(t) in
//    the load, k = 1e8 times the largest diagonal entry of Kbar over
//    beta2 dt^2, through the plain Newmark step (no prescribed columns at
//    all). The two must agree to 1e-6 of the peak displacement and of the
//    peak pressure (the penalty leaves ~1e-8). The same run without the
//    water's columns (solid M, D, K columns only), and without the damping
//    columns, must be off by more than 100 times that tolerance: both parts
//    of the update matter.
// C. The viscous boundary with water: the integrator with a general damping
//    matrix takes the boundary's dashpots. On the rock box of B without
//    water (the viscous boundary prescribes nothing), under a load pulse:
//    D = alpha M + beta K given as a matrix with the dashpots, against the
//    Rayleigh integrator with the same dashpots, to 1e-9 of the peak; the
//    general one without the dashpots must differ by more than 1e-4.

#include <archdam/geometry/splitter.h>
#include <archdam/physics/foundation/massed_foundation.h>
#include <archdam/physics/foundation/outer_boundary.h>
#include <archdam/physics/reservoir/coupled_system.h>
#include <archdam/physics/solid/solid_operators.h>

#include <deal.II/dofs/dof_tools.h>

#include "foundation_tests.h"

using namespace dealii;
using namespace archdam;
namespace reservoir = archdam::physics::reservoir;
namespace solid     = archdam::physics::solid;

namespace
{
  const double rho_w = 1000., c_w = 1440.;

  struct Box
  {
    double       Lx, Ly, Hr, Hw;
    unsigned int nx, ny, nr, nw;
    bool         truncated; ///< the water's face x = 0 radiates (id 4), else a rigid wall
  };

  /// Rock [0, Lx] x [0, Ly] x [-Hr, 0] (bottom id 1, sides id 2), water on
  /// top up to z = Hw (surface id 3, walls id 0 or the truncation), split at
  /// the wetted face z = 0 (ids 6/7).
  void
  make_model(const Box &b, parallel::shared::Triangulation<3> &tria)
  {
    std::vector<std::vector<double>> steps(3);
    steps[0].assign(b.nx, b.Lx / b.nx);
    steps[1].assign(b.ny, b.Ly / b.ny);
    steps[2].assign(b.nr, b.Hr / b.nr);
    steps[2].insert(steps[2].end(), b.nw, b.Hw / b.nw);
    Triangulation<3> full, split;
    GridGenerator::subdivided_hyper_rectangle(full, steps, Point<3>(0, 0, -b.Hr),
                                              Point<3>(b.Lx, b.Ly, b.Hw));
    const double tol = 1e-8 * (b.Hr + b.Hw);
    for (const auto &cell : full.active_cell_iterators())
      {
        const bool water = cell->center()[2] > 0;
        cell->set_material_id(water ? ids::water : ids::rock);
        for (const auto &face : cell->face_iterators())
          if (face->at_boundary())
            {
              const Point<3> f = face->center();
              if (water)
                face->set_boundary_id(std::abs(f[2] - b.Hw) < tol ? ids::reservoir_surface :
                                      b.truncated && std::abs(f[0]) < tol ?
                                                                    ids::reservoir_truncation :
                                                                    ids::free_surface_solid);
              else
                face->set_boundary_id(std::abs(f[2] + b.Hr) < tol ? ids::foundation_bottom :
                                                                    ids::foundation_sides);
            }
      }
    geometry::split_interfaces(full, split);
    tria.copy_triangulation(split);
  }

  /// The discrete model: space, solid and water operators, the coupled
  /// system; the outer boundary prescribed (constrained) or free.
  struct Model
  {
    Model(const parallel::shared::Triangulation<3> &tria, const bool prescribed)
      : space(tria, fe_parameters())
    {
      materials.rock = testing::test_rock();
      water.model    = reservoir::Model::compressible;
      space.pressure_in_water = true;
      space.setup(prescribed ? std::set<types::boundary_id>{ids::foundation_bottom,
                                                           ids::foundation_sides} :
                               std::set<types::boundary_id>{},
                  [&](AffineConstraints<double> &c) {
                    reservoir::constrain_free_surface(space, water, c);
                  });
      pairs              = reservoir::match_interface_faces(space);
      space.add_couplings = [this](DynamicSparsityPattern &dsp) {
        reservoir::add_interface_couplings(space, pairs, dsp);
      };
      solid::assemble_mass_and_stiffness(space, materials, solid::InertiaOf::dam_and_rock, M, K);
      reservoir::assemble_fluid_operators(space, water, 9.81, pairs, ops);
    }

    static fe::FiniteElementParameters
    fe_parameters()
    {
      fe::FiniteElementParameters p;
      p.degree = 1;
      return p;
    }

    void
    couple(const time::NewmarkParameters &tp, const std::pair<double, double> rayleigh)
    {
      reservoir::form_coupled_system(ops, water.density, tp.beta2, tp.time_step, M, K,
                                     {{rayleigh.first, &M}, {rayleigh.second, &K}}, coupled);
    }

    solid::MaterialParameters          materials;
    reservoir::ReservoirParameters     water;
    fe::FESpace                        space;
    std::vector<reservoir::InterfacePair> pairs;
    archdam::SparseMatrix              M, K;
    reservoir::FluidOperators          ops;
    reservoir::CoupledSystem           coupled;
  };

  /// The prescribed motion of a boundary DOF at time t.
  using Motion = std::function<double(const Point<3> &, unsigned int, double)>;

  /// The outer boundary's DOFs with their positions and components.
  struct Boundary
  {
    std::vector<types::global_dof_index> dofs;
    std::vector<std::pair<Point<3>, unsigned int>> where;
  };

  Boundary
  boundary_of(const fe::FESpace &space)
  {
    Boundary b;
    for (const auto &d : physics::foundation::outer_boundary_dofs(space))
      {
        b.dofs.push_back(d.index);
        b.where.emplace_back(d.position, d.component);
      }
    return b;
  }

  std::vector<double>
  values_at(const Boundary &b, const Motion &motion, const double t)
  {
    std::vector<double> u(b.dofs.size());
    for (unsigned int k = 0; k < u.size(); ++k)
      u[k] = motion(b.where[k].first, b.where[k].second, t);
    return u;
  }

  double
  value_at(const archdam::Vector &v, const types::global_dof_index i)
  {
    return Utilities::MPI::sum(v.locally_owned_elements().is_element(i) ? double(v(i)) : 0.,
                               MPI_COMM_WORLD);
  }

  /// The pressure DOF at @p x (support points of the water's element).
  types::global_dof_index
  pressure_dof_at(const fe::FESpace &space, const Point<3> &x)
  {
    const auto &fe      = space.fe_collection[fe::FESpace::fluid_index];
    const auto  support = fe.get_unit_support_points();
    std::vector<types::global_dof_index> dofs(fe.n_dofs_per_cell());
    for (const auto &cell : space.dof_handler.active_cell_iterators())
      if (cell->active_fe_index() == fe::FESpace::fluid_index)
        {
          cell->get_dof_indices(dofs);
          for (unsigned int i = 0; i < dofs.size(); ++i)
            if (fe.system_to_component_index(i).first == 3 &&
                MappingQ1<3>().transform_unit_to_real_cell(cell, support[i]).distance(x) < 1e-6)
              return dofs[i];
        }
    AssertThrow(false, ExcMessage("no pressure DOF at the point"));
    return 0;
  }

  enum class Columns
  {
    coupled,         ///< form_coupled_columns: the update under test
    without_water,   ///< solid columns only (the water's rows Phi S left out)
    without_damping, ///< the damping columns left out
  };

  /// Newmark with the boundary prescribed through its columns; @p record is
  /// called after every step.
  void
  run_prescribed(Model &m, const time::NewmarkParameters &tp,
                 const std::pair<double, double> rayleigh, const Motion &motion,
                 const unsigned int n_steps, const Columns columns,
                 const std::function<void(const time::NewmarkState &)> &record)
  {
    m.couple(tp, rayleigh);
    const Boundary       boundary = boundary_of(m.space);
    time::PrescribedDofs prescribed;
    prescribed.dofs = boundary.dofs;
    solid::assemble_mass_and_stiffness_columns(m.space, m.materials,
                                               solid::InertiaOf::dam_and_rock, prescribed.dofs,
                                               prescribed.mass_columns,
                                               prescribed.stiffness_columns);
    reservoir::linear_combination(prescribed.damping_columns,
                                  {{rayleigh.first, &prescribed.mass_columns},
                                   {rayleigh.second, &prescribed.stiffness_columns}});
    if (columns != Columns::without_water)
      reservoir::form_coupled_columns(m.space, m.pairs, m.water.density, tp.beta2,
                                      tp.time_step, prescribed);
    if (columns == Columns::without_damping)
      prescribed.damping_columns = 0.;

    time::NewmarkIntegrator newmark(tp, m.coupled.mass, m.coupled.damping, m.coupled.stiffness,
                                    m.space.constraints, false);
    time::NewmarkState      s;
    archdam::Vector         load;
    for (archdam::Vector *v : {&s.u, &s.v, &s.a, &load})
      m.space.reinit(*v);
    for (unsigned int n = 1; n <= n_steps; ++n)
      {
        newmark.advance(load, s, prescribed, values_at(boundary, motion, n * tp.time_step));
        record(s);
      }
  }

  /// The same model with the boundary free and held on the motion by
  /// penalty springs, through the plain Newmark step.
  void
  run_penalty(Model &m, const time::NewmarkParameters &tp, const std::pair<double, double> rayleigh,
              const Motion &motion, const unsigned int n_steps,
              const std::function<void(const time::NewmarkState &)> &record)
  {
    m.couple(tp, rayleigh);
    const Boundary boundary = boundary_of(m.space);
    const double   dt2      = tp.beta2 * tp.time_step * tp.time_step;
    const IndexSet &owned   = m.space.locally_owned;
    double          largest = 0.;
    for (const auto i : owned)
      largest = std::max(largest, std::abs(m.coupled.mass.diag_element(i)) +
                                    tp.beta1 * tp.time_step *
                                      std::abs(m.coupled.damping.diag_element(i)) +
                                    dt2 * std::abs(m.coupled.stiffness.diag_element(i)));
    const double k = 1e8 * Utilities::MPI::max(largest, MPI_COMM_WORLD) / dt2;
    for (const auto i : boundary.dofs)
      if (owned.is_element(i))
        m.coupled.stiffness.add(i, i, k);
    m.coupled.stiffness.compress(VectorOperation::add);

    time::NewmarkIntegrator newmark(tp, m.coupled.mass, m.coupled.damping, m.coupled.stiffness,
                                    m.space.constraints, false);
    time::NewmarkState      s;
    archdam::Vector         load;
    for (archdam::Vector *v : {&s.u, &s.v, &s.a, &load})
      m.space.reinit(*v);
    for (unsigned int n = 1; n <= n_steps; ++n)
      {
        const auto u = values_at(boundary, motion, n * tp.time_step);
        load         = 0.;
        for (unsigned int j = 0; j < u.size(); ++j)
          if (owned.is_element(boundary.dofs[j]))
            load(boundary.dofs[j]) = k * u[j];
        load.compress(VectorOperation::insert);
        newmark.advance(load, s);
        record(s);
      }
  }

  void
  rigid_base()
  {
    testing::log() << "A. rigid base under a water column (exact 1-D pressure wave)"
                   << std::endl;
    const Box b{1., 1., 1., 30., 1, 1, 1, 60, false};
    parallel::shared::Triangulation<3> tria(MPI_COMM_WORLD);
    make_model(b, tria);
    Model m(tria, true);

    const testing::Sin4Pulse g{0.001, 0.05};
    time::NewmarkParameters  tp;
    tp.time_step                = 2.5e-4;
    const unsigned int n_steps = 800; // 0.2 s: ~10 transits of the column
    const auto         exact   = [&](const double z, const double t) {
      double p = 0.;
      for (unsigned int n = 0; 2 * n * b.Hw / c_w < t; ++n)
        p += (n % 2 ? -1. : 1.) * (g.first(t - (2 * n * b.Hw + z) / c_w) -
                                   g.first(t - (2 * (n + 1) * b.Hw - z) / c_w));
      return rho_w * c_w * p;
    };
    const std::array<double, 2> z{{0., b.Hw / 2}};
    std::array<types::global_dof_index, 2> dof;
    for (unsigned int k = 0; k < 2; ++k)
      dof[k] = pressure_dof_at(m.space, Point<3>(0, 0, z[k]));
    std::array<double, 2> error{}, peak{};
    run_prescribed(
      m, tp, {0., 0.},
      [&](const Point<3> &, const unsigned int c, const double t) {
        return c == 2 ? g.value(t) : 0.;
      },
      n_steps, Columns::coupled, [&](const time::NewmarkState &s) {
        for (unsigned int k = 0; k < 2; ++k)
          {
            const double p_exact = exact(z[k], s.time);
            peak[k]              = std::max(peak[k], std::abs(p_exact));
            error[k] = std::max(error[k], std::abs(value_at(s.u, dof[k]) - p_exact));
          }
      });
    testing::log() << "  peak exact pressure at the base " << std::setprecision(3)
                   << peak[0] / 1e3 << " kPa" << std::endl;
    testing::check_below("  base: max |p - p_exact| / peak", error[0] / peak[0], 0.01);
    testing::check_below("  mid-depth: max |p - p_exact| / peak", error[1] / peak[1], 0.01);
  }

  void
  flexible_rock()
  {
    testing::log() << "B. flexible rock under water: prescribed columns against penalty "
                      "springs on the free boundary"
                   << std::endl;
    const Box b{40., 30., 30., 30., 4, 3, 3, 3, true};
    parallel::shared::Triangulation<3> tria(MPI_COMM_WORLD);
    make_model(b, tria);

    const testing::Sin4Pulse g{0.01, 0.1};
    time::NewmarkParameters  tp;
    tp.time_step                          = 2e-3;
    const unsigned int              n_steps  = 150;
    const std::pair<double, double> rayleigh{0.5, 0.002};
    const Tensor<1, 3>              direction({1., 0.3, 0.5});
    const Motion                    motion = [&](const Point<3> &x, const unsigned int c,
                                  const double t) {
      return direction[c] * (1 + 0.2 * x[0] / b.Lx - 0.1 * x[2] / b.Hr) * g.value(t);
    };

    // pressure and displacement DOFs (locally owned)
    Model         reference(tria, false);
    const IndexSet p_dofs = DoFTools::extract_dofs(
      reference.space.dof_handler,
      reference.space.fe_collection.component_mask(reference.space.pressure));
    std::vector<archdam::Vector> states;
    run_penalty(reference, tp, rayleigh, motion, n_steps,
                [&](const time::NewmarkState &s) { states.push_back(s.u); });
    // the largest |value| of displacements and pressures
    const auto keep_largest = [&](const types::global_dof_index i, const double value,
                                  double &u_max, double &p_max) {
      double &target = p_dofs.is_element(i) ? p_max : u_max;
      target         = std::max(target, std::abs(value));
    };
    double peak_u = 0., peak_p = 0.;
    for (const auto &u : states)
      for (const auto i : reference.space.locally_owned)
        keep_largest(i, u(i), peak_u, peak_p);
    peak_u = Utilities::MPI::max(peak_u, MPI_COMM_WORLD);
    peak_p = Utilities::MPI::max(peak_p, MPI_COMM_WORLD);
    testing::log() << "  peak displacement " << std::setprecision(2) << peak_u * 1e3
                   << " mm, peak pressure " << peak_p / 1e3 << " kPa" << std::endl;

    for (const Columns columns : {Columns::coupled, Columns::without_water, Columns::without_damping})
      {
        Model        m(tria, true);
        unsigned int n      = 0;
        double       err_u = 0., err_p = 0.;
        run_prescribed(m, tp, rayleigh, motion, n_steps, columns,
                       [&](const time::NewmarkState &s) {
                         for (const auto i : m.space.locally_owned)
                           keep_largest(i, double(s.u(i)) - double(states[n](i)), err_u, err_p);
                         ++n;
                       });
        err_u = Utilities::MPI::max(err_u, MPI_COMM_WORLD) / peak_u;
        err_p = Utilities::MPI::max(err_p, MPI_COMM_WORLD) / peak_p;
        if (columns == Columns::coupled)
          {
            testing::check_below("  full columns: max |u - u_ref| / peak u", err_u, 1e-6);
            testing::check_below("  full columns: max |p - p_ref| / peak p", err_p, 1e-6);
          }
        else
          testing::log() << (columns == Columns::without_water ? "  without the water's columns" :
                                                                 "  without the damping columns")
                         << ": off by more than 1e-4 of the peaks: "
                         << (std::max(err_u, err_p) > 1e-4 ? "yes" : "NO") << std::endl;
      }
  }

  void
  viscous_dashpots()
  {
    testing::log() << "C. dashpots of the viscous boundary with a general damping matrix"
                   << std::endl;
    parallel::shared::Triangulation<3> tria(MPI_COMM_WORLD);
    testing::rock_box(tria, Point<3>(0, 0, -30), Point<3>(40, 30, 0), {4, 3, 3},
                      ids::foundation_sides);
    physics::foundation::FoundationParameters fp;
    fp.model                 = physics::foundation::Model::massed;
    fp.transmitting_boundary = physics::foundation::TransmittingBoundary::viscous;
    fe::FiniteElementParameters fep;
    fep.degree = 1;
    fe::FESpace space(tria, fep);
    space.setup(fp.fixed_boundaries());
    solid::MaterialParameters materials;
    materials.rock = testing::test_rock();
    archdam::SparseMatrix M, K, D;
    solid::assemble_mass_and_stiffness(space, materials, solid::InertiaOf::dam_and_rock, M, K);
    const physics::foundation::FreeField free_field({}, materials.rock, 0., -30.);
    time::NewmarkParameters              tp;
    tp.time_step = 2e-3;
    const auto foundation_boundary = physics::foundation::make_massed_foundation(fp, space, materials,
                                                 solid::InertiaOf::dam_and_rock, free_field,
                                                 tp.time_step);
    auto &massed = *foundation_boundary;
    const std::pair<double, double> rayleigh{0.5, 0.002};
    reservoir::linear_combination(D, {{rayleigh.first, &M}, {rayleigh.second, &K}});

    // a vertical load pulse on the top surface's middle node
    archdam::Vector pattern;
    space.reinit(pattern);
    for (const auto &[i, pc] : testing::dof_positions(space))
      if (pc.second == 2 && pc.first.distance(Point<3>(20, 10, 0)) < 1e-6 &&
          space.locally_owned.is_element(i))
        pattern(i) = -1e6;
    pattern.compress(VectorOperation::insert);
    const testing::Sin4Pulse g{1., 0.05};

    const auto run = [&](time::NewmarkIntegrator &newmark) {
      std::vector<archdam::Vector> u;
      time::NewmarkState           s;
      archdam::Vector              load;
      for (archdam::Vector *v : {&s.u, &s.v, &s.a, &load})
        space.reinit(*v);
      for (unsigned int n = 1; n <= 100; ++n)
        {
          load = pattern;
          load *= g.value(n * tp.time_step);
          newmark.advance(load, s);
          u.push_back(s.u);
        }
      return u;
    };
    time::NewmarkIntegrator rayleigh_integrator(tp, M, K, rayleigh, space.constraints,
                                                massed.dashpots());
    time::NewmarkIntegrator general(tp, M, D, K, space.constraints, true, massed.dashpots());
    time::NewmarkIntegrator without(tp, M, D, K, space.constraints, true);
    const auto reference = run(rayleigh_integrator);
    double     peak      = 0.;
    for (const auto &u : reference)
      peak = std::max(peak, u.linfty_norm());
    const auto difference = [&](const std::vector<archdam::Vector> &u) {
      double d = 0.;
      for (unsigned int n = 0; n < u.size(); ++n)
        {
          archdam::Vector e = u[n];
          e -= reference[n];
          d = std::max(d, e.linfty_norm());
        }
      return d / peak;
    };
    testing::check_below("  with the dashpots: max |u - u_Rayleigh| / peak", difference(run(general)),
                         1e-9);
    testing::log() << "  without the dashpots: off by more than 1e-4 of the peak: "
                   << (difference(run(without)) > 1e-4 ? "yes" : "NO") << std::endl;
  }
} // namespace

int
main(int argc, char **argv)
{
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  rigid_base();
  flexible_rock();
  viscous_dashpots();
}
