#pragma once

#include <archdam/fe/fe_space.h>

#include <deal.II/base/point.h>
#include <deal.II/base/tensor.h>

#include <vector>

namespace archdam::physics::foundation
{
  /// A displacement DOF on the foundation's outer boundary.
  struct BoundaryDof
  {
    dealii::types::global_dof_index index;
    unsigned int                    component;
    dealii::Point<dim>              position;
    /// Unit outward normal at the node: the direction of int N n dA over the
    /// boundary faces around it (at an edge or corner, the mean direction).
    dealii::Tensor<1, dim> normal;
    /// int N dA of the node's shape function over the boundary faces.
    double area = 0.;
    /// int N n dA, the vector of tributary area.
    dealii::Tensor<1, dim> area_normal;
  };

  /**
   * Every displacement DOF on the outer (truncation) boundary of the
   * foundation, bottom and sides (boundary ids 1 and 2), sorted by index.
   * The list is the same on every rank (small data is replicated,
   * doc/theory/conventions.md §8).
   */
  std::vector<BoundaryDof>
  outer_boundary_dofs(const fe::FESpace &space);
} // namespace archdam::physics::foundation
