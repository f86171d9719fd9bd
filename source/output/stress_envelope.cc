#include <archdam/base/binary_io.h>
#include <archdam/base/input_error.h>
#include <archdam/base/on_rank_zero.h>
#include <archdam/geometry/ids.h>
#include <archdam/output/atomic_file.h>
#include <archdam/output/stress_envelope.h>

#include <deal.II/base/mpi.h>
#include <deal.II/base/qprojector.h>
#include <deal.II/fe/fe_values.h>

#include <algorithm>
#include <cmath>
#include <iomanip>
#include <memory>
#include <sstream>
#include <tuple>

namespace archdam::output
{
  using namespace dealii;

  namespace
  {
    /// Part, x, y, z, max s1, its time, min s3, its time, the arch's and
    /// the cantilever's extremes, the weight, and the arch's and the
    /// cantilever's largest DCR and durations: gathered as doubles.
    constexpr unsigned int values_per_entry = 19 + 2 * (1 + n_dcr_levels);
  } // namespace

  void
  StressEnvelope::Extremes::take(const double value, const double time, const bool first)
  {
    if (first || value > max)
      {
        max      = value;
        time_max = time;
      }
    if (first || value < min)
      {
        min      = value;
        time_min = time;
      }
  }

  std::pair<Tensor<1, dim>, Tensor<1, dim>>
  StressEnvelope::face_directions(const Tensor<1, dim> &n)
  {
    if (geometry::surface_part(n) == Part::crest)
      return {};
    const Tensor<1, dim> arch = cross_product_3d(Point<dim>(0, 0, 1), n);
    const double         length = arch.norm();
    if (length < 1e-12)
      return {};
    return {arch / length, cross_product_3d(n, arch / length)};
  }

