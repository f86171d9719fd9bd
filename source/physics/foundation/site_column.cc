#include <archdam/base/input_error.h>
#include <archdam/geometry/ids.h>
#include <archdam/physics/foundation/massed_foundation.h>
#include <archdam/physics/foundation/site_column.h>
#include <archdam/physics/solid/solid_operators.h>
#include <archdam/time/newmark.h>

#include <deal.II/base/mpi.h>
#include <deal.II/distributed/shared_tria.h>
#include <deal.II/fe/mapping_q1.h>
#include <deal.II/grid/grid_generator.h>

#include <algorithm>
#include <cmath>
#include <map>

namespace archdam::physics::foundation
{
  using namespace dealii;

  namespace
  {
    /// The column's cell sizes from the top down: every elevation of @p z a
    /// node, no cell longer than @p h.
    std::vector<double>
    cell_sizes(const double z_s, const double z_b, std::vector<double> z, const double h)
    {
      z.push_back(z_s);
      z.push_back(z_b);
      std::sort(z.begin(), z.end(), std::greater<>());
      z.erase(std::unique(z.begin(), z.end(),
                          [](const double a, const double b) { return std::abs(a - b) < 1e-6; }),
              z.end());
      std::vector<double> sizes;
      for (unsigned int i = 0; i + 1 < z.size(); ++i)
        {
          const unsigned int n = std::max(1., std::ceil((z[i] - z[i + 1]) / h - 1e-9));
          sizes.insert(sizes.end(), n, (z[i] - z[i + 1]) / n);
        }
      std::reverse(sizes.begin(), sizes.end()); // bottom up, as z grows
      return sizes;
    }

    /// Per elevation (in micrometres) and component, the DOF with the
    /// smallest index: the plane's master.
    std::map<std::pair<long, unsigned int>, types::global_dof_index>
    plane_masters(const fe::FESpace &space, AffineConstraints<double> *ties)
    {
      std::map<std::pair<long, unsigned int>, types::global_dof_index> master;
      const auto &fe      = space.fe_collection[fe::FESpace::solid_index];
      const auto  support = fe.get_unit_support_points();
      const MappingQ1<dim>                 mapping;
      std::map<types::global_dof_index, std::pair<long, unsigned int>> plane;
      std::vector<types::global_dof_index> dofs(fe.n_dofs_per_cell());
      for (const auto &cell : space.dof_handler.active_cell_iterators())
        {
          cell->get_dof_indices(dofs);
          for (unsigned int i = 0; i < dofs.size(); ++i)
            plane[dofs[i]] = {std::lround(mapping.transform_unit_to_real_cell(cell, support[i])[dim - 1] * 1e6),
                              fe.system_to_component_index(i).first};
        }
      for (const auto &[i, key] : plane) // increasing index: the first is the master
        if (!master.count(key))
          master[key] = i;
        else if (ties && space.locally_relevant.is_element(i) && !ties->is_constrained(i) &&
                 !ties->is_constrained(master[key]))
          {
            ties->add_line(i);
            ties->add_entry(i, master[key], 1.);
          }
      return master;
    }
  } // namespace

  SiteColumn::Histories
  SiteColumn::run(const FreeField           &free_field,
                  const unsigned int         d,
                  const std::vector<double> &z,
                  const double               dt,
                  const double               end,
                  MPI_Comm                   comm) const
  {
    const double z_s = free_field.surface(), z_b = free_field.bottom();
    for (const double zi : z)
      if (zi > z_s + 1e-6 || zi < z_b - 1e-6)
        throw InputError("Free-field check: the elevation " + std::to_string(zi) +
                         " m lies outside the rock column (" + std::to_string(z_b) + " to " +
                         std::to_string(z_s) + " m).");
    const auto sizes = cell_sizes(z_s, z_b, z, cell_size);

    parallel::shared::Triangulation<dim> tria(comm);
    GridGenerator::subdivided_hyper_rectangle(tria, {{cell_size}, {cell_size}, sizes},
                                              Point<dim>(0, 0, z_b),
                                              Point<dim>(cell_size, cell_size, z_s));
    for (const auto &cell : tria.active_cell_iterators())
      {
        cell->set_material_id(ids::rock);
        for (const auto f : cell->face_indices())
          if (cell->face(f)->at_boundary())
            {
              const double zf = cell->face(f)->center()[dim - 1];
              cell->face(f)->set_boundary_id(std::abs(zf - z_b) < 1e-6 ? ids::foundation_bottom :
                                                                       ids::free_surface_solid);
            }
      }
    fe::FiniteElementParameters fep;
    fep.degree = degree;
    fe::FESpace space(tria, fep);
    space.setup(foundation.fixed_boundaries(),
                [&](AffineConstraints<double> &c) { plane_masters(space, &c); });
    const auto master = plane_masters(space, nullptr);

    solid::MaterialParameters materials;
    materials.rock     = rock;
    materials.concrete = rock;
    SparseMatrix M, K, D;
    solid::assemble_mass_and_stiffness(space, materials, solid::InertiaOf::dam_and_rock, M, K,
                                       &damping, &D);
    const auto boundary = make_massed_foundation(foundation, space, materials,
                                                 solid::InertiaOf::dam_and_rock, free_field, dt,
                                                 &damping);
    boundary->add_springs(K);
    time::NewmarkParameters tp;
    tp.time_step = dt;
    time::NewmarkIntegrator newmark(tp, M, D, K, space.constraints, true, boundary->dashpots());

    time::NewmarkState s;
    Vector             load;
    for (Vector *v : {&s.u, &s.v, &s.a, &load})
      space.reinit(*v);
    boundary->start(s.u);
    std::vector<types::global_dof_index> at;
    for (const double zi : z)
      at.push_back(master.at({std::lround(zi * 1e6), d}));

    Histories h;
    h.acceleration.resize(z.size());
    const auto record = [&]() {
      h.times.push_back(s.time);
      for (unsigned int i = 0; i < at.size(); ++i)
        h.acceleration[i].push_back(Utilities::MPI::sum(
          space.locally_owned.is_element(at[i]) ? double(s.a(at[i])) : 0., comm));
    };
    record();
    const unsigned int n_steps = std::lround(end / dt);
    for (unsigned int n = 1; n <= n_steps; ++n)
      {
        boundary->advance(newmark, load, s);
        record();
      }
    return h;
  }

  SiteColumn::Comparison
  SiteColumn::compare(const FreeField           &free_field,
                      const loads::GroundMotion &motion,
                      const unsigned int         d,
                      const double               z_base,
                      const double               dt,
                      MPI_Comm                   comm) const
  {
    const double T = free_field.delay(d);
    const auto   h = run(free_field, d, {free_field.surface(), z_base}, dt,
                         motion.record(d).times.back() + T, comm);
    Comparison c;
    for (unsigned int k = 0; k < h.times.size(); ++k)
      if (h.times[k] >= T - 1e-9)
        {
          c.t.push_back(h.times[k] - T);
          c.control.push_back(motion.acceleration(h.times[k] - T)[d]);
          c.surface.push_back(h.acceleration[0][k]);
          c.base.push_back(h.acceleration[1][k]);
          c.free_field.push_back(free_field.acceleration(z_base, h.times[k])[d]);
        }
    return c;
  }
} // namespace archdam::physics::foundation
