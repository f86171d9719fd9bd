// The dam's mass-proportional damping relative to the ground on massed rock
// (doc/theory/solid.md §4; doc/verification.md, "Damping"): a box dam
// (10 m x 20 m x 20 m, one block, linear cells) on 20 m of massed rock with
// the MTF, shaken in x and z by a smooth pulse, Rayleigh damping 5 % at the
// model's first natural frequency f1 and at 5 f1. The energy balance
// (analysis/energy_balance.h) is fed kinematic sequences of states, so that
// what it reports is the damping's work on a motion known exactly.
//
// A. Rigid translation with the reference motion v_r (the free field's mean
//    over the dam-rock interface): u = iota d_r(t), v = iota v_r(t). With the
//    mass term relative to the ground the dam dissipates nothing and hands
//    nothing to the reference motion (below 1e-10 of the dam's largest
//    kinetic energy 1/2 m |v_r|^2, m = rho V of the box, closed form). With
//    the mass term on the total velocity (Mass proportional term = total
//    velocity, ArchDam up to 2026-12) the dam dissipates alpha m int |v_r|^2
//    dt, checked against that integral by Simpson's rule on a ten times finer
//    sampling within 1e-3 (the balance integrates by the trapezoidal rule in
//    the displacement): the test tells the two apart.
// B. The deformation is damped as before (the fix is not alpha = 0). The
//    first mode phi (K phi = w^2 M phi, the modal stage's solver) moving as
//    q(t) = q0 sin(w t) over two periods on ground at rest dissipates
//    int qdot^2 dt phi^T D phi = 2 zeta w int qdot^2 dt (phi mass-normalized),
//    so the damping ratio read from the balance must be the Rayleigh ratio
//    at f1, 5 %, within 1 % of it (the trapezoidal rule at 400 steps a
//    period). The same deformation riding on the rigid motion of A
//    (v = phi qdot + iota v_r) must dissipate in the dam what it dissipates
//    on ground at rest, within 1e-8, with the relative term, and more than
//    10 % more with the total velocity.

#include <archdam/analysis/energy_balance.h>
#include <archdam/analysis/modal_analysis.h>
#include <archdam/analysis/simulation.h>

#include <deal.II/dofs/dof_tools.h>

#include "archdam_tests.h"
#include "case_text.h"

#include <fstream>

using namespace dealii;
using namespace archdam;

namespace
{
  const double rho_c = 2400., volume = 10. * 20. * 20.;
  /// The mode's amplitude (phi mass-normalized): the dam then dissipates
  /// about 3 % as much in the mode as in the rigid motion with the total
  /// velocity.
  const double q0 = 1.;

