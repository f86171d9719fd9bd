#include <archdam/base/binary_io.h>
#include <archdam/base/input_error.h>
#include <archdam/geometry/ids.h>
#include <archdam/physics/foundation/multi_transmitting_boundary.h>

#include <deal.II/fe/mapping_q1.h>
#include <deal.II/grid/grid_tools.h>
#include <deal.II/grid/grid_tools_cache.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <sstream>


namespace archdam::physics::foundation
{
  using namespace dealii;

  namespace
  {
    double
    binomial(const unsigned int n, const unsigned int k)
    {
      double c = 1.;
      for (unsigned int i = 1; i <= k; ++i)
        c = c * (n - k + i) / i;
      return c;
    }
  } // namespace

  MultiTransmittingBoundary::MultiTransmittingBoundary(const FoundationParameters      &p,
                                                       const fe::FESpace               &space,
                                                       const solid::MaterialParameters &materials,
                                                       const FreeField                 &free_field,
                                                       const double                     time_step)
    : order(p.transmitting_boundary == TransmittingBoundary::mtf ? p.mtf_order : 0)
    , dt(time_step)
    , free_field(free_field)
    , comm(space.comm)
  {
    // The drift stabilization per step, gamma = rate dt: a fixed gamma would
    // decay faster per second at a smaller step (doc/theory/foundation.md §6).
    const double gamma = p.stabilization_rate * dt;
    if (order > 0 && gamma > 0.5)
      {
        std::ostringstream msg;
        msg << "Foundation: Stabilization rate = " << p.stabilization_rate
            << " /s at the time step " << dt << " s gives gamma = " << gamma
            << " per step, above 0.5: the MTF would damp rather than transmit. "
            << "Use a rate below " << 0.5 / dt << " /s (0.01 - 0.05 per step is usual).";
        throw InputError(msg.str());
      }
    for (unsigned int j = 1; j <= order; ++j)
      coefficient.push_back((j % 2 == 1 ? 1. : -1.) * binomial(order, j) *
                            std::pow(1. + gamma, -double(j)));

    const auto &rock = materials.rock;
    const double c_s = shear_wave_speed(rock), c_p = pressure_wave_speed(rock);
    const MappingQ1<dim>        mapping;
    const GridTools::Cache<dim> cache(space.dof_handler.get_triangulation(), mapping);
    const auto                 &fe = space.fe_collection[fe::FESpace::solid_index];
    // The cell around a point, a rock cell if there is one: where the water
    // lies on the rock, a point on the wetted face belongs to a water cell
    // too. The second search is restricted to the rock's vertices (the split
    // mesh gives water and rock no common vertex); it is only a fallback, as
    // a search from the nearest marked vertex can miss the cell of a point in
    // stretched cells. Throws if no cell contains the point.
    const auto       &tria = space.dof_handler.get_triangulation();
    std::vector<bool> rock_vertices(tria.n_vertices(), false);
    for (const auto &cell : tria.active_cell_iterators())
      if (cell->material_id() == ids::rock)
        for (const auto v : cell->vertex_indices())
          rock_vertices[cell->vertex_index(v)] = true;
    const auto in_rock = [&](const Point<dim> &x) {
      const auto found = GridTools::find_active_cell_around_point(cache, x);
      if (found.first.state() == IteratorState::valid && found.first->material_id() != ids::rock)
        {
          // A point on a face the rock shares with a dam cell (the rock's
          // top surface where the dam stands on it, reached along a side
          // boundary flush with the dam's end face) lies in the rock's
          // closure: a rock cell that touches the cell found holds it.
          for (const auto v : found.first->vertex_indices())
            for (const auto &cell : cache.get_vertex_to_cell_map()[found.first->vertex_index(v)])
              if (cell->material_id() == ids::rock)
                try
                  {
                    const Point<dim> unit = mapping.transform_real_to_unit_cell(cell, x);
                    if (GeometryInfo<dim>::is_inside_unit_cell(unit, 1e-10))
                      return std::make_pair(cell, unit);
                  }
                catch (const Mapping<dim>::ExcTransformationFailed &)
                  {}
        }
      if (found.first.state() == IteratorState::valid && found.first->material_id() != ids::rock)
        try
          {
            const auto rock = GridTools::find_active_cell_around_point(cache, x, {}, rock_vertices);
            if (rock.first.state() == IteratorState::valid && rock.first->material_id() == ids::rock)
              return rock;
          }
        catch (...)
          {}
      return found;
    };

    stencil_offset.push_back(0);
    IndexSet needed(space.dof_handler.n_dofs());
    for (const BoundaryDof &b : outer_boundary_dofs(space))
      {
        boundary_dofs.push_back(b.index);
        components.push_back(b.component);
        z_boundary.push_back(b.position[dim - 1]);
        needed.add_index(b.index);
        // c_a: given, or c_p along the normal and c_s across it (n_c^2 weights).
        const double nc2 = b.normal[b.component] * b.normal[b.component];
        const double c_a = p.artificial_speed > 0 ? p.artificial_speed : nc2 * c_p + (1 - nc2) * c_s;
        for (unsigned int j = 1; j <= order; ++j)
          {
            const Point<dim> x = b.position - j * c_a * dt * b.normal;
            std::pair<Triangulation<dim>::active_cell_iterator, Point<dim>> found;
            try
              {
                found = in_rock(x);
              }
            catch (...)
              {
                found.first = space.dof_handler.get_triangulation().end();
              }
            bool inside = found.first.state() == IteratorState::valid &&
                          found.first->material_id() == ids::rock;
            if (!inside)
              {
                // A node on the edge where the outer boundary meets a free
                // surface (or the water) of curved or inclined shape: the
                // normal runs close to that surface and x_j may lie just
                // outside the rock. Take the nearest point of the rock cell at
                // the node if it is close (a quarter of j c_a dt); a point far
                // outside means the rock is too thin for the formula.
                const auto at_node = in_rock(b.position);
                if (at_node.first.state() == IteratorState::valid &&
                    at_node.first->material_id() == ids::rock)
                  {
                    const Point<dim> unit = GeometryInfo<dim>::project_to_unit_cell(
                      mapping.transform_real_to_unit_cell(at_node.first, x));
                    if (mapping.transform_unit_to_real_cell(at_node.first, unit).distance(x) <
                        0.25 * j * c_a * dt)
                      {
                        found  = {at_node.first, unit};
                        inside = true;
                      }
                  }
              }
            if (!inside)
              {
                std::ostringstream msg;
                msg << "Foundation: the MTF of order " << order << " needs the motion at "
                    << j * c_a * dt << " m (j c_a dt with j = " << j << ", c_a = " << c_a
                    << " m/s, dt = " << dt << " s) inside the outer boundary, but from the "
                    << "boundary node at (" << b.position << ") that point (" << x
                    << ") is not inside the rock. Reduce the time step, the MTF order or "
                    << "the artificial speed, or extend the rock.";
                throw InputError(msg.str());
              }
            const DoFHandler<dim>::active_cell_iterator cell(
              &space.dof_handler.get_triangulation(), found.first->level(),
              found.first->index(), &space.dof_handler);
            if (j == 1)
              {
                // Liao's S = c_a dt / h with h the node spacing along the
                // normal: the cell's extent along it over the degree (not its
                // shortest edge, which in a flat cell lies across the normal).
                double lowest = std::numeric_limits<double>::max(), highest = -lowest;
                for (const unsigned int v : cell->vertex_indices())
                  {
                    lowest  = std::min(lowest, cell->vertex(v) * b.normal);
                    highest = std::max(highest, cell->vertex(v) * b.normal);
                  }
                max_courant = std::max(max_courant, c_a * dt * space.degree / (highest - lowest));
              }
            std::vector<types::global_dof_index> cell_dofs(fe.n_dofs_per_cell());
            cell->get_dof_indices(cell_dofs);
            for (unsigned int i = 0; i < fe.n_dofs_per_cell(); ++i)
              if (fe.system_to_component_index(i).first == b.component)
                {
                  const double w = fe.shape_value(i, found.second);
                  if (std::abs(w) > 1e-13)
                    {
                      stencil_dof.push_back(cell_dofs[i]);
                      stencil_weight.push_back(w);
                      needed.add_index(cell_dofs[i]);
                    }
                }
            stencil_offset.push_back(stencil_dof.size());
            z_point.push_back(x[dim - 1]);
          }
      }
    // The free field depends on the elevation alone, and the boundary's
    // nodes and points lie on few elevations: it is evaluated once per
    // elevation and step.
    const auto elevation_indices = [&](const std::vector<double> &z) {
      std::vector<unsigned int> index(z.size());
      for (unsigned int k = 0; k < z.size(); ++k)
        index[k] = std::lower_bound(elevations.begin(), elevations.end(), z[k]) -
                   elevations.begin();
      return index;
    };
    elevations = z_boundary;
    elevations.insert(elevations.end(), z_point.begin(), z_point.end());
    std::sort(elevations.begin(), elevations.end());
    elevations.erase(std::unique(elevations.begin(), elevations.end()), elevations.end());
    elevation_of_boundary = elevation_indices(z_boundary);
    elevation_of_point    = elevation_indices(z_point);
    free_field_at.resize(elevations.size());
    IndexSet relevant = space.locally_owned;
    relevant.add_indices(needed);
    ghosted.reinit(space.locally_owned, relevant, comm);
    history.assign(std::max(order, 1u), std::vector<double>(z_point.size(), 0.));
    values.resize(boundary_dofs.size());
  }

