#include <archdam/output/field_writer.h>
#include <archdam/physics/solid/stress.h>

#include <deal.II/numerics/data_out.h>

#include <fstream>

namespace archdam::output
{
  using namespace dealii;

  void
  OutputParameters::add_parameters(ParameterHandler &prm)
  {
    prm.add_parameter("Directory", directory,
                      "Directory for all results (created if missing).",
                      Patterns::DirectoryName());
    prm.add_parameter("Field output interval", field_interval,
                      "Write fields every this many time steps (and after the "
                      "static stage); 0 = no field output.",
                      Patterns::Integer(0));
    prm.add_parameter("Field formats", field_formats,
                      "Formats of the field output: vtu (VTU/PVTU + PVD), hdf5 "
                      "(HDF5 + XDMF).",
                      Patterns::MultipleSelection("vtu|hdf5"));
    prm.add_parameter("Progress", progress,
                      "Print the step, time, percent done and an estimate of the "
                      "time left while the dynamic stage runs.",
                      Patterns::Bool());
    prm.add_parameter("Timer summary", timer_summary,
                      "Print wall times per stage at the end.", Patterns::Bool());
  }

  FieldWriter::FieldWriter(const OutputParameters                   &p,
                           const fe::FESpace                        &space,
                           const physics::solid::MaterialParameters &materials)
    : p(p)
    , space(space)
    , materials(materials)
    , vtu(p.field_formats.find("vtu") != std::string::npos)
    , hdf5(p.field_formats.find("hdf5") != std::string::npos)
  {}

  void
  FieldWriter::write(const time::NewmarkState &s)
  {
    const auto names = [](const std::string &u, const std::string &pr) {
      std::vector<std::string> n(dim, u);
      n.push_back(pr);
      return n;
    };
    std::vector<DataComponentInterpretation::DataComponentInterpretation> interp(
      dim, DataComponentInterpretation::component_is_part_of_vector);
    interp.push_back(DataComponentInterpretation::component_is_scalar);

    Vector u, v, a;
    for (auto [ghosted, owned] : {std::pair{&u, &s.u}, {&v, &s.v}, {&a, &s.a}})
      {
        space.reinit_ghosted(*ghosted);
        *ghosted = *owned;
      }

    const physics::solid::StressPostprocessor stress(materials);
    dealii::Vector<float> material(space.dof_handler.get_triangulation().n_active_cells());
    dealii::Vector<float> subdomain(material.size());
    for (const auto &cell : space.dof_handler.active_cell_iterators())
      if (cell->is_locally_owned())
        {
          material(cell->active_cell_index())  = cell->material_id();
          subdomain(cell->active_cell_index()) = cell->subdomain_id();
        }

    DataOut<dim> data_out;
    data_out.attach_dof_handler(space.dof_handler);
    data_out.add_data_vector(u, names("displacement", "pressure"),
                             DataOut<dim>::type_dof_data, interp);
    data_out.add_data_vector(v, names("velocity", "pressure_rate"),
                             DataOut<dim>::type_dof_data, interp);
    data_out.add_data_vector(a, names("acceleration", "pressure_acceleration"),
                             DataOut<dim>::type_dof_data, interp);
    data_out.add_data_vector(u, stress);
    data_out.add_data_vector(material, "material_id");
    data_out.add_data_vector(subdomain, "subdomain");
    data_out.build_patches(space.degree);

    const unsigned int index = n_written++;
    if (vtu)
      {
        const std::string pvtu = data_out.write_vtu_with_pvtu_record(
          p.directory + "/", "solution", index, space.comm, 5, 0);
        pvd_records.emplace_back(s.time, pvtu);
        if (Utilities::MPI::this_mpi_process(space.comm) == 0)
          {
            std::ofstream pvd(p.directory + "/solution.pvd");
            DataOutBase::write_pvd_record(pvd, pvd_records);
          }
      }
    if (hdf5)
      {
        DataOutBase::DataOutFilter filter(DataOutBase::DataOutFilterFlags(true, true));
        data_out.write_filtered_data(filter);
        const std::string h5 = "solution_" + Utilities::int_to_string(index, 5) + ".h5";
        data_out.write_hdf5_parallel(filter, p.directory + "/" + h5, space.comm);
        xdmf_entries.push_back(data_out.create_xdmf_entry(filter, h5, s.time, space.comm));
        data_out.write_xdmf_file(xdmf_entries, p.directory + "/solution.xdmf", space.comm);
      }
  }
} // namespace archdam::output
