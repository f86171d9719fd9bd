#pragma once

#include <archdam/fe/fe_space.h>
#include <archdam/physics/foundation/foundation.h>
#include <archdam/physics/foundation/free_field.h>
#include <archdam/physics/foundation/outer_boundary.h>
#include <archdam/physics/solid/materials.h>

#include <vector>

namespace archdam::physics::foundation
{
  /**
   * The viscous-spring boundary (doc/theory/foundation.md §8, the comparison boundary):
   * at each outer-boundary DOF (component c, unit outward normal n, tributary
   * area A = int N dA) a dashpot and a spring to the free field,
   *   c_i = rho (n_c^2 c_p + (1 - n_c^2) c_s) A         (Lysmer & Kuhlemeyer 1969),
   *   k_i = G/R (n_c^2 + (1 - n_c^2)/2) A               (Liu et al. 2006; R = Spring distance),
   * lumped at the nodes. The free field enters through the equivalent forces
   *   F_i(t) = [sigma_ff(z_i, t) int N n dA]_c + c_i v_ff,c(z_i, t) + k_i u_ff,c(z_i, t),
   * so that the boundary passes the free field and absorbs the scattered
   * motion (exactly for plane waves at normal incidence without springs).
   */
  class ViscousSpringBoundary
  {
  public:
    ViscousSpringBoundary(const FoundationParameters      &p,
                          const fe::FESpace               &space,
                          const solid::MaterialParameters &materials,
                          const FreeField                 &free_field);

    /// The dashpot coefficients c_i as a vector (a diagonal damping matrix).
    const Vector &
    dashpots() const
    {
      return dashpot_vector;
    }

    /// Add the springs k_i to the diagonal of @p stiffness.
    void
    add_springs(SparseMatrix &stiffness) const;

    /// Add the equivalent free-field forces at time @p t to @p load.
    void
    add_free_field_load(double t, Vector &load) const;

  private:
    const FreeField         &free_field;
    std::vector<BoundaryDof> owned;
    std::vector<double>      dashpot, spring;
    /// The DOFs each boundary DOF acts on, with weights (itself, or its
    /// masters if it is tied to others).
    std::vector<std::vector<std::pair<dealii::types::global_dof_index, double>>> targets;
    Vector                   dashpot_vector;
  };
} // namespace archdam::physics::foundation
