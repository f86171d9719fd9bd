#pragma once

#include <archdam/fe/fe_space.h>
#include <archdam/physics/solid/materials.h>
#include <archdam/physics/solid/thermal.h>

#include <deal.II/base/point.h>
#include <deal.II/numerics/data_postprocessor.h>

namespace archdam::physics::solid
{
  /**
   * Stress recovered from the displacement gradient (doc/theory/solid.md §6) for
   * output: the stress tensor and the major and minor principal stress
   * (tension positive). Zero in water cells.
   */
  class StressPostprocessor : public dealii::DataPostprocessor<dim>
  {
  public:
    /// How the stress tensor is written: as one 3x3 tensor ("stress", for
    /// VTU), or as its nine components, "stress_xx", "stress_xy", ... in the
    /// tensor's row-major order, for formats that know no tensors (deal.II's
    /// XDMF writer keeps only the first three components of a tensor).
    enum class Layout
    {
      tensor,
      components
    };

    /// The stress is C (eps - alpha dT I) with the dam's temperature
    /// change @p temperature (thermal.h).
    StressPostprocessor(const MaterialParameters &materials,
                        const TemperatureField   &temperature,
                        Layout                    layout = Layout::tensor);

    void
    evaluate_vector_field(const dealii::DataPostprocessorInputs::Vector<dim> &inputs,
                          std::vector<dealii::Vector<double>> &computed) const override;
    std::vector<std::string>
    get_names() const override;
    std::vector<dealii::DataComponentInterpretation::DataComponentInterpretation>
    get_data_component_interpretation() const override;
    dealii::UpdateFlags
    get_needed_update_flags() const override;

  private:
    const MaterialParameters &materials;
    const TemperatureField   &temperature;
    const Layout              layout;
  };

  struct PeakStress
  {
    double             value = 0.;
    dealii::Point<dim> where;
  };

  /**
   * The largest major principal stress over the dam's quadrature points, for
   * a ghosted displacement vector and the dam's temperature change; the same
   * on every rank.
   */
  PeakStress
  peak_major_principal_stress(const fe::FESpace        &space,
                              const MaterialParameters &materials,
                              const TemperatureField   &temperature,
                              const Vector             &ghosted_u);
} // namespace archdam::physics::solid
