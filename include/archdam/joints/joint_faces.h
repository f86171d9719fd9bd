#pragma once

#include <archdam/base/types.h>

#include <deal.II/dofs/dof_handler.h>
#include <deal.II/grid/tria.h>
#include <deal.II/lac/affine_constraints.h>

#include <vector>

namespace archdam::joints
{
  /// The two coincident faces of one joint face (doc/theory/joints.md §1): side 1 on
  /// block k (id 100 + 2k), side 2 on block k + 1 (id 101 + 2k).
  struct JointFacePair
  {
    unsigned int                             joint;
    dealii::Triangulation<dim>::cell_iterator cell_1, cell_2;
    unsigned int                             face_1, face_2;
  };

  /**
   * Pair the joint faces the splitter made, by coincident vertices. A face
   * without its partner, or whose partner lies on another joint, is an input
   * error naming the joint and the place.
   */
  std::vector<JointFacePair>
  pair_joint_faces(const dealii::Triangulation<dim> &tria);

  /// The joint's faces and node pairs: the coincident support points of side
  /// 1 and side 2 of elements of @p degree that the analysis pairs (the
  /// mesh vertices at degree 1; at degree 2 also each edge whose two sides
  /// are different edges and each face centre), less those on the model's
  /// truncation (boundary ids 1, 2), which move alike on both sides: the
  /// number the run reports.
  struct JointNodeCount
  {
    unsigned int faces = 0, node_pairs = 0;
  };
  std::vector<JointNodeCount>
  count_joint_nodes(const std::vector<JointFacePair> &pairs, unsigned int n_joints,
                    unsigned int degree = 1);

  /**
   * Glued joints (`Contraction joints/Model = glued`): tie every displacement
   * DOF of side 2 to the coincident DOF of side 1 (u2 = u1), which restores the
   * monolithic dam. Adds lines only for locally relevant DOFs; DOFs already
   * constrained (a fixed base) are left as they are.
   */
  void
  tie_joint_dofs(const dealii::DoFHandler<dim>          &dof_handler,
                 const std::vector<JointFacePair>       &pairs,
                 const dealii::IndexSet                 &locally_relevant,
                 dealii::AffineConstraints<double>      &constraints);
} // namespace archdam::joints
