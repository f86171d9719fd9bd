#include <archdam/geometry/ids.h>
#include <archdam/physics/solid/materials.h>

namespace archdam::physics::solid
{
  using namespace dealii;

  void
  ElasticMaterial::add_parameters(ParameterHandler &prm)
  {
    // Bounds that no concrete or rock leaves, so that a unit mistake (MPa for
    // Pa, t/m^3 for kg/m^3) or an empty value is named here, not met later as
    // a singular matrix or a zero input energy.
    prm.add_parameter("Young's modulus", youngs_modulus,
                      "Young's modulus E [Pa], from 1e5 to 1e13.",
                      Patterns::Double(1e5, 1e13));
    prm.add_parameter("Poisson's ratio", poissons_ratio, "Poisson's ratio nu [-].",
                      Patterns::Double(-0.999, 0.4999));
    prm.add_parameter("Density", density,
                      "Mass density [kg/m^3] (a unit weight of 24 kN/m^3 is "
                      "24000/9.81 = 2446.5 kg/m^3), from 1 to 50000.",
                      Patterns::Double(1., 5e4));
  }

  void
  MaterialParameters::add_parameters(ParameterHandler &prm)
  {
    prm.enter_subsection("Concrete");
    concrete.add_parameters(prm);
    prm.add_parameter("Thermal expansion coefficient", concrete.thermal_expansion,
                      "alpha [1/degree C] of the concrete, for Static loads/Temperature "
                      "change, from 0 to 1e-4 (concrete: about 1e-5).",
                      Patterns::Double(0., 1e-4));
    prm.leave_subsection();
    prm.enter_subsection("Rock");
    rock.add_parameters(prm);
    prm.leave_subsection();
  }

  const ElasticMaterial &
  MaterialParameters::of(const types::material_id id) const
  {
    return ids::is_dam(id) ? concrete : rock;
  }

  std::pair<double, double>
  principal_stresses(const SymmetricTensor<2, dim> &stress)
  {
    // The iterative QL method, not the closed form of eigenvalues(): the
    // latter loses half the digits (acos near -1) when two principal stresses
    // coincide, as in the uniaxial and biaxial states of free faces.
    // The pairs come in descending order of the eigenvalue.
    const auto ev = eigenvectors(stress, SymmetricTensorEigenvectorMethod::ql_implicit_shifts);
    return {ev[0].first, ev[dim - 1].first};
  }
} // namespace archdam::physics::solid