  void
  MultiTransmittingBoundary::gather_stencils(const Vector &u)
  {
    // (one pass over u's local array: an access by entry would ask PETSc
    // for the array each time)
    ghosted = u;
    stencil_value.resize(stencil_dof.size());
    ghosted.extract_subvector_to(stencil_dof.begin(), stencil_dof.end(), stencil_value.begin());
  }

  double
  MultiTransmittingBoundary::interpolate(const unsigned int point) const
  {
    double value = 0.;
    for (unsigned int s = stencil_offset[point]; s < stencil_offset[point + 1]; ++s)
      value += stencil_weight[s] * stencil_value[s];
    return value;
  }

  void
  MultiTransmittingBoundary::initialize(const Vector &u0)
  {
    gather_stencils(u0);
    u0_boundary.resize(boundary_dofs.size());
    ghosted.extract_subvector_to(boundary_dofs.begin(), boundary_dofs.end(), u0_boundary.begin());
    u0_point.resize(z_point.size());
    for (unsigned int q = 0; q < z_point.size(); ++q)
      u0_point[q] = interpolate(q);
    for (auto &h : history)
      std::fill(h.begin(), h.end(), 0.);
  }

  void
  MultiTransmittingBoundary::evaluate_free_field(const double t)
  {
    for (unsigned int e = 0; e < elevations.size(); ++e)
      free_field_at[e] = free_field.displacement(elevations[e], t);
  }

