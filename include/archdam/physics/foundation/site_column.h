#pragma once

#include <archdam/base/types.h>
#include <archdam/fe/fe_space.h>
#include <archdam/loads/ground_motion.h>
#include <archdam/physics/foundation/foundation.h>
#include <archdam/physics/foundation/free_field.h>
#include <archdam/physics/solid/damping.h>
#include <archdam/physics/solid/materials.h>

#include <mpi.h>

#include <vector>

namespace archdam::physics::foundation
{
  /**
   * The finite element check of the free field (doc/theory/foundation.md §4):
   * a column of the rock alone from the free surface z_s down to the model's
   * bottom z_b, one cell wide with every plane's DOFs tied (u = u(z, t): a
   * 1-D column in 3-D), meshed with nodes at the depths asked for, with the
   * case's element degree, rock damping, outer boundary and time step, and
   * driven at its bottom by the free field as the model is. What it shows
   * is what the model's rock makes of the free field, with no dam and no
   * canyon: at the surface the control motion, at depth the damped free
   * field.
   */
  struct SiteColumn
  {
    /// The outer boundary (its bottom; the sides carry no load: the column
    /// is tied), the rock, its damping (the rock's coefficients of
    /// `Damping`), the element degree and the largest cell size [m].
    FoundationParameters      foundation;
    solid::ElasticMaterial    rock;
    solid::DampingParameters  damping;
    unsigned int              degree    = 2;
    double                    cell_size = 10.;

    /// The accelerations of component @p d at the elevations @p z (between
    /// z_b and z_s of @p free_field, each a node) at every step of
    /// @p dt up to @p end: one history per elevation, and the times.
    struct Histories
    {
      std::vector<double>              times;
      std::vector<std::vector<double>> acceleration;
    };
    Histories
    run(const FreeField           &free_field,
        unsigned int               d,
        const std::vector<double> &z,
        double                     dt,
        double                     end,
        MPI_Comm                   comm) const;

    /// Component @p d of @p motion through the column until its record has
    /// reached the surface whole, from its arrival there on (times t from
    /// the arrival): the control motion, the column at the free surface
    /// and at @p z_base, and the free field at @p z_base [m/s^2].
    struct Comparison
    {
      std::vector<double> t, control, surface, base, free_field;
    };
    Comparison
    compare(const FreeField           &free_field,
            const loads::GroundMotion &motion,
            unsigned int               d,
            double                     z_base,
            double                     dt,
            MPI_Comm                   comm) const;
  };
} // namespace archdam::physics::foundation
