#include <archdam/base/wall_time.h>
#include <archdam/physics/foundation/massed_foundation.h>

#include <iomanip>
#include <sstream>

namespace archdam::physics::foundation
{
  using namespace dealii;

  namespace
  {
    /// The MTF, or the fixed boundary (the free field prescribed): the
    /// boundary values computed before each solve.
    class PrescribedBoundary : public MassedFoundation
    {
    public:
      PrescribedBoundary(const FoundationParameters      &p,
                         const fe::FESpace               &space,
                         const solid::MaterialParameters &materials,
                         const solid::InertiaOf           inertia,
                         const FreeField                 &free_field,
                         const double                     time_step,
                         const solid::DampingParameters  *damping)
        : boundary(p, space, materials, free_field, time_step)
        , transmitting(p.transmitting_boundary == TransmittingBoundary::mtf)
        , order(p.mtf_order)
        , dt(time_step)
      {
        prescribed.dofs = boundary.dofs();
        solid::assemble_mass_and_stiffness_columns(space, materials, inertia, prescribed.dofs,
                                                   prescribed.mass_columns,
                                                   prescribed.stiffness_columns, damping,
                                                   &prescribed.damping_columns);
      }

      time::PrescribedDofs *
      prescribed_dofs() override
      {
        return &prescribed;
      }

      std::string
      details() const override
      {
        if (!transmitting)
          return "";
        std::ostringstream text;
        // Liao's S (doc/theory/foundation.md §6): at most 1 for an undamped
        // boundary; measured stable up to 1.22 with the dam's Rayleigh damping.
        const double S = boundary.largest_courant_number();
        text << std::setprecision(4) << "MTF order " << order << ", largest c_a dt / h = " << S;
        if (S > 1.)
          text << " (above 1: stable only with the model's damping, measured up to 1.22; "
               << "doc/theory/foundation.md §6)";
        return text.str();
      }

      void
      start(const Vector &u0) override
      {
        boundary.initialize(u0);
      }

      void
      advance(time::NewmarkIntegrator                   &newmark,
              const Vector                              &load_next,
              time::NewmarkState                        &s,
              const time::NewmarkIntegrator::StepSolver &solve) override
      {
        const std::vector<double> *values = nullptr;
        update_seconds += seconds_of([&] { values = &boundary.next_values(s.time + dt); });
        newmark.advance(load_next, s, prescribed, *values, solve);
        update_seconds += seconds_of([&] { boundary.record(s.u, s.time); });
      }

      void
      save(std::ostream &out) const override
      {
        boundary.save(out);
      }

      void
      load(std::istream &in) override
      {
        boundary.load(in);
      }

    private:
      MultiTransmittingBoundary boundary;
      const bool                transmitting;
      const unsigned int        order;
      time::PrescribedDofs      prescribed;
      const double              dt;
    };

    /// Lysmer's dashpots (with springs): the free-field forces added to the
    /// load of each step.
    class ViscousBoundary : public MassedFoundation
    {
    public:
      ViscousBoundary(const FoundationParameters      &p,
                      const fe::FESpace               &space,
                      const solid::MaterialParameters &materials,
                      const FreeField                 &free_field,
                      const double                     time_step)
        : boundary(p, space, materials, free_field)
        , dt(time_step)
      {
        space.reinit(load_with_free_field);
      }

      void
      add_springs(SparseMatrix &stiffness) const override
      {
        boundary.add_springs(stiffness);
      }

      const Vector *
      dashpots() const override
      {
        return &boundary.dashpots();
      }

      const ViscousSpringBoundary *
      viscous_boundary() const override
      {
        return &boundary;
      }

      void
      advance(time::NewmarkIntegrator                   &newmark,
              const Vector                              &load_next,
              time::NewmarkState                        &s,
              const time::NewmarkIntegrator::StepSolver &solve) override
      {
        update_seconds += seconds_of([&] {
          load_with_free_field = load_next;
          boundary.add_free_field_load(s.time + dt, load_with_free_field);
        });
        newmark.advance(load_with_free_field, s, solve);
      }

    private:
      ViscousSpringBoundary boundary;
      Vector                load_with_free_field;
      const double          dt;
    };
  } // namespace

  void
  MassedFoundation::add_springs(SparseMatrix &) const
  {}

  const Vector *
  MassedFoundation::dashpots() const
  {
    return nullptr;
  }

  time::PrescribedDofs *
  MassedFoundation::prescribed_dofs()
  {
    return nullptr;
  }

  const ViscousSpringBoundary *
  MassedFoundation::viscous_boundary() const
  {
    return nullptr;
  }

  std::string
  MassedFoundation::details() const
  {
    return "";
  }

  void
  MassedFoundation::start(const Vector &)
  {}

  void
  MassedFoundation::save(std::ostream &) const
  {}

  void
  MassedFoundation::load(std::istream &)
  {}

  std::unique_ptr<MassedFoundation>
  make_massed_foundation(const FoundationParameters      &p,
                         const fe::FESpace               &space,
                         const solid::MaterialParameters &materials,
                         const solid::InertiaOf           inertia,
                         const FreeField                 &free_field,
                         const double                     time_step,
                         const solid::DampingParameters  *damping)
  {
    if (p.transmitting_boundary == TransmittingBoundary::viscous)
      return std::make_unique<ViscousBoundary>(p, space, materials, free_field, time_step);
    return std::make_unique<PrescribedBoundary>(p, space, materials, inertia, free_field,
                                                time_step, damping);
  }
} // namespace archdam::physics::foundation
