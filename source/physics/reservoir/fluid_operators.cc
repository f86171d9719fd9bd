#include <archdam/base/input_error.h>
#include <archdam/base/point_text.h>
#include <archdam/geometry/ids.h>
#include <archdam/physics/reservoir/fluid_operators.h>

#include <deal.II/base/bounding_box.h>
#include <deal.II/base/quadrature_lib.h>
#include <deal.II/dofs/dof_tools.h>
#include <deal.II/fe/fe_values.h>
#include <deal.II/fe/mapping_q1.h>
#include <deal.II/hp/fe_values.h>
#include <deal.II/lac/dynamic_sparsity_pattern.h>
#include <deal.II/lac/full_matrix.h>
#include <deal.II/lac/sparsity_tools.h>
#include <deal.II/numerics/rtree.h>
#include <deal.II/numerics/vector_tools.h>

#include <algorithm>
#include <sstream>

namespace archdam::physics::reservoir
{
  using namespace dealii;

  namespace
  {
    struct WettedFace
    {
      CellIterator cell;
      unsigned int face;
      double       area;
    };

    std::vector<WettedFace>
    faces_with_id(const fe::FESpace &space, const types::boundary_id id)
    {
      std::vector<WettedFace> faces;
      for (const auto &cell : space.dof_handler.active_cell_iterators())
        for (const unsigned int f : cell->face_indices())
          if (cell->face(f)->at_boundary() && cell->face(f)->boundary_id() == id)
            faces.push_back({cell, f, cell->face(f)->measure()});
      return faces;
    }

    /// Whether @p x lies on face @p f of @p cell (within a relative tolerance).
    bool
    lies_on_face(const CellIterator &cell, const unsigned int f, const Point<dim> &x)
    {
      try
        {
          const Point<dim> u =
            StaticMappingQ1<dim>::mapping.transform_real_to_unit_cell(cell, x);
          const double tol = 1e-6;
          for (unsigned int d = 0; d < dim; ++d)
            if (d == f / 2 ? std::abs(u[d] - f % 2) > tol : (u[d] < -tol || u[d] > 1 + tol))
              return false;
          return true;
        }
      catch (const Mapping<dim>::ExcTransformationFailed &)
        {
          return false;
        }
    }

  } // namespace

  std::vector<InterfacePair>
  match_interface_faces(const fe::FESpace &space)
  {
    const auto fluid = faces_with_id(space, ids::fluid_interface);
    const auto solid = faces_with_id(space, ids::solid_interface);

    // Solid faces in an R-tree of their bounding boxes, widened a little so
    // that coincident faces always intersect.
    std::vector<std::pair<BoundingBox<dim>, unsigned int>> boxes;
    for (unsigned int i = 0; i < solid.size(); ++i)
      {
        BoundingBox<dim> box(solid[i].cell->face(solid[i].face)->bounding_box());
        box.extend(1e-6 * std::sqrt(solid[i].area));
        boxes.emplace_back(box, i);
      }
    const auto tree = pack_rtree(boxes);

    std::vector<InterfacePair> pairs;
    std::vector<double>        solid_covered(solid.size(), 0.);
    for (const auto &ff : fluid)
      {
        BoundingBox<dim> box(ff.cell->face(ff.face)->bounding_box());
        box.extend(1e-6 * std::sqrt(ff.area));
        std::vector<std::pair<BoundingBox<dim>, unsigned int>> hits;
        tree.query(boost::geometry::index::intersects(box), std::back_inserter(hits));

        double covered = 0.;
        for (const auto &hit : hits)
          {
            const auto &sf = solid[hit.second];
            // Integrate on the smaller face; all its vertices must lie on the
            // larger one.
            const bool on_fluid = ff.area <= sf.area * (1 + 1e-8);
            const auto &small   = on_fluid ? ff : sf;
            const auto &large   = on_fluid ? sf : ff;
            bool        inside  = true;
            for (const unsigned int v : small.cell->face(small.face)->vertex_indices())
              inside = inside &&
                       lies_on_face(large.cell, large.face, small.cell->face(small.face)->vertex(v));
            if (!inside)
              continue;
            pairs.push_back({ff.cell, ff.face, sf.cell, sf.face, on_fluid});
            const double a = std::min(ff.area, sf.area);
            covered += a;
            solid_covered[hit.second] += a;
          }
        if (std::abs(covered - ff.area) > 1e-6 * ff.area)
          throw InputError("Reservoir: the wetted water face at " +
                           point_text(ff.cell->face(ff.face)->center()) +
                           " is not matched by solid faces (the water and solid "
                           "meshes must meet face to face, one side a refinement of "
                           "the other).");
      }
    for (unsigned int i = 0; i < solid.size(); ++i)
      if (std::abs(solid_covered[i] - solid[i].area) > 1e-6 * solid[i].area)
        throw InputError("Reservoir: the wetted solid face at " +
                         point_text(solid[i].cell->face(solid[i].face)->center()) +
                         " is not matched by water faces (the water and solid "
                         "meshes must meet face to face, one side a refinement of "
                         "the other).");
    return pairs;
  }

