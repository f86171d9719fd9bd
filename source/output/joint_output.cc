#include <archdam/base/binary_io.h>
#include <archdam/base/input_error.h>
#include <archdam/base/on_rank_zero.h>
#include <archdam/output/joint_output.h>
#include <archdam/output/atomic_file.h>

#include <deal.II/base/data_out_base.h>
#include <deal.II/base/utilities.h>

#include <cmath>
#include <iomanip>
#include <map>
#include <sstream>

namespace archdam::output
{
  using namespace dealii;

  namespace
  {
    /// `Contraction joints/Monitor points`: the name of each and the node
    /// pair nearest to it.
    std::vector<std::pair<std::string, unsigned int>>
    monitored_pairs(const std::string &text, const joints::NodePairs &pairs)
    {
      std::vector<std::pair<std::string, unsigned int>> result;
      for (const auto &entry : Utilities::split_string_list(text, ';'))
        {
          const auto colon = entry.find(':');
          const auto xyz   = colon == std::string::npos ?
                               std::vector<std::string>() :
                               Utilities::split_string_list(entry.substr(colon + 1), ',');
          if (xyz.size() != dim)
            throw InputError("Contraction joints/Monitor points: '" + entry +
                             "' is not 'name: x, y, z'.");
          Point<dim> x;
          try
            {
              for (unsigned int d = 0; d < dim; ++d)
                x[d] = Utilities::string_to_double(xyz[d]);
            }
          catch (...)
            {
              throw InputError("Contraction joints/Monitor points: '" + entry +
                               "' has a coordinate that is not a number.");
            }
          if (pairs.size() == 0)
            throw InputError("Contraction joints/Monitor points: the model has no joint "
                             "node pairs to monitor.");
          result.emplace_back(Utilities::trim(entry.substr(0, colon)), pairs.nearest(x));
        }
      return result;
    }

    /// Time, then opening and slip of each monitored pair.
    std::vector<std::string>
    history_columns(const std::vector<std::pair<std::string, unsigned int>> &monitored)
    {
      std::vector<std::string> names{"time [s]"};
      for (const auto &[name, pair] : monitored)
        {
          names.push_back(name + ".opening [m]");
          names.push_back(name + ".slip [m]");
        }
      return names;
    }
  } // namespace

  JointOutput::JointOutput(const joints::JointParameters &p, const joints::NodePairs &pairs,
                           const std::string &directory, const std::string &stage,
                           const unsigned int field_interval)
    : HistoryRecorder(directory + "/joint_histories_" + stage + ".csv",
                      history_columns(monitored_pairs(p.monitor_points, pairs)),
                      pairs.communicator())
    , pairs(pairs)
    , directory(directory)
    , stage(stage)
    , writer(Utilities::MPI::this_mpi_process(pairs.communicator()) == 0)
    , field_interval(field_interval)
    , peak_opening(pairs.size(), 0.)
    , peak_time(pairs.size(), 0.)
    , peak_slip(pairs.size(), 0.)
    , peak_slip_time(pairs.size(), 0.)
  {
    for (const auto &[name, pair] : monitored_pairs(p.monitor_points, pairs))
      monitored.push_back(pair);
  }

  void
  JointOutput::start(const StepRecord &s)
  {
    add_row(s.state.time, *s.joints);
    if (field_interval > 0)
      write_fields(s.state.time, *s.joints);
  }

  void
  JointOutput::record(const StepRecord &s)
  {
    add_row(s.state.time, *s.joints);
    if (field_interval > 0 && s.state.step % field_interval == 0)
      write_fields(s.state.time, *s.joints);
  }