  StressEnvelope::StressEnvelope(const fe::FESpace                        &space,
                                 const physics::solid::MaterialParameters &materials,
                                 const physics::solid::TemperatureField   &temperature,
                                 const std::string                        &directory,
                                 const EvaluationParameters               &evaluation,
                                 const std::function<double(unsigned int)> &joint_tensile_strength)
    : space(space)
    , directory(directory)
    , evaluation(evaluation)
  {
    const auto &fe = space.fe_collection[fe::FESpace::solid_index];
    const auto &q  = space.face_q_collection[fe::FESpace::solid_index];
    for (unsigned int i = 0; i < fe.dofs_per_cell; ++i)
      component.push_back(fe.system_to_component_index(i).first);
    // Per face number: the face's points on the unit cell, the shape
    // gradients there, and an FEValues that maps them onto a cell.
    std::vector<std::unique_ptr<FEValues<dim>>> at_face;
    for (const unsigned int f : GeometryInfo<dim>::face_indices())
      {
        const Quadrature<dim> points =
          QProjector<dim>::project_to_face(ReferenceCells::Hexahedron, q, f);
        at_face.push_back(std::make_unique<FEValues<dim>>(
          fe, points, update_quadrature_points | update_inverse_jacobians));
        unit_gradients[f].resize(points.size());
        for (unsigned int k = 0; k < points.size(); ++k)
          for (unsigned int i = 0; i < fe.dofs_per_cell; ++i)
            unit_gradients[f][k].push_back(fe.shape_grad(i, points.point(k)));
      }
    // The normals at the face rule's points, in the order of at_face[f]'s.
    FEFaceValues<dim> normals(fe, q, update_normal_vectors | update_JxW_values);
    // The lines where the surface meets the rock and the joints, for the
    // bands of the evaluation.
    const std::unique_ptr<const geometry::SurfaceEdges> edges =
      evaluation.evaluate && (evaluation.base_band > 0. || evaluation.joint_band > 0.) ?
        std::make_unique<const geometry::SurfaceEdges>(space.dof_handler.get_triangulation()) :
        nullptr;
    // A joint without tensile strength in the band: 1 + its number (0: none).
    unsigned int without_strength = 0;
    const auto   evaluate_at      = [&](Entry &e) {
      e.arch_capacity = evaluation.tensile_strength;
      if (!edges)
        return;
      e.evaluated = !(edges->to_base(e.where) < evaluation.base_band);
      if (const auto [joint, d] = edges->nearest_joint(e.where); d < evaluation.joint_band)
        {
          e.arch_capacity = joint_tensile_strength ? joint_tensile_strength(joint) : 0.;
          if (!(e.arch_capacity > 0.))
            without_strength = std::max(without_strength, joint + 1);
        }
    };

    for (const auto &cell : space.dof_handler.active_cell_iterators())
      if (cell->is_locally_owned() && ids::is_dam(cell->material_id()))
        for (const unsigned int f : cell->face_indices())
          if (cell->face(f)->at_boundary() && geometry::on_dam_surface(cell->face(f)->boundary_id()))
            {
              normals.reinit(cell, f);
              Tensor<1, dim> mean_normal;
              for (const unsigned int k : normals.quadrature_point_indices())
                mean_normal += normals.normal_vector(k);
              const Part part = geometry::surface_part(mean_normal / mean_normal.norm());

              Face face{std::vector<types::global_dof_index>(fe.dofs_per_cell),
                        materials.of(cell->material_id()), f,
                        static_cast<unsigned int>(entries.size())};
              cell->get_dof_indices(face.dofs);
              faces.push_back(face);
              at_face[f]->reinit(cell);
              for (const unsigned int k : at_face[f]->quadrature_point_indices())
                {
                  entries.push_back({part, at_face[f]->quadrature_point(k)});
                  entries.back().weight = normals.JxW(k);
                  evaluate_at(entries.back());
                  inverse_jacobians.push_back(Tensor<2, dim>(at_face[f]->inverse_jacobian(k)));
                  temperature_changes.push_back(
                    temperature.change(cell->material_id(), at_face[f]->quadrature_point(k)));
                  directions.push_back(face_directions(normals.normal_vector(k)));
                }
            }
    // Every process stops alike (the joint's points may all be on one).
    without_strength = Utilities::MPI::max(without_strength, space.comm);
    if (without_strength > 0)
      throw InputError("Evaluation/Joint band width measures the arch stress near joint " +
                       std::to_string(without_strength - 1) + " against its tensile strength, " +
                       "which is not positive (Contraction joints/Tensile strength or Per joint): " +
                       "give it one, or set the band to 0.");
    space.reinit_ghosted(ghosted_u);
  }

  void
  StressEnvelope::record(const StepRecord &s)
  {
    const double t = s.state.time;
    ghosted_u      = s.state.u;
    std::vector<double> values(component.size());
    for (const Face &face : faces)
      {
        ghosted_u.extract_subvector_to(face.dofs.begin(), face.dofs.end(), values.begin());
        const auto &gradients = unit_gradients[face.face_no];
        for (unsigned int k = 0; k < gradients.size(); ++k)
          {
            // grad u = (sum_i u_i grad_unit phi_i) J^-1: row c is component c.
            Tensor<2, dim> unit_gradient;
            for (unsigned int i = 0; i < values.size(); ++i)
              unit_gradient[component[i]] += values[i] * gradients[k][i];
            Entry &e = entries[face.first_entry + k];
            // Hooke's law and the principal stresses (doc/theory/solid.md §6).
            const SymmetricTensor<2, dim> sigma = face.material.stress(
              symmetrize(unit_gradient * inverse_jacobians[face.first_entry + k]),
              temperature_changes[face.first_entry + k]);
            const auto [s1, s3] = physics::solid::principal_stresses(sigma);
            const auto &[arch, cantilever] = directions[face.first_entry + k];
            const double sa = arch * (sigma * arch), sc = cantilever * (sigma * cantilever);
            e.arch.take(sa, t, !started);
            e.cantilever.take(sc, t, !started);
            if (evaluation.evaluate)
              {
                const double dt = started ? t - t_prev : 0.;
                e.arch_demand.add(sa / e.arch_capacity, dt, evaluation.levels);
                e.cantilever_demand.add(sc / evaluation.tensile_strength, dt, evaluation.levels);
              }
            if (!started || s1 > e.max_s1)
              {
                e.max_s1      = s1;
                e.time_max_s1 = t;
              }
            if (!started || s3 < e.min_s3)
              {
                e.min_s3      = s3;
                e.time_min_s3 = t;
              }
          }
      }
    started = true;
    t_prev  = t;
  }

