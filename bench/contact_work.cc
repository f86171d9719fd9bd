// Benchmark (issue 20; doc/verification.md, "Where the joints create energy
// (diagnosis)"): which state transitions of the joints' node pairs, and
// which pairs, do the negative contact work, i.e. put energy into the dam.
//
//   bench_contact_work [--end T] [--scale s] [--time-steps dt1,dt2,...]
//
// The case: the 14-block arch dam on the coarse Q1 mesh (one cell across
// each block and through the thickness, 4 over the height; 13 joints, 104
// node pairs), massless rock, empty reservoir, the default 5 % Rayleigh
// damping (1 and 10 Hz), the paper's joint law mu = 0.7, c = 0,
// sigma_t = 0.5 MPa (doc/theory/joints.md §2). Gravity with the joints in
// contact is the static stage (run by the program); from that state the
// dynamic steps are taken here with the program's Newmark integrator and
// mixed joint solver, one step exactly as the dynamic stage takes it
// (doc/theory/joints.md §5), under El Centro (180) in x times s, from t = 0
// to T, so that every pair can be followed through every step.
//
// The contact work of pair i over a step is the work of its force on its
// relative displacement with the trapezoidal rule of the energy balance's
// contact term (doc/theory/results.md §7):
//   W_i = (f_i,n + f_i,n+1) / 2 . (w_i,n+1 - w_i,n),
// positive = dissipated (friction), negative = created. It is classified by
// the pair's state at the start and at the end of the step. The sum over the
// pairs is checked against the energy balance run alongside.
// Cases: at each time step, the trapezoidal pair forces with Beta1 = 0.5,
// Beta2 = 0.25 (average acceleration) and Beta1 = 0.6, Beta2 = 0.3025, and the
// step impulse with Beta1 = 0.5 (doc/theory/joints.md §10), in one process
// run; a case that diverges is reported up to its last good step.
// Reported per case: the input work, the contact work (sum over the pairs,
// and the energy balance's term), its positive (dissipated) and negative
// (created) parts; by transition: pair-steps, net, dissipated, created, the
// normal part; by joint; the 10 pairs creating the most. Across the cases:
// created / input every 0.5 s, and the ratios of the created energy between
// the schemes and between successive time steps, up to the last report time
// every case reached.

#include <archdam/analysis/energy_balance.h>
#include <archdam/analysis/simulation.h>
#include <archdam/base/run_stopped.h>
#include <archdam/parameters/parameters.h>
#include <archdam/physics/solid/solid_operators.h>
#include <archdam/time/divergence_check.h>

#include <deal.II/base/mpi.h>
#include <deal.II/base/timer.h>

#include <algorithm>
#include <array>
#include <iomanip>
#include <iostream>
#include <numeric>
#include <set>
#include <sstream>

#include "bench_common.h"

using namespace archdam;
using joints::PairState;

namespace
{
  /// A pair's state transition over a step.
  enum Kind
  {
    stick_stick,
    slip_slip,
    separation_separation,
    closing,
    opening,
    stick_to_slip,
    slip_to_stick,
    n_kinds
  };

  const std::array<std::string, n_kinds> kind_names = {{"stick->stick", "slip->slip",
                                                        "separation->separation",
                                                        "closing (separation->contact)",
                                                        "opening (contact->separation)",
                                                        "stick->slip", "slip->stick"}};

  Kind
  kind_of(const PairState from, const PairState to)
  {
    if (from == PairState::separation)
      return to == PairState::separation ? separation_separation : closing;
    if (to == PairState::separation)
      return opening;
    if (from == PairState::stick)
      return to == PairState::stick ? stick_stick : stick_to_slip;
    return to == PairState::slip ? slip_slip : slip_to_stick;
  }

  /// Contact work of a set of pair-steps [J].
  struct Work
  {
    unsigned long count = 0, creating = 0; ///< pair-steps; of which with negative work
    double        dissipated = 0., created = 0.; ///< sums of the positive, negative works
    double        normal     = 0.;               ///< the normal (xi) part of the net work

    void
    add(const double work, const double normal_work)
    {
      ++count;
      (work < 0. ? created : dissipated) += work;
      creating += work < 0.;
      normal += normal_work;
    }
    double
    net() const
    {
      return dissipated + created;
    }
  };

