// Verification (doc/theory/reservoir.md §6-§8, doc/verification.md "Reservoir"): the water
// models without waves on a vertical dam face, against closed forms and the
// exact series:
//  - hydrostatic load: resultant rho_w g h^2 W / 2 and moment about the base
//    rho_w g W h^3 / 6 for the water level at the top of the water mesh
//    (h = H) and at a given level (h = H/2); the pressure is linear and Q2
//    integrates it exactly, so the tolerance is round-off (1e-10);
//  - generalized Westergaard added mass M_a = (7/8) rho_w sqrt(H h_i) A_i n_i n_i^T:
//    under a unit rigid acceleration in x, its resultant must reproduce
//    Westergaard's parabola integrated over the face, (7/12) rho_w W H^2, and
//    its moment about the base (7/30) rho_w W H^3. The nodal (lumped) rule
//    integrates sqrt(h) inexactly near the surface: the error must shrink
//    with the mesh (ratio < 0.6 per halving) and be below 0.2 % on the
//    finest mesh (32 cells over the height);
//  - incompressible water (c -> infinity, physics/reservoir with the
//    incompressible model, fixed rigid dam, truncation at L = 3H with a rigid
//    end wall since radiation is dropped): the face pressure at four heights
//    and the resultant against the exact series for the same channel
//    (reservoir_reference.h with c = infinity), within 0.1 % on h = H/16,
//    error shrinking with the mesh. Westergaard's resultant exceeds the exact
//    incompressible one (infinite channel: 16/pi^3 sum 1/(2n-1)^3 =
//    0.5427 rho_w W H^2 against 7/12 = 0.5833): printed for the record.

#include <archdam/physics/reservoir/fluid_operators.h>
#include <archdam/physics/reservoir/wetted_face_loads.h>

#include <deal.II/base/function.h>
#include <deal.II/numerics/vector_tools.h>

#include "archdam_tests.h"
#include "harmonic_response.h"
#include "reservoir_reference.h"

using namespace archdam;
using namespace archdam::testing;
namespace reservoir = archdam::physics::reservoir;

namespace
{
  /// The nodal field u = f(z) e_x on the solid (pressure 0).
  class RigidX : public dealii::Function<dim>
  {
  public:
    explicit RigidX(const unsigned int power)
      : dealii::Function<dim>(dim + 1)
      , power(power)
    {}
    double
    value(const dealii::Point<dim> &x, const unsigned int c) const override
    {
      return c == 0 ? std::pow(x[2], power) : 0.;
    }
    unsigned int power;
  };

  struct DryModel
  {
    DryModel(const Channel &ch, unsigned int nz)
      : tria(MPI_COMM_WORLD)
    {
      make_channel(ch, 3, nz, 0, tria);
      space                    = std::make_unique<fe::FESpace>(tria, fe::FiniteElementParameters{});
      space->pressure_in_water = false;
      space->setup({});
      for (unsigned int k = 0; k < 2; ++k)
        {
          space->reinit(rigid[k]);
          dealii::VectorTools::interpolate(space->dof_handler, RigidX(k), rigid[k]);
        }
    }
    dealii::parallel::shared::Triangulation<dim> tria;
    std::unique_ptr<fe::FESpace>                 space;
    std::array<Vector, 2>                        rigid; // e_x and z e_x
  };
} // namespace