  void
  add_interface_couplings(const fe::FESpace                &space,
                          const std::vector<InterfacePair> &pairs,
                          DynamicSparsityPattern           &dsp)
  {
    std::vector<types::global_dof_index> fluid_dofs, solid_dofs;
    for (const auto &pair : pairs)
      if (pair.fluid_cell->is_locally_owned())
        {
          fluid_dofs.resize(pair.fluid_cell->get_fe().n_dofs_per_cell());
          solid_dofs.resize(pair.solid_cell->get_fe().n_dofs_per_cell());
          pair.fluid_cell->get_dof_indices(fluid_dofs);
          pair.solid_cell->get_dof_indices(solid_dofs);
          space.constraints.add_entries_local_to_global(fluid_dofs, solid_dofs, dsp, false);
          space.constraints.add_entries_local_to_global(solid_dofs, fluid_dofs, dsp, false);
        }
  }

  void
  constrain_free_surface(const fe::FESpace         &space,
                         const ReservoirParameters &p,
                         AffineConstraints<double> &constraints)
  {
    if (!p.has_pressure() || p.gravity_waves())
      return;
    std::map<types::boundary_id, const Function<dim> *> surface;
    const Functions::ZeroFunction<dim>                  zero(fe::FESpace::n_components);
    surface[ids::reservoir_surface] = &zero;
    VectorTools::interpolate_boundary_values(space.dof_handler, surface, constraints,
                                             space.fe_collection.component_mask(
                                               space.pressure));
  }

