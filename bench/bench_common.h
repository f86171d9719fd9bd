// Helpers shared by the benchmark drivers in bench/ (not a benchmark itself:
// the top-level CMakeLists.txt builds only bench/*.cc).
//
// The model is the box "dam on rock" of prm/box_dam_on_rock.prm (a 10 m x 40 m
// x 30 m concrete block in 4 cantilever blocks on a 30 m deep massless rock
// block reaching 30 m beyond it), Q2, with finer cells chosen on the command
// line. It is built with the library functions (not Simulation::setup_model)
// so that mesh, DOFs and the assembly of M and K can be timed separately.
#pragma once

#include <archdam/fe/fe_space.h>
#include <archdam/geometry/mesh.h>
#include <archdam/parameters/parameters.h>
#include <archdam/physics/solid/solid_operators.h>

#include <deal.II/base/mpi.h>
#include <deal.II/base/timer.h>
#include <deal.II/base/utilities.h>
#include <deal.II/distributed/shared_tria.h>

#include <cstdlib>
#include <fstream>
#include <functional>
#include <iomanip>
#include <iostream>
#include <memory>
#include <sstream>
#include <string>
#include <vector>

namespace archdam::bench
{
  /// The case file of a benchmark run on a case (default @p file) and its
  /// `--set "Section/Name=value"` overrides from the command line; every
  /// other option goes to @p option, which takes its value from argv[++i]
  /// and returns false for an option it does not know (then taken as the
  /// case file).
  struct CaseArguments
  {
    std::string              file;
    std::vector<std::string> overrides;
  };
  inline CaseArguments
  case_arguments(const int argc, char **argv, const std::string &file,
                 const std::function<bool(const std::string &, int &)> &option = {})
  {
    CaseArguments c{file, {}};
    for (int i = 1; i < argc; ++i)
      {
        const std::string a = argv[i];
        if (a == "--set" && i + 1 < argc)
          c.overrides.push_back(argv[++i]);
        else if (!(option && i + 1 < argc && option(a, i)))
          c.file = a;
      }
    return c;
  }

  /// The cells of the box model (the dam is always 10 x 40 x 30 m on 30 m of rock).
  struct BoxSize
  {
    unsigned int cells_x        = 4;
    unsigned int cells_y        = 32;
    unsigned int cells_z        = 16;
    double       rock_cell_size = 8.;
  };

  inline std::string
  prm_text(const BoxSize &s, const double time_step = 0.01)
  {
    std::ostringstream o;
    o << "subsection Mesh\n  set Source = box\n  subsection Box\n"
      << "    set Length = 10\n    set Width = 40\n    set Height = 30\n"
      << "    set Number of blocks = 4\n"
      << "    set Cells in x = " << s.cells_x << "\n"
      << "    set Cells in y = " << s.cells_y << "\n"
      << "    set Cells in z = " << s.cells_z << "\n"
      << "    set Rock depth = 30\n    set Rock extent = 30\n"
      << "    set Rock cell size = " << s.rock_cell_size << "\n  end\nend\n"
      << "subsection Finite element\n  set Degree = 2\nend\n"
      << "subsection Damping\n  set Mode = damping ratio\n  set Damping ratio = 0.05\n"
      << "  set First frequency = 2\n  set Second frequency = 15\nend\n"
      << "subsection Time integration\n  set Time step = " << time_step
      << "\n  set End time = 10\nend\n"
      << "subsection Output\n  set Directory = bench_results\n"
      << "  set Field output interval = 0\nend\n";
    return o.str();
  }

  /// Mesh, DOFs, M and K, gravity and influence loads, with the time each took.
  struct Model
  {
    explicit Model(const BoxSize &size, MPI_Comm comm = MPI_COMM_WORLD)
      : p(parameters_from_string(prm_text(size)))
      , triangulation(comm)
    {}

