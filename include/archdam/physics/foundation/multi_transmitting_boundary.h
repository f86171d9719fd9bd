#pragma once

#include <archdam/fe/fe_space.h>
#include <archdam/physics/foundation/foundation.h>
#include <archdam/physics/foundation/free_field.h>
#include <archdam/physics/foundation/outer_boundary.h>
#include <archdam/physics/solid/materials.h>

#include <iosfwd>
#include <vector>

namespace archdam::physics::foundation
{
  /**
   * Liao's multi-transmitting formula on the outer boundary of a massed
   * foundation (doc/theory/foundation.md §5-§7), or, with `Transmitting boundary = fixed`, the
   * free-field motion alone. At every outer-boundary DOF 0 (component c,
   * inward normal -n) the scattered motion u_s = u - u_0 - u_ff (u_0: the
   * state the dynamic stage starts from) at t + dt is
   *
   *   u_s,0(t + dt) = sum_{j=1..N} (-1)^{j+1} C(N, j) (1 + gamma)^(-j) u_s(t - (j-1) dt, x_j),
   *   x_j = x_0 - j c_a dt n,
   *
   * with the interior values from the finite element interpolation at x_j:
   * the cells holding the points and the shape values there are found once,
   * so a step costs one weighted sum per point. The result, plus u_0 and the
   * free field, is the prescribed displacement of the step
   * (time::PrescribedDofs): the boundary is explicit, the interior implicit,
   * and Kbar stays factorized once.
   */
  class MultiTransmittingBoundary
  {
  public:
    /// InputError if a point x_j lies outside the rock.
    MultiTransmittingBoundary(const FoundationParameters      &p,
                              const fe::FESpace               &space,
                              const solid::MaterialParameters &materials,
                              const FreeField                 &free_field,
                              double                           time_step);

    /// The prescribed DOFs, sorted, the same on every rank.
    const std::vector<dealii::types::global_dof_index> &
    dofs() const
    {
      return boundary_dofs;
    }

    /// Start from the state @p u0 at rest at t = 0: the scattered history is 0.
    void
    initialize(const Vector &u0);

    /// The boundary displacements at @p t_next = t_n + dt, one per dofs().
    const std::vector<double> &
    next_values(double t_next);

    /// Store the interior values of @p u, the displacement at time @p t
    /// after a step, for the following steps.
    void
    record(const Vector &u, double t);

    /// Largest c_a dt / h over the boundary, h the distance from a boundary
    /// node to the nearest interior node along its normal (Liao's S).
    double
    largest_courant_number() const
    {
      return max_courant;
    }

    /// The initial values and the scattered-motion histories, for a
    /// checkpoint (output/checkpoint.h).
    void
    save(std::ostream &out) const;
    void
    load(std::istream &in);

  private:
    /// stencil_value = u at stencil_dof (through ghosted).
    void
    gather_stencils(const Vector &u);
    /// u at point @p point, from stencil_value.
    double
    interpolate(unsigned int point) const;
    /// free_field_at = the free-field displacement at every elevation, time @p t.
    void
    evaluate_free_field(double t);

    const unsigned int                       order;
    const double                             dt;
    const FreeField                         &free_field;
    const MPI_Comm                           comm;
    std::vector<dealii::types::global_dof_index> boundary_dofs;
    std::vector<unsigned int>                components;
    std::vector<double>                      z_boundary;
    /// coefficient (-1)^{j+1} C(N, j) (1 + gamma)^(-j), j = 1..N (0 for fixed)
    std::vector<double> coefficient;
    /// Point (k, j) = k * order + j - 1: its elevation and its stencil
    /// (DOFs and shape values in stencil_offset[p] .. stencil_offset[p+1]).
    std::vector<double>                          z_point;
    std::vector<unsigned int>                    stencil_offset;
    std::vector<dealii::types::global_dof_index> stencil_dof;
    std::vector<double>                          stencil_weight, stencil_value;
    /// u_0 at the boundary DOFs and at the points.
    std::vector<double> u0_boundary, u0_point;
    /// history[m][p]: u_s at point p, m steps before the last recorded time.
    std::vector<std::vector<double>> history;
    std::vector<double>              values;
    /// The distinct elevations of the boundary's DOFs and points (sorted),
    /// each one's index there, and the free field at them.
    std::vector<double>                 elevations;
    std::vector<unsigned int>           elevation_of_boundary, elevation_of_point;
    std::vector<dealii::Tensor<1, dim>> free_field_at;
    Vector                              ghosted;
    double                           max_courant = 0.;
  };
} // namespace archdam::physics::foundation