  void
  JointOutput::add_row(const double time, const joints::JointSolver &joints)
  {
    std::vector<double> row{time};
    for (const unsigned int i : monitored)
      {
        row.push_back(std::max(0., joints.gap(i)));
        row.push_back(joints.slip(i));
      }
    table.append(row);
    for (unsigned int i = 0; i < pairs.size(); ++i)
      {
        const double gap = joints.gap(i);
        if (gap > peak_opening[i])
          {
            peak_opening[i] = gap;
            peak_time[i]    = time;
          }
        const double slip = joints.slip(i);
        if (slip > peak_slip[i])
          {
            peak_slip[i]      = slip;
            peak_slip_time[i] = time;
          }
        if (-gap > deepest)
          {
            deepest      = -gap;
            deepest_pair = i;
            deepest_time = time;
          }
      }
  }

  void
  JointOutput::save(std::ostream &out) const
  {
    HistoryRecorder::save(out);
    binary::write_all(out, peak_opening, peak_time, peak_slip, peak_slip_time, pvd_records, deepest, deepest_time, deepest_pair);
  }

  void
  JointOutput::load(std::istream &in)
  {
    HistoryRecorder::load(in);
    binary::read_all(in, peak_opening, peak_time, peak_slip, peak_slip_time, pvd_records, deepest, deepest_time, deepest_pair);
    if (peak_opening.size() != pairs.size())
      throw InputError("Checkpoint: the saved joint state has " +
                       std::to_string(peak_opening.size()) + " node pairs, the model " +
                       std::to_string(pairs.size()) + ".");
  }

  void
  JointOutput::write_fields(const double time, const joints::JointSolver &joints)
  {
    if (!writer)
      return;
    const std::string name =
      "joints_" + stage + "_" + Utilities::int_to_string(pvd_records.size(), 4) + ".vtu";
    std::ostringstream vtu;
    const unsigned int n = pairs.size();
    vtu << "<?xml version=\"1.0\"?>\n<VTKFile type=\"UnstructuredGrid\" version=\"0.1\">\n"
        << "<UnstructuredGrid><Piece NumberOfPoints=\"" << n << "\" NumberOfCells=\"" << n
        << "\">\n<Points><DataArray type=\"Float64\" NumberOfComponents=\"3\" "
           "format=\"ascii\">\n"
        << std::setprecision(10);
    for (unsigned int i = 0; i < n; ++i)
      vtu << pairs[i].position << '\n';
    vtu << "</DataArray></Points>\n<Cells>\n<DataArray type=\"Int32\" Name=\"connectivity\" "
           "format=\"ascii\">\n";
    for (unsigned int i = 0; i < n; ++i)
      vtu << i << ' ';
    vtu << "\n</DataArray>\n<DataArray type=\"Int32\" Name=\"offsets\" format=\"ascii\">\n";
    for (unsigned int i = 0; i < n; ++i)
      vtu << i + 1 << ' ';
    vtu << "\n</DataArray>\n<DataArray type=\"UInt8\" Name=\"types\" format=\"ascii\">\n";
    for (unsigned int i = 0; i < n; ++i)
      vtu << "1 "; // VTK_VERTEX
    vtu << "\n</DataArray>\n</Cells>\n<PointData>\n";
    const auto field = [&](const std::string &field_name, auto value) {
      vtu << "<DataArray type=\"Float64\" Name=\"" << field_name << "\" format=\"ascii\">\n";
      for (unsigned int i = 0; i < n; ++i)
        vtu << value(i) << ' ';
      vtu << "\n</DataArray>\n";
    };
    field("joint", [&](unsigned int i) { return pairs[i].joint; });
    field("opening", [&](unsigned int i) { return std::max(0., joints.gap(i)); });
    field("slip", [&](unsigned int i) { return joints.slip(i); });
    field("normal_stress", [&](unsigned int i) { return joints.force[dim * i] / pairs[i].area; });
    field("shear_stress", [&](unsigned int i) {
      return std::hypot(joints.force[dim * i + 1], joints.force[dim * i + 2]) / pairs[i].area;
    });
    field("state", [&](unsigned int i) { return static_cast<int>(joints.state[i]); });
    vtu << "</PointData>\n</Piece></UnstructuredGrid>\n</VTKFile>\n";
    output::write_atomically(directory + "/" + name, [&](std::ostream &f) { f << vtu.str(); });

    pvd_records.emplace_back(time, name);
    output::write_atomically(directory + "/joints_" + stage + ".pvd", [&](std::ostream &pvd) {
      DataOutBase::write_pvd_record(pvd, pvd_records);
    });
  }