  std::vector<StressEnvelope::Entry>
  StressEnvelope::gather() const
  {
    std::vector<double> local;
    local.reserve(values_per_entry * entries.size());
    for (const Entry &e : entries)
      {
        local.insert(local.end(), {static_cast<double>(e.part), e.where[0], e.where[1],
                                   e.where[2], e.max_s1, e.time_max_s1, e.min_s3,
                                   e.time_min_s3, e.arch.max, e.arch.time_max, e.arch.min,
                                   e.arch.time_min, e.cantilever.max, e.cantilever.time_max,
                                   e.cantilever.min, e.cantilever.time_min, e.weight,
                                   e.arch_capacity, e.evaluated ? 1. : 0.});
        for (const Exceedance *x : {&e.arch_demand, &e.cantilever_demand})
          {
            local.push_back(x->largest_dcr);
            local.insert(local.end(), x->duration.begin(), x->duration.end());
          }
      }
    std::vector<Entry> all;
    for (const auto &from_rank : Utilities::MPI::all_gather(space.comm, local))
      for (std::size_t i = 0; i < from_rank.size(); i += values_per_entry)
        {
          const double *v = &from_rank[i];
          all.push_back({static_cast<Part>(static_cast<int>(v[0])), Point<dim>(v[1], v[2], v[3]),
                         v[4], v[5], v[6], v[7], {v[8], v[9], v[10], v[11]},
                         {v[12], v[13], v[14], v[15]}, v[16]});
          all.back().arch_capacity = v[17];
          all.back().evaluated     = v[18] > 0.5;
          v += 19;
          for (Exceedance *x : {&all.back().arch_demand, &all.back().cantilever_demand})
            {
              x->largest_dcr = *v++;
              std::copy(v, v + n_dcr_levels, x->duration.begin());
              v += n_dcr_levels;
            }
        }
    std::sort(all.begin(), all.end(), [](const Entry &a, const Entry &b) {
      return std::make_tuple(a.part, a.where[2], a.where[1], a.where[0]) <
             std::make_tuple(b.part, b.where[2], b.where[1], b.where[0]);
    });
    return all;
  }

