#pragma once

#include <archdam/fe/fe_space.h>
#include <archdam/time/newmark.h>

#include <vector>

namespace archdam::time
{
  /**
   * The health of each dynamic step (doc/user-guide.md, "When a run stops"). A
   * step fails if
   *  - any entry of u, v or a (displacements and the pressure with its rates)
   *    is NaN or infinite, or
   *  - a displacement exceeds the size of the model, the diagonal L of its
   *    bounding box.
   * The bound cannot fire on a healthy run: the model is linear elastic with
   * small strains, so |u| ~ L means strains of order one (concrete cracks at
   * 1e-4), and the rigid ground displacement of a total-motion run (massed
   * foundation) is at most a few metres against a foundation block hundreds
   * of metres wide. It still catches a divergence within a few steps, because
   * an unstable step amplifies the solution by a fixed factor: from 1 mm to
   * 100 m at a factor 2 per step takes 17 steps. Pressures are not bounded
   * (they are coupled to the displacements of the wetted face, which are).
   * The check costs one pass over the owned entries of u, v, a and one
   * all-reduce per step.
   */
  class DivergenceCheck
  {
  public:
    explicit DivergenceCheck(const fe::FESpace &space);

    /// Throw RunStopped naming the time, the step, the value and where (the
    /// node's position, component and region) if @p s after step @p step
    /// fails the check. Collective: every rank throws the same message.
    void
    check(const NewmarkState &s, unsigned int step) const;

  private:
    /// "component x of u = 3.1e+296 m at the node (x, y, z) m in dam block 1".
    std::string
    describe(dealii::types::global_dof_index dof, const std::string &what,
             double value) const;

    const fe::FESpace &space;
    double             bound;
    /// Per owned DOF (in order): whether it is a pressure.
    std::vector<bool>  is_pressure;
  };
} // namespace archdam::time