  namespace
  {
    /// G, H and Q of the water cells (doc/theory/reservoir.md §3).
    void
    assemble_water_cells(const fe::FESpace &space, const ReservoirParameters &p,
                         const double g, FluidOperators &ops)
    {
      const bool   compressible = p.model == Model::compressible;
      const double inv_c2       = compressible ? 1. / (p.sound_speed * p.sound_speed) : 0.;
      const double radiation    = compressible ? 1. / p.sound_speed : 0.;
      const double absorption   = p.bottom_absorption();
      const double surface      = p.gravity_waves() ? 1. / g : 0.;

      const auto        &fe = space.fe_collection[fe::FESpace::fluid_index];
      FEValues<dim>      fv(fe, space.q_collection[fe::FESpace::fluid_index],
                       update_values | update_gradients | update_JxW_values);
      FEFaceValues<dim>  fv_face(fe, space.face_q_collection[fe::FESpace::fluid_index],
                                update_values | update_JxW_values);
      const unsigned int n = fe.n_dofs_per_cell();
      FullMatrix<double> cell_g(n, n), cell_h(n, n), cell_q(n, n);
      std::vector<types::global_dof_index> dofs(n);

      for (const auto &cell : space.dof_handler.active_cell_iterators())
        if (cell->is_locally_owned() && cell->active_fe_index() == fe::FESpace::fluid_index)
          {
            cell_g = 0.;
            cell_h = 0.;
            cell_q = 0.;
            fv.reinit(cell);
            for (const unsigned int q : fv.quadrature_point_indices())
              for (unsigned int i = 0; i < n; ++i)
                for (unsigned int j = 0; j < n; ++j)
                  {
                    cell_g(i, j) += inv_c2 * fv[space.pressure].value(i, q) *
                                    fv[space.pressure].value(j, q) * fv.JxW(q);
                    cell_q(i, j) += fv[space.pressure].gradient(i, q) *
                                    fv[space.pressure].gradient(j, q) * fv.JxW(q);
                  }
            for (const unsigned int f : cell->face_indices())
              if (cell->face(f)->at_boundary())
                {
                  const auto   id = cell->face(f)->boundary_id();
                  FullMatrix<double> *target = nullptr;
                  double       coefficient   = 0.;
                  if (id == ids::reservoir_surface)
                    target = &cell_g, coefficient = surface; // (1/g) p_tt + dp/dn = 0
                  else if (id == ids::reservoir_truncation)
                    target = &cell_h, coefficient = radiation; // Sommerfeld
                  else if (id == ids::reservoir_bottom)
                    target = &cell_h, coefficient = absorption; // dp/dn = -q p_t
                  if (coefficient == 0.)
                    continue;
                  fv_face.reinit(cell, f);
                  for (const unsigned int q : fv_face.quadrature_point_indices())
                    for (unsigned int i = 0; i < n; ++i)
                      for (unsigned int j = 0; j < n; ++j)
                        (*target)(i, j) += coefficient * fv_face[space.pressure].value(i, q) *
                                           fv_face[space.pressure].value(j, q) *
                                           fv_face.JxW(q);
                }
            cell->get_dof_indices(dofs);
            space.constraints.distribute_local_to_global(cell_g, dofs, ops.G);
            space.constraints.distribute_local_to_global(cell_h, dofs, ops.H);
            space.constraints.distribute_local_to_global(cell_q, dofs, ops.Q);
          }
    }

    /**
     * S = rho_w int N_f^T n^T N_s of one interface pair, on the smaller
     * face's quadrature; the larger face's cell is evaluated at those points
     * through the inverse of its mapping (doc/theory/reservoir.md §4, doc/theory/conventions.md §6).
     * Also the pair's part of the influence S iota_d.
     */
    class PairCoupling
    {
    public:
      PairCoupling(const fe::FESpace &space, const double density)
        : space(space)
        , density(density)
        , fe_f(space.fe_collection[fe::FESpace::fluid_index])
        , fe_s(space.fe_collection[fe::FESpace::solid_index])
        , face_f(mapping, fe_f, space.face_q_collection[fe::FESpace::fluid_index], flags())
        , face_s(mapping, fe_s, space.face_q_collection[fe::FESpace::fluid_index], flags())
        , matrix(fe_f.n_dofs_per_cell(), fe_s.n_dofs_per_cell())
        , dofs_f(fe_f.n_dofs_per_cell())
        , dofs_s(fe_s.n_dofs_per_cell())
      {
        for (auto &v : influence)
          v.reinit(fe_f.n_dofs_per_cell());
      }

      static UpdateFlags
      flags()
      {
        return update_values | update_quadrature_points | update_normal_vectors |
               update_JxW_values;
      }