  void
  StressEnvelope::finish(Summary &summary, const dealii::ConditionalOStream &screen)
  {
    std::vector<std::string> beyond; // the verdict's limits exceeded
    const std::vector<Entry> all = gather();
    on_rank_zero(space.comm, [&] {
      write_atomically(directory + "/stress_envelope_dynamic.csv", [&](std::ostream &out) {
        out << "face,x [m],y [m],z [m],max s1 [Pa],time of max s1 [s],min s3 [Pa],"
               "time of min s3 [s],max arch [Pa],time of max arch [s],min arch [Pa],"
               "time of min arch [s],max cantilever [Pa],time of max cantilever [s],"
               "min cantilever [Pa],time of min cantilever [s]";
        if (evaluation.evaluate)
          for (const std::string what : {"arch", "cantilever"})
            {
              out << ",largest " << what << " DCR";
              for (const double level : evaluation.levels)
                out << "," << what << " CID above DCR " << level << " [s]";
            }
        if (evaluation.evaluate)
          out << ",arch capacity [Pa],evaluated";
        out << ",area [m^2]\n" << std::setprecision(10);
        for (const Entry &e : all)
          {
            out << geometry::name(e.part) << ',' << e.where[0] << ',' << e.where[1] << ',' << e.where[2]
                << ',' << e.max_s1 << ',' << e.time_max_s1 << ',' << e.min_s3 << ','
                << e.time_min_s3;
            for (const Extremes *x : {&e.arch, &e.cantilever})
              out << ',' << x->max << ',' << x->time_max << ',' << x->min << ',' << x->time_min;
            if (evaluation.evaluate)
              for (const Exceedance *x : {&e.arch_demand, &e.cantilever_demand})
                {
                  out << ',' << x->largest_dcr;
                  for (const double d : x->duration)
                    out << ',' << d;
                }
            if (evaluation.evaluate)
              out << ',' << e.arch_capacity << ',' << (e.evaluated ? 1 : 0);
            out << ',' << e.weight << '\n';
          }
      });
    });

    // The extremes of each part, with place and time (the same on every rank).
    const auto place = [&](const std::string &key, const double value, const double time,
                           const Point<dim> &where) {
      summary.set(key + "/value", value);
      summary.set(key + "/time [s]", time);
      for (unsigned int d = 0; d < dim; ++d)
        summary.set(key + "/" + std::string(1, "xyz"[d]) + " [m]", where[d]);
    };
    for (const Part part : {Part::upstream, Part::downstream, Part::crest, Part::side})
      {
        const Entry *largest = nullptr, *smallest = nullptr;
        unsigned int n       = 0;
        for (const Entry &e : all)
          if (e.part == part)
            {
              ++n;
              if (!largest || e.max_s1 > largest->max_s1)
                largest = &e;
              if (!smallest || e.min_s3 < smallest->min_s3)
                smallest = &e;
            }
        if (n == 0)
          continue;
        const std::string key = "stress envelope/" + geometry::name(part) + "/";
        summary.set(key + "points", n);
        place(key + "max major principal stress [Pa]", largest->max_s1, largest->time_max_s1,
              largest->where);
        place(key + "min minor principal stress [Pa]", smallest->min_s3, smallest->time_min_s3,
              smallest->where);
        if (part != Part::upstream && part != Part::downstream)
          continue;
        for (const auto &[what, of] :
             {std::pair<std::string, Extremes Entry::*>{"arch", &Entry::arch},
              {"cantilever", &Entry::cantilever}})
          {
            const auto tension = std::max_element(all.begin(), all.end(), [&](const Entry &a, const Entry &b) {
              return (a.part != part ? -HUGE_VAL : (a.*of).max) < (b.part != part ? -HUGE_VAL : (b.*of).max);
            });
            const auto compression = std::min_element(all.begin(), all.end(), [&](const Entry &a, const Entry &b) {
              return (a.part != part ? HUGE_VAL : (a.*of).min) < (b.part != part ? HUGE_VAL : (b.*of).min);
            });
            place(key + "largest " + what + " stress [Pa]", ((*tension).*of).max,
                  ((*tension).*of).time_max, tension->where);
            place(key + "smallest " + what + " stress [Pa]", ((*compression).*of).min,
                  ((*compression).*of).time_min, compression->where);
          }
        if (evaluation.evaluate)
          summarize_demand(all, part, key, summary, beyond);
      }
    if (evaluation.judges())
      {
        // EM 1110-2-6053's reading of a linear analysis (doc/theory/results.md §3).
        const std::string verdict =
          beyond.empty() ? "within the limits of a linear analysis" :
                           "beyond the limits of a linear analysis: a nonlinear analysis is needed";
        summary.set("evaluation/verdict", verdict);
        std::string reasons;
        for (const std::string &b : beyond)
          reasons += (reasons.empty() ? "" : "; ") + b;
        summary.set("evaluation/limits exceeded", reasons);
        screen << "Evaluation: " << verdict << (beyond.empty() ? "" : " (" + reasons + ")") << "."
               << std::endl;
      }
    const auto peak = std::max_element(all.begin(), all.end(), [](const Entry &a, const Entry &b) {
      return a.max_s1 < b.max_s1;
    });
    if (peak == all.end())
      return;
    const std::string key = "peaks/major principal stress in the dam [Pa]";
    place(key, peak->max_s1, peak->time_max_s1, peak->where);
    summary.set(key + "/note", "the largest over the dam's surface points of the stress "
                               "envelope, every step");
  }

