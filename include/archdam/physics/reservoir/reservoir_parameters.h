#pragma once

#include <deal.II/base/parameter_handler.h>

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

  /// The `Reservoir` subsection.
  struct ReservoirParameters
  {
    std::string model           = "none";
    double      density         = 1000.;
    double      sound_speed     = 1440.;
    double      reflection      = 1.;
    std::string free_surface    = "zero pressure";
    bool        level_from_mesh = true;
    double      water_level     = 0.;
    std::string pressure_points;
    std::string profile_times;

    void
    add_parameters(dealii::ParameterHandler &prm);

    /// Throws InputError for values no water has (density or sound speed 0).
    void
    check() const;

    Model
    kind() const;
    /// Whether the water cells carry the pressure field.
    bool
    has_pressure() const
    {
      return kind() == Model::compressible || kind() == Model::incompressible;
    }
    /// q = (1 - alpha_r) / (c (1 + alpha_r)) of the absorbing bottom and banks
    /// (doc/theory/reservoir.md §2); 0 for a rigid bottom or incompressible water.
    double
    bottom_absorption() const;
    bool
    gravity_waves() const
    {
      return free_surface == "gravity waves";
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
} // namespace archdam::physics::reservoir
