#pragma once

#include <archdam/fe/fe_space.h>
#include <archdam/physics/foundation/foundation.h>
#include <archdam/physics/foundation/free_field.h>
#include <archdam/physics/foundation/multi_transmitting_boundary.h>
#include <archdam/physics/foundation/viscous_boundary.h>
#include <archdam/physics/solid/solid_operators.h>
#include <archdam/time/newmark.h>

#include <iosfwd>
#include <memory>
#include <string>

namespace archdam::physics::foundation
{
  /**
   * The outer boundary of a massed foundation in the dynamic stage
   * (doc/theory/foundation.md §7-§9), whichever its kind: a step with the MTF
   * (or the fixed boundary) prescribes the boundary displacements computed
   * before the solve (time::PrescribedDofs); a step with the viscous boundary
   * adds the free-field forces to the load, its dashpots being part of Kbar.
   * Each kind is one implementation of this interface; make_massed_foundation()
   * builds the one `Foundation/Transmitting boundary` names.
   *
   * Use: add_springs() to the stiffness before anything is factorized, make
   * the integrator with dashpots(), start() from the initial state, then
   * advance() every step.
   */
  class MassedFoundation
  {
  public:
    virtual ~MassedFoundation() = default;

    /// The springs of the viscous-spring boundary (nothing for the others).
    virtual void
    add_springs(SparseMatrix &stiffness) const;

    /// The dashpots of the viscous boundary for the integrator, else nullptr.
    virtual const Vector *
    dashpots() const;

    /// The boundary DOFs a step prescribes (MTF, fixed), else nullptr.
    virtual time::PrescribedDofs *
    prescribed_dofs();

    /// The viscous boundary (for the energy balance's free-field work),
    /// else nullptr.
    virtual const ViscousSpringBoundary *
    viscous_boundary() const;

    /// What the run log says about the boundary beyond its name (e.g. the
    /// MTF's order and Courant number), empty if nothing.
    virtual std::string
    details() const;

    /// The dynamic stage starts at rest from @p u0 at t = 0.
    virtual void
    start(const Vector &u0);

    /// One step from t_n to t_{n+1} under the load @p load_next (no
    /// free-field terms in it) at t_{n+1}; @p solve as in
    /// NewmarkIntegrator::advance() (e.g. the joints' contact solve).
    virtual void
    advance(time::NewmarkIntegrator                    &newmark,
            const Vector                               &load_next,
            time::NewmarkState                         &s,
            const time::NewmarkIntegrator::StepSolver &solve = {}) = 0;

    /// Wall time spent in the boundary update (MTF values and history, or
    /// free-field forces), s.
    double
    boundary_update_time() const
    {
      return update_seconds;
    }

    /// The boundary's histories, for a checkpoint (output/checkpoint.h).
    virtual void
    save(std::ostream &out) const;
    virtual void
    load(std::istream &in);

  protected:
    double update_seconds = 0.;
  };

  /// The massed foundation with the outer boundary @p p chooses
  /// (Foundation/Transmitting boundary), for time step @p time_step. With
  /// @p damping a prescribed boundary also holds the columns of the damping
  /// matrix (time::PrescribedDofs::damping_columns), for an integrator with
  /// a general damping matrix.
  std::unique_ptr<MassedFoundation>
  make_massed_foundation(const FoundationParameters      &p,
                         const fe::FESpace               &space,
                         const solid::MaterialParameters &materials,
                         solid::InertiaOf                 inertia,
                         const FreeField                 &free_field,
                         double                           time_step,
                         const solid::DampingParameters  *damping = nullptr);
} // namespace archdam::physics::foundation
