#include <archdam/base/input_error.h>
#include <archdam/base/on_rank_zero.h>
#include <archdam/output/atomic_file.h>
#include <archdam/base/binary_io.h>
#include <archdam/output/pressure_recorder.h>

#include <deal.II/base/mpi.h>
#include <deal.II/base/utilities.h>
#include <deal.II/fe/mapping_q1.h>

#include <algorithm>
#include <fstream>
#include <iomanip>
#include <sstream>

namespace archdam::output
{
  using namespace dealii;

  PressureRecorder::PressureRecorder(const std::string &point_text,
                                     const std::string &profile_times,
                                     const fe::FESpace &space,
                                     const std::string &directory)
    : HistoryRecorder(directory + "/pressure_histories.csv",
                      [&] {
                        std::vector<std::string> names{"time [s]"};
                        for (const auto &pt : parse_monitor_points(point_text))
                          names.push_back(pt.name + ".p [Pa]");
                        return names;
                      }(),
                      space.comm)
    , space(space)
    , points(parse_monitor_points(point_text))
    , directory(directory)
  {
    for (const auto &t : Utilities::split_string_list(profile_times, ','))
      times.push_back(std::stod(t));
    // Every rank holds the whole mesh: all find the same (first) water cell.
    for (const auto &pt : points)
      {
        Weights w;
        for (const auto &cell : space.dof_handler.active_cell_iterators())
          if (cell->active_fe_index() == fe::FESpace::fluid_index)
            {
              BoundingBox<dim> box = cell->bounding_box();
              box.extend(1e-8 * cell->diameter());
              if (!box.point_inside(pt.location))
                continue;
              const Point<dim> u =
                StaticMappingQ1<dim>::mapping.transform_real_to_unit_cell(cell, pt.location);
              if (!GeometryInfo<dim>::is_inside_unit_cell(u, 1e-8))
                continue;
              const auto &fe = cell->get_fe();
              w.dofs.resize(fe.n_dofs_per_cell());
              cell->get_dof_indices(w.dofs);
              for (unsigned int i = 0; i < fe.n_dofs_per_cell(); ++i)
                w.value.push_back(fe.shape_value_component(i, u, fe::FESpace::pressure_comp));
              break;
            }
        if (w.dofs.empty())
          throw InputError("Reservoir/Pressure points: point '" + pt.name +
                           "' lies in no water cell.");
        weights.push_back(w);
      }
  }

  std::vector<double>
  PressureRecorder::evaluate(const Vector &u) const
  {
    std::vector<double> p(points.size(), 0.);
    for (unsigned int k = 0; k < points.size(); ++k)
      for (unsigned int i = 0; i < weights[k].dofs.size(); ++i)
        if (space.locally_owned.is_element(weights[k].dofs[i]))
          p[k] += weights[k].value[i] * u(weights[k].dofs[i]);
    MPI_Allreduce(MPI_IN_PLACE, p.data(), p.size(), MPI_DOUBLE, MPI_SUM, space.comm);
    return p;
  }

  void
  PressureRecorder::record(const StepRecord &s)
  {
    if (points.empty())
      return;
    std::vector<double> row{s.state.time};
    const auto          p = evaluate(s.state.u);
    row.insert(row.end(), p.begin(), p.end());
    table.append(row);
  }

  void
  PressureRecorder::finish(Summary &, const dealii::ConditionalOStream &)
  {
    const auto &rows = table.rows();
    if (points.empty() || rows.empty() || Utilities::MPI::this_mpi_process(space.comm) != 0)
      return;
    // the recorded step nearest to each profile time
    std::vector<unsigned int> at;
    for (const double t : times)
      {
        unsigned int best = 0;
        for (unsigned int r = 0; r < rows.size(); ++r)
          if (std::abs(rows[r][0] - t) < std::abs(rows[best][0] - t))
            best = r;
        at.push_back(best);
      }
    std::ostringstream csv;
    csv << "name,x [m],y [m],z [m]";
    for (const unsigned int r : at)
      csv << ",p at t = " << rows[r][0] << " s [Pa]";
    csv << ",max p [Pa],min p [Pa]\n" << std::setprecision(10);
    for (unsigned int k = 0; k < points.size(); ++k)
      {
        csv << points[k].name;
        for (unsigned int d = 0; d < dim; ++d)
          csv << "," << points[k].location[d];
        double hi = rows[0][k + 1], lo = hi;
        for (const auto &row : rows)
          hi = std::max(hi, row[k + 1]), lo = std::min(lo, row[k + 1]);
        for (const unsigned int r : at)
          csv << "," << rows[r][k + 1];
        csv << "," << hi << "," << lo << "\n";
      }
    write_atomically(directory + "/pressure_profile.csv",
                     [&](std::ostream &f) { f << csv.str(); });
  }
} // namespace archdam::output
