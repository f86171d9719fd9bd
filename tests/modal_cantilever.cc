// Verification: the modal stage (doc/theory/loading-sequence.md §2) on a uniform square
// concrete cantilever 1 m x 1 m x 10 m (clamped base, Q2, nu = 0), on two
// meshes, against independent references:
//  - bending modes 1-2 (x and y, degenerate) and 3-4 against the first two
//    roots of Huang's Timoshenko frequency equation (checked against shooting
//    on the Timoshenko ODEs, see beam_reference.h);
//  - the first axial mode against the 1-D bar, f = c/(4L), c = sqrt(E/rho):
//    with nu = 0 the uniform axial field u_z(z) solves 3-D elasticity exactly
//    (no lateral coupling, traction-free sides), so only the discretization
//    error remains;
//  - effective modal masses against the continuum: 8/pi^2 of the mass for the
//    axial mode (phi = sin(pi z/2L)), 0.6131 for the first bending mode of an
//    Euler-Bernoulli cantilever (the Timoshenko and 3-D corrections are of
//    order (h/L)^2 = 1 %, hence the 2 % tolerance);
//  - the eigenpairs themselves: M-orthonormality phi_i^T M phi_j = delta_ij
//    and the relative residual |K phi - omega^2 M phi| / |K phi|.
// Tolerances: the bending frequencies are checked with the bounds the
// time-domain test of the same column met (0.2 % for the first mode on the
// finer mesh, 1 % on the coarse one); the second bending mode has a
// wavelength ~ 2.5 L, where the 3-D/Timoshenko difference grows to a few
// 0.1 %, so 1 % on the finer mesh (5 % on the coarse one, one cell per 2.5 m).

#include <archdam/analysis/simulation.h>
#include <archdam/parameters/parameters.h>

#include <deal.II/base/mpi.h>

#include <cmath>
#include <iomanip>
#include <sstream>
#include <string>

#include "archdam_tests.h"
#include "beam_reference.h"

using archdam::testing::check_below;
using archdam::testing::check_relative;
using archdam::testing::first_root;
using archdam::testing::log;

namespace
{
  constexpr double E = 22e9, rho = 2446.5, nu = 0., h = 1., length = 10.;
  const archdam::testing::SquareCantilever beam{E, rho, nu, h, length};

  std::string
  case_text(const unsigned int n)
  {
    std::ostringstream prm;
    prm << "subsection Mesh\n  set Source = box\n  subsection Box\n"
        << "    set Length = " << h << "\n    set Width = " << h << "\n"
        << "    set Height = " << length << "\n    set Number of blocks = 1\n"
        << "    set Cells in x = " << n << "\n    set Cells in y = " << n << "\n"
        << "    set Cells in z = " << 4 * n << "\n    set Rock depth = 0\n  end\nend\n"
        << "subsection Finite element\n  set Degree = 2\nend\n"
        << "subsection Materials\n  subsection Concrete\n"
        << "    set Young's modulus = " << E << "\n    set Poisson's ratio = " << nu << "\n"
        << "    set Density = " << rho << "\n  end\nend\n"
        << "subsection Static loads\n  set Gravity = false\nend\n"
        << "subsection Analysis\n  set Case name = modal_cantilever\n"
        << "  set Stages = modal\nend\n"
        << "subsection Modal analysis\n  set Number of modes = 8\n"
        << "  set Write mode shapes = " << (n == 2 ? "true" : "false") << "\nend\n"
        << "subsection Output\n  set Directory = results_modal_" << n << "\n"
        << "  set Field output interval = 0\n  set Progress = false\n"
        << "  set Timer summary = false\nend\n";
    return prm.str();
  }

  struct Result
  {
    std::vector<double>                frequency; // Hz
    std::vector<std::array<double, 3>> mass_ratio; // Gamma_d^2 / (rho V)
    double                             orthonormality_error = 0.;
    double                             residual             = 0.;
  };

