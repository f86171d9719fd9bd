#pragma once

#include <archdam/fe/fe_space.h>
#include <archdam/joints/joint_faces.h>

#include <deal.II/base/point.h>
#include <deal.II/base/tensor.h>

#include <array>
#include <vector>

namespace archdam::joints
{
  /**
   * A node pair of a joint (doc/theory/joints.md §1): the coincident support points of
   * side 1 and side 2, with the local frame (xi = unit normal from side 1 to
   * side 2, eta horizontal, zeta = xi x eta) and the tributary area
   * A = int_face N_i dA from the face quadrature of side 1.
   */
  struct NodePair
  {
    unsigned int                               joint;
    dealii::Point<dim>                         position;
    std::array<dealii::Tensor<1, dim>, dim>    frame;
    double                                     area;
    /// Displacement DOFs of side 1 and side 2, by global direction.
    std::array<dealii::types::global_dof_index, dim> dofs_1, dofs_2;
    /// false where a DOF is constrained (a fixed support: it does not move).
    std::array<bool, dim>                      free_1, free_2;

    /// Row k of the pair map B: action(DOF, value) for each free DOF, with
    /// w_k = sum value u[DOF] (side 2 minus side 1, along frame[k]).
    template <typename Action>
    void
    for_each_B_entry(const unsigned int k, Action &&action) const
    {
      for (unsigned int c = 0; c < dim; ++c)
        {
          if (free_2[c])
            action(dofs_2[c], frame[k][c]);
          if (free_1[c])
            action(dofs_1[c], -frame[k][c]);
        }
    }
    /// The same row as a list of (DOF, value).
    std::vector<std::pair<dealii::types::global_dof_index, double>>
    B_row(const unsigned int k) const
    {
      std::vector<std::pair<dealii::types::global_dof_index, double>> row;
      for_each_B_entry(k, [&](const auto dof, const double v) { row.emplace_back(dof, v); });
      return row;
    }
  };

  /**
   * All node pairs of the model, replicated on every rank (they are few), and
   * the pair map B: global DOFs -> relative displacement w = u2 - u1 of every
   * pair in its local frame (3 values per pair, xi first). Pairs whose two
   * sides share their DOFs (the joint's edge grouted into the rock) or whose
   * DOFs are all fixed are left out: they cannot open.
   */
  class NodePairs
  {
  public:
    NodePairs(const fe::FESpace &space, const std::vector<JointFacePair> &faces);

    unsigned int
    size() const
    {
      return pairs.size();
    }
    unsigned int
    n_joints() const
    {
      return joints;
    }
    const NodePair &
    operator[](const unsigned int i) const
    {
      return pairs[i];
    }

    /// w = B u on every rank (the owners contribute, then one reduction).
    void
    relative_displacement(const Vector &u, std::vector<double> &w) const;

    /// rhs += factor B^T f on the DOFs this rank owns (f: 3 per pair, local).
    void
    add_transpose(const std::vector<double> &f, double factor, Vector &rhs) const;

    /// Every DOF the pair map B touches, sorted: the interface the mixed
    /// method's factorization can be condensed on (time/condensed_factorization.h).
    std::vector<dealii::types::global_dof_index>
    interface() const;

    /// The pair nearest to @p p.
    unsigned int
    nearest(const dealii::Point<dim> &p) const;

    MPI_Comm
    communicator() const
    {
      return comm;
    }

  private:
    MPI_Comm              comm;
    dealii::IndexSet      owned;
    std::vector<NodePair> pairs;
    unsigned int          joints = 0;
  };
} // namespace archdam::joints