  /// The case: @p mass_term is the value of Damping/Mass proportional term,
  /// @p f1 the frequency with 5 % (and 5 f1).
  std::string
  case_text(const std::string &mass_term, const double f1)
  {
    std::ostringstream out;
    out << R"(
subsection Mesh
  subsection Box
    set Length = 10
    set Width = 20
    set Height = 20
    set Number of blocks = 1
    set Cells in x = 1
    set Cells in y = 2
    set Cells in z = 2
    set Rock depth = 20
    set Rock extent = 20
    set Rock cell size = 10
  end
end
subsection Materials
  subsection Concrete
    set Density = 2400
  end
end
subsection Foundation
  set Model = massed
end
subsection Time integration
  set Time step = 0.001
end
subsection Damping
  set Mode = damping ratio
  set Damping ratio = 0.05
  set First frequency = )"
        << f1 << "\n  set Second frequency = " << 5 * f1
        << "\n  set Mass proportional term = " << mass_term << "\nend\n"
        << testing::case_text::linear_elements << R"(
subsection Ground motion
  subsection Component x
    set File = damping_rigid_motion_x.txt
    set Format = two-column
    set Units = m/s^2
  end
  subsection Component z
    set File = damping_rigid_motion_z.txt
    set Format = two-column
    set Units = m/s^2
  end
end
)" << testing::case_text::quiet_output("results_damping_rigid_motion", 0);
    return out.str();
  }

  /// A smooth pulse a(t) = A sin^4(pi t / T) sin(2 pi t / T) of zero mean,
  /// sampled every 1 ms, into @p file.
  void
  write_pulse(const std::string &file, const double A, const double T)
  {
    if (Utilities::MPI::this_mpi_process(MPI_COMM_WORLD) != 0)
      return;
    std::ofstream out(file);
    out << std::setprecision(17);
    for (double t = 0.; t <= T + 0.2 + 1e-9; t += 1e-3)
      {
        const double s = t < T ? std::pow(std::sin(M_PI * t / T), 4) : 0.;
        out << t << " " << A * s * std::sin(2 * M_PI * t / T) << "\n";
      }
  }

  struct Model
  {
    std::unique_ptr<analysis::Simulation> sim;
    std::array<archdam::Vector, dim>      iota;
  };

  Model
  make_model(const std::string &mass_term, const double f1)
  {
    static std::ostringstream quiet;
    Model                     m;
    const Parameters          p = parameters_from_string(case_text(mass_term, f1));
    m.sim = std::make_unique<analysis::Simulation>(p, MPI_COMM_WORLD, quiet);
    m.sim->setup_model();
    const auto &space = m.sim->model().space();
    for (unsigned int d = 0; d < dim; ++d)
      {
        space.reinit(m.iota[d]);
        std::vector<bool> mask(fe::FESpace::n_components, false);
        mask[d] = true;
        const IndexSet dofs = DoFTools::extract_dofs(space.dof_handler, ComponentMask(mask));
        for (const auto i : dofs)
          if (m.iota[d].locally_owned_elements().is_element(i))
            m.iota[d](i) = 1.;
        m.iota[d].compress(VectorOperation::insert);
      }
    return m;
  }

  analysis::EnergyBalance::Model
  balance_operators(const Model &m, const Parameters &p)
  {
    analysis::EnergyBalance::Model o;
    const auto                    &model = m.sim->model();
    o.space       = &model.space();
    o.mass        = &model.mass();
    o.stiffness   = &model.stiffness();
    o.rayleigh    = p.damping.rayleigh_coefficients();
    o.dam_damping = model.dam_damping();
    if (model.reference_motion())
      {
        o.reference       = model.reference_motion();
        o.reference_loads = &model.reference_loads();
      }
    return o;
  }

  /// The damping terms of the balance of @p m fed u = iota d_r + phi q,
  /// v = iota v_r + phi qdot over [t0, t0 + n dt], d_r and v_r those of
  /// @p reference (@p rigid, @p phi may be off).
  analysis::EnergyTerms
  feed(const Model &m, const Parameters &p, const physics::foundation::ReferenceMotion *reference,
       const bool rigid, const archdam::Vector *phi, const double omega, const double t0,
       const double dt, const unsigned int n, double *kinetic_max = nullptr)
  {
    analysis::EnergyBalance balance(balance_operators(m, p));
    time::NewmarkState s;
    for (archdam::Vector *v : {&s.u, &s.v, &s.a})
      m.sim->model().space().reinit(*v);
    const auto state = [&](const double t) {
      s.time = t;
      s.u    = 0.;
      s.v    = 0.;
      s.a    = 0.;
      if (rigid)
        {
          const Tensor<1, dim> d = reference->displacement(t), v = reference->velocity(t);
          for (unsigned int c = 0; c < dim; ++c)
            {
              s.u.add(d[c], m.iota[c]);
              s.v.add(v[c], m.iota[c]);
            }
          if (kinetic_max)
            *kinetic_max = std::max(*kinetic_max, 0.5 * rho_c * volume * v.norm_square());
        }
      if (phi)
        {
          s.u.add(q0 * std::sin(omega * (t - t0)), *phi);
          s.v.add(q0 * omega * std::cos(omega * (t - t0)), *phi);
        }
    };
    state(t0);
    balance.start(s, nullptr);
    for (unsigned int k = 1; k <= n; ++k)
      {
        state(t0 + k * dt);
        balance.add_step(s, Tensor<1, dim>(), nullptr);
      }
    return balance.terms();
  }
} // namespace