int
main(int argc, char **argv)
{
  dealii::Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  Channel      ch;
  const double g = 9.81, rho = ch.rho, H = ch.H, W = ch.W;
  bool         ok = true;

  log() << "Hydrostatic load" << std::endl;
  {
    DryModel m(ch, 4);
    reservoir::ReservoirParameters rp;
    rp.model = reservoir::Model::westergaard;
    for (const bool from_mesh : {true, false})
      {
        rp.level_from_mesh = from_mesh;
        rp.water_level     = H / 2;
        const double level = reservoir::water_level(rp, m.tria);
        Vector       load;
        m.space->reinit(load);
        reservoir::add_hydrostatic_load(*m.space, rho, g, level, load);
        const std::string what = from_mesh ? "  level from the mesh" : "  level H/2";
        ok &= check_relative(what + ": resultant [N]", load * m.rigid[0],
                             rho * g * level * level * W / 2, 1e-10);
        ok &= check_relative(what + ": moment about the base [N m]", load * m.rigid[1],
                             rho * g * W * std::pow(level, 3) / 6, 1e-10);
      }
  }

  log() << "Westergaard added mass (unit acceleration in x)" << std::endl;
  std::vector<double> force_errors, moment_errors;
  double              westergaard_force = 0.;
  for (const unsigned int nz : {4u, 8u, 16u, 32u})
    {
      DryModel     m(ch, nz);
      SparseMatrix M;
      m.space->reinit(M);
      reservoir::add_westergaard_mass(*m.space, rho, H, M);
      Vector Mu;
      m.space->reinit(Mu);
      M.vmult(Mu, m.rigid[0]);
      westergaard_force = Mu * m.rigid[0];
      const double moment = Mu * m.rigid[1];
      force_errors.push_back(std::abs(westergaard_force / (7. / 12 * rho * W * H * H) - 1));
      moment_errors.push_back(std::abs(moment / (7. / 30 * rho * W * H * H * H) - 1));
      log() << "  " << nz << " cells over the height: resultant error " << std::setprecision(2)
            << force_errors.back() << ", moment error " << moment_errors.back() << std::endl;
    }
  ok &= check_below("  finest mesh: resultant error", force_errors.back(), 2e-3);
  ok &= check_below("  finest mesh: moment error", moment_errors.back(), 2e-3);
  for (unsigned int i = 1; i < force_errors.size(); ++i)
    ok &= check_below("  resultant error ratio, mesh " + std::to_string(i + 1) + " to " +
                        std::to_string(i),
                      force_errors[i] / force_errors[i - 1], 0.6);

  log() << "Incompressible water, rigid dam, channel of 3H with a rigid end" << std::endl;
  Channel incompressible = ch;
  incompressible.c       = std::numeric_limits<double>::infinity();
  std::vector<double> z_ref;
  for (unsigned int i = 0; i <= 400; ++i)
    z_ref.push_back(H * i / 400.);
  // resultant of the series by Simpson's rule on 400 intervals (sqrt-free,
  // smooth integrand apart from the 1/n^2 tail: far below the FE errors)
  const auto   p_ref = face_pressure(incompressible, 0., z_ref, ch.L);
  double       force_ref = 0.;
  for (unsigned int i = 0; i <= 400; ++i)
    force_ref += (i == 0 || i == 400 ? 1 : i % 2 ? 4 : 2) * p_ref[i].real();
  force_ref *= W * (H / 400) / 3;
  const double force_infinite = 16 / std::pow(M_PI, 3) * rho * W * H * H *
                                [] {
                                  double s = 0;
                                  for (unsigned int n = 1; n < 100000; ++n)
                                    s += 1. / std::pow(2. * n - 1, 3);
                                  return s;
                                }();
  log() << "  series resultant: channel of 3H " << std::setprecision(5) << -force_ref / (rho * W * H * H)
        << " rho_w W H^2, infinite channel " << force_infinite / (rho * W * H * H)
        << ", Westergaard 7/12 = " << 7. / 12 << std::endl;

  reservoir::ReservoirParameters rp;
  rp.model   = reservoir::Model::incompressible;
  rp.density = rho;
  std::vector<double> errors;
  for (const unsigned int n : {4u, 8u, 16u})
    {
      dealii::parallel::shared::Triangulation<dim> tria(MPI_COMM_WORLD);
      make_channel(ch, 3 * n, n, 0, tria);
      fe::FESpace space(tria, fe::FiniteElementParameters{});
      space.setup({}, [&](dealii::AffineConstraints<double> &c) {
        fix_solid(space, c);
        reservoir::constrain_free_surface(space, rp, c);
      });
      const auto pairs    = reservoir::match_interface_faces(space);
      space.add_couplings = [&](dealii::DynamicSparsityPattern &dsp) {
        reservoir::add_interface_couplings(space, pairs, dsp);
      };
      reservoir::FluidOperators ops;
      reservoir::assemble_fluid_operators(space, rp, g, pairs, ops);
      Vector pr, pi, ghosted;
      harmonic_pressure(space, ops, 1., 0, pr, pi);
      // the force of the water on the dam in x: int p n_x = (1/rho) iota_x^T S^T p
      const double force = (ops.influence[0] * pr) / rho;
      space.reinit_ghosted(ghosted);
      ghosted = pr;
      double err = std::abs(force / force_ref - 1);
      for (const double zz : {0., 0.25, 0.5, 0.75})
        {
          const double fe  = point_value(space, ghosted, dealii::Point<dim>(0, W / 2, zz * H), dim);
          const double ref = face_pressure(incompressible, 0., {zz * H}, ch.L)[0].real();
          err              = std::max(err, std::abs(fe - ref) / std::abs(p_ref[0].real()));
        }
      errors.push_back(err);
      log() << "  h = H/" << n << ": resultant " << std::setprecision(5)
            << -force / (rho * W * H * H) << " rho_w W H^2, error (pressures and resultant) "
            << std::setprecision(2) << err << std::endl;
    }
  ok &= check_below("  finest mesh: error", errors.back(), 1e-3);
  for (unsigned int i = 1; i < errors.size(); ++i)
    ok &= check_below("  error ratio, mesh " + std::to_string(i + 1) + " to " + std::to_string(i),
                      errors[i] / errors[i - 1], 0.5);
  log() << "  Westergaard / exact incompressible resultant (infinite channel): "
        << std::setprecision(3) << westergaard_force / force_infinite << std::endl;
  log() << (ok ? "OK" : "FAILED") << std::endl;
}
