#pragma once

#include <archdam/base/types.h>
#include <archdam/output/summary.h>

#include <deal.II/base/point.h>
#include <deal.II/grid/tria.h>

#include <iosfwd>
#include <vector>

namespace archdam::output
{
  /**
   * What the model mesh holds (issue "mesh report"), printed by every run and
   * written into summary.json under "mesh". Computed on the whole split model,
   * water included (build_model_mesh()), identically on every rank.
   */
  struct MeshReport
  {
    struct Region
    {
      unsigned int cells = 0;
      /// Degrees of freedom of the region's nodes for Lagrange elements of
      /// the run's degree: 3 per node in dam and rock, 1 (the pressure) per
      /// node in water. Nodes on the dam-rock interface count in both.
      unsigned long long dofs = 0;
    };
    Region dam, rock, water;
    double dam_volume   = 0.; // [m^3]
    double water_volume = 0.; // [m^3]
    /// Area of the dam faces against water: faces with id 7 (solid side of
    /// the fluid-solid interface) on dam cells [m^2].
    double wetted_area = 0.;
    /// Per joint k: its faces and node pairs (the support-point pairs of the
    /// analysis at the element degree, joints::count_joint_nodes()).
    std::vector<unsigned int> joint_faces, joint_node_pairs;
    /// The worst cell (mesh_checks.h): its scaled Jacobian, centre, material.
    double                     min_scaled_jacobian = 1.;
    dealii::Point<dim>         worst_cell_center;
    dealii::types::material_id worst_cell_material = 0;

    /// The report as a few lines of text.
    void
    print(std::ostream &out) const;
    /// The same entries under "mesh/..." in summary.json.
    void
    add_to(output::Summary &summary) const;
  };

  /// The report of a split model mesh for elements of polynomial @p degree.
  MeshReport
  make_mesh_report(const dealii::Triangulation<dim> &model, unsigned int degree);
} // namespace archdam::output