  struct Case
  {
    double       beta1 = 0.5, beta2 = 0.25, dt = 0.01;
    joints::ContactInTime contact = joints::ContactInTime::trapezoidal;
    unsigned int steps = 0, steps_run = 0;
    std::string  stopped; ///< why the case ended early, if it did
    double       input = 0., balance_contact = 0., algorithmic = 0., balance_error = 0.;
    std::array<Work, n_kinds> kinds;
    std::vector<Work>         joint, pair;
    /// Created energy of every pair by transition kind.
    std::vector<std::array<double, n_kinds>> pair_created;
    /// Every 0.5 s of the run: the time, the input work and the created energy so far.
    std::vector<std::array<double, 3>> history;
    unsigned long                      iterations = 0;
    unsigned int                       max_iterations = 0, not_converged = 0;
    double                             wall = 0.;

    Work
    total() const
    {
      Work t;
      for (const Work &k : kinds)
        {
          t.count += k.count;
          t.creating += k.creating;
          t.dissipated += k.dissipated;
          t.created += k.created;
          t.normal += k.normal;
        }
      return t;
    }
  };

  std::string
  case_text(const double scale)
  {
    std::ostringstream prm;
    prm << "subsection Mesh\n set Source = arch dam\n subsection Arch dam\n"
        << "  set Cells over height = 4\n  set Cells across each block = 1\n"
        << "  set Cells through thickness = 1\n end\nend\n"
        << "subsection Finite element\n set Degree = 1\nend\n"
        << "subsection Contraction joints\n set Model = frictional contact\n"
        << " set Friction coefficient = 0.7\n set Cohesion = 0\n set Tensile strength = 5e5\n"
        << "end\n"
        << "subsection Analysis\n set Stages = static\nend\n"
        << "subsection Ground motion\n subsection Component x\n  set File = "
        << "ground_motions/RSN6_IMPVALL.I_I-ELC180.AT2\n"
        << "  set Scale factor = " << scale << "\n end\nend\n"
        << "subsection Output\n set Directory = bench_contact_work_output\n"
        << " set Field output interval = 0\n set Progress = false\n"
        << " set Timer summary = false\nend\n";
    return prm.str();
  }

  /// The model after the static stage, and the loads of the dynamic steps.
  struct Model
  {
    const Parameters               &p;
    const analysis::Simulation     &sim;
    Vector                          gravity;
    std::array<Vector, dim>         influence;
    const loads::GroundMotion       motion;

    Model(const Parameters &p, const analysis::Simulation &sim)
      : p(p)
      , sim(sim)
      , motion(p.ground_motion, p.base_directory)
    {
      // Self-weight of the dam (the static stage's load without water) and
      // M iota_d of the relative formulation (doc/theory/foundation.md §2).
      namespace solid = physics::solid;
      dealii::Tensor<1, dim> g;
      g[dim - 1] = -p.static_loads.g;
      solid::assemble_inertia_load(sim.model().space(), p.materials, solid::InertiaOf::dam, g, gravity);
      for (unsigned int d = 0; d < dim; ++d)
        solid::assemble_inertia_load(sim.model().space(), p.materials, solid::InertiaOf::dam,
                                     dealii::Point<dim>::unit_vector(d), influence[d]);
    }
  };

