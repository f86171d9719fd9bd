// The fundamental frequency of a flexible dam with an empty reservoir, with
// compressible water, with incompressible water and with Westergaard added
// mass (doc/theory/reservoir.md and doc/theory/loading-sequence.md §2; doc/verification.md "Reservoir"), side by side.
//
// Model. A concrete wall 50 m high, 5 m thick (x) and 10 m wide (y), fixed at
// its base, Q2 with 8 cells over the height, in the channel of
// reservoir_rigid_dam (water as deep as the wall, 3H long, rigid bottom,
// Sommerfeld truncation, rigid side walls). Light stiffness-proportional
// damping (beta = 0.002 s, 0.6 % of critical at the fundamental).
//
// Method. The resonance of the steady-state crest displacement under a
// harmonic ground acceleration (tests/harmonic_response.h: the
// complex symmetric 2x2-block system of the dam with its water), located by
// a scan and a golden-section search; with 0.6 % damping it is within 4e-5
// of the undamped natural frequency.
//
// Checks.
//  - empty reservoir: Euler-Bernoulli cantilever, omega = 1.8751^2
//    sqrt(E I / (rho A L^4)), within 5 % (the 3-D wall is 10 % as thick as
//    tall: shear, rotary inertia and plate action move it by a few percent);
//  - Westergaard: the ratio omega_W / omega_empty against the same ratio of
//    an independent 1-D model, the Euler-Bernoulli cantilever carrying the
//    Westergaard added mass (7/8) rho_w W sqrt(H (H - z)) per unit height,
//    solved by Rayleigh-Ritz with the polynomials z^2 ... z^7 (Gauss-Legendre
//    integration, LAPACK generalized eigenvalues): within 1 %, since the
//    ratio cancels most of what the beam model leaves out;
//  - every model with water is below the empty one; compressible and
//    incompressible water agree within 2 % (omega << pi c / (2H), the first
//    resonance of the water); Westergaard, which overestimates the added
//    mass (reservoir_added_mass), is the lowest.

#include <archdam/physics/reservoir/fluid_operators.h>
#include <archdam/physics/reservoir/wetted_face_loads.h>
#include <archdam/physics/solid/solid_operators.h>

#include <deal.II/base/quadrature_lib.h>
#include <deal.II/lac/lapack_full_matrix.h>

#include "archdam_tests.h"
#include "harmonic_response.h"
#include "reservoir_reference.h"

using namespace archdam;
using namespace archdam::testing;
namespace reservoir = archdam::physics::reservoir;

namespace
{
  const std::pair<double, double> rayleigh{0., 0.002};
  const physics::solid::MaterialParameters materials;

  /// The resonance frequency [rad/s] of the wall with the given water model.
  double
  resonance(const Channel &ch, const reservoir::Model model)
  {
    dealii::parallel::shared::Triangulation<dim> tria(MPI_COMM_WORLD);
    make_channel(ch, 24, 8, 0, tria);
    reservoir::ReservoirParameters rp;
    rp.model       = model;
    rp.density     = ch.rho;
    rp.sound_speed = ch.c;
    fe::FESpace space(tria, fe::FiniteElementParameters{});
    space.pressure_in_water = rp.has_pressure();
    space.setup({ids::foundation_bottom}, [&](dealii::AffineConstraints<double> &c) {
      reservoir::constrain_free_surface(space, rp, c);
    });
    std::vector<reservoir::InterfacePair> pairs;
    if (rp.has_pressure())
      {
        pairs               = reservoir::match_interface_faces(space);
        space.add_couplings = [&](dealii::DynamicSparsityPattern &dsp) {
          reservoir::add_interface_couplings(space, pairs, dsp);
        };
      }
    SparseMatrix M, K;
    physics::solid::assemble_mass_and_stiffness(space, materials, physics::solid::InertiaOf::dam,
                                                M, K);
    Vector inertia;
    physics::solid::assemble_inertia_load(space, materials, physics::solid::InertiaOf::dam,
                                          dealii::Point<dim>::unit_vector(0), inertia);
    if (model == reservoir::Model::westergaard)
      reservoir::add_westergaard_mass(space, ch.rho, ch.H, M);
    std::unique_ptr<reservoir::FluidOperators> ops;
    if (rp.has_pressure())
      {
        ops = std::make_unique<reservoir::FluidOperators>();
        reservoir::assemble_fluid_operators(space, rp, 9.81, pairs, *ops);
      }

    const dealii::Point<dim> crest(ch.dam / 2, ch.W / 2, ch.H);
    const auto amplitude = [&](const double omega) {
      Vector re, im, g_re, g_im;
      harmonic_response(space, M, K, rayleigh, inertia, ops.get(), ch.rho, omega, 0, re, im);
      space.reinit_ghosted(g_re);
      space.reinit_ghosted(g_im);
      g_re = re;
      g_im = im;
      return std::hypot(point_value(space, g_re, crest, 0), point_value(space, g_im, crest, 0));
    };
    // scan 3 ... 9 rad/s, then golden section around the largest value
    double best = 3., best_value = 0.;
    for (double w = 3.; w <= 9.; w += 0.25)
      if (const double a = amplitude(w); a > best_value)
        best = w, best_value = a;
    double       a = best - 0.25, b = best + 0.25;
    const double r = (std::sqrt(5.) - 1) / 2;
    double       c = b - r * (b - a), d = a + r * (b - a), fc = amplitude(c), fd = amplitude(d);
    while (b - a > 1e-6 * b)
      if (fc > fd)
        b = d, d = c, fd = fc, c = b - r * (b - a), fc = amplitude(c);
      else
        a = c, c = d, fc = fd, d = a + r * (b - a), fd = amplitude(d);
    return (a + b) / 2;
  }

