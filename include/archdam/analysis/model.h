#pragma once

#include <archdam/fe/fe_space.h>
#include <archdam/joints/joint_faces.h>
#include <archdam/joints/node_pairs.h>
#include <archdam/loads/ground_motion.h>
#include <archdam/output/monitors.h>
#include <archdam/output/summary.h>
#include <archdam/parameters/parameters.h>
#include <archdam/physics/foundation/massed_foundation.h>
#include <archdam/physics/foundation/reference_motion.h>
#include <archdam/physics/reservoir/fluid_operators.h>
#include <archdam/physics/solid/solid_operators.h>
#include <archdam/physics/solid/thermal.h>

#include <deal.II/base/conditional_ostream.h>
#include <deal.II/distributed/shared_tria.h>

#include <array>
#include <memory>
#include <vector>

namespace archdam::analysis
{
  /**
   * The model a case describes, built once before the stages run
   * (doc/theory/conventions.md §1): the mesh with its joints and water, the
   * finite element space, the solid's M and K (Westergaard's added mass and
   * the foundation's boundary springs included), the water's operators, the
   * static and influence loads, the ground motion, the massed foundation's
   * free field and outer boundary, the joints' node pairs and the monitor
   * points. The stages (simulation.h) read it; only the outer boundary keeps
   * a state of its own (the histories of its transmitting formula).
   */
  class Model
  {
  public:
    /// Build everything, saying what was built on @p screen and putting the
    /// mesh report into @p summary.
    Model(const Parameters &p, MPI_Comm comm, const dealii::ConditionalOStream &screen,
          output::Summary &summary);

    /// The model mesh as the case describes it, water included
    /// (geometry::build_model_mesh()), with its report on @p screen and in
    /// @p summary, and checked for the static stage (check_static_support());
    /// first its size against the machine's memory, with the factorization
    /// of a run that @p solves (geometry::check_model_size()).
    static void
    build_mesh(const Parameters &p, const dealii::ConditionalOStream &screen,
               output::Summary &summary, dealii::Triangulation<dim> &mesh, bool solves);