      void
      integrate(const InterfacePair &pair)
      {
        // The smaller face gives the points, weights and normal; the other
        // cell is evaluated at the same points.
        FEFaceValues<dim> &own = pair.integrate_on_fluid ? face_f : face_s;
        own.reinit(pair.integrate_on_fluid ? pair.fluid_cell : pair.solid_cell,
                   pair.integrate_on_fluid ? pair.fluid_face : pair.solid_face);
        const auto &other_cell = pair.integrate_on_fluid ? pair.solid_cell : pair.fluid_cell;
        const auto &other_fe   = pair.integrate_on_fluid ? fe_s : fe_f;
        std::vector<Point<dim>> unit(own.n_quadrature_points);
        for (const unsigned int q : own.quadrature_point_indices())
          unit[q] = mapping.transform_real_to_unit_cell(other_cell, own.quadrature_point(q));
        FEValues<dim> other(mapping, other_fe, Quadrature<dim>(unit), update_values);
        other.reinit(other_cell);
        const FEValuesBase<dim> &at_f =
          pair.integrate_on_fluid ? static_cast<const FEValuesBase<dim> &>(own) : other;
        const FEValuesBase<dim> &at_s =
          pair.integrate_on_fluid ? other : static_cast<const FEValuesBase<dim> &>(own);

        const unsigned int n_f = dofs_f.size(), n_s = dofs_s.size();
        std::vector<double>         phi_f(n_f);
        std::vector<Tensor<1, dim>> phi_s(n_s);
        matrix = 0.;
        for (auto &v : influence)
          v = 0.;
        for (const unsigned int q : own.quadrature_point_indices())
          {
            // the water's outward normal points into the solid
            const Tensor<1, dim> n = pair.integrate_on_fluid ?
                                       own.normal_vector(q) :
                                       Tensor<1, dim>(-own.normal_vector(q));
            const double w = density * own.JxW(q);
            for (unsigned int i = 0; i < n_f; ++i)
              phi_f[i] = at_f[space.pressure].value(i, q);
            for (unsigned int j = 0; j < n_s; ++j)
              phi_s[j] = at_s[space.displacement].value(j, q);
            for (unsigned int i = 0; i < n_f; ++i)
              {
                for (unsigned int j = 0; j < n_s; ++j)
                  matrix(i, j) += phi_f[i] * (n * phi_s[j]) * w;
                for (unsigned int d = 0; d < dim; ++d)
                  influence[d](i) += phi_f[i] * n[d] * w;
              }
          }
        pair.fluid_cell->get_dof_indices(dofs_f);
        pair.solid_cell->get_dof_indices(dofs_s);
      }

    private:
      const Mapping<dim>   &mapping = StaticMappingQ1<dim>::mapping;
      const fe::FESpace    &space;
      const double          density;
      const FiniteElement<dim> &fe_f, &fe_s;
      FEFaceValues<dim>     face_f, face_s;

    public:
      // The last pair's results: its cell matrix of S (fluid x solid DOFs),
      // influence and DOFs.
      FullMatrix<double>                      matrix;
      std::array<dealii::Vector<double>, dim> influence;
      std::vector<types::global_dof_index>    dofs_f, dofs_s;
    };

    /// S, S^T and the influence S iota_d over every interface pair.
    void
    assemble_coupling(const fe::FESpace &space, const ReservoirParameters &p,
                      const std::vector<InterfacePair> &pairs, FluidOperators &ops)
    {
      PairCoupling       coupling(space, p.density);
      FullMatrix<double> transposed;
      for (const auto &pair : pairs)
        if (pair.fluid_cell->is_locally_owned())
          {
            coupling.integrate(pair);
            transposed.copy_transposed(coupling.matrix);
            space.constraints.distribute_local_to_global(coupling.matrix, coupling.dofs_f,
                                                         coupling.dofs_s, ops.S);
            space.constraints.distribute_local_to_global(transposed, coupling.dofs_s,
                                                         coupling.dofs_f, ops.S_transpose);
            for (unsigned int d = 0; d < dim; ++d)
              space.constraints.distribute_local_to_global(coupling.influence[d],
                                                           coupling.dofs_f, ops.influence[d]);
          }
    }
  } // namespace

