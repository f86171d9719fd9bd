#include <archdam/base/on_rank_zero.h>
#include <archdam/output/atomic_file.h>
#include <archdam/output/field_writer.h>
#include <archdam/analysis/mode_shapes.h>

#include <deal.II/numerics/data_out.h>


namespace archdam::analysis
{
  using namespace dealii;

  void
  write_mode_shapes(const std::string &directory, const fe::FESpace &space,
                    const NaturalModes &modes)
  {
    std::vector<std::string> names(dim, "mode_shape");
    names.emplace_back("mode_pressure");
    std::vector<DataComponentInterpretation::DataComponentInterpretation> interp(
      dim, DataComponentInterpretation::component_is_part_of_vector);
    interp.push_back(DataComponentInterpretation::component_is_scalar);

    dealii::Vector<float> material(space.dof_handler.get_triangulation().n_active_cells());
    for (const auto &cell : space.dof_handler.active_cell_iterators())
      if (cell->is_locally_owned())
        material(cell->active_cell_index()) = cell->material_id();

    std::vector<std::pair<double, std::string>> records;
    for (unsigned int k = 0; k < modes.shapes.size(); ++k)
      {
        Vector shape;
        space.reinit_ghosted(shape);
        shape = modes.shapes[k];

        DataOut<dim> data_out;
        data_out.attach_dof_handler(space.dof_handler);
        data_out.add_data_vector(shape, names, DataOut<dim>::type_dof_data, interp);
        data_out.add_data_vector(material, "material_id");
        data_out.build_patches(space.degree);
        records.emplace_back(k + 1,
                             output::write_vtu_record(data_out, directory, "modes", k + 1, space.comm));
      }
    on_rank_zero(space.comm, [&] {
      output::write_atomically(directory + "/modes.pvd", [&](std::ostream &pvd) {
        DataOutBase::write_pvd_record(pvd, records);
      });
    });
  }
} // namespace archdam::analysis