  const std::vector<double> &
  MultiTransmittingBoundary::next_values(const double t_next)
  {
    evaluate_free_field(t_next);
    for (unsigned int k = 0; k < boundary_dofs.size(); ++k)
      {
        double scattered = 0.;
        for (unsigned int j = 1; j <= order; ++j)
          scattered += coefficient[j - 1] * history[j - 1][k * order + j - 1];
        values[k] = u0_boundary[k] + free_field_at[elevation_of_boundary[k]][components[k]] +
                    scattered;
      }
    return values;
  }

  void
  MultiTransmittingBoundary::record(const Vector &u, const double t)
  {
    if (order == 0)
      return;
    gather_stencils(u);
    std::rotate(history.rbegin(), history.rbegin() + 1, history.rend()); // newest first
    evaluate_free_field(t);
    for (unsigned int q = 0; q < z_point.size(); ++q)
      history[0][q] = interpolate(q) - u0_point[q] -
                      free_field_at[elevation_of_point[q]][components[q / order]];
  }

  void
  MultiTransmittingBoundary::save(std::ostream &out) const
  {
    binary::write_all(out, u0_boundary, u0_point, history);
  }

  void
  MultiTransmittingBoundary::load(std::istream &in)
  {
    const auto n_boundary = u0_boundary.size(), n_points = u0_point.size(),
               n_history = history.size();
    binary::read_all(in, u0_boundary, u0_point, history);
    if (u0_boundary.size() != n_boundary || u0_point.size() != n_points ||
        history.size() != n_history)
      throw InputError("Checkpoint: the saved transmitting boundary does not match the "
                       "model's.");
  }
} // namespace archdam::physics::foundation
