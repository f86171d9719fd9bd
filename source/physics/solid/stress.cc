#include <archdam/geometry/ids.h>
#include <archdam/physics/solid/stress.h>

#include <deal.II/base/mpi.h>
#include <deal.II/fe/fe_values.h>
#include <deal.II/hp/fe_values.h>

namespace archdam::physics::solid
{
  using namespace dealii;

  StressPostprocessor::StressPostprocessor(const MaterialParameters &materials,
                                           const TemperatureField   &temperature,
                                           const Layout              layout)
    : materials(materials)
    , temperature(temperature)
    , layout(layout)
  {}

  void
  StressPostprocessor::evaluate_vector_field(const DataPostprocessorInputs::Vector<dim> &inputs,
                                             std::vector<dealii::Vector<double>> &computed) const
  {
    const auto cell  = inputs.template get_cell<dim>();
    const bool solid = cell->active_fe_index() == fe::FESpace::solid_index;
    const ElasticMaterial &mat = materials.of(cell->material_id());
    for (unsigned int q = 0; q < computed.size(); ++q)
      {
        computed[q] = 0;
        if (!solid)
          continue;
        Tensor<2, dim> grad;
        for (unsigned int d = 0; d < dim; ++d)
          grad[d] = inputs.solution_gradients[q][d];
        const SymmetricTensor<2, dim> sigma = mat.stress(
          symmetrize(grad), temperature.change(cell->material_id(), inputs.evaluation_points[q]));
        for (unsigned int i = 0; i < dim; ++i)
          for (unsigned int j = 0; j < dim; ++j)
            computed[q](i * dim + j) = sigma[i][j];
        const auto [s1, s3]         = principal_stresses(sigma);
        computed[q](dim * dim)      = s1;
        computed[q](dim * dim + 1)  = s3;
      }
  }

  std::vector<std::string>
  StressPostprocessor::get_names() const
  {
    std::vector<std::string> names(dim * dim, "stress");
    if (layout == Layout::components)
      for (unsigned int i = 0; i < dim; ++i)
        for (unsigned int j = 0; j < dim; ++j)
          names[i * dim + j] = std::string("stress_") + "xyz"[i] + "xyz"[j];
    names.emplace_back("major_principal_stress");
    names.emplace_back("minor_principal_stress");
    return names;
  }

  std::vector<DataComponentInterpretation::DataComponentInterpretation>
  StressPostprocessor::get_data_component_interpretation() const
  {
    std::vector<DataComponentInterpretation::DataComponentInterpretation> interp(
      dim * dim, layout == Layout::tensor ? DataComponentInterpretation::component_is_part_of_tensor :
                                           DataComponentInterpretation::component_is_scalar);
    interp.push_back(DataComponentInterpretation::component_is_scalar);
    interp.push_back(DataComponentInterpretation::component_is_scalar);
    return interp;
  }

  UpdateFlags
  StressPostprocessor::get_needed_update_flags() const
  {
    return update_gradients | update_quadrature_points;
  }

  PeakStress
  peak_major_principal_stress(const fe::FESpace        &space,
                              const MaterialParameters &materials,
                              const TemperatureField   &temperature,
                              const Vector             &ghosted_u)
  {
    hp::FEValues<dim> hp_fe_values(space.fe_collection, space.q_collection,
                                   update_gradients | update_quadrature_points);
    std::vector<Tensor<2, dim>> grads;
    PeakStress                  local{-std::numeric_limits<double>::max(), Point<dim>()};
    for (const auto &cell : space.dof_handler.active_cell_iterators())
      if (cell->is_locally_owned() && ids::is_dam(cell->material_id()))
        {
          hp_fe_values.reinit(cell);
          const FEValues<dim> &fv = hp_fe_values.get_present_fe_values();
          grads.resize(fv.n_quadrature_points);
          fv[space.displacement].get_function_gradients(ghosted_u, grads);
          const ElasticMaterial &mat = materials.of(cell->material_id());
          for (const unsigned int q : fv.quadrature_point_indices())
            {
              const double s1 =
                principal_stresses(
                  mat.stress(symmetrize(grads[q]),
                             temperature.change(cell->material_id(), fv.quadrature_point(q))))
                  .first;
              if (s1 > local.value)
                local = {s1, fv.quadrature_point(q)};
            }
        }
    // The rank holding the global maximum tells the others where it is.
    const auto global = Utilities::MPI::min_max_avg(local.value, space.comm);
    const unsigned int owner = Utilities::MPI::min(
      local.value == global.max ? Utilities::MPI::this_mpi_process(space.comm) :
                                  Utilities::MPI::n_mpi_processes(space.comm),
      space.comm);
    PeakStress result{global.max, local.where};
    result.where = Utilities::MPI::broadcast(space.comm, local.where, owner);
    return result;
  }
} // namespace archdam::physics::solid
