#pragma once

#include <archdam/fe/fe_space.h>
#include <archdam/geometry/dam_surface.h>
#include <archdam/output/face_evaluation.h>
#include <archdam/output/recorder.h>
#include <archdam/physics/solid/materials.h>
#include <archdam/physics/solid/thermal.h>

#include <deal.II/base/point.h>
#include <deal.II/base/tensor.h>

#include <array>
#include <functional>
#include <iosfwd>
#include <string>
#include <vector>

namespace archdam::output
{
  /**
   * The stress envelope on the dam faces (doc/theory/results.md §3): at every point of
   * the dam's surface, the largest major principal stress s1 and the smallest
   * (most compressive) minor principal stress s3 over the dynamic stage, with
   * the time of each. The stage's initial state (t = 0, the static state when
   * the static stage ran) counts, as it does for the monitor histories; a tie
   * keeps the earlier time.
   *
   * The points are the face quadrature points (QGauss(degree + 1), the rule of
   * the surface loads) of the dam cells' faces that carry boundary id 0 (free
   * surface) or 7 (wetted face, doc/theory/conventions.md §5): inside a face, so each
   * point belongs to exactly one dam cell and its stress has one value. Joint
   * faces (ids 100 + 2k, 101 + 2k from the splitter), the dam-rock interface
   * (an interior face) and a truncated base (ids 1, 2) are never taken.
   *
   * Each face belongs to one part of the surface, from the outward normal
   * averaged over the face (geometry::surface_part()).
   *
   * The stress is Hooke's law of the displacement gradient, as for the
   * fields (physics/solid/stress.h). The geometry is fixed, so what the
   * gradient needs besides the DOF values is computed once: at each point the
   * inverse Jacobian of the cell map, and the shape gradients on the unit
   * cell (the same for every face with the same face number). An update is
   * then grad u = (sum_i u_i grad_unit phi_i) J^-1, a few multiply-adds per
   * DOF. Each rank updates the points of the faces of its own cells; the
   * results are gathered at the end.
   *
   * The largest s1 over all points is also the run's peak major principal
   * stress in the dam (summary: peaks/major principal stress in the dam):
   * taken every step, so it does not depend on the field output interval.
   */
  class StressEnvelope : public Recorder
  {
  public:
    using Part = geometry::SurfacePart;

    /// The largest and smallest value of one stress over the stage, with
    /// their times (a tie keeps the earlier).
    struct Extremes
    {
      double max = 0., time_max = 0., min = 0., time_min = 0.;
      /// Take @p value at @p time (@p first: the first value taken).
      void
      take(double value, double time, bool first);
    };

    struct Entry
    {
      Part               part;
      dealii::Point<dim> where;
      double             max_s1 = 0., time_max_s1 = 0.;
      double             min_s3 = 0., time_min_s3 = 0.;
      /// The normal stresses along the face's horizontal tangent (arch) and
      /// along the tangent normal to it (cantilever), upstream and
      /// downstream faces only (zero elsewhere; face_directions()).
      Extremes arch, cantilever;
      /// The point's share of its face's area [m^2] (its quadrature weight).
      double weight = 0.;
      /// With `Evaluation/Evaluate`: the arch's and the cantilever's DCR and
      /// cumulative inelastic durations (face_evaluation.h).
      Exceedance arch_demand, cantilever_demand;
      /// The tensile strength the arch's DCR is measured against: the
      /// concrete's, or a contraction joint's within the joint band.
      double arch_capacity = 0.;
      /// Whether the point counts in the evaluation (not in the band left
      /// out at the base).
      bool evaluated = true;
    };

    /// The arch direction of a face with unit outward normal @p n, its
    /// horizontal tangent e_z x n / |e_z x n|, and the cantilever direction
    /// n x arch, the tangent in the face normal to it (doc/theory/results.md
    /// §3); for a normal within 45 degrees of the vertical (crest), where
    /// the face has no horizontal tangent of its own, both zero.
    static std::pair<dealii::Tensor<1, dim>, dealii::Tensor<1, dim>>
    face_directions(const dealii::Tensor<1, dim> &n);

    /// With @p evaluation (its Evaluate set), also the demand-capacity
    /// evaluation of the arch and cantilever stresses, the arch stress
    /// within the joint band of joint k against @p joint_tensile_strength(k)
    /// (InputError if that is not positive). The stress is C (eps - alpha dT
    /// I) with the dam's temperature change @p temperature.
    StressEnvelope(const fe::FESpace &space, const physics::solid::MaterialParameters &materials,
                   const physics::solid::TemperatureField &temperature,
                   const std::string &directory, const EvaluationParameters &evaluation = {},
                   const std::function<double(unsigned int)> &joint_tensile_strength = {});

    std::string
    name() const override
    {
      return "stress envelope";
    }
    /// Take the state into the envelope. Collective (ghost exchange).
    void
    record(const StepRecord &s) override;

    /// Every rank's entries on every rank, ordered by part, then z, y, x (the
    /// same order for any number of ranks). Collective.
    std::vector<Entry>
    gather() const;

    /**
     * Write `stress_envelope_dynamic.csv` in the output directory (rank 0,
     * atomically), the extremes of each part into @p summary under "stress
     * envelope/" and the largest s1 of all under "peaks/". Collective.
     */
    void
    finish(Summary &summary, const dealii::ConditionalOStream &screen) override;

    /// The extremes so far on this rank, for a checkpoint (output/checkpoint.h).
    void
    save(std::ostream &out) const override;
    void
    load(std::istream &in) override;

  private:
    struct Face
    {
      std::vector<dealii::types::global_dof_index> dofs;
      physics::solid::ElasticMaterial              material;
      unsigned int                                 face_no;
      unsigned int                                 first_entry;
    };

    /// The demand-capacity evaluation of @p part into @p summary under @p
    /// key; with the verdict asked for, the limits exceeded are appended to
    /// @p beyond.
    void
    summarize_demand(const std::vector<Entry> &all, Part part, const std::string &key,
                     Summary &summary, std::vector<std::string> &beyond) const;

    const fe::FESpace        &space;
    std::string               directory;
    EvaluationParameters      evaluation;
    /// The time of the last state taken.
    double                    t_prev = 0.;
    std::vector<Face>         faces;
    std::vector<Entry>        entries; // this rank's points
    /// The temperature change at each entry's point.
    std::vector<double>       temperature_changes;
    /// d(unit coordinates)/dx at each entry's point.
    std::vector<dealii::Tensor<2, dim>> inverse_jacobians;
    /// The arch and cantilever directions at each entry's point.
    std::vector<std::pair<dealii::Tensor<1, dim>, dealii::Tensor<1, dim>>> directions;
    /// Unit-cell shape gradients [face number][point][local DOF], and the
    /// displacement component of each local DOF.
    std::array<std::vector<std::vector<dealii::Tensor<1, dim>>>, 6> unit_gradients;
    std::vector<unsigned int> component;
    Vector                    ghosted_u;
    bool                      started = false;
  };
} // namespace archdam::output
