#include <archdam/geometry/ids.h>
#include <archdam/geometry/mesh_checks.h>
#include <archdam/output/mesh_report.h>
#include <archdam/joints/joint_faces.h>

#include <deal.II/base/quadrature_lib.h>
#include <deal.II/dofs/dof_handler.h>
#include <deal.II/fe/fe_q.h>

#include <iomanip>
#include <ostream>
#include <set>

namespace archdam::output
{
  using namespace dealii;

  namespace
  {
    /// Area of a (possibly non-planar) bilinear face: the integral of
    /// |x_a x x_b| over the unit square, 4 x 4 Gauss points.
    double
    face_area(const Triangulation<dim>::face_iterator &face)
    {
      const QGauss<dim - 1> q(4);
      double                area = 0;
      for (unsigned int i = 0; i < q.size(); ++i)
        {
          const double         a = q.point(i)[0], b = q.point(i)[1];
          const Tensor<1, dim> xa = (1 - b) * (face->vertex(1) - face->vertex(0)) +
                                    b * (face->vertex(3) - face->vertex(2));
          const Tensor<1, dim> xb = (1 - a) * (face->vertex(2) - face->vertex(0)) +
                                    a * (face->vertex(3) - face->vertex(1));
          area += q.weight(i) * cross_product_3d(xa, xb).norm();
        }
      return area;
    }

    std::string
    region_of(const types::material_id m)
    {
      if (m == ids::water)
        return "water";
      if (m == ids::rock)
        return "rock";
      return "dam block " + std::to_string(m - ids::first_dam_block);
    }
  } // namespace

  MeshReport
  make_mesh_report(const Triangulation<dim> &model, const unsigned int degree)
  {
    MeshReport r;

    // Nodes per region: the DOFs of a scalar Lagrange element of the run's
    // degree, counted once per region.
    DoFHandler<dim> nodes(model);
    nodes.distribute_dofs(FE_Q<dim>(degree));
    std::set<types::global_dof_index>    dam_nodes, rock_nodes, water_nodes;
    std::vector<types::global_dof_index> cell_nodes(nodes.get_fe().n_dofs_per_cell());
    bool                                 first = true;
    for (const auto &cell : nodes.active_cell_iterators())
      {
        const auto m = cell->material_id();
        cell->get_dof_indices(cell_nodes);
        auto &region = m == ids::water ? r.water : m == ids::rock ? r.rock : r.dam;
        auto &set    = m == ids::water ? water_nodes : m == ids::rock ? rock_nodes : dam_nodes;
        ++region.cells;
        set.insert(cell_nodes.begin(), cell_nodes.end());
        if (ids::is_dam(m))
          r.dam_volume += cell->measure();
        if (m == ids::water)
          r.water_volume += cell->measure();
        for (const unsigned int f : cell->face_indices())
          if (ids::is_dam(m) && cell->at_boundary(f) &&
              cell->face(f)->boundary_id() == ids::solid_interface)
            r.wetted_area += face_area(cell->face(f));

        const double q = geometry::scaled_jacobian(cell);
        if (first || q < r.min_scaled_jacobian)
          {
            r.min_scaled_jacobian = q;
            r.worst_cell_center   = cell->center();
            r.worst_cell_material = m;
            first                 = false;
          }
      }
    r.dam.dofs   = dim * dam_nodes.size();
    r.rock.dofs  = dim * rock_nodes.size();
    r.water.dofs = water_nodes.size();

    unsigned int n_joints = 0;
    const auto   pairs    = joints::pair_joint_faces(model);
    for (const auto &p : pairs)
      n_joints = std::max(n_joints, p.joint + 1);
    for (const auto &count : joints::count_joint_nodes(pairs, n_joints, degree))
      {
        r.joint_faces.push_back(count.faces);
        r.joint_node_pairs.push_back(count.node_pairs);
      }
    return r;
  }

  void
  MeshReport::print(std::ostream &out) const
  {
    out << "Mesh report:\n"
        << "  region       cells        DOFs\n";
    for (const auto &[name, region] :
         {std::make_pair("dam", dam), std::make_pair("rock", rock), std::make_pair("water", water)})
      out << "  " << std::left << std::setw(7) << name << std::right << std::setw(10)
          << region.cells << std::setw(12) << region.dofs << "\n";
    out << "  (3 DOFs per solid node, 1 per water node; dam-rock interface nodes in both)\n"
        << std::setprecision(6) << "  dam volume " << dam_volume << " m^3, water volume "
        << water_volume << " m^3, wetted area of the dam face " << wetted_area << " m^2\n"
        << "  joints: " << joint_faces.size();
    if (!joint_faces.empty())
      {
        out << "; faces / node pairs per joint:";
        for (unsigned int k = 0; k < joint_faces.size(); ++k)
          out << (k % 8 == 0 ? "\n   " : "") << " " << k << ": " << joint_faces[k] << "/"
              << joint_node_pairs[k];
      }
    out << "\n  minimum scaled Jacobian " << std::setprecision(3) << min_scaled_jacobian
        << " in the cell centred at (" << std::setprecision(6) << worst_cell_center[0] << ", "
        << worst_cell_center[1] << ", " << worst_cell_center[2] << ") m, "
        << region_of(worst_cell_material) << std::endl;
  }

  void
  MeshReport::add_to(output::Summary &summary) const
  {
    for (const auto &[name, region] :
         {std::make_pair("dam", dam), std::make_pair("rock", rock), std::make_pair("water", water)})
      {
        summary.set(std::string("mesh/") + name + "/cells", region.cells);
        summary.set(std::string("mesh/") + name + "/dofs", region.dofs);
      }
    summary.set("mesh/dam volume [m^3]", dam_volume);
    summary.set("mesh/water volume [m^3]", water_volume);
    summary.set("mesh/wetted area of the dam face [m^2]", wetted_area);
    summary.set("mesh/joints/count", joint_faces.size());
    for (unsigned int k = 0; k < joint_faces.size(); ++k)
      {
        summary.set("mesh/joints/joint " + std::to_string(k) + "/faces", joint_faces[k]);
        summary.set("mesh/joints/joint " + std::to_string(k) + "/node pairs",
                    joint_node_pairs[k]);
      }
    summary.set("mesh/minimum scaled Jacobian/value", min_scaled_jacobian);
    for (unsigned int d = 0; d < dim; ++d)
      summary.set("mesh/minimum scaled Jacobian/cell centre " + std::string(1, "xyz"[d]) +
                    " [m]",
                  worst_cell_center[d]);
    summary.set("mesh/minimum scaled Jacobian/material id", worst_cell_material);
    summary.set("mesh/minimum scaled Jacobian/region", region_of(worst_cell_material));
  }
} // namespace archdam::output