  void
  assemble_fluid_operators(const fe::FESpace                &space,
                           const ReservoirParameters        &p,
                           const double                      g,
                           const std::vector<InterfacePair> &pairs,
                           FluidOperators                   &ops)
  {
    // The water's operators take the couplings of the water cells and of
    // the interface only, a subset of the model's pattern: on the reference
    // dam's production mesh a tenth of the DOFs are water's, and five
    // matrices on the model's whole pattern would hold more than the solid's
    // M and K together (linear_combination() adds them into full ones).
    space.reinit(ops.Q, [&](DynamicSparsityPattern &dsp) {
      std::vector<types::global_dof_index> dofs(
        space.fe_collection[fe::FESpace::fluid_index].n_dofs_per_cell());
      for (const auto &cell : space.dof_handler.active_cell_iterators())
        if (cell->is_locally_owned() && cell->active_fe_index() == fe::FESpace::fluid_index)
          {
            cell->get_dof_indices(dofs);
            space.constraints.add_entries_local_to_global(dofs, dsp, false);
          }
      add_interface_couplings(space, pairs, dsp);
    });
    for (SparseMatrix *m : {&ops.G, &ops.H, &ops.S, &ops.S_transpose})
      m->reinit(ops.Q);
    for (auto &v : ops.influence)
      space.reinit(v);
    assemble_water_cells(space, p, g, ops);
    assemble_coupling(space, p, pairs, ops);
    for (SparseMatrix *m : {&ops.G, &ops.H, &ops.Q, &ops.S, &ops.S_transpose})
      m->compress(VectorOperation::add);
    for (auto &v : ops.influence)
      v.compress(VectorOperation::add);
  }

  void
  assemble_coupling_columns(const fe::FESpace                          &space,
                            const double                                density,
                            const std::vector<InterfacePair>           &pairs,
                            const std::vector<types::global_dof_index> &columns,
                            SparseMatrix                               &S_columns)
  {
    std::vector<bool> is_column(space.dof_handler.n_dofs(), false);
    for (const auto i : columns)
      is_column[i] = true;
    // The model's constraints without the lines of the columns themselves
    // (the rows keep the model's: p = 0 on the free surface).
    const AffineConstraints<double> others = fe::constraints_without(space, is_column);
    const auto touches = [&](const InterfacePair &pair, std::vector<types::global_dof_index> &dofs) {
      dofs.resize(pair.solid_cell->get_fe().n_dofs_per_cell());
      pair.solid_cell->get_dof_indices(dofs);
      return pair.fluid_cell->is_locally_owned() &&
             std::any_of(dofs.begin(), dofs.end(), [&](const auto i) { return is_column[i]; });
    };

    DynamicSparsityPattern               dsp(space.locally_relevant);
    std::vector<types::global_dof_index> dofs_f, dofs_s;
    for (const auto &pair : pairs)
      if (touches(pair, dofs_s))
        {
          dofs_f.resize(pair.fluid_cell->get_fe().n_dofs_per_cell());
          pair.fluid_cell->get_dof_indices(dofs_f);
          space.constraints.add_entries_local_to_global(dofs_f, others, dofs_s, dsp, false);
        }
    SparsityTools::distribute_sparsity_pattern(dsp, space.locally_owned, space.comm,
                                               space.locally_relevant);
    S_columns.reinit(space.locally_owned, space.locally_owned, dsp, space.comm);

    PairCoupling coupling(space, density);
    for (const auto &pair : pairs)
      if (touches(pair, dofs_s))
        {
          coupling.integrate(pair);
          space.constraints.distribute_local_to_global(coupling.matrix, coupling.dofs_f, others,
                                                       coupling.dofs_s, S_columns);
        }
    S_columns.compress(VectorOperation::add);
  }

  IndexSet
  free_pressure_dofs(const fe::FESpace &space)
  {
    IndexSet free = DoFTools::extract_dofs(space.dof_handler,
                                           space.fe_collection.component_mask(space.pressure));
    IndexSet constrained(free.size());
    for (const auto i : free)
      if (space.constraints.is_constrained(i))
        constrained.add_index(i);
    free.subtract_set(constrained);
    return free;
  }
} // namespace archdam::physics::reservoir
