#include <archdam/physics/foundation/massed_foundation.h>

#include <chrono>

namespace archdam::physics::foundation
{
  using namespace dealii;

  namespace
  {
    double
    seconds_since(const std::chrono::steady_clock::time_point start)
    {
      return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    }
  } // namespace

  MassedFoundation::MassedFoundation(const FoundationParameters      &p,
                                     const fe::FESpace               &space,
                                     const solid::MaterialParameters &materials,
                                     const solid::InertiaOf           inertia,
                                     const FreeField                 &free_field,
                                     const double                     time_step)
    : dt(time_step)
  {
    if (p.transmitting_boundary == TransmittingBoundary::viscous)
      viscous = std::make_unique<ViscousSpringBoundary>(p, space, materials, free_field);
    else
      {
        mtf = std::make_unique<MultiTransmittingBoundary>(p, space, materials, free_field,
                                                          time_step);
        prescribed.dofs = mtf->dofs();
        solid::assemble_mass_and_stiffness_columns(space, materials, inertia, prescribed.dofs,
                                                   prescribed.mass_columns,
                                                   prescribed.stiffness_columns);
      }
    space.reinit(load_with_free_field);
  }

  void
  MassedFoundation::add_springs(SparseMatrix &stiffness) const
  {
    if (viscous)
      viscous->add_springs(stiffness);
  }

  const Vector *
  MassedFoundation::dashpots() const
  {
    return viscous ? &viscous->dashpots() : nullptr;
  }

  void
  MassedFoundation::start(const Vector &u0)
  {
    if (mtf)
      mtf->initialize(u0);
  }

  void
  MassedFoundation::advance(time::NewmarkIntegrator                   &newmark,
                            const Vector                              &load_next,
                            time::NewmarkState                        &s,
                            const time::NewmarkIntegrator::StepSolver &solve)
  {
    const double t_next = s.time + dt;
    if (mtf)
      {
        auto        start  = std::chrono::steady_clock::now();
        const auto &values = mtf->next_values(t_next);
        update_seconds += seconds_since(start);
        newmark.advance(load_next, s, prescribed, values, solve);
        start = std::chrono::steady_clock::now();
        mtf->record(s.u, s.time);
        update_seconds += seconds_since(start);
      }
    else
      {
        const auto start = std::chrono::steady_clock::now();
        load_with_free_field = load_next;
        viscous->add_free_field_load(t_next, load_with_free_field);
        update_seconds += seconds_since(start);
        newmark.advance(load_with_free_field, s, solve);
      }
  }

  void
  MassedFoundation::save(std::ostream &out) const
  {
    if (mtf)
      mtf->save(out);
  }

  void
  MassedFoundation::load(std::istream &in)
  {
    if (mtf)
      mtf->load(in);
  }
} // namespace archdam::physics::foundation
