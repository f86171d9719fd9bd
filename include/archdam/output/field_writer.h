#pragma once

#include <archdam/fe/fe_space.h>
#include <archdam/output/earlier_results.h>
#include <archdam/output/recorder.h>
#include <archdam/physics/solid/materials.h>
#include <archdam/physics/solid/thermal.h>
#include <archdam/time/newmark.h>

#include <deal.II/base/data_out_base.h>
#include <deal.II/base/parameter_handler.h>

#include <iosfwd>
#include <string>
#include <utility>
#include <vector>

namespace archdam::output
{
  /// The `Output` subsection.
  struct OutputParameters
  {
    std::string  directory       = "results";
    unsigned int field_interval  = 10;
    std::string  field_formats   = "vtu, hdf5";
    bool         progress        = true;
    bool         timer_summary   = true;
    bool         report          = true;
    EarlierResults earlier_results = EarlierResults::replace;

    void
    add_parameters(dealii::ParameterHandler &prm);
  };

  /**
   * DataOutInterface::write_vtu_with_pvtu_record() with every file written
   * atomically (output/atomic_file.h): each rank writes its piece
   * `BASE_NNNNN.R.vtu`, then rank 0 the record `BASE_NNNNN.pvtu` naming them,
   * so a record never names a missing or partial piece. Returns the record's
   * name relative to @p directory. Collective.
   */
  std::string
  write_vtu_record(const dealii::DataOutInterface<dim, dim> &data_out,
                   const std::string &directory, const std::string &base, unsigned int index,
                   MPI_Comm comm);

  /**
   * Fields for ParaView: displacement, velocity, acceleration (with the
   * pressure component p and its rates), stress tensor, major and minor
   * principal stress, material id and MPI subdomain; as VTU pieces with a PVTU
   * per output and a PVD time series (`solution.pvd`), and as HDF5 with an
   * XDMF index (`solution.xdmf`). Every file is written atomically, the PVD
   * and XDMF indexes after the files they list. As a recorder of the
   * dynamic stage, it writes every Output/Field interval steps (the stage's
   * initial state is the static stage's, written there).
   */
  class FieldWriter : public Recorder
  {
  public:
    FieldWriter(const OutputParameters &p, const fe::FESpace &space,
                const physics::solid::MaterialParameters &materials,
                const physics::solid::TemperatureField   &temperature);

    /// Write the fields of @p s (its time labels the output), with
    /// @p acceleration in place of s.a if given (StepRecord::acceleration).
    void
    write(const time::NewmarkState &s, const Vector *acceleration = nullptr);

    std::string
    name() const override
    {
      return "fields";
    }
    void
    start(const StepRecord &) override
    {}
    void
    record(const StepRecord &s) override;
    void
    finish(Summary &, const dealii::ConditionalOStream &) override
    {}

    /// The records of the fields written so far (PVD, XDMF), for a
    /// checkpoint (output/checkpoint.h).
    void
    save(std::ostream &out) const override;
    void
    load(std::istream &in) override;

  private:
    const OutputParameters                   &p;
    const fe::FESpace                        &space;
    const physics::solid::MaterialParameters &materials;
    const physics::solid::TemperatureField   &temperature;
    bool                                      vtu, hdf5;
    std::vector<std::pair<double, std::string>> pvd_records;
    std::vector<dealii::XDMFEntry>            xdmf_entries;
    unsigned int                              n_written = 0;
  };
} // namespace archdam::output