  void
  StressEnvelope::summarize_demand(const std::vector<Entry> &all, const Part part,
                                   const std::string &key, Summary &summary,
                                   std::vector<std::string> &beyond) const
  {
    // Per stress: the largest DCR, the longest CID at each level, and the
    // share of the part's evaluated area whose largest DCR exceeds each level
    // (and 1, for the verdict).
    double area = 0., left_out = 0.;
    for (const Entry &e : all)
      if (e.part == part)
        (e.evaluated ? area : left_out) += e.weight;
    summary.set(key + "evaluated area [m^2]", area);
    summary.set(key + "area left out at the base [m^2]", left_out);
    struct Stress
    {
      std::string       what;
      Exceedance Entry::*of;
      Extremes Entry::  *stress;
    };
    for (const auto &[what, of, stress] :
         {Stress{"arch", &Entry::arch_demand, &Entry::arch},
          Stress{"cantilever", &Entry::cantilever_demand, &Entry::cantilever}})
      {
        FaceDemand                        d;
        std::array<double, n_dcr_levels> overstressed{};
        double                            above_one = 0.;
        for (const Entry &e : all)
          if (e.part == part && e.evaluated)
            {
              const Exceedance &x = e.*of;
              d.largest_dcr       = std::max(d.largest_dcr, x.largest_dcr);
              for (unsigned int i = 0; i < n_dcr_levels; ++i)
                {
                  d.longest_cid[i] = std::max(d.longest_cid[i], x.duration[i]);
                  if (x.largest_dcr > evaluation.levels[i])
                    overstressed[i] += e.weight;
                }
              if (x.largest_dcr > 1.)
                above_one += e.weight;
            }
        d.share_above_one   = area > 0. ? above_one / area : 0.;
        const std::string k = key + what + " DCR/";
        summary.set(k + "largest", d.largest_dcr);
        summary.set(k + "overstressed share of the area above 1", d.share_above_one);
        if (evaluation.compressive_strength > 0.)
          {
            // The largest compression of this stress on the part.
            double compression = 0.;
            for (const Entry &e : all)
              if (e.part == part && e.evaluated)
                compression = std::max(compression, -(e.*stress).min);
            summary.set(key + what + " compression to the compressive strength",
                        compression / evaluation.compressive_strength);
          }
        for (unsigned int i = 0; i < n_dcr_levels; ++i)
          {
            std::ostringstream level;
            level << evaluation.levels[i];
            summary.set(k + "above " + level.str() + "/longest CID [s]", d.longest_cid[i]);
            summary.set(k + "above " + level.str() + "/overstressed share of the area",
                        area > 0. ? overstressed[i] / area : 0.);
          }
        if (!evaluation.judges())
          continue;
        const auto exceeded = exceeded_limits(d, evaluation);
        summary.set(k + "verdict", exceeded.empty() ? "within the limits" : "beyond the limits");
        for (const std::string &x : exceeded)
          beyond.push_back(geometry::name(part) + " " + what + ": " + x);
      }
  }

  void
  StressEnvelope::save(std::ostream &out) const
  {
    binary::write_all(out, entries, started, t_prev);
  }

  void
  StressEnvelope::load(std::istream &in)
  {
    const auto n = entries.size();
    binary::read_all(in, entries, started, t_prev);
    if (entries.size() != n)
      throw InputError("Checkpoint: the saved stress envelope has " +
                       std::to_string(entries.size()) + " points on this process, the model " +
                       std::to_string(n) + ".");
  }
} // namespace archdam::output