    const dealii::Triangulation<dim> &
    triangulation() const
    {
      return mesh;
    }
    const fe::FESpace &
    space() const
    {
      return *fe_space;
    }
    const SparseMatrix &
    mass() const
    {
      return mass_matrix;
    }
    const SparseMatrix &
    stiffness() const
    {
      return stiffness_matrix;
    }
    /// The damping matrix D assembled with each material's coefficients
    /// (doc/theory/solid.md §4) when the rock has a damping of its own, else
    /// null: D = alpha M + beta K of the whole model, never assembled.
    const SparseMatrix *
    damping() const
    {
      return damping_matrix.m() > 0 ? &damping_matrix : nullptr;
    }
    /// D_dam, the dam's own damping matrix (doc/theory/solid.md §4), for
    /// the energy balance's damping in the dam; null without damping.
    const SparseMatrix *
    dam_damping() const
    {
      return dam_damping_matrix.m() > 0 ? &dam_damping_matrix : nullptr;
    }
    /// On massed rock with the dam's mass term relative to the ground
    /// (`Damping/Mass proportional term`): the reference motion v_r, else null.
    const physics::foundation::ReferenceMotion *
    reference_motion() const
    {
      return reference.get();
    }
    /// alpha_d M_dam iota_d, d = x, y, z: the load v_r,d(t) alpha_d M_dam iota_d
    /// that makes the dam's mass term act on v - iota v_r (with
    /// reference_motion() only).
    const std::array<Vector, dim> &
    reference_loads() const
    {
      return reference_forces;
    }
    /// Free M, D and K, once a system that holds them in its blocks (the
    /// coupled dam-water system) replaces them for the rest of the run:
    /// mass(), damping() and stiffness() are empty from then on.
    void
    release_solid_matrices()
    {
      mass_matrix.clear();
      stiffness_matrix.clear();
      damping_matrix.clear();
    }
    /// F_static: self-weight, hydrostatic pressure and the temperature
    /// change's load as the case asks.
    const Vector &
    static_load() const
    {
      return static_forces;
    }
    /// The self-weight part of F_static (the dam's, and the rock's if asked).
    const Vector &
    self_weight() const
    {
      return weight_forces;
    }
    /// M iota_d of the relative formulation, d = x, y, z (doc/theory/foundation.md §2).
    const std::array<Vector, dim> &
    influence_loads() const
    {
      return influence;
    }
    /// The water's operators (compressible and incompressible models), else null.
    const physics::reservoir::FluidOperators *
    fluid() const
    {
      return fluid_operators.get();
    }
    /// The dam-water and rock-water face pairs (water with a pressure only).
    const std::vector<physics::reservoir::InterfacePair> &
    interface_pairs() const
    {
      return interfaces;
    }
    const loads::GroundMotion &
    ground_motion() const
    {
      return *motion;
    }
    /// The rock's damping as the massed foundation's free field sees it
    /// (`Foundation/Free field`, `Band limit`, the rock's coefficients of
    /// `Damping`).
    static physics::foundation::FreeFieldDamping
    free_field_damping(const Parameters &p);
    /// How much later than the record the ground motion reaches the free
    /// surface: on massed rock the longest travel time of the free field
    /// from the model's bottom (FreeField::delay()), else 0.
    double
    ground_motion_delay() const;
    /// The massed foundation's outer boundary, else null.
    physics::foundation::MassedFoundation *
    foundation()
    {
      return massed_foundation.get();
    }
    const physics::foundation::MassedFoundation *
    foundation() const
    {
      return massed_foundation.get();
    }
    /// The dam's temperature change since grouting (empty without
    /// `Static loads/Temperature change`): every stress is C (eps - alpha dT I).
    const physics::solid::TemperatureField &
    temperature() const
    {
      return temperature_change;
    }
    const output::Monitors &
    monitors() const
    {
      return *monitor;
    }
    /// The joints' node pairs (Contraction joints/Model = frictional), else null.
    const joints::NodePairs *
    joint_pairs() const
    {
      return node_pairs.get();
    }

  private:
    /// The static stage with frictional joints and the mixed method needs
    /// every dam block held by more than its joints: an InputError naming
    /// the blocks that are not (geometry/support.h).
    static void
    check_static_support(const Parameters &p, const dealii::Triangulation<dim> &mesh);
    /// Massed foundation (doc/theory/foundation.md §3-§4): free field from the
    /// ground motion and the transmitting boundary.
    void
    setup_massed_foundation(const Parameters &p, physics::solid::InertiaOf inertia,
                            const dealii::ConditionalOStream &screen);

    dealii::parallel::shared::Triangulation<dim>           mesh;
    std::vector<joints::JointFacePair>                     joint_faces;
    std::unique_ptr<fe::FESpace>                           fe_space;
    SparseMatrix                                           mass_matrix, stiffness_matrix,
      damping_matrix, dam_damping_matrix;
    physics::solid::TemperatureField                       temperature_change;
    Vector                                                 static_forces, weight_forces;
    std::array<Vector, dim>                                influence;
    std::vector<physics::reservoir::InterfacePair>         interfaces;
    std::unique_ptr<physics::reservoir::FluidOperators>    fluid_operators;
    std::unique_ptr<loads::GroundMotion>                   motion;
    std::unique_ptr<physics::foundation::FreeField>        free_field;
    std::unique_ptr<physics::foundation::MassedFoundation> massed_foundation;
    std::unique_ptr<physics::foundation::ReferenceMotion>  reference;
    std::array<Vector, dim>                                reference_forces;
    std::unique_ptr<output::Monitors>                      monitor;
    std::unique_ptr<joints::NodePairs>                     node_pairs;
  };
} // namespace archdam::analysis
