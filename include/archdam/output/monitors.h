#pragma once

#include <archdam/fe/fe_space.h>
#include <archdam/physics/solid/materials.h>
#include <archdam/physics/solid/thermal.h>
#include <archdam/time/newmark.h>

#include <deal.II/base/parameter_handler.h>
#include <deal.II/base/point.h>

#include <string>
#include <vector>

namespace archdam::output
{
  /// The `Monitors` subsection: named points and what is recorded there.
  struct MonitorParameters
  {
    std::string points;
    std::string quantities = "displacement, principal stress";

    void
    add_parameters(dealii::ParameterHandler &prm);
  };

  struct MonitorPoint
  {
    std::string        name;
    dealii::Point<dim> location;
  };

  /// Parse "name: x, y, z; name: x, y, z" (InputError naming the bad item).
  std::vector<MonitorPoint>
  parse_monitor_points(const std::string &text);

  /// What the peak of a column is (doc/theory/results.md §1): the value of
  /// largest magnitude, or for the major principal stress its largest value
  /// (the largest tension) and for the minor one its smallest (the largest
  /// compression), so that a larger compression cannot hide a tension.
  enum class Peak
  {
    magnitude,
    largest,
    smallest
  };

  /// The row of @p rows where column @p c peaks in the sense of @p kind.
  unsigned int
  peak_row(const std::vector<std::vector<double>> &rows, unsigned int c, Peak kind);

  /**
   * Evaluates the solution at the monitor points. The FE weights of each
   * point (shape values and gradients at its reference coordinates) are
   * computed once; an evaluation gathers the few DOF values involved from
   * their owners (one small all-reduce), so every rank gets the same row.
   */
  class Monitors
  {
  public:
    /// The stress is C (eps - alpha dT I) with the dam's temperature change
    /// @p temperature (physics/solid/thermal.h).
    Monitors(const MonitorParameters &p, const fe::FESpace &space,
             const physics::solid::MaterialParameters &materials,
             const physics::solid::TemperatureField   &temperature);

    /// Column headers with units, in the order of evaluate().
    const std::vector<std::string> &
    column_names() const
    {
      return names;
    }

    /// The peak of each column of column_names().
    const std::vector<Peak> &
    column_peaks() const
    {
      return peaks;
    }

    /// One row: the time, then each point's values of @p state, with
    /// @p acceleration in place of state.a if given (StepRecord::acceleration).
    std::vector<double>
    evaluate(const time::NewmarkState &state, const Vector *acceleration = nullptr) const;

    /// Displacement vector at point @p k for the nodal vector @p u.
    dealii::Tensor<1, dim>
    displacement(unsigned int k, const Vector &u) const;

    const std::vector<MonitorPoint> &
    monitor_points() const
    {
      return points;
    }

  private:
    struct Weights
    {
      std::vector<dealii::types::global_dof_index> dofs;
      std::vector<dealii::Tensor<1, dim>>          value;    // per dof
      std::vector<dealii::Tensor<2, dim>>          gradient; // per dof
      physics::solid::ElasticMaterial              material;
      double                                       temperature_change; // dT at the point
    };

    std::vector<double>
    gather(const Vector &vec, const Weights &w) const;
    /// The vector at point @p k from the gathered nodal values.
    dealii::Tensor<1, dim>
    interpolate(unsigned int k, const std::vector<double> &values) const;

    const fe::FESpace        &space;
    std::vector<MonitorPoint> points;
    std::vector<Weights>      weights;
    bool                      record_u, record_v, record_a, record_stress;
    std::vector<std::string>  names;
    std::vector<Peak>         peaks;
  };
} // namespace archdam::output
