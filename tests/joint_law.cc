// The contact law on one joint: tension cut-off, residual strength, an
// initial gap that closes, and an oblique load slipping in its direction
// (doc/verification.md, joints; doc/theory/joints.md §2): a 1 m cube (block 1, m = 2400
// kg) on a fixed base block (block 0) across one horizontal joint (mu = 0.5,
// c = sigma_t = 1e4 Pa, residual values 0), loaded by a
// uniform vertical body force F(t) (no gravity), mixed method with Kbar
// (the trapezoidal pair forces with Beta1 = 0.6, which damps the block's own
// vibration, whose period is far below dt; item 5 also runs the step impulse
// with Beta1 = 1/2). The block is stiff (E = 1e11 Pa), so the joint force follows the load
// while the joint is closed: sum f_xi = F (quasi-static, the ramps take 20
// steps). References written here:
//  1. F = 0.3 sigma_t A: the intact joint holds, sum f_xi = F (tolerance 2 %
//     for the damped vibration after the ramp);
//  2. F ramped to 1.2 sigma_t A: the joint opens when F reaches sigma_t A; no
//     pair ever carries more than sigma_t A_i (1e-6 for the tolerances);
//  3. F = -1.2 sigma_t A pushes the block back: the joint closes again
//     (the block bounces: the impact is nearly elastic);
//  4. then F = 0.3 sigma_t A again: with the residual strength 0 no pair
//     carries tension any more (the intact joint carried 0.3 sigma_t in 1.).
//  5. An initial gap delta_0 = 1 mm under a downward acceleration a = 1 m/s^2
//     closes at t = sqrt(2 delta_0 / a) (Newmark is exact for a constant
//     acceleration: the step that contains it), with both schemes of the
//     pair forces in time (doc/theory/joints.md §10): with the trapezoidal
//     forces the block never penetrates (gap >= -Gap tolerance); with the
//     step impulse (a closed pair holds its velocity, not its position) it
//     penetrates by at most dt / 2 times the impact velocity a t. A pair
//     starts open where its joint has a gap (held closed in the air, the
//     step impulse would keep the block from falling). The joints' recorder
//     (output/joint_output.h), fed the same steps, reports as its largest
//     penetration exactly the lowest gap found here.
//  6. Oblique slip: under its weight W (mu = 0.5, c = 0) the block gets a
//     horizontal load 0.8 W at 30 degrees from x: it slides along the load
//     (isotropic friction) with acceleration (0.8 - 0.5) g, slip 0.3 g t^2 / 2
//     after t = 0.1 s (tolerance 2 %: the load jump is averaged over the
//     first step, a lag of dt / 2, relative 2 (dt / 2) / t = 1 %); the slip
//     direction within 0.1 degree.
//  7. The softening shear key (Law = softening shear key, Softening opening
//     delta_s = 1 mm, residual values 0): the block is pulled open by
//     1.2 sigma_t A for a few steps and pushed back shut; kappa, the largest
//     opening of each pair, is taken from the gaps the test records every
//     step. Pulled again by a slow ramp (0.5 % of sigma_t A a step), no
//     closed pair carries more than its residual strength
//     sigma_t (1 - kappa_i / delta_s) A_i, and the first pair opens when
//     its force reaches it (within 2 %: one ramp step); in a second run,
//     shut under its weight W, a slow horizontal ramp starts the slip at
//     H = c (1 - kappa / delta_s) A + mu W (tolerance 2 %: one ramp step
//     and the block's vibration). With Law = Mohr-Coulomb the same history
//     leaves the residual strength 0: opening at once (within the first
//     ramp steps, F <= 0.02 sigma_t A) and slip at H = mu W.

#include <archdam/output/joint_output.h>
#include <archdam/time/newmark.h>

#include "archdam_tests.h"
#include "joint_tests.h"

using namespace dealii;
using namespace archdam;

namespace
{
  /// The joint of these tests: frictional contact, its pair forces in time
  /// as chosen (the law is the same with both schemes; Run takes each with
  /// its Newmark rule).
  joints::JointParameters
  frictional(const joints::ContactInTime contact = joints::ContactInTime::trapezoidal)
  {
    joints::JointParameters jp;
    jp.model           = joints::Model::frictional_contact;
    jp.contact_in_time = contact;
    return jp;
  }

  struct Run
  {
    testing::BlockModel               m{2, 2, Point<dim>(1., 1., 2.), 1, 1, 1e11, 0.2, 2400., {0}};
    archdam::Vector                   iota_x, iota_y, iota_z;
    time::NewmarkState                s;
    std::unique_ptr<time::NewmarkIntegrator> newmark;
    std::unique_ptr<joints::JointSolver>     solver;
    double                            t = 0.;
    bool                              converged = true;

