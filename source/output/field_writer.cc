#include <archdam/base/binary_io.h>
#include <archdam/base/on_rank_zero.h>
#include <archdam/output/atomic_file.h>
#include <archdam/output/field_writer.h>
#include <archdam/physics/solid/stress.h>

#include <boost/archive/binary_iarchive.hpp>
#include <boost/archive/binary_oarchive.hpp>
#include <boost/serialization/vector.hpp>

#include <deal.II/numerics/data_out.h>


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
    prm.add_parameter("Report", report,
                      "At the end of a run (and of a record suite) write report.html: one "
                      "self-contained page with the case, the model, the input, the static "
                      "state, the peaks, the joints, the stress and DCR maps, the energy "
                      "balance and the warnings (doc/user-guide.md, \"The run report\"); "
                      "needs /usr/bin/python3 with matplotlib, else the command that writes "
                      "it is printed.",
                      Patterns::Bool());
    add_selection(prm, "Earlier results", earlier_results, earlier_results_names(),
                  "What a new run (not --resume) does with an earlier run's results in "
                  "Directory (its summary, histories, tables, field, mesh and checkpoint "
                  "files, and nothing else): replace = remove them first, so that the "
                  "directory holds this run's alone; keep = write over them and leave "
                  "the rest; refuse = stop, naming them.");
  }

  std::string
  write_vtu_record(const DataOutInterface<dim, dim> &data_out, const std::string &directory,
                   const std::string &base, const unsigned int index, const MPI_Comm comm)
  {
    const unsigned int n_ranks = Utilities::MPI::n_mpi_processes(comm);
    const std::string  name    = base + "_" + Utilities::int_to_string(index, 5);
    const auto piece = [&](const unsigned int rank) {
      return name + "." + Utilities::int_to_string(rank, Utilities::needed_digits(n_ranks - 1)) +
             ".vtu";
    };
    std::string problem;
    try
      {
        write_atomically(directory + "/" + piece(Utilities::MPI::this_mpi_process(comm)),
                         [&](std::ostream &out) { data_out.write_vtu(out); });
      }
    catch (const InputError &e)
      {
        problem = e.what();
      }
    // Every piece is complete before the record names it, and if one rank
    // could not write its piece, all stop.
    if (Utilities::MPI::max(problem.empty() ? 0 : 1, comm) == 1)
      throw InputError(problem.empty() ? "Output: another MPI process cannot write its piece "
                                         "of '" + name + "'." :
                                         problem);
    on_rank_zero(comm, [&] {
      std::vector<std::string> pieces;
      for (unsigned int r = 0; r < n_ranks; ++r)
        pieces.push_back(piece(r));
      write_atomically(directory + "/" + name + ".pvtu",
                       [&](std::ostream &out) { data_out.write_pvtu_record(out, pieces); });
    });
    return name + ".pvtu";
  }

  FieldWriter::FieldWriter(const OutputParameters                   &p,
                           const fe::FESpace                        &space,
                           const physics::solid::MaterialParameters &materials,
                           const physics::solid::TemperatureField   &temperature)
    : p(p)
    , space(space)
    , materials(materials)
    , temperature(temperature)
    , vtu(p.field_formats.find("vtu") != std::string::npos)
    , hdf5(p.field_formats.find("hdf5") != std::string::npos)
  {}

  void
  FieldWriter::record(const StepRecord &s)
  {
    if (p.field_interval > 0 && s.state.step % p.field_interval == 0)
      write(s.state, s.acceleration);
  }

  void
  FieldWriter::write(const time::NewmarkState &s, const Vector *acceleration)
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
    for (auto [ghosted, owned] :
         {std::pair{&u, &s.u}, {&v, &s.v}, {&a, acceleration ? acceleration : &s.a}})
      {
        space.reinit_ghosted(*ghosted);
        *ghosted = *owned;
      }

    dealii::Vector<float> material(space.dof_handler.get_triangulation().n_active_cells());
    dealii::Vector<float> subdomain(material.size());
    for (const auto &cell : space.dof_handler.active_cell_iterators())
      if (cell->is_locally_owned())
        {
          material(cell->active_cell_index())  = cell->material_id();
          subdomain(cell->active_cell_index()) = cell->subdomain_id();
        }

    using Stress = physics::solid::StressPostprocessor;
    const auto patches = [&](DataOut<dim> &data_out, const Stress &stress) {
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
    };

    const unsigned int index = n_written++;
    if (vtu)
      {
        const Stress stress(materials, temperature, Stress::Layout::tensor);
        DataOut<dim> data_out;
        patches(data_out, stress);
        // zlib's fastest level: a few times faster than its best, for files a
        // little larger (doc/performance.md §9)
        DataOutBase::VtkFlags flags;
        flags.compression_level = DataOutBase::VtkFlags::best_speed;
        data_out.set_flags(flags);
        const std::string pvtu =
          write_vtu_record(data_out, p.directory, "solution", index, space.comm);
        pvd_records.emplace_back(s.time, pvtu);
        on_rank_zero(space.comm, [&] {
          write_atomically(p.directory + "/solution.pvd", [&](std::ostream &pvd) {
            DataOutBase::write_pvd_record(pvd, pvd_records);
          });
        });
      }
    if (hdf5)
      {
        const Stress stress(materials, temperature, Stress::Layout::components);
        DataOut<dim> data_out;
        patches(data_out, stress);
        // Points are not merged: the two faces of a joint, and the solid and
        // water at their interface, share coordinates but not values.
        DataOutBase::DataOutFilter filter(DataOutBase::DataOutFilterFlags(false, true));
        data_out.write_filtered_data(filter);
        const std::string h5 = "solution_" + Utilities::int_to_string(index, 5) + ".h5";
        // Its size: coordinates, cells and every data set, in doubles.
        double values = (dim + 0.) * filter.n_nodes() + 8. * filter.n_cells();
        for (unsigned int i = 0; i < filter.n_data_sets(); ++i)
          values += double(filter.get_data_set_dim(i)) * filter.n_nodes();
        write_hdf5_file(temporary_name(p.directory + "/" + h5),
                        8. * Utilities::MPI::sum(values, space.comm), space.comm, [&] {
          data_out.write_hdf5_parallel(filter, temporary_name(p.directory + "/" + h5), space.comm);
        });
        on_rank_zero(space.comm, [&] { commit_temporary(p.directory + "/" + h5); });
        xdmf_entries.push_back(data_out.create_xdmf_entry(filter, h5, s.time, space.comm));
        data_out.write_xdmf_file(xdmf_entries, temporary_name(p.directory + "/solution.xdmf"),
                                 space.comm);
        on_rank_zero(space.comm, [&] { commit_temporary(p.directory + "/solution.xdmf"); });
      }
  }

  void
  FieldWriter::save(std::ostream &out) const
  {
    std::ostringstream xdmf;
    {
      boost::archive::binary_oarchive archive(xdmf);
      archive << xdmf_entries;
    }
    binary::write_all(out, pvd_records, xdmf.str(), n_written);
  }

  void
  FieldWriter::load(std::istream &in)
  {
    std::string xdmf;
    binary::read_all(in, pvd_records, xdmf, n_written);
    std::istringstream              text(xdmf);
    boost::archive::binary_iarchive archive(text);
    archive >> xdmf_entries;
  }
} // namespace archdam::output
