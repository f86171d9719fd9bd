#include <archdam/base/input_error.h>
#include <archdam/geometry/box_mesh.h>
#include <archdam/geometry/ids.h>

#include <deal.II/grid/grid_generator.h>

#include <cmath>
#include <set>

namespace archdam::geometry
{
  using namespace dealii;

  void
  BoxParameters::add_parameters(ParameterHandler &prm)
  {
    prm.enter_subsection("Box");
    prm.add_parameter("Length", length,
                      "Dam thickness in the stream direction x [m].",
                      Patterns::Double(0., Patterns::Double::max_double_value));
    prm.add_parameter("Width", width,
                      "Dam length across the stream, along y [m].",
                      Patterns::Double(0., Patterns::Double::max_double_value));
    prm.add_parameter("Height", height, "Dam height [m].",
                      Patterns::Double(0., Patterns::Double::max_double_value));
    prm.add_parameter("Number of blocks", n_blocks,
                      "Cantilever blocks along y; block k gets material id 10+k.",
                      Patterns::Integer(1, 100));
    prm.add_parameter("Cells in x", cells_x,
                      "Cells through the dam thickness.",
                      Patterns::Integer(1));
    prm.add_parameter("Cells in y", cells_y,
                      "Cells along the dam; a multiple of the number of blocks.",
                      Patterns::Integer(1));
    prm.add_parameter("Cells in z", cells_z, "Cells over the dam height.",
                      Patterns::Integer(1));
    prm.add_parameter("Rock depth", rock_depth,
                      "Depth of the rock block below the dam base [m]; 0 = no "
                      "rock, the dam base is then fixed.",
                      Patterns::Double(0.));
    prm.add_parameter("Rock extent", rock_extent,
                      "How far the rock reaches beyond the dam upstream, "
                      "downstream and to the sides [m].",
                      Patterns::Double(0.));
    prm.add_parameter("Rock cell size", rock_cell_size,
                      "Target edge length of rock cells outside the dam "
                      "footprint and below it [m], at least 1 mm.",
                      Patterns::Double(1e-3, Patterns::Double::max_double_value));
    prm.leave_subsection();
  }

  namespace
  {
    // Grid line spacings of one axis: the rock segments before and after the
    // dam (if any) and the dam segment in between.
    std::vector<double>
    spacings(const double       before,
             const double       dam,
             const unsigned int dam_cells,
             const double       after,
             const double       rock_cell)
    {
      std::vector<double> h;
      const auto          segment = [&](const double len, const unsigned int n) {
        for (unsigned int i = 0; i < n; ++i)
          h.push_back(len / n);
      };
      const auto rock_cells = [&](const double len) {
        return static_cast<unsigned int>(std::max(1., std::ceil(len / rock_cell - 1e-9)));
      };
      if (before > 0)
        segment(before, rock_cells(before));
      segment(dam, dam_cells);
      if (after > 0)
        segment(after, rock_cells(after));
      return h;
    }
  } // namespace

  double
  box_cell_count(const BoxParameters &p)
  {
    const bool   rock       = p.rock_depth > 0;
    const auto   rock_cells = [&](const double len) {
      return len > 0 ? std::max(1., std::ceil(len / p.rock_cell_size - 1e-9)) : 0.;
    };
    const double e  = rock ? p.rock_extent : 0.;
    const double nx = p.cells_x + 2 * rock_cells(e), ny = p.cells_y + 2 * rock_cells(e);
    return double(p.cells_x) * p.cells_y * p.cells_z + (rock ? nx * ny * rock_cells(p.rock_depth) : 0.);
  }

  void
  generate_box(const BoxParameters &p, Triangulation<dim> &tria)
  {
    if (p.cells_y % p.n_blocks != 0)
      throw InputError("Mesh/Box: 'Cells in y' (" + std::to_string(p.cells_y) +
                       ") must be a multiple of 'Number of blocks' (" +
                       std::to_string(p.n_blocks) + ").");

    const bool   rock = p.rock_depth > 0;
    const double e    = rock ? p.rock_extent : 0.;
    const std::vector<std::vector<double>> steps = {
      spacings(e, p.length, p.cells_x, e, p.rock_cell_size),
      spacings(e, p.width, p.cells_y, e, p.rock_cell_size),
      spacings(rock ? p.rock_depth : 0., p.height, p.cells_z, 0., p.rock_cell_size)};

    const Point<dim> lower(-e, -e, rock ? -p.rock_depth : 0.);
    const Point<dim> upper(p.length + e, p.width + e, p.height);

    Triangulation<dim> full;
    GridGenerator::subdivided_hyper_rectangle(full, steps, lower, upper);

    // Cells above the ground surface outside the dam footprint are air.
    const double tol = 1e-6 * std::max({p.length, p.width, p.height});
    const auto   in_dam_footprint = [&](const Point<dim> &c) {
      return c[0] > 0 && c[0] < p.length && c[1] > 0 && c[1] < p.width;
    };
    std::set<Triangulation<dim>::active_cell_iterator> air;
    for (const auto &cell : full.active_cell_iterators())
      if (cell->center()[2] > 0 && !in_dam_footprint(cell->center()))
        air.insert(cell);
    GridGenerator::create_triangulation_with_removed_cells(full, air, tria);

    for (const auto &cell : tria.active_cell_iterators())
      {
        const Point<dim> c = cell->center();
        if (c[2] < 0)
          cell->set_material_id(ids::rock);
        else
          {
            // Blocks are numbered left to right looking downstream (+x), i.e.
            // from +y to -y (doc/theory/conventions.md §4).
            const auto k = p.n_blocks - 1 -
                           std::min<unsigned int>(
                             static_cast<unsigned int>(c[1] / p.width * p.n_blocks),
                             p.n_blocks - 1);
            cell->set_material_id(ids::first_dam_block + k);
          }

        for (const auto &face : cell->face_iterators())
          if (face->at_boundary())
            {
              const Point<dim> f = face->center();
              if (std::abs(f[2] - lower[2]) < tol)
                face->set_boundary_id(ids::foundation_bottom);
              else if (rock && f[2] < 0 &&
                       (std::abs(f[0] - lower[0]) < tol || std::abs(f[0] - upper[0]) < tol ||
                        std::abs(f[1] - lower[1]) < tol || std::abs(f[1] - upper[1]) < tol))
                face->set_boundary_id(ids::foundation_sides);
              else
                face->set_boundary_id(ids::free_surface_solid);
            }
      }
  }
} // namespace archdam::geometry
