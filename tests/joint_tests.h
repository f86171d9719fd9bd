// Small models for the joint tests: cantilever blocks made of box cells along
// one axis, split into contraction joints by the splitter, with the FE space,
// M, K and the node pairs ready (doc/theory/joints.md §1).
#pragma once

#include <archdam/fe/fe_space.h>
#include <archdam/geometry/splitter.h>
#include <archdam/joints/joint_solver.h>
#include <archdam/physics/solid/solid_operators.h>
#include <archdam/time/newmark.h>

#include <deal.II/grid/grid_generator.h>

#include <cmath>
#include <functional>
#include <memory>
#include <vector>

namespace archdam::testing
{
  /**
   * Blocks 0 ... n-1 of equal length along @p axis inside the box [0, size],
   * @p cells cells per block along the axis and one across; every face of a
   * block in @p fixed_blocks gets boundary id 1, and id 1 together with
   * @p fixed_ids are fixed. Material: E, nu, rho for every block.
   */
  struct BlockModel
  {
    dealii::parallel::shared::Triangulation<dim> tria{MPI_COMM_WORLD};
    std::unique_ptr<fe::FESpace>                 space;
    physics::solid::MaterialParameters           materials;
    SparseMatrix                                 M, K;
    std::unique_ptr<joints::NodePairs>           pairs;

    BlockModel(const unsigned int n_blocks, const unsigned int axis,
               const dealii::Point<dim> &size, const unsigned int cells,
               const unsigned int degree, const double E, const double nu, const double rho,
               const std::set<unsigned int>               &fixed_blocks = {},
               const std::set<dealii::types::boundary_id> &fixed_ids    = {})
    {
      dealii::Triangulation<dim> conforming;
      std::vector<unsigned int>  repetitions(dim, 1);
      repetitions[axis] = n_blocks * cells;
      dealii::GridGenerator::subdivided_hyper_rectangle(conforming, repetitions,
                                                        dealii::Point<dim>(), size);
      for (const auto &cell : conforming.active_cell_iterators())
        {
          const unsigned int k =
            static_cast<unsigned int>(cell->center()[axis] / size[axis] * n_blocks);
          cell->set_material_id(10 + k);
          if (fixed_blocks.count(k))
            for (const unsigned int f : cell->face_indices())
              if (cell->face(f)->at_boundary())
                cell->face(f)->set_boundary_id(1);
        }
      geometry::split_interfaces(conforming, tria);

      fe::FiniteElementParameters fep;
      fep.degree = degree;
      space      = std::make_unique<fe::FESpace>(tria, fep);
      std::set<dealii::types::boundary_id> fixed = fixed_ids;
      fixed.insert(1);
      space->setup(fixed);
      materials.concrete = {E, nu, rho};
      physics::solid::assemble_mass_and_stiffness(*space, materials,
                                                  physics::solid::InertiaOf::dam, M, K);
      pairs = std::make_unique<joints::NodePairs>(*space, joints::pair_joint_faces(tria));
    }

    /// A vector of the model, with @p value in direction @p d on the cells
    /// of block @p block (all blocks if block < 0).
    Vector
    uniform_field(const int block, const unsigned int d, const double value) const
    {
      Vector v;
      space->reinit(v);
      std::vector<dealii::types::global_dof_index> dofs;
      for (const auto &cell : space->dof_handler.active_cell_iterators())
        if (block < 0 || cell->material_id() == static_cast<dealii::types::material_id>(10 + block))
          {
            dofs.resize(cell->get_fe().n_dofs_per_cell());
            cell->get_dof_indices(dofs);
            for (unsigned int i = 0; i < dofs.size(); ++i)
              if (cell->get_fe().system_to_component_index(i).first == d &&
                  space->locally_owned.is_element(dofs[i]) &&
                  !space->constraints.is_constrained(dofs[i]))
                v(dofs[i]) = value;
          }
      v.compress(dealii::VectorOperation::insert);
      return v;
    }
  };

  /// Sum of the normal forces over all pairs (compression negative).
  inline double
  total_normal_force(const joints::JointSolver &s)
  {
    double sum = 0.;
    for (unsigned int i = 0; i < s.pairs.size(); ++i)
      sum += s.force[dim * i];
    return sum;
  }

  /**
   * The Newmark rule the joint tests pair with each scheme of the pair
   * forces in time (doc/theory/joints.md §10): the average acceleration rule
   * with the step impulse, Beta1 = 0.6 (and Beta2 = (Beta1 + 1/2)^2 / 4) with
   * the trapezoidal forces, which need its numerical damping.
   */
  inline time::NewmarkParameters
  newmark_for(const joints::ContactInTime contact, const double dt)
  {
    time::NewmarkParameters np;
    np.time_step       = dt;
    const bool impulse = contact == joints::ContactInTime::step_impulse;
    np.beta1           = impulse ? 0.5 : 0.6;
    np.beta2           = impulse ? 0.25 : 0.3025;
    return np;
  }
  /// Rigid-block relative slip s(t) (block minus base) for the driving
  /// acceleration @p drive(t) and the friction capacity @p capacity (as
  /// accelerations), every @p out_dt: s'' = drive - capacity sign(s') while
  /// it slides, s' = 0 while |drive| <= capacity, integrated event by event
  /// with exact sub-steps of 1e-6 s (the joint tests' independent reference).
  inline std::vector<double>
  rigid_block(const std::function<double(double)> &drive, const double capacity,
              const double end, const double out_dt)
  {
    const double        h = 1e-6;
    double              s = 0., v = 0.;
    std::vector<double> out{0.};
    const unsigned int  n = std::lround(end / h), every = std::lround(out_dt / h);
    for (unsigned int k = 0; k < n; ++k)
      {
        const double a = drive(k * h + 0.5 * h);
        if (v != 0. || std::abs(a) > capacity)
          {
            const double dir = v != 0. ? (v > 0 ? 1. : -1.) : (a > 0 ? 1. : -1.);
            const double acc = a - capacity * dir;
            const double v1  = v + acc * h;
            if (v != 0. && v1 * v < 0.)
              {
                const double tau = -v / acc; // it stops inside the sub-step
                s += v * tau + 0.5 * acc * tau * tau;
                v = 0.;
              }
            else
              {
                s += v * h + 0.5 * acc * h * h;
                v = v1;
              }
          }
        if ((k + 1) % every == 0)
          out.push_back(s);
      }
    return out;
  }

} // namespace archdam::testing