    /// @p alpha: mass-proportional damping [1/s] (0: none).
    Run(const joints::JointParameters &jp, const double dt, const double alpha = 0.)
    {
      for (const unsigned int d : {0u, 1u, 2u})
        physics::solid::assemble_inertia_load(*m.space, m.materials,
                                              physics::solid::InertiaOf::dam,
                                              Point<dim>::unit_vector(d),
                                              d == 0 ? iota_x : d == 1 ? iota_y : iota_z);
      const time::NewmarkParameters np = testing::newmark_for(jp.contact_in_time, dt);
      newmark = std::make_unique<time::NewmarkIntegrator>(np, m.M, m.K, std::pair<double, double>{alpha, 0.},
                                                          m.space->constraints);
      solver  = joints::make_joint_solver(jp, *m.pairs, newmark->displacement_factor(),
                                         newmark->effective(), newmark->effective_factor());
      m.space->reinit(s.u);
      m.space->reinit(s.v);
      m.space->reinit(s.a);
    }

    /// One step with the body force (Fx, Fy, F) [N] on the block (acceleration / m).
    void
    step(const double F, const double Fx = 0., const double Fy = 0.)
    {
      archdam::Vector load(iota_z);
      load *= F / 2400.;
      load.add(Fx / 2400., iota_x, Fy / 2400., iota_y);
      const auto st = joints::advance_with_contact(*newmark, *solver, load, s);
      converged     = converged && st.converged;
      t += newmark->time_step();
    }

    bool
    all(const joints::PairState state) const
    {
      for (const auto st : solver->state)
        if (st != state)
          return false;
      return true;
    }

    /// Mean relative displacement w of the pairs in global coordinates.
    Tensor<1, dim>
    mean_w() const
    {
      Tensor<1, dim> sum;
      for (unsigned int i = 0; i < m.pairs->size(); ++i)
        for (unsigned int k = 0; k < dim; ++k)
          for (unsigned int c = 0; c < dim; ++c)
            sum[c] += solver->w[dim * i + k] * (*m.pairs)[i].frame[k][c];
      return sum / m.pairs->size();
    }

    /// The largest opening of every pair so far, updated after each step.
    std::vector<double> kappa;
    void
    track_openings()
    {
      kappa.resize(m.pairs->size(), 0.);
      for (unsigned int i = 0; i < m.pairs->size(); ++i)
        kappa[i] = std::max(kappa[i], solver->gap(i));
    }

    double
    min_gap() const
    {
      double g = 1e300;
      for (unsigned int i = 0; i < m.pairs->size(); ++i)
        g = std::min(g, solver->gap(i));
      return g;
    }
  };
} // namespace