  Result
  run(const unsigned int n)
  {
    const archdam::Parameters     p = archdam::parameters_from_string(case_text(n));
    std::ostringstream            screen;
    archdam::analysis::Simulation sim(p, MPI_COMM_WORLD, screen);
    sim.run();

    const auto &space = sim.model().space();
    const auto &modes = sim.natural_modes();
    // The rigid-body translation iota_d, built here from the DOF numbering.
    std::array<archdam::Vector, 3> iota, m_iota;
    std::vector<dealii::types::global_dof_index> dofs;
    for (unsigned int d = 0; d < 3; ++d)
      {
        space.reinit(iota[d]);
        space.reinit(m_iota[d]);
      }
    for (const auto &cell : space.dof_handler.active_cell_iterators())
      if (cell->is_locally_owned())
        {
          dofs.resize(cell->get_fe().dofs_per_cell);
          cell->get_dof_indices(dofs);
          for (unsigned int i = 0; i < dofs.size(); ++i)
            if (space.locally_owned.is_element(dofs[i]))
              iota[cell->get_fe().system_to_component_index(i).first](dofs[i]) = 1.;
        }
    for (unsigned int d = 0; d < 3; ++d)
      {
        iota[d].compress(dealii::VectorOperation::insert);
        sim.model().mass().vmult(m_iota[d], iota[d]);
      }

    Result           r;
    const double     total_mass = rho * h * h * length;
    archdam::Vector  m_phi;
    space.reinit(m_phi);
    for (unsigned int i = 0; i < modes.shapes.size(); ++i)
      {
        r.frequency.push_back(modes.omega[i] / (2. * M_PI));
        std::array<double, 3> ratio;
        for (unsigned int d = 0; d < 3; ++d)
          {
            const double gamma = modes.shapes[i] * m_iota[d];
            ratio[d]           = gamma * gamma / total_mass;
          }
        r.mass_ratio.push_back(ratio);
        sim.model().mass().vmult(m_phi, modes.shapes[i]);
        for (unsigned int j = 0; j < modes.shapes.size(); ++j)
          r.orthonormality_error = std::max(r.orthonormality_error,
                                            std::abs(modes.shapes[j] * m_phi - (i == j)));
      }
    r.residual = modes.max_residual;
    return r;
  }
} // namespace

int
main(int argc, char **argv)
{
  dealii::Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  try
    {
      // References.
      const double w_eb1 = beam.euler_bernoulli_omega(1.875104);
      const auto   root  = [&](const double lo, const double hi) {
        return first_root([&](const double w) { return beam.huang(w, beam.r2(), beam.s2()); },
                          lo, hi);
      };
      const double f_b1 = root(0.5 * w_eb1, 1.5 * w_eb1) / (2 * M_PI);
      const double f_b2 = root(2. * w_eb1, 7. * w_eb1) / (2 * M_PI);
      const double f_b2_shoot =
        first_root([](const double w) { return beam.shooting(w); }, 2. * w_eb1, 7. * w_eb1,
                   100) /
        (2 * M_PI);
      check_relative("Timoshenko second bending frequency [Hz], Huang vs shooting", f_b2,
                     f_b2_shoot, 1e-8, 6);
      const double f_axial = std::sqrt(E / rho) / (4. * length);
      log() << "references: bending 1 " << std::setprecision(5) << f_b1 << " Hz, bending 2 "
            << f_b2 << " Hz, axial 1 " << f_axial << " Hz" << std::endl;

      double previous_error = 1.;
      for (const unsigned int n : {1u, 2u})
        {
          const Result r = run(n);
          log() << "Q2 mesh " << n << "x" << n << "x" << 4 * n << ":" << std::endl;
          const double err1 = std::max(std::abs(r.frequency[0] - f_b1),
                                       std::abs(r.frequency[1] - f_b1)) / f_b1;
          check_relative("  modes 1-2 (first bending x, y) [Hz]", r.frequency[0], f_b1,
                         n == 1 ? 0.01 : 0.002, 4);
          check_relative("  mode 2 = mode 1 (square section)", r.frequency[1], r.frequency[0],
                         1e-6, 4);
          check_relative("  modes 3-4 (second bending x, y) [Hz]", r.frequency[2], f_b2,
                         n == 1 ? 0.05 : 0.01, 3);
          check_relative("  mode 4 = mode 3", r.frequency[3], r.frequency[2], 1e-6, 3);
          // The axial mode: the one with the largest effective mass in z.
          unsigned int axial = 0;
          for (unsigned int k = 0; k < r.frequency.size(); ++k)
            if (r.mass_ratio[k][2] > r.mass_ratio[axial][2])
              axial = k;
          check_relative("  axial mode [Hz]", r.frequency[axial], f_axial, 1e-3, 5);
          check_relative("  axial mode effective mass / mass", r.mass_ratio[axial][2],
                         8. / (M_PI * M_PI), 2e-3, 4);
          // Modes 1 and 2 may be any rotation of the x and y modes: the sum of
          // their effective masses in x is that of one x mode.
          check_relative("  first bending effective mass / mass (x, modes 1+2)",
                         r.mass_ratio[0][0] + r.mass_ratio[1][0], 0.6131, 0.02, 3);
          check_below("  M-orthonormality error max |phi_i^T M phi_j - delta_ij|",
                      r.orthonormality_error, 1e-8);
          check_below("  largest relative residual |K phi - w^2 M phi| / |K phi|", r.residual,
                      1e-8);
          log() << "  first bending error decreases with refinement: "
                << (err1 < previous_error ? "yes" : "NO") << std::endl;
          previous_error = err1;
        }
    }
  catch (const std::exception &e)
    {
      log() << "error: " << e.what() << std::endl;
      return 1;
    }
  return 0;
}
