#pragma once

#include <archdam/base/types.h>

#include <deal.II/grid/tria.h>

namespace archdam::geometry
{
  /**
   * The splitter (doc/theory/conventions.md §6), shared by every mesh source: from a
   * conforming coarse mesh with material ids (1 rock, 2 water, 10 + k dam
   * block k) and boundary ids 0-5, build the model mesh in which
   *  - the vertices of faces between dam blocks k and k + 1 are duplicated,
   *    except those that also touch rock (the joint's edge against the
   *    foundation: the block is grouted into the rock), so that joint k
   *    becomes two coincident boundary faces with ids 100 + 2k (block k's
   *    side, "side 1") and 101 + 2k (block k+1's side, "side 2");
   *  - water and solid cells share no vertex; the water side of each
   *    interface face gets id 6, the solid side id 7;
   *  - every other face keeps its id; cells keep their order and material.
   * Two different blocks that touch but are not neighbours (|k - j| != 1) are
   * an input error.
   */
  void
  split_interfaces(const dealii::Triangulation<dim> &conforming,
                   dealii::Triangulation<dim>       &split);

  /// Boundary ids the splitter adds.
  constexpr dealii::types::boundary_id
  joint_side_1(const unsigned int joint)
  {
    return 100 + 2 * joint;
  }
  constexpr dealii::types::boundary_id
  joint_side_2(const unsigned int joint)
  {
    return 101 + 2 * joint;
  }
  inline bool
  is_joint_face(const dealii::types::boundary_id id)
  {
    return id >= 100 && id != dealii::numbers::internal_face_boundary_id;
  }
  /// The joint a face with id 100 + 2k or 101 + 2k belongs to.
  inline unsigned int
  joint_of(const dealii::types::boundary_id id)
  {
    return (id - 100) / 2;
  }
} // namespace archdam::geometry
