#pragma once

#include <archdam/fe/fe_space.h>
#include <archdam/physics/foundation/foundation.h>
#include <archdam/physics/foundation/free_field.h>
#include <archdam/physics/foundation/multi_transmitting_boundary.h>
#include <archdam/physics/foundation/viscous_boundary.h>
#include <archdam/physics/solid/solid_operators.h>
#include <archdam/time/newmark.h>

#include <memory>

namespace archdam::physics::foundation
{
  /**
   * The outer boundary of a massed foundation in the dynamic stage
   * (doc/theory/foundation.md §7-§9), whichever its kind: a step with the MTF (or the fixed
   * boundary) prescribes the boundary displacements computed before the
   * solve (time::PrescribedDofs); a step with the viscous boundary adds the
   * free-field forces to the load, its dashpots being part of Kbar.
   *
   * Use: add_springs() to the stiffness before anything is factorized, make
   * the integrator with dashpots(), start() from the initial state, then
   * advance() every step.
   */
  class MassedFoundation
  {
  public:
    MassedFoundation(const FoundationParameters      &p,
                     const fe::FESpace               &space,
                     const solid::MaterialParameters &materials,
                     solid::InertiaOf                 inertia,
                     const FreeField                 &free_field,
                     double                           time_step);

    /// The springs of the viscous-spring boundary (nothing for the others).
    void
    add_springs(SparseMatrix &stiffness) const;

    /// The dashpots of the viscous boundary for the integrator, else nullptr.
    const Vector *
    dashpots() const;

    /// The dynamic stage starts at rest from @p u0 at t = 0.
    void
    start(const Vector &u0);

    /// One step from t_n to t_{n+1} under the load @p load_next (no
    /// free-field terms in it) at t_{n+1}; @p solve as in
    /// NewmarkIntegrator::advance() (e.g. the joints' contact solve).
    void
    advance(time::NewmarkIntegrator                    &newmark,
            const Vector                               &load_next,
            time::NewmarkState                         &s,
            const time::NewmarkIntegrator::StepSolver &solve = {});

    /// Wall time spent in the boundary update (MTF values and history, or
    /// free-field forces), s.
    double
    boundary_update_time() const
    {
      return update_seconds;
    }

    /// The prescribed outer boundary (MTF and fixed boundary; nullptr for the
    /// viscous one), whose columns hold the solid's M and K: the coupled
    /// dam-water system extends them to its own
    /// (reservoir::form_coupled_columns) before the first step.
    time::PrescribedDofs *
    prescribed_dofs()
    {
      return mtf ? &prescribed : nullptr;
    }

    const MultiTransmittingBoundary *
    transmitting_boundary() const
    {
      return mtf.get();
    }
    /// The viscous boundary (nullptr for the prescribed ones).
    const ViscousSpringBoundary *
    viscous_boundary() const
    {
      return viscous.get();
    }

    /// The boundary's state (MTF histories; the viscous boundary has none),
    /// for a checkpoint (output/checkpoint.h); load() after start().
    void
    save(std::ostream &out) const;
    void
    load(std::istream &in);

  private:
    std::unique_ptr<MultiTransmittingBoundary> mtf;
    std::unique_ptr<ViscousSpringBoundary>     viscous;
    time::PrescribedDofs                       prescribed;
    /// The viscous boundary's step load: the stage's plus the free field's.
    Vector                                     load_with_free_field;
    double                                     dt;
    double                                     update_seconds = 0.;
  };
} // namespace archdam::physics::foundation