int
main(int argc, char **argv)
{
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  auto                            &log = testing::log();
  const double                     dt = 1e-3, sigma_t = 1e4, A = 1.;

  {
    auto jp = frictional();
    jp.law.friction_coefficient = 0.5;
    jp.law.tensile_strength     = sigma_t;
    jp.law.cohesion             = sigma_t; // shear capacity c - mu f_xi > 0 up to sigma_t
    Run          r(jp, dt);
    const double F1 = 0.3 * sigma_t * A, F2 = 1.2 * sigma_t * A;
    double       largest_pair_tension = 0., F_at_opening = 0.;
    const auto   watch = [&](const double F) {
      r.step(F);
      for (unsigned int i = 0; i < r.m.pairs->size(); ++i)
        largest_pair_tension =
          std::max(largest_pair_tension, r.solver->force[dim * i] / (sigma_t * (*r.m.pairs)[i].area));
      if (F_at_opening == 0. && r.all(joints::PairState::separation))
        F_at_opening = F;
    };
    for (unsigned int k = 1; k <= 50; ++k)
      watch(F1 * std::min(1., k / 20.));
    log << "1. intact joint under 0.3 sigma_t A:" << std::endl;
    log << "  all pairs stick: " << (r.all(joints::PairState::stick) ? "yes" : "NO") << std::endl;
    testing::check_relative("  joint tension [N]", testing::total_normal_force(*r.solver), F1, 0.02);
    for (unsigned int k = 1; k <= 30; ++k)
      watch(F1 + (F2 - F1) * std::min(1., k / 20.));
    log << "2. ramp to 1.2 sigma_t A:" << std::endl;
    testing::check_relative("  load when the joint opens [N] (sigma_t A, one ramp step 4.5 %)",
                            F_at_opening, sigma_t * A, 0.05);
    testing::check_below("  largest pair tension / (sigma_t A_i) - 1", largest_pair_tension - 1.,
                         1e-6);
    // 3./4. back into contact and pulled again: every pair has opened, so
    // with the residual tensile strength 0 no pair may carry tension now.
    double most_compressed = 0., largest_residual_tension = 0.;
    const auto watch_damaged = [&](const double F) {
      r.step(F);
      for (unsigned int i = 0; i < r.m.pairs->size(); ++i)
        {
          const double f = r.solver->force[dim * i] / (sigma_t * (*r.m.pairs)[i].area);
          most_compressed          = std::min(most_compressed, f);
          largest_residual_tension = std::max(largest_residual_tension, f);
        }
    };
    for (unsigned int k = 1; k <= 120; ++k)
      watch_damaged(-F2);
    for (unsigned int k = 1; k <= 50; ++k)
      watch_damaged(F1 * std::min(1., k / 20.));
    log << "3./4. pushed back by -1.2 sigma_t A, then 0.3 sigma_t A (residual strength 0):"
        << std::endl;
    log << "  the joint closed again (a pair in compression): "
        << (most_compressed < -0.01 ? "yes" : "NO") << std::endl;
    testing::check_below("  largest pair tension / (sigma_t A_i) after opening",
                         largest_residual_tension, 1e-6);
    log << "  contact problem converged every step: " << (r.converged ? "yes" : "NO") << std::endl;
  }

  for (const auto contact : {joints::ContactInTime::trapezoidal, joints::ContactInTime::step_impulse})
    {
      auto jp                     = frictional(contact);
      jp.law.friction_coefficient = 0.5;
      jp.law.initial_gap          = 1e-3;
      Run          r(jp, dt);
      const double a = 1., m = 2400.;
      double       t_close = 0., lowest = 1e300;
      r.s.a = r.m.uniform_field(1, 2, -a); // the load acts from t = 0
      // The joints' recorder follows the same steps; its largest
      // penetration must be the lowest gap seen here.
      output::JointOutput recorder(jp, *r.m.pairs, ".", "initial_gap", 0);
      recorder.start(output::StepRecord{r.s, r.solver.get(), {}, nullptr});
      for (unsigned int k = 1; k <= 100; ++k)
        {
          r.step(-m * a);
          recorder.record(output::StepRecord{r.s, r.solver.get(), {}, nullptr});
          lowest = std::min(lowest, r.min_gap());
          if (t_close == 0. && !r.all(joints::PairState::separation))
            t_close = r.t;
        }
      log << "5. initial gap 1 mm under 1 m/s^2, "
          << (contact == joints::ContactInTime::trapezoidal ? "trapezoidal forces" : "step impulse")
          << ":" << std::endl;
      const double t_ref = std::sqrt(2e-3 / a);
      log << "  closes in the step containing sqrt(2 delta_0 / a): "
          << (t_close >= t_ref && t_close - dt < t_ref ? "yes" : "NO") << std::endl;
      if (contact == joints::ContactInTime::trapezoidal)
        log << "  no penetration: " << (lowest >= -1e-9 ? "yes" : "NO") << std::endl;
      else
        testing::check_below("  penetration [m] against dt / 2 times the impact velocity a t",
                             -lowest, 0.5 * dt * a * t_ref);
      log << "  recorded largest penetration equals the lowest gap of every step: "
          << (recorder.largest_penetration() == std::max(0., -lowest) ? "yes" : "NO") << std::endl;
      log << "  contact problem converged every step: " << (r.converged ? "yes" : "NO") << std::endl;
    }

  {
    auto jp = frictional();
    jp.law.friction_coefficient = 0.5;
    Run          r(jp, dt);
    const double g = 9.81, W = 2400. * g, theta = M_PI / 6, T = 0.1;
    for (unsigned int k = 1; k <= 50; ++k)
      r.step(-W);
    const Tensor<1, dim> w0 = r.mean_w();
    for (unsigned int k = 1; k <= std::lround(T / dt); ++k)
      r.step(-W, 0.8 * W * std::cos(theta), 0.8 * W * std::sin(theta));
    const Tensor<1, dim> slip = r.mean_w() - w0;
    log << "6. oblique load 0.8 W at 30 degrees, mu = 0.5:" << std::endl;
    testing::check_relative("  slip [m] (0.3 g t^2 / 2)", std::hypot(slip[0], slip[1]),
                            0.3 * g * T * T / 2, 0.02);
    testing::check_below("  |slip direction - load direction| [degree]",
                         std::abs(std::atan2(slip[1], slip[0]) - theta) * 180 / M_PI, 0.1);
    log << "  all pairs slip, contact problem converged every step: "
        << (r.all(joints::PairState::slip) && r.converged ? "yes" : "NO") << std::endl;
  }

  // 7. The softening shear key against Mohr-Coulomb after the same opening.
  for (const auto law : {joints::Law::softening_shear_key, joints::Law::mohr_coulomb})
    {
      auto jp = frictional();
      jp.strength_law             = law;
      jp.law.friction_coefficient = 0.5;
      jp.law.tensile_strength     = sigma_t;
      jp.law.cohesion             = sigma_t;
      jp.law.softening_opening    = 1e-3;
      const bool   softening      = law == joints::Law::softening_shear_key;
      const double W = 2400. * 9.81, F2 = 1.2 * sigma_t * A;
      log << "7. " << (softening ? "softening shear key" : "Mohr-Coulomb")
          << ", after an opening kappa:" << std::endl;
      // opened for 20 ms, then pushed shut until the block has settled (the
      // mass-proportional damping of these runs, 200 1/s, makes its flight
      // slow, about 0.025 m/s, and stops its bouncing)
      const auto open_and_shut = [&](Run &r, const double push) {
        for (unsigned int k = 1; k <= 20; ++k)
          {
            r.step(F2);
            r.track_openings();
          }
        for (unsigned int k = 1; k <= 300; ++k)
          {
            r.step(push);
            r.track_openings();
          }
      };
      const auto strength_left = [&](const Run &r) {
        double sum = 0.;
        for (unsigned int i = 0; i < r.m.pairs->size(); ++i)
          sum += (softening ? std::max(0., 1. - r.kappa[i] / jp.law.softening_opening) : 0.) *
                 (*r.m.pairs)[i].area;
        return sum / A; // the intact fraction of the joint's area
      };
      {
        Run r(jp, dt, 200.);
        open_and_shut(r, -F2);
        double kappa_min = 1e300, kappa_max = 0.;
        for (const double k : r.kappa)
          {
            kappa_min = std::min(kappa_min, k);
            kappa_max = std::max(kappa_max, k);
          }
        log << "  kappa between " << std::setprecision(3) << kappa_min * 1e3 << " and "
            << kappa_max * 1e3 << " mm: " << (kappa_min > 0.2e-3 && kappa_max < 0.8e-3 ? "yes" : "NO")
            << " (0.2 to 0.8 mm)" << std::endl;
        const double step_load = 0.005 * sigma_t * A;
        double       F_open    = -1.;
        // Each pair's tensile force against its own residual strength
        // sigma_t (1 - kappa_i / delta_s) A_i while every pair is closed:
        // the largest of the step before the first pair opens. (The joint's
        // total at which all have opened is not the reference: the pairs'
        // normal forces differ by up to 7 % after the frictional push, by a
        // path that round-off decides, and they unzip from the most loaded.)
        double largest_ratio = 0., ratio_before_opening = -1., worst_excess = 0.;
        for (unsigned int k = 1; k <= 240 && F_open < 0.; ++k)
          {
            r.step(k * step_load);
            bool   one_open = false;
            double largest  = 0.;
            for (unsigned int i = 0; i < r.m.pairs->size(); ++i)
              {
                one_open = one_open || r.solver->state[i] == joints::PairState::separation;
                const double strength_i = sigma_t *
                                          (1. - r.kappa[i] / jp.law.softening_opening) *
                                          (*r.m.pairs)[i].area;
                largest = std::max(largest, r.solver->force[dim * i] / strength_i);
              }
            if (one_open && ratio_before_opening < 0.)
              ratio_before_opening = largest_ratio;
            if (!one_open)
              {
                largest_ratio = largest;
                worst_excess  = std::max(worst_excess, largest - 1.);
              }
            if (r.all(joints::PairState::separation))
              F_open = k * step_load;
          }
        if (softening)
          {
            testing::check_below("  a closed pair's tensile force above its residual strength "
                                 "sigma_t (1 - kappa_i / delta_s) A_i, relative,",
                                 std::max(0., worst_excess), 1e-9);
            // the ramp adds under 1 % of a pair's strength per step
            testing::check_below("  the most loaded pair's force in the step before the first "
                                 "opens, relative error against that strength,",
                                 std::abs(1. - ratio_before_opening), 0.02);
          }
        else
          log << "  opens at once (residual tensile strength 0), F = " << F_open << " N: "
              << (F_open <= 0.02 * sigma_t * A ? "yes" : "NO") << " (at most 0.02 sigma_t A)"
              << std::endl;
        log << "  contact problem converged every step: " << (r.converged ? "yes" : "NO")
            << std::endl;
      }
      {
        Run r(jp, dt, 200.);
        open_and_shut(r, -W);
        const double step_load = 0.002 * W;
        double       H_slip    = -1.;
        for (unsigned int k = 1; k <= 1000 && H_slip < 0.; ++k)
          {
            r.step(-W, k * step_load);
            if (r.all(joints::PairState::slip))
              H_slip = k * step_load;
          }
        const double expected = sigma_t * A * strength_left(r) + 0.5 * W;
        testing::check_relative("  horizontal load when the block slides [N]", H_slip, expected,
                                0.02);
        log << "  contact problem converged every step: " << (r.converged ? "yes" : "NO")
            << std::endl;
      }
    }
}
