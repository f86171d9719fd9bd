#pragma once

#include <archdam/fe/fe_space.h>
#include <archdam/loads/static_loads.h>
#include <archdam/physics/solid/materials.h>

#include <deal.II/base/point.h>
#include <deal.II/base/tensor.h>
#include <deal.II/grid/tria.h>

#include <optional>
#include <vector>

namespace archdam::physics::solid
{
  /**
   * The through-thickness coordinate of the dam (doc/theory/temperature.md
   * §1): s = d_u / (d_u + d_d), d_u and d_d the distances of a point to the
   * dam's upstream and downstream faces (geometry::surface_part(), the
   * faces of the stress envelope), so s = 0 on the upstream face and 1 on
   * the downstream face, for any mesh. The distance to a face is the
   * distance to the plane of the face nearest by its centre (its centre and
   * the unit normal of its diagonals): exact for plane faces, second order
   * in the cell size on curved ones.
   */
  class ThroughThickness
  {
  public:
    explicit ThroughThickness(const dealii::Triangulation<dim> &tria);

    double
    operator()(const dealii::Point<dim> &x) const;

  private:
    struct Plane
    {
      dealii::Point<dim>     centre;
      dealii::Tensor<1, dim> normal;
    };
    static double
    distance(const std::vector<Plane> &faces, const dealii::Point<dim> &x);

    std::vector<Plane> upstream, downstream;
  };

  /**
   * The dam's temperature change since grouting (doc/theory/temperature.md
   * §1): dT(x) = T_m(z) + T_d(z) (1/2 - s(x)) in the dam's cells, zero in the
   * rock and without a table. The table must cover the dam's elevations.
   */
  class TemperatureField
  {
  public:
    /// No temperature change.
    TemperatureField() = default;
    TemperatureField(const loads::TemperatureTable &table, const dealii::Triangulation<dim> &tria);

    bool
    empty() const
    {
      return table.empty();
    }

    /// dT at @p x in a cell of material @p material.
    double
    change(dealii::types::material_id material, const dealii::Point<dim> &x) const;

  private:
    loads::TemperatureTable         table;
    std::optional<ThroughThickness> thickness; // with a table
  };

  /**
   * The load of the thermal strain, f_i = int (3 lambda + 2 mu) alpha dT
   * div N_i dx over the dam's cells (doc/theory/temperature.md §2), added to
   * @p load with the model's constraints.
   */
  void
  add_thermal_load(const fe::FESpace        &space,
                   const MaterialParameters &materials,
                   const TemperatureField   &temperature,
                   Vector                   &load);
} // namespace archdam::physics::solid