    /// Build everything; the wall times go to the members below.
    void
    build()
    {
      dealii::Timer timer;
      geometry::create_mesh(p.mesh, triangulation);
      space = std::make_unique<fe::FESpace>(triangulation, p.finite_element);
      space->setup(p.foundation.fixed_boundaries());
      time_mesh_and_dofs = timer.wall_time();

      timer.restart();
      physics::solid::assemble_mass_and_stiffness(*space, p.materials,
                                                  physics::solid::InertiaOf::dam, mass,
                                                  stiffness);
      time_assembly = timer.wall_time();

      timer.restart();
      dealii::Tensor<1, dim> g;
      g[dim - 1] = -p.static_loads.g;
      physics::solid::assemble_inertia_load(*space, p.materials,
                                            physics::solid::InertiaOf::dam, g, gravity);
      for (unsigned int d = 0; d < dim; ++d)
        physics::solid::assemble_inertia_load(*space, p.materials,
                                              physics::solid::InertiaOf::dam,
                                              dealii::Point<dim>::unit_vector(d),
                                              influence[d]);
      time_loads = timer.wall_time();
    }

    dealii::types::global_dof_index
    n_dofs() const
    {
      return space->dof_handler.n_dofs();
    }

    /// The number of nonzero entries stored for K (PETSc's count).
    double
    nnz() const
    {
      MatInfo info;
      MatGetInfo(static_cast<Mat>(const_cast<SparseMatrix &>(stiffness)), MAT_GLOBAL_SUM,
                 &info);
      return info.nz_used;
    }

    Parameters                                   p;
    dealii::parallel::shared::Triangulation<dim> triangulation;
    std::unique_ptr<fe::FESpace>                 space;
    SparseMatrix                                 mass, stiffness;
    Vector                                       gravity;
    std::array<Vector, dim>                      influence;
    double time_mesh_and_dofs = 0, time_assembly = 0, time_loads = 0;
  };

  /// Kbar = (1 + alpha beta1 dt) M + (beta beta1 dt + beta2 dt^2) K, built
  /// exactly as time::NewmarkIntegrator builds it (doc/theory/time-integration.md §3, eq. 2.4).
  inline void
  effective_matrix(const Model &m, SparseMatrix &kbar)
  {
    const auto   r  = m.p.damping.rayleigh_coefficients();
    const auto  &t  = m.p.time_integration;
    const double dt = t.time_step;
    kbar.reinit(m.stiffness);
    kbar.copy_from(m.stiffness);
    kbar *= r.second * t.beta1 * dt + t.beta2 * dt * dt;
    kbar.add(1. + r.first * t.beta1 * dt, m.mass);
  }

  /// A field of /proc/self/status in GB (VmHWM = peak resident, VmRSS = now).
  inline double
  memory_gb(const std::string &field)
  {
    std::ifstream in("/proc/self/status");
    std::string   line;
    while (std::getline(in, line))
      if (line.rfind(field + ":", 0) == 0)
        return std::atof(line.c_str() + field.size() + 1) / (1024. * 1024.); // kB -> GB
    return -1;
  }

  /// A size preset name or "cx,cy,cz,h" (cells in x, y, z of the dam and rock
  /// cell size in m).
  inline BoxSize
  parse_size(const std::string &s)
  {
    if (s == "tiny") // 13,413 DOFs
      return {2, 8, 6, 10.};
    if (s == "small") // 27,747 DOFs
      return {2, 12, 6, 8.};
    if (s == "large") // 110,835 DOFs
      return {4, 32, 16, 8.};
    BoxSize            b;
    char               c1, c2, c3;
    std::istringstream in(s);
    if (!(in >> b.cells_x >> c1 >> b.cells_y >> c2 >> b.cells_z >> c3 >> b.rock_cell_size))
      throw std::runtime_error("size must be tiny|small|large or cx,cy,cz,h; got '" + s + "'");
    return b;
  }

  /// std::cout on rank 0, a sink elsewhere.
  inline std::ostream &
  screen()
  {
    static std::ostringstream sink;
    return dealii::Utilities::MPI::this_mpi_process(MPI_COMM_WORLD) == 0 ? std::cout : sink;
  }

  /// "name: value unit" lines are what the benches print; this keeps them aligned.
  inline std::ostream &
  figure(std::ostream &out, const std::string &name)
  {
    return out << std::left << std::setw(44) << name << std::right << " ";
  }
} // namespace archdam::bench
