#pragma once

#include <archdam/base/types.h>

#include <deal.II/base/parameter_handler.h>
#include <deal.II/base/symmetric_tensor.h>
#include <deal.II/base/types.h>

namespace archdam::physics::solid
{
  /// Linear isotropic elastic material (doc/theory/solid.md §1).
  struct ElasticMaterial
  {
    double youngs_modulus = 22e9; // Pa
    double poissons_ratio = 0.167;
    double density        = 2446.5; // kg/m^3
    /// alpha [1/degree C]: concrete only (the rock's temperature does not
    /// change, doc/theory/temperature.md §2).
    double thermal_expansion = 1e-5;

    void
    add_parameters(dealii::ParameterHandler &prm);

    double
    lambda() const
    {
      return youngs_modulus * poissons_ratio /
             ((1 + poissons_ratio) * (1 - 2 * poissons_ratio));
    }
    double
    mu() const
    {
      return youngs_modulus / (2 * (1 + poissons_ratio));
    }

    /// Hooke's law: sigma = lambda tr(eps) I + 2 mu eps (tension positive).
    dealii::SymmetricTensor<2, dim>
    stress(const dealii::SymmetricTensor<2, dim> &strain) const
    {
      return lambda() * dealii::trace(strain) * dealii::unit_symmetric_tensor<dim>() +
             2 * mu() * strain;
    }

    /// The stress of a temperature change @p dT under no strain:
    /// -(3 lambda + 2 mu) alpha dT I = -E alpha dT / (1 - 2 nu) I.
    double
    thermal_pressure(const double dT) const
    {
      return (3 * lambda() + 2 * mu()) * thermal_expansion * dT;
    }

    /// Hooke's law with the thermal strain alpha dT I taken out:
    /// sigma = C (eps - alpha dT I) (doc/theory/temperature.md §2).
    dealii::SymmetricTensor<2, dim>
    stress(const dealii::SymmetricTensor<2, dim> &strain, const double dT) const
    {
      return stress(strain) - thermal_pressure(dT) * dealii::unit_symmetric_tensor<dim>();
    }
  };

  /// The `Materials` subsection: concrete of all dam blocks, and the rock.
  struct MaterialParameters
  {
    ElasticMaterial concrete;
    ElasticMaterial rock{22e9, 0.25, 2650., 0.};

    void
    add_parameters(dealii::ParameterHandler &prm);

    /// The solid material of a cell with the given material id.
    const ElasticMaterial &
    of(dealii::types::material_id id) const;
  };

  /// Major (largest, tension positive) and minor principal stress.
  std::pair<double, double>
  principal_stresses(const dealii::SymmetricTensor<2, dim> &stress);
} // namespace archdam::physics::solid
