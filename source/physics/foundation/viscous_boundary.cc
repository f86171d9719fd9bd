#include <archdam/physics/foundation/viscous_boundary.h>

namespace archdam::physics::foundation
{
  using namespace dealii;

  ViscousSpringBoundary::ViscousSpringBoundary(const FoundationParameters      &p,
                                               const fe::FESpace               &space,
                                               const solid::MaterialParameters &materials,
                                               const FreeField                 &free_field)
    : free_field(free_field)
  {
    const auto  &rock = materials.rock;
    const double c_s = shear_wave_speed(rock), c_p = pressure_wave_speed(rock);
    space.reinit(dashpot_vector);
    for (const BoundaryDof &b : outer_boundary_dofs(space))
      if (space.locally_owned.is_element(b.index))
        {
          const double nc2 = b.normal[b.component] * b.normal[b.component];
          owned.push_back(b);
          dashpot.push_back(rock.density * (nc2 * c_p + (1 - nc2) * c_s) * b.area);
          spring.push_back(p.spring_distance > 0 ? rock.mu() / p.spring_distance *
                                                     (nc2 + 0.5 * (1 - nc2)) * b.area :
                                                   0.);
          // A DOF tied to others (u_i = sum w u_m) acts on them: c w^2 on the
          // diagonal (exact for the ties u_i = u_m that occur), forces times w.
          std::vector<std::pair<types::global_dof_index, double>> to{{b.index, 1.}};
          if (const auto *entries = space.constraints.get_constraint_entries(b.index))
            to = *entries;
          targets.push_back(to);
          for (const auto &[m, w] : to)
            dashpot_vector(m) += dashpot.back() * w * w;
        }
    dashpot_vector.compress(VectorOperation::add);
  }

  void
  ViscousSpringBoundary::add_springs(SparseMatrix &stiffness) const
  {
    for (unsigned int k = 0; k < owned.size(); ++k)
      if (spring[k] != 0.)
        for (const auto &[m, w] : targets[k])
          stiffness.add(m, m, spring[k] * w * w);
    stiffness.compress(VectorOperation::add);
  }

  void
  ViscousSpringBoundary::add_free_field_load(const double t, Vector &load) const
  {
    for (unsigned int k = 0; k < owned.size(); ++k)
      {
        const BoundaryDof &b = owned[k];
        const double       z = b.position[dim - 1];
        const unsigned int c = b.component;
        const double       f = (free_field.stress(z, t) * b.area_normal)[c] +
                         dashpot[k] * free_field.velocity(z, t)[c] +
                         spring[k] * free_field.displacement(z, t)[c];
        for (const auto &[m, w] : targets[k])
          load(m) += w * f;
      }
    load.compress(VectorOperation::add);
  }
} // namespace archdam::physics::foundation
