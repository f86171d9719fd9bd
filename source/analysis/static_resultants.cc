#include <archdam/analysis/static_resultants.h>
#include <archdam/geometry/ids.h>

#include <deal.II/base/mpi.h>
#include <deal.II/fe/fe_values.h>

#include <algorithm>
#include <cmath>
#include <iomanip>
#include <ostream>

namespace archdam::analysis
{
  using namespace dealii;

  double
  StaticResultants::out_of_balance() const
  {
    const double scale = weight.norm() + water.norm();
    return scale > 0 ? (weight + water + support).norm() / scale : 0.;
  }

  void
  StaticResultants::print(std::ostream &out) const
  {
    // Components below round-off of the largest force are printed as 0: they
    // differ with the order of the sums (the number of MPI processes).
    const double scale = std::max({weight.norm(), water.norm(), support.norm()});
    const auto   mn    = [&](const char *name, const Tensor<1, dim> &f) {
      out << "  " << std::left << std::setw(14) << name << std::right << std::setprecision(6);
      for (unsigned int d = 0; d < dim; ++d)
        out << std::setw(14) << (std::abs(f[d]) < 1e-10 * scale ? 0. : f[d] / 1e6);
      out << '\n';
    };
    out << "Static resultants on the dam [MN]:        x             y             z\n";
    mn("weight", weight);
    mn("water", water);
    mn("support", support);
    out << "  out of balance ";
    if (out_of_balance() < 1e-9)
      out << "below 1e-9";
    else
      out << std::setprecision(2) << out_of_balance();
    out << " of the applied loads" << std::endl;
  }

  StaticResultants
  static_resultants(const fe::FESpace                        &space,
                    const physics::solid::MaterialParameters &materials,
                    const Vector                             &u,
                    const Tensor<1, dim>                     &gravity,
                    const std::function<double(double)>      &pressure)
  {
    const auto        &fe = space.fe_collection[fe::FESpace::solid_index];
    FEValues<dim>      cell_values(fe, space.q_collection[fe::FESpace::solid_index],
                              update_JxW_values);
    FEFaceValues<dim>  face_values(fe, space.face_q_collection[fe::FESpace::solid_index],
                                  update_gradients | update_quadrature_points |
                                    update_normal_vectors | update_JxW_values);
    std::vector<Tensor<2, dim>> gradients(face_values.n_quadrature_points);

    StaticResultants r;
    for (const auto &cell : space.dof_handler.active_cell_iterators())
      if (cell->is_locally_owned() && ids::is_dam(cell->material_id()))
        {
          const auto &material = materials.of(cell->material_id());
          cell_values.reinit(cell);
          for (const unsigned int q : cell_values.quadrature_point_indices())
            r.weight += material.density * gravity * cell_values.JxW(q);

          for (const unsigned int f : cell->face_indices())
            {
              const auto face     = cell->face(f);
              const bool wetted   = face->at_boundary() &&
                                  face->boundary_id() == ids::solid_interface;
              // The support: the rock, or where no rock is meshed under the
              // dam the fixed truncation itself.
              const bool on_rock =
                face->at_boundary() ?
                  (face->boundary_id() == ids::foundation_bottom ||
                   face->boundary_id() == ids::foundation_sides) :
                  cell->neighbor(f)->material_id() == ids::rock;
              if (!wetted && !on_rock)
                continue;
              face_values.reinit(cell, f);
              if (on_rock)
                face_values[space.displacement].get_function_gradients(u, gradients);
              for (const unsigned int q : face_values.quadrature_point_indices())
                {
                  const Tensor<1, dim> n = face_values.normal_vector(q);
                  if (wetted)
                    r.water -= pressure(face_values.quadrature_point(q)[dim - 1]) * n *
                               face_values.JxW(q);
                  else
                    r.support += material.stress(symmetrize(gradients[q])) * n * face_values.JxW(q);
                }
            }
        }
    for (Tensor<1, dim> *f : {&r.weight, &r.water, &r.support})
      *f = Utilities::MPI::sum(*f, space.comm);
    return r;
  }
} // namespace archdam::analysis
