#include <archdam/base/input_error.h>
#include <archdam/physics/reservoir/reservoir_parameters.h>

namespace archdam::physics::reservoir
{
  using namespace dealii;

  void
  ReservoirParameters::add_parameters(ParameterHandler &prm)
  {
    add_selection(prm, "Model", model, model_names(),
                  "compressible = pressure in the water cells with the wave "
                  "equation, radiation upstream and absorbing bottom "
                  "(doc/theory/reservoir.md, paper eq. 3.1-3.2); incompressible = the "
                  "same with an infinite sound speed; westergaard = "
                  "generalized Westergaard added mass on the wetted dam "
                  "face, no water unknowns; none = empty reservoir.");
    prm.add_parameter("Water density", density, "rho_w [kg/m^3].",
                      Patterns::Double(0., Patterns::Double::max_double_value));
    prm.add_parameter("Sound speed", sound_speed, "Speed of pressure waves c in water [m/s].",
                      Patterns::Double(0., Patterns::Double::max_double_value));
    prm.add_parameter("Bottom reflection coefficient", reflection,
                      "Wave reflection coefficient alpha_r of the reservoir bottom "
                      "and banks where no rock is meshed (boundary id 5): 1 = rigid, "
                      "0 = fully absorbing.",
                      Patterns::Double(0., 1.));
    add_selection(prm, "Free surface", free_surface, free_surface_names(),
                  "zero pressure (p = 0) or gravity waves "
                  "((1/g) p_tt + dp/dn = 0).");
    prm.add_parameter("Water level from mesh", level_from_mesh,
                      "Take the water level from the top of the water cells (if "
                      "the mesh has any) instead of 'Water level'.",
                      Patterns::Bool());
    prm.add_parameter("Water level", water_level,
                      "Elevation z of the water surface [m], for the hydrostatic "
                      "load and the Westergaard added mass, when not taken from "
                      "the mesh.",
                      Patterns::Double());
    prm.add_parameter("Pressure points", pressure_points,
                      "Named points in the water, 'name: x, y, z; ...' [m], "
                      "e.g. along the dam face: their hydrodynamic pressure is "
                      "written every step to pressure_histories.csv, and as a "
                      "profile (one row per point) at the profile times with "
                      "its envelope to pressure_profile.csv.",
                      Patterns::Anything());
    prm.add_parameter("Profile times", profile_times,
                      "Times [s] of the pressure profile, comma-separated (the "
                      "step nearest to each); the envelope is always written.",
                      Patterns::List(Patterns::Double(0.), 0, 1000, ","));
  }

  void
  ReservoirParameters::check() const
  {
    if (model == Model::none)
      return;
    if (density <= 0)
      throw InputError("Reservoir/Water density must be positive (it is " +
                       std::to_string(density) + ").");
    if (model == Model::compressible && sound_speed <= 0)
      throw InputError("Reservoir/Sound speed must be positive for compressible water (it "
                       "is " + std::to_string(sound_speed) + ").");
  }

  double
  ReservoirParameters::bottom_absorption() const
  {
    if (model != Model::compressible)
      return 0.;
    return (1. - reflection) / (sound_speed * (1. + reflection));
  }
} // namespace archdam::physics::reservoir

#include <archdam/geometry/ids.h>

#include <deal.II/base/mpi.h>

#include <algorithm>
#include <limits>
#include <sstream>

namespace archdam::physics::reservoir
{
  std::optional<double>
  top_of_water(const dealii::Triangulation<dim> &mesh)
  {
    std::optional<double> top;
    for (const auto &cell : mesh.active_cell_iterators())
      if (cell->material_id() == ids::water)
        for (const unsigned int v : cell->vertex_indices())
          top = std::max(top.value_or(cell->vertex(v)[dim - 1]), cell->vertex(v)[dim - 1]);
    return top;
  }

  double
  water_level(const ReservoirParameters &p, const dealii::Triangulation<dim> &mesh)
  {
    const std::optional<double> water_top = top_of_water(mesh);
    const bool                  has_water = water_top.has_value();
    const double                top       = water_top.value_or(0.);
    if (p.model != Model::none && !has_water)
      throw InputError("Reservoir/Model = " + selection_name(p.model, model_names()) +
                       " needs water cells (material id 2) in front of the dam, and the "
                       "mesh has none (Mesh/Source = box has no reservoir; use the arch "
                       "dam, or set Reservoir/Model = none).");
    if (p.has_pressure() && !p.level_from_mesh &&
        std::abs(p.water_level - top) > 1e-6 * std::max(1., std::abs(top)))
      throw InputError("Reservoir/Water level = " + std::to_string(p.water_level) +
                       " m, but the water cells reach z = " + std::to_string(top) +
                       " m: with model " + selection_name(p.model, model_names()) +
                       " the water mesh defines the level (set 'Water level from mesh', "
                       "or change the mesh's water level).");
    // Westergaard's added mass takes the level as given: the depth of the
    // water on the dam's upstream face, between its base and its crest.
    if (p.model == Model::westergaard && !p.level_from_mesh)
      {
        double base = std::numeric_limits<double>::max(), crest = -base;
        for (const auto &cell : mesh.active_cell_iterators())
          if (ids::is_dam(cell->material_id()))
            for (const unsigned int v : cell->vertex_indices())
              {
                base  = std::min(base, cell->vertex(v)[dim - 1]);
                crest = std::max(crest, cell->vertex(v)[dim - 1]);
              }
        const double tolerance = 1e-9 * std::max(1., crest - base);
        if (base <= crest && !(p.water_level >= base - tolerance && p.water_level <= crest + tolerance))
          {
            std::ostringstream text;
            text << "Reservoir/Water level = " << p.water_level << " m lies "
                 << (p.water_level > crest ? "above the dam's crest" : "below the dam's base")
                 << " (the dam reaches from z = " << base << " to " << crest
                 << " m): Westergaard's added mass needs the water's depth on the dam's face, "
                 << "a level between the two.";
            throw InputError(text.str());
          }
      }
    return p.level_from_mesh && has_water ? top : p.water_level;
  }
} // namespace archdam::physics::reservoir