  Case
  run_case(const Model &model, const double beta1, const joints::ContactInTime contact,
           const double dt, const double end)
  {
    const Parameters         &p     = model.p;
    const fe::FESpace        &space = model.sim.model().space();
    const joints::NodePairs  &pairs = *model.sim.model().joint_pairs();
    Case                      c;
    c.beta1   = beta1;
    c.contact = contact;
    // The strongest damping of the highest frequencies for this Beta1
    // (doc/theory/time-integration.md §6).
    c.beta2 = (beta1 + 0.5) * (beta1 + 0.5) / 4.;
    c.dt    = dt;
    c.steps = std::lround(end / dt);
    c.joint.resize(pairs.n_joints());
    c.pair.resize(pairs.size());
    c.pair_created.assign(pairs.size(), {});

    dealii::Timer           timer;
    time::NewmarkParameters np = p.time_integration;
    np.time_step               = dt;
    np.beta1                   = c.beta1;
    np.beta2                   = c.beta2;
    const auto rayleigh        = p.damping.rayleigh_coefficients();
    // Kbar factorized condensed on the pairs' DOFs, as the dynamic stage does
    // with the default Mixed method solves.
    time::NewmarkIntegrator newmark(np, model.sim.model().mass(), model.sim.model().stiffness(), rayleigh,
                                    space.constraints, nullptr, pairs.interface());
    joints::JointParameters jp = p.joints;
    jp.contact_in_time         = contact;
    auto solver = joints::make_joint_solver(jp, pairs, newmark.displacement_factor(),
                                            newmark.effective(), newmark.effective_factor());
    solver->set_state(*model.sim.joint_state());

    time::NewmarkState s;
    Vector             load;
    for (Vector *v : {&s.u, &s.v, &s.a, &load})
      space.reinit(*v);
    s.u = model.sim.static_displacement();

    analysis::EnergyBalance::Model em;
    em.space     = &space;
    em.mass      = &model.sim.model().mass();
    em.stiffness = &model.sim.model().stiffness();
    em.rayleigh  = rayleigh;
    em.newmark   = np;
    em.influence = &model.influence;
    analysis::EnergyBalance balance(em);
    balance.start(s, solver.get());

    const time::DivergenceCheck divergence(space);
    for (unsigned int n = 1; n <= c.steps; ++n)
      {
        const std::vector<PairState> state = solver->state;
        const std::vector<double>    force = solver->pair_load, w = solver->w;
        const auto                   ag    = model.motion.acceleration(n * dt);
        load                               = model.gravity;
        for (unsigned int d = 0; d < dim; ++d)
          load.add(-ag[d], model.influence[d]);
        const auto step = joints::advance_with_contact(newmark, *solver, load, s);
        s.time          = n * dt;
        c.iterations += step.iterations;
        c.max_iterations = std::max(c.max_iterations, step.iterations);
        c.not_converged += !step.converged;
        try
          {
            divergence.check(s, n);
          }
        catch (const RunStopped &stop)
          {
            c.stopped = stop.what();
            break;
          }
        balance.add_step(s, ag, solver.get());
        for (unsigned int i = 0; i < pairs.size(); ++i)
          {
            double work = 0., normal = 0.;
            for (unsigned int k = 0; k < dim; ++k)
              {
                const unsigned int j = dim * i + k;
                const double       w_k =
                  0.5 * (force[j] + solver->pair_load[j]) * (solver->w[j] - w[j]);
                work += w_k;
                if (k == 0)
                  normal = w_k;
              }
            const Kind kind = kind_of(state[i], solver->state[i]);
            c.kinds[kind].add(work, normal);
            c.joint[pairs[i].joint].add(work, normal);
            c.pair[i].add(work, normal);
            if (work < 0.)
              c.pair_created[i][kind] += work;
          }
        c.steps_run = n;
        if (n % std::lround(0.5 / dt) == 0)
          c.history.push_back({{s.time, balance.terms().input, c.total().created}});
      }
    const auto e      = balance.terms();
    c.input           = e.input;
    c.balance_contact = e.contact;
    c.algorithmic     = e.algorithmic;
    c.balance_error   = e.balance_error();
    c.wall            = timer.wall_time();
    return c;
  }

  /// 100 part / whole, rounded to a whole per cent.
  long
  percent(const double part, const double whole)
  {
    return whole == 0. ? 0 : std::lround(100. * part / whole);
  }

  /// "Beta1 = 0.5" and, for the step impulse, ", step impulse".
  std::string
  scheme_name(const Case &c)
  {
    std::ostringstream s;
    s << "Beta1 = " << c.beta1
      << (c.contact == joints::ContactInTime::step_impulse ? ", step impulse" : "");
    return s.str();
  }

