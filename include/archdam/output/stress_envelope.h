#pragma once

#include <archdam/fe/fe_space.h>
#include <archdam/output/summary.h>
#include <archdam/physics/solid/materials.h>

#include <deal.II/base/point.h>
#include <deal.II/dofs/dof_handler.h>

namespace dealii
{
  template <int dim, int spacedim>
  class FEFaceValues;
}

#include <memory>
#include <string>
#include <vector>

namespace archdam::output
{
  /**
   * The stress envelope on the dam faces (numerics.md §7): at every point of
   * the dam's surface, the largest major principal stress s1 and the smallest
   * (most compressive) minor principal stress s3 over the dynamic stage, with
   * the time of each. The stage's initial state (t = 0, the static state when
   * the static stage ran) counts, as it does for the monitor histories; a tie
   * keeps the earlier time.
   *
   * The points are the face quadrature points (QGauss(degree + 1), the rule of
   * the surface loads) of the dam cells' faces that carry boundary id 0 (free
   * surface) or 7 (wetted face, architecture.md §3): inside a face, so each
   * point belongs to exactly one dam cell and its stress has one value. Joint
   * faces (ids 100 + 2k, 101 + 2k from the splitter), the dam-rock interface
   * (an interior face) and a truncated base (ids 1, 2) are never taken.
   *
   * Each face belongs to one part of the surface, from the outward normal n
   * averaged over the face (axes of architecture.md §3):
   *  - crest:      n_z is the largest component (the normal within about 45
   *                degrees of the vertical);
   *  - upstream:   otherwise, n_x <= -0.1;
   *  - downstream: otherwise, n_x >= 0.1;
   *  - side:       the rest, faces that look across the stream or down (the
   *                free ends of a box model; an arch dam has none).
   *
   * The stress is Hooke's law of the displacement gradient, as for the
   * fields (physics/solid/stress.h). Each rank updates the points of the
   * faces of its own cells; the results are gathered at the end.
   */
  class StressEnvelope
  {
  public:
    enum class Part
    {
      upstream,
      downstream,
      crest,
      side
    };
    static std::string
    name(Part part);

    struct Entry
    {
      Part               part;
      dealii::Point<dim> where;
      double             max_s1 = 0., time_max_s1 = 0.;
      double             min_s3 = 0., time_min_s3 = 0.;
    };

    StressEnvelope(const fe::FESpace &space, const physics::solid::MaterialParameters &materials);
    ~StressEnvelope();

    /// Take the state @p u (a distributed vector) at time @p t into the
    /// envelope. Collective (ghost exchange).
    void
    update(const Vector &u, double t);

    /// Every rank's entries on every rank, ordered by part, then z, y, x (the
    /// same order for any number of ranks). Collective.
    std::vector<Entry>
    gather() const;

    /**
     * Write `stress_envelope_dynamic.csv` in @p directory (rank 0, atomically)
     * and the extremes of each part into @p summary under "stress envelope/".
     * Collective.
     */
    void
    write(const std::string &directory, Summary &summary) const;

  private:
    struct Face
    {
      dealii::DoFHandler<dim>::active_cell_iterator cell;
      unsigned int                                  face_no;
      unsigned int                                  first_entry;
    };

    const fe::FESpace                        &space;
    const physics::solid::MaterialParameters &materials;
    std::vector<Face>                         faces;
    std::vector<Entry>                        entries; // this rank's points
    Vector                                    ghosted_u;
    std::unique_ptr<dealii::FEFaceValues<dim, dim>> face_values;
    bool                                      started = false;
  };
} // namespace archdam::output
