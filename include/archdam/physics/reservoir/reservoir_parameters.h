#pragma once

#include <archdam/base/selection.h>

#include <deal.II/base/parameter_handler.h>

#include <optional>
#include <string>

namespace archdam::physics::reservoir
{
  /// How the reservoir acts on the dam and the rock (doc/theory/reservoir.md).
  enum class Model
  {
    compressible,   ///< pressure p in the water cells, wave equation, radiation
    incompressible, ///< the same with c -> infinity (no 1/c^2, no radiation)
    westergaard,    ///< generalized Westergaard added mass, no water DOFs
    none            ///< empty reservoir: the water cells are left out
  };

  /// The names of Model in the case file (`Reservoir/Model`).
  inline const SelectionNames<Model> &
  model_names()
  {
    static const SelectionNames<Model> names{{"compressible", Model::compressible},
                                             {"incompressible", Model::incompressible},
                                             {"westergaard", Model::westergaard},
                                             {"none", Model::none}};
    return names;
  }

  /// `Reservoir/Free surface`: the condition on the water surface.
  enum class FreeSurface
  {
    zero_pressure, ///< p = 0
    gravity_waves  ///< (1/g) p_tt + dp/dn = 0
  };

  /// The names of FreeSurface in the case file.
  inline const SelectionNames<FreeSurface> &
  free_surface_names()
  {
    static const SelectionNames<FreeSurface> names{
      {"zero pressure", FreeSurface::zero_pressure},
      {"gravity waves", FreeSurface::gravity_waves}};
    return names;
  }

  /// The `Reservoir` subsection.
  struct ReservoirParameters
  {
    Model       model           = Model::none;
    double      density         = 1000.;
    double      sound_speed     = 1440.;
    double      reflection      = 1.;
    FreeSurface free_surface    = FreeSurface::zero_pressure;
    bool        level_from_mesh = true;
    double      water_level     = 0.;
    std::string pressure_points;
    std::string profile_times;

    void
    add_parameters(dealii::ParameterHandler &prm);

    /// Throws InputError for values no water has (density or sound speed 0).
    void
    check() const;

    /// Whether the water cells carry the pressure field.
    bool
    has_pressure() const
    {
      return model == Model::compressible || model == Model::incompressible;
    }
    /// q = (1 - alpha_r) / (c (1 + alpha_r)) of the absorbing bottom and banks
    /// (doc/theory/reservoir.md §2); 0 for a rigid bottom or incompressible water.
    double
    bottom_absorption() const;
    bool
    gravity_waves() const
    {
      return free_surface == FreeSurface::gravity_waves;
    }
  };
} // namespace archdam::physics::reservoir

#include <archdam/base/types.h>

#include <deal.II/grid/tria.h>

namespace archdam::physics::reservoir
{
  /// Elevation of the water surface: the top of the water cells when
  /// `Water level from mesh` is set and the mesh has water, else `Water level`.
  /// Throws InputError if a model other than none finds no water cells (it
  /// needs the wetted faces, ids 6/7), or if a model with pressure is given
  /// a level other than the top of its water cells.
  double
  water_level(const ReservoirParameters &p, const dealii::Triangulation<dim> &mesh);

  /// The top of the water cells (material id 2) of @p mesh [m], or nothing
  /// when it has none.
  std::optional<double>
  top_of_water(const dealii::Triangulation<dim> &mesh);
} // namespace archdam::physics::reservoir
