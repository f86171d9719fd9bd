// Undamped elastic blocks sliding, lifting and landing on a joint with the
// program's default scheme for the joints (doc/theory/joints.md §10-§11:
// the step impulse with the average acceleration rule, the dissipative
// closure and the position correction, the mixed solver) and no damping at
// all (doc/verification.md,
// "Undamped blocks on a joint").
//
// A concrete block (E = 22 GPa, rho = 2400 kg/m^3, Q2, one cell) on a base
// block whose outer faces are fixed (it moves with the ground, relative
// formulation), the joint between them horizontal in the mesh. Every block is
// squat enough not to rock (width over height 1, above every base
// acceleration over g) and stiff enough to act rigidly (first frequency about
// 700 Hz, more than 20 times the inputs'). The weight rises first (it has no
// support but the joint, and a static stage needs the relaxation, tested in
// mesh_errors), then the ground moves. References, written here
// independently of the program:
//  - flat joint, rectangular pulse A g for t0 with sharp edges (Newmark
//    1965): permanent slip V^2 / (2 g mu) (1 - mu / A), V = A g t0; once
//    after a smooth rise of the weight, once after a rise in 2 ms (the block
//    rings);
//  - inclined joint under a sine along the slope: the joint is inclined by
//    theta against the weight (the weight turned in the mesh's frame, which
//    is the same problem), the rigid block's equation
//    s'' = -a_g + g sin(theta) - mu g cos(theta) sign(s') while it slides,
//    s' = 0 while |g sin(theta) - a_g| <= mu g cos(theta), integrated event
//    by event with exact sub-steps of 1e-6 s;
//  - a block thrown up by the ground falling at A g > g for t0: it lifts at
//    once, rises with (A - 1) g during the pulse and flies freely after it,
//    landing after t0 + (v0 + sqrt(v0^2 + 2 g s0)) / g, v0 = (A - 1) g t0,
//    s0 = (A - 1) g t0^2 / 2 (2 %, about a step); its energy after the
//    landing at most its energy in flight.
// Each sliding case at two time steps: the permanent slip within 2 % of the
// rigid block, the joint's largest opening at most 0.1 mm (the elastic
// block deforms by micrometres; the former default opened it by
// millimetres), the energy balance below 1e-3 of the input (measured
// 1e-10 to 7e-5: the block's ringing left from the settling, which the
// balance started at rest does not hold), the joints' work in every step
// zero or a loss (the closure's property), and the position correction's
// energy (EnergyTerms::correction, its own formula) at most 1e-3 of the
// input (measured: none, a sliding block does not land, so no step
// corrects).

#include <archdam/analysis/energy_balance.h>

#include <archdam/analysis/simulation.h>
#include <archdam/parameters/parameters.h>

#include "archdam_tests.h"
#include "gmsh_example.h"
#include "joint_tests.h"

#include <dlfcn.h>

using namespace dealii;
using namespace archdam;

namespace
{
  constexpr double g = 9.81, rho = 2400., E = 2.2e10, nu = 0.167;

  /// One run: the ground acceleration (x along the joint, z normal to it),
  /// the joint's inclination against the weight, friction, how fast the
  /// weight rises, and how long the ground moves.
  struct Case
  {
    std::string                                    name;
    std::function<Tensor<1, dim>(double)>          ground;
    double                                         theta = 0., mu = 0.2;
    double                                         ramp = 0.04, settle = 0.06, end = 0.5;
  };

  struct Result
  {
    std::vector<double>   slip;       // mean x of w over the pairs, from rest, each step
    std::vector<double>   gap;        // mean normal gap over the pairs, each step
    double                largest_opening = 0.;
    analysis::EnergyTerms energy;
    std::vector<double>   mechanical; // kinetic + strain (with the weight's potential)
    std::vector<double>   normal_force; // sum over the pairs, each step
    double                least_joint_work = 0.; // the joints' smallest work in a step [J]
    unsigned long         corrections = 0;
  };