int
main(int argc, char **argv)
{
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  write_pulse("damping_rigid_motion_x.txt", 3., 0.4);
  write_pulse("damping_rigid_motion_z.txt", 2., 0.3);
  MPI_Barrier(MPI_COMM_WORLD);

  // The first natural frequency of the model (its outer boundary fixed).
  double f1 = 0.;
  archdam::Vector phi;
  {
    const Model m = make_model("relative to the ground", 2.);
    analysis::ModalParameters mp;
    mp.n_modes = 1;
    const auto modes = analysis::compute_natural_modes(m.sim->model().mass(),
                                                       m.sim->model().stiffness(),
                                                       m.sim->model().space().constraints, mp);
    f1  = modes.omega[0] / (2 * M_PI);
    phi = modes.shapes[0];
  }
  const double omega = 2 * M_PI * f1;

  const Model relative = make_model("relative to the ground", f1);
  const Model total    = make_model("total velocity", f1);
  const Parameters p_rel = parameters_from_string(case_text("relative to the ground", f1));
  const Parameters p_tot = parameters_from_string(case_text("total velocity", f1));
  const auto *reference  = relative.sim->model().reference_motion();
  const double alpha     = p_rel.damping.rayleigh_coefficients().first;

  // A. The pulse passes the dam's base between t0 and t0 + 0.7 s.
  const double     t0 = 0., dt = 1e-3;
  const unsigned   n  = 1200;
  double           kinetic = 0.;
  const auto       a_rel   = feed(relative, p_rel, reference, true, nullptr, 0., t0, dt, n, &kinetic);
  const auto       a_tot   = feed(total, p_tot, reference, true, nullptr, 0., t0, dt, n);
  double           integral = 0.; // int |v_r|^2 dt, Simpson on dt / 10
  {
    const double h = dt / 10;
    for (unsigned int k = 0; k <= 10 * n; ++k)
      integral += (k == 0 || k == 10 * n ? 1. : k % 2 ? 4. : 2.) * h / 3 *
                  reference->velocity(t0 + k * h).norm_square();
  }
  testing::log() << "A. the dam translated rigidly with the reference motion (largest kinetic "
                    "energy "
                 << std::setprecision(3) << kinetic << " J)" << std::endl;
  testing::check_below("  relative to the ground: |damping in the dam| / kinetic energy",
                       std::abs(a_rel.damping_dam) / kinetic, 1e-10);
  testing::check_below("  relative to the ground: |work handed to the reference| / kinetic "
                       "energy",
                       std::abs(a_rel.damping_reference) / kinetic, 1e-10);
  testing::check_relative("  total velocity: damping in the dam [J]", a_tot.damping_dam,
                          alpha * rho_c * volume * integral, 1e-3);

  // B. The first mode, two periods of 400 steps.
  const double   T  = 1. / f1, h = T / 400;
  // Centred on the reference motion's largest velocity.
  double t1 = 0., v_max = 0.;
  for (unsigned int k = 0; k <= n; ++k)
    if (const double v = reference->velocity(t0 + k * dt).norm(); v > v_max)
      {
        v_max = v;
        t1    = t0 + k * dt - T;
      }
  // On ground at rest both formulations are alpha M + beta K.
  const auto     b_rest = feed(total, p_tot, reference, false, &phi, omega, t1, h, 800);
  // int qdot^2 dt = q0^2 w^2 T over two periods.
  const double   zeta   = b_rest.damping / (2 * omega * (q0 * q0 * omega * omega * T));
  testing::log() << "B. the first mode (" << std::setprecision(4) << f1 << " Hz)" << std::endl;
  testing::check_relative("  damping ratio from the dissipation on ground at rest", zeta, 0.05,
                          0.01);
  const auto b_rel = feed(relative, p_rel, reference, true, &phi, omega, t1, h, 800);
  const auto b_tot = feed(total, p_tot, reference, true, &phi, omega, t1, h, 800);
  testing::check_below("  riding on the rigid motion, relative to the ground: |change of the "
                       "dam's dissipation| / it",
                       std::abs(b_rel.damping_dam - b_rest.damping_dam) / b_rest.damping_dam,
                       1e-8);
  testing::log() << "  riding on the rigid motion, total velocity: the dam's dissipation "
                    "changes by more than 10 %: "
                 << testing::yes(std::abs(b_tot.damping_dam - b_rest.damping_dam) >
                                 0.1 * b_rest.damping_dam)
                 << std::endl;
}
