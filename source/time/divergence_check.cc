#include <archdam/base/point_text.h>
#include <archdam/base/run_stopped.h>
#include <archdam/geometry/ids.h>
#include <archdam/time/divergence_check.h>

#include <deal.II/base/mpi.h>
#include <deal.II/fe/mapping_q1.h>
#include <deal.II/grid/grid_tools.h>

#include <petscvec.h>

#include <cmath>
#include <limits>
#include <map>
#include <sstream>

namespace archdam::time
{
  using namespace dealii;

  namespace
  {
    /// The owned entries of a PETSc vector as one array, read only.
    class OwnedEntries
    {
    public:
      explicit OwnedEntries(const Vector &v)
        : vec(static_cast<const Vec &>(v))
      {
        VecGetArrayRead(vec, &data);
      }
      ~OwnedEntries()
      {
        VecRestoreArrayRead(vec, &data);
      }
      double
      operator[](const std::size_t i) const
      {
        return data[i];
      }

    private:
      const Vec         &vec;
      const PetscScalar *data = nullptr;
    };

    std::string
    region_of(const types::material_id m)
    {
      if (ids::is_dam(m))
        return "dam block " + std::to_string(m - ids::first_dam_block);
      return m == ids::water ? "the water" : m == ids::rock ? "the rock" : "material " + std::to_string(m);
    }
  } // namespace

  DivergenceCheck::DivergenceCheck(const fe::FESpace &space)
    : space(space)
    , is_pressure(space.locally_owned.n_elements(), false)
  {
    const auto box = GridTools::compute_bounding_box(space.dof_handler.get_triangulation());
    bound          = box.get_boundary_points().first.distance(box.get_boundary_points().second);

    fe::visit_owned_cell_dofs(space, [&](const auto &cell, const unsigned int i, const auto dof) {
      if (space.locally_owned.is_element(dof) &&
          cell->get_fe().system_to_component_index(i).first == fe::FESpace::pressure_comp)
        is_pressure[space.locally_owned.index_within_set(dof)] = true;
      return false;
    });
  }

  void
  DivergenceCheck::check(const NewmarkState &s, const unsigned int step) const
  {
    // The worst owned entry: the first non-finite one (score +inf), else the
    // largest displacement.
    const OwnedEntries       u(s.u), v(s.v), a(s.a);
    const std::size_t        n     = is_pressure.size();
    const double             inf   = std::numeric_limits<double>::infinity();
    struct
    {
      double score;
      int    rank;
    } worst{0., static_cast<int>(Utilities::MPI::this_mpi_process(space.comm))};
    std::size_t worst_index = 0;
    std::string worst_what  = "u";
    for (std::size_t i = 0; i < n && worst.score < inf; ++i)
      {
        for (const auto &[x, name] : {std::pair{&u, "u"}, {&v, "v"}, {&a, "a"}})
          if (!std::isfinite((*x)[i]))
            {
              worst       = {inf, worst.rank};
              worst_index = i;
              worst_what  = name;
              break;
            }
        if (worst.score < inf && !is_pressure[i] && std::abs(u[i]) > worst.score)
          {
            worst.score = std::abs(u[i]);
            worst_index = i;
          }
      }
    MPI_Allreduce(MPI_IN_PLACE, &worst, 1, MPI_DOUBLE_INT, MPI_MAXLOC, space.comm);
    if (!(worst.score > bound))
      return;

    // The owner of the worst entry describes it; everyone throws its text.
    std::string message;
    if (worst.rank == static_cast<int>(Utilities::MPI::this_mpi_process(space.comm)))
      {
        const double      dt   = step > 0 ? s.time / step : 0.;
        const auto        dof  = space.locally_owned.nth_index_in_set(worst_index);
        const OwnedEntries &x  = worst_what == "u" ? u : worst_what == "v" ? v : a;
        std::ostringstream m;
        m << "Time integration: the solution diverged in step " << step << " (t = " << s.time
          << " s): "
          << describe(dof, worst_what, x[worst_index]);
        if (worst.score < inf)
          m << " exceeds the size of the model, " << bound
            << " m (no displacement of a small-strain model can)";
        else
          m << " (not a finite number)";
        m << ". The results up to t = " << s.time - dt
          << " s are written. Check the ground motion (an absurd sample), the time step, "
             "with a massed foundation the transmitting boundary (c_a dt / h <= 1), and "
             "with frictional joints the Newmark parameters (Beta1 > 0.5 damps the "
             "contact chatter that the average acceleration rule lets grow).";
        message = m.str();
      }
    message = Utilities::MPI::broadcast(space.comm, message, worst.rank);
    throw RunStopped(message, s.time, step);
  }

  std::string
  DivergenceCheck::describe(const types::global_dof_index dof, const std::string &what,
                            const double value) const
  {
    std::string text;
    fe::visit_owned_cell_dofs(space, [&](const auto &cell, const unsigned int i, const auto d) {
      if (d != dof)
        return false;
      const auto &fe = cell->get_fe();
      const unsigned int c = fe.system_to_component_index(i).first;
      const Point<dim>   x = StaticMappingQ1<dim>::mapping.transform_unit_to_real_cell(
        cell, fe.unit_support_point(i));
      std::ostringstream m;
      const bool p = c == fe::FESpace::pressure_comp;
      const std::map<std::string, std::string> label{
        {"u", p ? "pressure p" : "displacement u_"},
        {"v", p ? "pressure rate dp/dt" : "velocity v_"},
        {"a", p ? "pressure acceleration d2p/dt2" : "acceleration a_"}};
      const std::map<std::string, std::string> unit{{"u", p ? "Pa" : "m"},
                                                    {"v", p ? "Pa/s" : "m/s"},
                                                    {"a", p ? "Pa/s^2" : "m/s^2"}};
      m << "the " << label.at(what);
      if (!p)
        m << "xyz"[c];
      m << " = " << value << " " << unit.at(what) << " at the node " << point_text(x) << " m in "
        << region_of(cell->material_id());
      text = m.str();
      return true;
    });
    if (!text.empty())
      return text;
    return "the entry " + what + " of DOF " + std::to_string(dof) + " = " + std::to_string(value);
  }
} // namespace archdam::time