  /// The joints' scheme: the program's defaults unless changed.
  struct Scheme
  {
    joints::Closure closure             = joints::JointParameters().closure;
    bool            position_correction = joints::JointParameters().position_correction;
    double          gap_tolerance       = joints::JointParameters().gap_tolerance;   // m
    double          force_tolerance     = joints::JointParameters().force_tolerance; // relative
  };

  Result
  run(const Case &c, const double dt, const Scheme &scheme = Scheme())
  {
    testing::BlockModel m(2, 2, Point<dim>(1., 1., 2.), 1, 2, E, nu, rho, {0});
    archdam::Vector                  gravity;
    std::array<archdam::Vector, dim> iota;
    Tensor<1, dim>                   weight;
    weight[0] = g * std::sin(c.theta);
    weight[2] = -g * std::cos(c.theta);
    physics::solid::assemble_inertia_load(*m.space, m.materials, physics::solid::InertiaOf::dam,
                                          Point<dim>(weight), gravity);
    for (unsigned int d = 0; d < dim; ++d)
      physics::solid::assemble_inertia_load(*m.space, m.materials,
                                            physics::solid::InertiaOf::dam,
                                            Point<dim>::unit_vector(d), iota[d]);
    joints::JointParameters jp; // the defaults: step impulse, closure at positions
    jp.model                    = joints::Model::frictional_contact;
    jp.law.friction_coefficient = c.mu;
    jp.law.cohesion = jp.law.residual_cohesion = 0.;
    jp.closure                  = scheme.closure;
    jp.position_correction      = scheme.position_correction;
    jp.gap_tolerance            = scheme.gap_tolerance;
    jp.force_tolerance          = scheme.force_tolerance;
    const time::NewmarkParameters np = testing::newmark_for(jp.contact_in_time, dt);
    time::NewmarkIntegrator newmark(np, m.M, m.K, {0., 0.}, m.space->constraints);
    auto solver = joints::make_joint_solver(jp, *m.pairs, newmark.displacement_factor(),
                                            newmark.effective(), newmark.effective_factor());
    time::NewmarkState s;
    archdam::Vector    load;
    for (archdam::Vector *v : {&s.u, &s.v, &s.a, &load})
      m.space->reinit(*v);
    analysis::EnergyBalance::Model em;
    em.space     = m.space.get();
    em.mass      = &m.M;
    em.stiffness = &m.K;
    em.newmark   = np;
    em.influence = &iota;
    analysis::EnergyBalance balance(em);

    const unsigned int n_pairs = m.pairs->size();
    const auto         mean_w  = [&](const unsigned int component) {
      double sum = 0.;
      for (unsigned int i = 0; i < n_pairs; ++i)
        for (unsigned int k = 0; k < dim; ++k)
          sum += solver->w[dim * i + k] * (*m.pairs)[i].frame[k][component];
      return sum / n_pairs;
    };
    Result             r;
    double             slip_at_rest = 0., contact_before = 0.;
    const unsigned int n_settle = std::lround(c.settle / dt), n = std::lround(c.end / dt);
    for (unsigned int k = 1; k <= n_settle + n; ++k)
      {
        const double t = (double(k) - n_settle) * dt;
        load           = gravity;
        if (k * dt < c.ramp)
          load *= 0.5 * (1 - std::cos(M_PI * k * dt / c.ramp));
        const Tensor<1, dim> ag = k > n_settle ? c.ground(t) : Tensor<1, dim>();
        for (unsigned int d = 0; d < dim; ++d)
          load.add(-ag[d], iota[d]);
        const auto step = joints::advance_with_contact(newmark, *solver, load, s);
        AssertThrow(step.converged, ExcMessage(c.name + ": " + solver->describe(step)));
        if (k == n_settle)
          {
            balance.start(s, solver.get());
            slip_at_rest = mean_w(0);
          }
        if (k < n_settle)
          continue;
        if (k > n_settle)
          balance.add_step(s, ag, solver.get());
        r.slip.push_back(mean_w(0) - slip_at_rest);
        r.gap.push_back(mean_w(2));
        for (unsigned int i = 0; i < n_pairs; ++i)
          r.largest_opening = std::max(r.largest_opening, solver->gap(i));
        const auto e = balance.terms();
        r.mechanical.push_back(e.kinetic + e.strain);
        r.normal_force.push_back(testing::total_normal_force(*solver));
        r.least_joint_work = std::min(r.least_joint_work, e.contact - contact_before);
        contact_before     = e.contact;
      }
    r.energy      = balance.terms();
    r.corrections = solver->corrections;
    return r;
  }