  /// Rayleigh-Ritz on the Euler-Bernoulli cantilever with the mass per unit
  /// height m(z) = rho_c A + added(z): the lowest omega.
  double
  beam_frequency(const Channel &ch, const bool westergaard)
  {
    const auto  &concrete = materials.concrete;
    const double EI = concrete.youngs_modulus * ch.W * std::pow(ch.dam, 3) / 12;
    const double L = ch.H, mc = concrete.density * ch.W * ch.dam;
    const unsigned int n = 6; // phi_k = (z/L)^(k+2)
    dealii::LAPACKFullMatrix<double> Kb(n, n), Mb(n, n);
    const dealii::QGauss<1> gauss(40);
    for (unsigned int q = 0; q < gauss.size(); ++q)
      {
        const double s = gauss.point(q)[0], z = s * L, w = gauss.weight(q) * L;
        const double m = mc + (westergaard ? 7. / 8 * ch.rho * ch.W * std::sqrt(ch.H * (ch.H - z)) : 0.);
        for (unsigned int i = 0; i < n; ++i)
          for (unsigned int j = 0; j < n; ++j)
            {
              const double pi = i + 2., pj = j + 2.;
              Kb(i, j) += EI * pi * (pi - 1) * std::pow(s, pi - 2) * pj * (pj - 1) *
                          std::pow(s, pj - 2) / std::pow(L, 4) * w;
              Mb(i, j) += m * std::pow(s, pi) * std::pow(s, pj) * w;
            }
      }
    std::vector<dealii::Vector<double>> vectors(n, dealii::Vector<double>(n));
    Kb.compute_generalized_eigenvalues_symmetric(Mb, vectors);
    double lowest = std::numeric_limits<double>::max();
    for (unsigned int i = 0; i < n; ++i)
      lowest = std::min(lowest, Kb.eigenvalue(i).real());
    return std::sqrt(lowest);
  }
} // namespace

int
main(int argc, char **argv)
{
  dealii::Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  Channel ch;
  bool    ok = true;

  const double empty          = resonance(ch, reservoir::Model::none);
  const double compressible   = resonance(ch, reservoir::Model::compressible);
  const double incompressible = resonance(ch, reservoir::Model::incompressible);
  const double westergaard    = resonance(ch, reservoir::Model::westergaard);
  log() << "Fundamental frequency [Hz] of the 50 m wall:" << std::endl
        << std::setprecision(4) << "  empty " << empty / (2 * M_PI) << ", compressible "
        << compressible / (2 * M_PI) << ", incompressible " << incompressible / (2 * M_PI)
        << ", Westergaard " << westergaard / (2 * M_PI) << std::endl
        << "  ratios to empty: compressible " << compressible / empty << ", incompressible "
        << incompressible / empty << ", Westergaard " << westergaard / empty << std::endl;

  const double eb = 1.8751 * 1.8751 *
                    std::sqrt(materials.concrete.youngs_modulus * ch.dam * ch.dam /
                              (12 * materials.concrete.density * std::pow(ch.H, 4)));
  ok &= check_relative("  empty, against Euler-Bernoulli [rad/s]", empty, eb, 5e-2);
  ok &= check_relative("  Ritz check of the 1-D model without water [rad/s]",
                       beam_frequency(ch, false), eb, 1e-4);
  ok &= check_relative("  Westergaard / empty, against the 1-D beam with added mass",
                       westergaard / empty, beam_frequency(ch, true) / beam_frequency(ch, false),
                       1e-2);
  ok &= check_below("  compressible / empty", compressible / empty, 1.);
  ok &= check_below("  incompressible / empty", incompressible / empty, 1.);
  ok &= check_below("  Westergaard / empty", westergaard / empty, 1.);
  ok &= check_relative("  compressible against incompressible", compressible, incompressible,
                       2e-2);
  ok &= check_below("  Westergaard / incompressible", westergaard / incompressible, 1.);
  log() << (ok ? "OK" : "FAILED") << std::endl;
}