  void
  print_case(std::ostream &out, const Case &c, const joints::NodePairs &pairs)
  {
    const Work total = c.total();
    out << std::setprecision(4) << "\n=== " << scheme_name(c) << ", Beta2 = " << c.beta2
        << ", dt = " << c.dt << " s: " << c.steps_run << " of " << c.steps << " steps (t = "
        << c.steps_run * c.dt << " s), wall " << std::setprecision(3) << c.wall
        << " s, contact iterations per step average "
        << double(c.iterations) / std::max(c.steps_run, 1u) << " maximum " << c.max_iterations
        << ", steps not converged " << c.not_converged << "\n";
    if (!c.stopped.empty())
      out << "stopped: " << c.stopped << "\n";
    out << "input work [J] " << c.input << "; contact work [J] " << total.net()
        << " (the energy balance's term " << c.balance_contact << ", relative difference "
        << std::abs(total.net() - c.balance_contact) / std::abs(c.balance_contact)
        << "), dissipated " << total.dissipated << ", created " << total.created
        << ", created / input " << -total.created / c.input << "; algorithmic dissipation "
        << c.algorithmic << "; balance error " << c.balance_error << "\n";
    out << std::left << std::setw(32) << "transition" << std::right << std::setw(10)
        << "pair-steps" << std::setw(10) << "creating" << std::setw(12) << "net [J]"
        << std::setw(12) << "dissipated" << std::setw(12) << "created" << std::setw(12)
        << "normal part" << std::setw(10) << "% created" << "\n";
    for (unsigned int k = 0; k < n_kinds; ++k)
      {
        const Work &w = c.kinds[k];
        out << std::left << std::setw(32) << kind_names[k] << std::right << std::setw(10)
            << w.count << std::setw(10) << w.creating << std::setw(12) << w.net()
            << std::setw(12) << w.dissipated << std::setw(12) << w.created << std::setw(12)
            << w.normal << std::setw(10) << percent(w.created, total.created) << "\n";
      }
    out << "per joint: net / dissipated / created [J]\n";
    for (unsigned int j = 0; j < c.joint.size(); ++j)
      out << "  joint " << std::setw(2) << j << ": " << std::setw(11) << c.joint[j].net()
          << std::setw(11) << c.joint[j].dissipated << std::setw(11) << c.joint[j].created
          << "\n";
    std::vector<unsigned int> order(pairs.size());
    std::iota(order.begin(), order.end(), 0u);
    std::sort(order.begin(), order.end(), [&](const unsigned int a, const unsigned int b) {
      return c.pair[a].created < c.pair[b].created;
    });
    out << "the 10 pairs creating the most energy: joint, position [m], created, net [J], "
           "and the transition that created most of it\n";
    for (unsigned int r = 0; r < std::min<std::size_t>(10, order.size()); ++r)
      {
        const unsigned int i    = order[r];
        const auto        &pc   = c.pair_created[i];
        const auto         most = std::min_element(pc.begin(), pc.end()) - pc.begin();
        out << "  joint " << std::setw(2) << pairs[i].joint << " at (" << pairs[i].position
            << "): " << std::setw(11) << c.pair[i].created << std::setw(11) << c.pair[i].net()
            << "  " << kind_names[most] << " (" << percent(pc[most], c.pair[i].created)
            << " %)\n";
      }
  }
} // namespace