  void
  JointOutput::finish(Summary &summary, const dealii::ConditionalOStream &)
  {
    // Envelope along the height: the largest opening at each z of each joint.
    std::map<std::pair<unsigned int, double>, double> along_height;
    std::map<unsigned int, double>                    crest_z;
    for (unsigned int i = 0; i < pairs.size(); ++i)
      {
        const double z   = std::round(pairs[i].position[2] * 1e6) / 1e6;
        auto        &env = along_height[{pairs[i].joint, z}];
        env              = std::max(env, peak_opening[i]);
        crest_z[pairs[i].joint] =
          std::max(crest_z.count(pairs[i].joint) ? crest_z[pairs[i].joint] : -1e300, z);
      }
    std::vector<int> peak_of(pairs.n_joints(), -1), crest_of(pairs.n_joints(), -1),
      slip_of(pairs.n_joints(), -1);
    for (unsigned int i = 0; i < pairs.size(); ++i)
      {
        const unsigned int j = pairs[i].joint;
        if (peak_of[j] < 0 || peak_opening[i] > peak_opening[peak_of[j]])
          peak_of[j] = i;
        if (slip_of[j] < 0 || peak_slip[i] > peak_slip[slip_of[j]])
          slip_of[j] = i;
        if (std::round(pairs[i].position[2] * 1e6) / 1e6 == crest_z[j] &&
            (crest_of[j] < 0 || peak_opening[i] > peak_opening[crest_of[j]]))
          crest_of[j] = i;
      }
    if (writer)
      {
        std::ostringstream env, crest;
        env << "joint,z [m],max opening [m]\n" << std::setprecision(10);
        for (const auto &[key, value] : along_height)
          env << key.first << ',' << key.second << ',' << value << '\n';
        crest << "joint,x [m],y [m],z [m],max opening [m],time [s]\n" << std::setprecision(10);
        for (unsigned int j = 0; j < pairs.n_joints(); ++j)
          if (crest_of[j] >= 0)
            crest << j << ',' << pairs[crest_of[j]].position[0] << ','
                  << pairs[crest_of[j]].position[1] << ',' << pairs[crest_of[j]].position[2]
                  << ',' << peak_opening[crest_of[j]] << ',' << peak_time[crest_of[j]] << '\n';
        for (const auto &[file, text] :
             {std::pair{"/joint_envelopes_", &env}, {"/joint_crest_", &crest}})
          output::write_atomically(directory + file + stage + ".csv",
                                   [&](std::ostream &f) { f << text->str(); });
      }
    for (unsigned int j = 0; j < pairs.n_joints(); ++j)
      if (peak_of[j] >= 0)
        {
          const std::string key = stage + "/joints/joint " + std::to_string(j) + "/peak opening";
          summary.set(key + " [m]", peak_opening[peak_of[j]]);
          summary.set(key + " time [s]", peak_time[peak_of[j]]);
          for (unsigned int d = 0; d < dim; ++d)
            summary.set(key + " " + std::string(1, "xyz"[d]) + " [m]",
                        pairs[peak_of[j]].position[d]);
          const std::string slip = stage + "/joints/joint " + std::to_string(j) + "/peak slip";
          summary.set(slip + " [m]", peak_slip[slip_of[j]]);
          summary.set(slip + " time [s]", peak_slip_time[slip_of[j]]);
        }
    const std::string key = stage + "/joints/largest penetration";
    summary.set(key + " [m]", deepest);
    summary.set(key + " joint", deepest > 0. ? pairs[deepest_pair].joint : 0.);
    summary.set(key + " time [s]", deepest_time);
  }
} // namespace archdam::output