  void
  report(const Result &r, const std::string &label)
  {
    if (std::getenv("JOINT_BLOCK_NUMBERS"))
      std::cerr << label << ": slip " << r.slip.back() << " largest opening "
                << r.largest_opening << " corrections " << r.corrections << " input "
                << r.energy.input << " kinetic " << r.energy.kinetic << " strain "
                << r.energy.strain << " contact " << r.energy.contact << " correction "
                << r.energy.correction << " balance "
                << r.energy.balance_error() << std::endl;
  }
} // namespace

int
main(int argc, char **argv)
{
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  auto                            &log = testing::log();

  const double A = 0.5, t0 = 0.1, mu = 0.2;
  const auto   pulse = [&](const double t) {
    Tensor<1, dim> a;
    a[0] = t > 0 && t <= t0 + 1e-12 ? A * g : 0.;
    return a;
  };
  const double theta = 10. * M_PI / 180., mu_slope = 0.4, Ah = 0.4, T = 0.5;
  const std::vector<Case> cases{
    {"flat joint, rectangular pulse A = 0.5, t0 = 0.1 s, mu = 0.2, the weight risen in 40 ms",
     pulse, 0., mu, 0.04},
    {"flat joint, the same pulse, the weight risen in 2 ms (the block rings)", pulse, 0., mu,
     0.002},
    {"joint inclined by 10 deg, mu = 0.4, two periods of 0.4 g sin(2 pi t / 0.5 s) along the "
     "slope",
     [&](const double t) {
       Tensor<1, dim> a;
       a[0] = t < 2 * T ? Ah * g * std::sin(2 * M_PI * t / T) : 0.;
       return a;
     },
     theta, mu_slope, 0.04, 0.06, 1.4}};
  const Case *const slope = &cases.back();

  // Every check of one run. The joints' work in a step is zero or a loss by
  // construction (doc/theory/joints.md §11): the smallest over the steps
  // is checked against the round-off of the work sums, 1e-9 of the input.
  const auto check_run = [&](const Result &r, const double slip_ref, const std::string &label) {
    report(r, label);
    testing::check_relative("    permanent slip [m] (rigid block)", r.slip.back(), slip_ref, 0.02);
    testing::check_below("    largest opening [m]", r.largest_opening, 1e-4);
    testing::check_below("    energy balance error", r.energy.balance_error(), 1e-3);
    log << "    the joints' work in every step zero or a loss: "
        << testing::yes(r.least_joint_work >= -1e-9 * r.energy.input) << std::endl;
    testing::check_below("    the position correction's energy / the input",
                         std::abs(r.energy.correction) / r.energy.input, 1e-3);
  };
  for (const Case &c : cases)
    {
      log << c.name << ":" << std::endl;
      for (const double dt : {1e-3, 5e-4})
        {
          const auto ref = testing::rigid_block(
            [&](const double t) { return g * std::sin(c.theta) - c.ground(t)[0]; },
            c.mu * g * std::cos(c.theta), c.end, dt);
          log << "  dt = " << dt * 1e3 << " ms:" << std::endl;
          check_run(run(c, dt), ref.back(), c.name + ", dt " + std::to_string(dt));
        }
    }

  // The block thrown up: the landing is the first step after the pulse in
  // which the pairs carry a force again.
  const double Af = 2., tf = 0.05;
  const Case   thrown{"block thrown up by the ground falling at 2 g for 0.05 s",
                    [&](const double t) {
                      Tensor<1, dim> a;
                      a[2] = t > 0 && t <= tf + 1e-12 ? -Af * g : 0.;
                      return a;
                    },
                    0., 0.5, 0.04, 0.06, 0.4};
  const double v0 = (Af - 1) * g * tf, s0 = 0.5 * (Af - 1) * g * tf * tf;
  const double flight = tf + (v0 + std::sqrt(v0 * v0 + 2 * g * s0)) / g;
  log << thrown.name << ":" << std::endl;
  for (const double dt : {1e-3, 5e-4})
    {
      const Result r = run(thrown, dt);
      report(r, "thrown, dt " + std::to_string(dt));
      unsigned int landing = 0;
      for (unsigned int k = std::lround(tf / dt) + 1; k < r.normal_force.size() && !landing; ++k)
        if (r.normal_force[k] < 0.)
          landing = k;
      double after = 0.;
      for (unsigned int k = landing; k < r.mechanical.size(); ++k)
        after = std::max(after, r.mechanical[k]);
      log << "  dt = " << dt * 1e3 << " ms:" << std::endl;
      testing::check_relative("    flight time [s] (free flight after the pulse)", landing * dt,
                              flight, 0.02);
      log << "    no energy gained at the landing (kinetic + strain after it at most in "
             "flight): "
          << testing::yes(landing > 1 && after <= r.mechanical[landing - 2]) << std::endl;
      testing::check_below("    energy balance error", r.energy.balance_error(), 1e-3);
      log << "    the joints' work in every step zero or a loss: "
          << testing::yes(r.least_joint_work >= -1e-9 * r.energy.input) << std::endl;
    }

  // The former default (velocities and the position correction) on the
  // same block: it hops (its joint opens by millimetres), and the work its
  // corrections do, which no force of the model does (EnergyTerms::
  // correction, from the displacements they moved), is what its balance
  // misses: with the term the balance closes as the new default's does
  // (to the block's ringing left from the settling, measured 7e-5 of the
  // input), without it it is open by more than 1e-2 (measured 0.13).
  {
    const Result r = run(*slope, 5e-4, Scheme{joints::Closure::velocities, true});
    report(r, "slope, velocities and position correction");
    auto without       = r.energy;
    without.correction = 0.;
    log << "former default (velocities and position correction) on the slope, dt = 0.5 ms:"
        << std::endl
        << "  corrections made, its joint open by more than 1 mm: "
        << testing::yes(r.corrections > 0 && r.largest_opening > 1e-3) << std::endl;
    testing::check_below("  balance error with the correction's term", r.energy.balance_error(),
                         2e-4);
    log << "  balance error without it above 1e-2: "
        << testing::yes(without.balance_error() > 1e-2) << std::endl;
  }

  // A block resting on its joint alone, its static stage by the mixed
  // method with dynamic relaxation (doc/theory/joints.md §8: the one solve
  // needs K^-1, which such a block does not have): two unit cubes stacked in
  // z (gmsh_example::two_cubes), the lower one fixed on its bottom face. The
  // joint carries the upper cube's weight, rho g V, to the relaxation's
  // tolerance (1e-6 of the load; checked to 1e-4), and no shear.
  {
    std::string mesh = testing::gmsh_example::two_cubes(true, 0, 2);
    mesh.replace(mesh.find("$Elements\n2\n"), 12, "$Elements\n3\n");
    mesh.replace(mesh.find("$EndElements"), 0, "3 3 2 1 1 1 3 7 5\n");
    if (Utilities::MPI::this_mpi_process(MPI_COMM_WORLD) == 0)
      std::ofstream("stacked_blocks.msh") << mesh;
    MPI_Barrier(MPI_COMM_WORLD);
    const Parameters p = parameters_from_string(
      "subsection Mesh\n  set Source = gmsh\n  subsection Gmsh\n    set File = stacked_blocks.msh\n"
      "  end\nend\nsubsection Contraction joints\n  set Model = frictional contact\n"
      "  set Static solution = dynamic relaxation\nend\n"
      "subsection Analysis\n  set Stages = static\nend\n"
      "subsection Output\n  set Directory = stacked_blocks_results\nend\n");
    std::ostringstream   quiet;
    analysis::Simulation sim(p, MPI_COMM_WORLD, quiet);
    sim.run();
    // The resultant of the pair forces on the lower block, in the global
    // frame (each pair's force in its frame xi, eta, zeta): the weight
    // downwards, nothing across (the pairs' shear from the blocks' unequal
    // Poisson expansion cancels).
    const auto    &joints = *sim.joint_state();
    Tensor<1, dim> resultant;
    for (unsigned int i = 0; i < joints.pairs.size(); ++i)
      for (unsigned int k = 0; k < dim; ++k)
        resultant += joints.force[dim * i + k] * joints.pairs[i].frame[k];
    const double weight = p.materials.concrete.density * g * 1.;
    log << "a block resting on its joint alone, static stage by dynamic relaxation:" << std::endl;
    testing::check_relative("  the joint's resultant force downwards [N] (the block's weight)",
                            -resultant[2], weight, 1e-4);
    testing::check_below("  its horizontal part / the weight",
                         std::hypot(resultant[0], resultant[1]) / weight, 1e-4);
  }

  // The number of BLAS threads (OpenBLAS's, where the library runs on it)
  // changes the round-off of the factorization and of the contact problem's
  // dense algebra, not the results: every case at 0.5 ms with one and with
  // two agrees to 1e-8 of the slip. On the flat joint at the default contact
  // tolerances (measured 5e-15 and 3e-12). On the slope the pairs stick and
  // slip many times, and each solve is exact only to the contact tolerances
  // (gap 1e-9 m, force 1e-8): the two runs differ by 5e-7 of the slip there
  // (measured; 2e-8 m, about 20 gap tolerances), bounded here by 1e-5, and
  // with tolerances a thousand times tighter by 2e-9 (measured), checked
  // against 1e-8: the difference is the tolerance's, not the threads'.
  using SetThreads       = void (*)(int);
  const auto set_threads =
    reinterpret_cast<SetThreads>(dlsym(RTLD_DEFAULT, "openblas_set_num_threads"));
  const auto with_threads = [&](const int n, const Case &c, const Scheme &scheme) {
    if (set_threads)
      set_threads(n);
    const double slip = run(c, 5e-4, scheme).slip.back();
    if (set_threads)
      set_threads(1);
    return slip;
  };
  Scheme tight;
  tight.gap_tolerance   = 1e-3 * tight.gap_tolerance;
  tight.force_tolerance = 1e-3 * tight.force_tolerance;
  log << "every case at 0.5 ms with one and two BLAS threads:" << std::endl;
  for (unsigned int k = 0; k < cases.size(); ++k)
    {
      const Case        &c      = cases[k];
      const std::string  label  = "  case " + std::to_string(k + 1);
      const double       one    = with_threads(1, c, Scheme()), two = with_threads(2, c, Scheme());
      testing::check_below(label + ": |slip(1) - slip(2)| / slip",
                           std::abs(one - two) / std::abs(one), &c == slope ? 1e-5 : 1e-8);
      if (&c == slope)
        {
          const double one_tight = with_threads(1, c, tight), two_tight = with_threads(2, c, tight);
          testing::check_below(label + ", contact tolerances 1e-3 times the default: |slip(1) - "
                                       "slip(2)| / slip",
                               std::abs(one_tight - two_tight) / std::abs(one_tight), 1e-8);
        }
    }
}