int
main(int argc, char **argv)
{
  dealii::Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  double                                   end = 4., scale = 2.;
  std::vector<double>                      time_steps = {0.01, 0.005, 0.0025};
  for (int i = 1; i + 1 < argc; i += 2)
    {
      const std::string a = argv[i];
      if (a == "--end")
        end = std::stod(argv[i + 1]);
      else if (a == "--scale")
        scale = std::stod(argv[i + 1]);
      else if (a == "--time-steps")
        {
          time_steps.clear();
          std::istringstream list(argv[i + 1]);
          for (std::string dt; std::getline(list, dt, ',');)
            time_steps.push_back(std::stod(dt));
        }
    }
  const Parameters     p = parameters_from_string(case_text(scale));
  std::ostringstream   quiet;
  analysis::Simulation sim(p, MPI_COMM_WORLD, quiet);
  sim.run(); // the static stage
  const Model model(p, sim);
  const auto &pairs = *sim.model().joint_pairs();
  // The mass at the pairs' nodes (the row sums of M there, M iota_x): what a
  // redistribution of the mass away from the contact nodes would move.
  std::set<dealii::types::global_dof_index> pair_dofs;
  for (unsigned int i = 0; i < pairs.size(); ++i)
    for (const auto &dofs : {pairs[i].dofs_1, pairs[i].dofs_2})
      if (model.influence[0].in_local_range(dofs[0]))
        pair_dofs.insert(dofs[0]);
  double at_pairs = 0.;
  for (const auto d : pair_dofs)
    at_pairs += model.influence[0](d);
  at_pairs = dealii::Utilities::MPI::sum(at_pairs, MPI_COMM_WORLD);
  auto &out = bench::screen();
  out << "arch dam, 14 blocks, Q1, 4 cells over the height: " << sim.model().space().dof_handler.n_dofs()
      << " DOFs, " << pairs.size() << " node pairs on " << pairs.n_joints()
      << " joints; gravity (static stage), then El Centro (180) x " << scale << " in x for "
      << end << " s; 5 % Rayleigh damping; mu = 0.7, c = 0, sigma_t = 0.5 MPa; "
      << dealii::Utilities::MPI::n_mpi_processes(MPI_COMM_WORLD) << " MPI process(es)\n"
      << "mass of the dam " << model.influence[0].l1_norm() << " kg, of which at the node "
      << "pairs' nodes " << at_pairs << " kg (" << percent(at_pairs, model.influence[0].l1_norm())
      << " %)\n";

  // The schemes at every time step: the trapezoidal pair forces with Beta1 =
  // 0.5 and 0.6, and the step impulse with Beta1 = 0.5 (doc/theory/joints.md §10).
  const std::vector<std::pair<double, joints::ContactInTime>> schemes = {
    {0.5, joints::ContactInTime::trapezoidal},
    {0.6, joints::ContactInTime::trapezoidal},
    {0.5, joints::ContactInTime::step_impulse}};
  std::vector<Case> cases;
  for (const double dt : time_steps)
    for (const auto &[beta1, contact] : schemes)
      {
        cases.push_back(run_case(model, beta1, contact, dt, end));
        print_case(out, cases.back(), pairs);
        out << std::flush;
      }

  out << "\n=== summary [J]: created = the sum of the negative pair-step works\n"
      << std::left << std::setw(28) << "scheme" << std::setw(8) << "dt [s]" << std::right
      << std::setw(7) << "t end" << std::setw(11) << "input" << std::setw(11) << "contact"
      << std::setw(11) << "dissipated" << std::setw(11) << "created" << std::setw(10)
      << "cr./inp.";
  for (const Kind k : {closing, opening, stick_to_slip, slip_to_stick, stick_stick, slip_slip})
    out << std::setw(13) << kind_names[k].substr(0, kind_names[k].find(' '));
  out << "\n";
  for (const Case &c : cases)
    {
      const Work t = c.total();
      out << std::setprecision(3) << std::left << std::setw(28) << scheme_name(c) << std::setw(8)
          << c.dt << std::right << std::setw(7) << c.steps_run * c.dt << std::setw(11)
          << c.input << std::setw(11) << t.net() << std::setw(11) << t.dissipated
          << std::setw(11) << t.created << std::setw(10) << -t.created / c.input;
      for (const Kind k : {closing, opening, stick_to_slip, slip_to_stick, stick_stick, slip_slip})
        out << std::setw(13) << c.kinds[k].created;
      out << "\n";
    }
  out << "created energy / input work so far, at t [s] =";
  std::size_t common = cases.front().history.size(); // report times every case reached
  const Case *longest = &cases.front();
  for (const Case &c : cases)
    {
      common = std::min(common, c.history.size());
      if (c.history.size() > longest->history.size())
        longest = &c;
    }
  for (const auto &h : longest->history)
    out << std::setw(10) << h[0];
  out << "\n";
  for (const Case &c : cases)
    {
      out << "  " << scheme_name(c) << ", dt = " << std::setw(6) << c.dt << ":";
      for (const auto &h : c.history)
        out << std::setw(10) << -h[2] / h[1];
      out << "\n";
    }
  if (common == 0)
    return 0;
  const auto created = [&](const Case &c) { return c.history[common - 1][2]; };
  out << "ratios of the created energy measured in this run, up to t = "
      << cases.front().history[common - 1][0] << " s (reached by every case):\n";
  const std::size_t n = schemes.size();
  for (unsigned int i = 0; i + 1 < cases.size(); i += n)
    out << "  dt = " << cases[i].dt << " s: Beta1 = 0.5 / Beta1 = 0.6: "
        << created(cases[i]) / created(cases[i + 1]) << "\n";
  for (unsigned int i = 0; i + n < cases.size(); ++i)
    out << "  " << scheme_name(cases[i]) << ": dt = " << cases[i].dt << " s / dt = "
        << cases[i + n].dt << " s: " << created(cases[i]) / created(cases[i + n]) << "\n";
}
