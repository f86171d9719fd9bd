#include <archdam/base/input_error.h>
#include <archdam/base/point_text.h>
#include <archdam/geometry/ids.h>
#include <archdam/geometry/mesh_checks.h>

#include <deal.II/base/tensor.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <map>
#include <set>
#include <sstream>

namespace archdam::geometry
{
  using namespace dealii;

  namespace
  {
    std::string
    material_name(const types::material_id m)
    {
      if (m == ids::rock)
        return "rock";
      if (m == ids::water)
        return "water";
      return "dam block " + std::to_string(m - ids::first_dam_block);
    }
  } // namespace

  double
  scaled_jacobian(const Triangulation<dim>::cell_iterator &cell)
  {
    // Vertices in deal.II's lexicographic order: the neighbour of vertex v
    // along direction d is v ^ (1 << d); the edge is taken in the +d sense so
    // that a right-handed cell has positive determinants everywhere.
    double worst = 1;
    for (unsigned int v = 0; v < 8; ++v)
      {
        Tensor<1, dim> e[dim];
        for (unsigned int d = 0; d < dim; ++d)
          {
            const unsigned int w = v ^ (1u << d);
            e[d] = cell->vertex(std::max(v, w)) - cell->vertex(std::min(v, w));
            const double length = e[d].norm();
            if (length == 0.)
              return 0.; // two corners coincide: degenerate
            e[d] /= length;
          }
        worst = std::min(worst, scalar_product(e[0], cross_product_3d(e[1], e[2])));
      }
    Tensor<1, dim> axis[dim];
    for (unsigned int v = 0; v < 8; ++v)
      for (unsigned int d = 0; d < dim; ++d)
        if (!(v & (1u << d)))
          axis[d] += cell->vertex(v | (1u << d)) - cell->vertex(v);
    for (auto &a : axis)
      {
        if (a.norm() == 0.)
          return 0.;
        a /= a.norm();
      }
    return std::min(worst, scalar_product(axis[0], cross_product_3d(axis[1], axis[2])));
  }

  void
  check_cell_shapes(const Triangulation<dim> &conforming)
  {
    for (const auto &cell : conforming.active_cell_iterators())
      {
        const double q = scaled_jacobian(cell);
        if (!(q >= min_valid_scaled_jacobian))
          {
            std::ostringstream s;
            s << "Mesh: the cell centred at " << point_text(cell->center()) << " m ("
              << material_name(cell->material_id()) << ", material id "
              << static_cast<unsigned int>(cell->material_id()) << ") is "
              << (q < 0 ? "inverted or tangled" : "degenerate") << ": scaled Jacobian " << q
              << ", it must be positive (at least " << min_valid_scaled_jacobian
              << "). Check the order of its nodes and that no two coincide.";
            throw InputError(s.str());
          }
      }
  }

  namespace
  {
    /// Dam blocks numbered 10, 11, ... without gaps.
    void
    check_dam_block_numbers(const Triangulation<dim> &conforming)
    {
      // Blocks 10, 11, ... without gaps, left to right (doc/theory/conventions.md):
      // a Gmsh volume without a physical group is dropped when the file is
      // saved, and leaves a hole between its neighbours that no later check
      // would name.
      std::set<unsigned int> blocks;
      for (const auto &cell : conforming.active_cell_iterators())
        if (ids::is_dam(cell->material_id()))
          blocks.insert(cell->material_id() - ids::first_dam_block);
      unsigned int expected = 0;
      for (const unsigned int k : blocks)
        {
          if (k != expected)
            throw InputError("Mesh: dam block " + std::to_string(expected) + " (material id " +
                             std::to_string(ids::first_dam_block + expected) +
                             ") is missing, but block " + std::to_string(k) +
                             " is there: dam blocks are numbered 10, 11, ... without gaps, "
                             "left to right. (Gmsh drops a volume without a physical group "
                             "when it saves the mesh.)");
          ++expected;
        }
    }

    /// Each dam block k shares faces, its joint, with block k + 1.
    void
    check_dam_block_neighbours(const Triangulation<dim> &conforming)
    {
      unsigned int n_blocks = 0;
      for (const auto &cell : conforming.active_cell_iterators())
        if (ids::is_dam(cell->material_id()))
          n_blocks = std::max<unsigned int>(n_blocks, cell->material_id() - ids::first_dam_block + 1);
      std::vector<bool> joined(n_blocks == 0 ? 0 : n_blocks - 1, false);
      for (const auto &cell : conforming.active_cell_iterators())
        if (ids::is_dam(cell->material_id()))
          for (const unsigned int f : cell->face_indices())
            if (!cell->at_boundary(f) && cell->neighbor(f)->material_id() == cell->material_id() + 1)
              joined[cell->material_id() - ids::first_dam_block] = true;
      for (unsigned int k = 0; k < joined.size(); ++k)
        if (!joined[k])
          throw InputError("Mesh: dam blocks " + std::to_string(k) + " and " +
                           std::to_string(k + 1) + " (material ids " +
                           std::to_string(ids::first_dam_block + k) + " and " +
                           std::to_string(ids::first_dam_block + k + 1) +
                           ") share no face, so there is no joint between them: neighbouring "
                           "blocks must meet in a conforming joint (is a block missing, or "
                           "are the blocks not numbered left to right?).");
    }
  } // namespace

  void
  check_model_ids(const Triangulation<dim> &conforming)
  {
    // material ids
    for (const auto &cell : conforming.active_cell_iterators())
      {
        const auto m = cell->material_id();
        if (m != ids::rock && m != ids::water && !ids::is_dam(m))
          throw InputError(
            "Mesh: the cell centred at " + point_text(cell->center()) + " m has material id " +
            std::to_string(m) +
            ", which no material defines: use 1 (rock), 2 (water) or 10 + k (dam block k)" +
            (m == 0 ? "; 0 is what a cell outside every physical volume of a Gmsh file gets." :
                      "."));
      }

    check_dam_block_numbers(conforming);

    // boundary ids, and coincident boundary faces (a non-conforming mesh)
    std::map<std::array<long long, 12>, Triangulation<dim>::active_cell_iterator> faces;
    // Faces are compared by their vertex coordinates rounded to 1e-9 of the
    // model's size.
    double scale = 1.;
    for (const auto &x : conforming.get_vertices())
      for (unsigned int d = 0; d < dim; ++d)
        scale = std::max(scale, std::abs(x[d]));
    for (const auto &cell : conforming.active_cell_iterators())
      for (const unsigned int f : cell->face_indices())
        if (cell->at_boundary(f))
          {
            const auto id    = cell->face(f)->boundary_id();
            const bool water = cell->material_id() == ids::water;
            const bool valid = water ? (id >= 3 && id <= 5) : id <= 2;
            if (!valid)
              {
                std::string why;
                if (id >= 6)
                  why = "ids 6, 7 and 100 and above are set by ArchDam's splitter, not "
                        "by the mesh";
                else if (water)
                  why = id == 0 ?
                          "a water face needs a condition: 3 (free surface), 4 "
                          "(upstream truncation) or 5 (bottom or bank); in Gmsh, put the "
                          "face in one of these physical surfaces" :
                          "1 and 2 are solid truncations; a water face takes 3, 4 or 5";
                else
                  why = "3, 4 and 5 are water conditions; a solid face takes 0 "
                        "(traction-free, the default), 1 or 2";
                throw InputError("Mesh: the boundary face centred at " +
                                 point_text(cell->face(f)->center()) + " m of a " +
                                 material_name(cell->material_id()) + " cell has boundary id " +
                                 std::to_string(id) + ": " + why + ".");
              }

            // Key: the face's vertex coordinates, rounded, in sorted order.
            std::array<std::array<long long, dim>, 4> v;
            for (unsigned int i = 0; i < 4; ++i)
              for (unsigned int d = 0; d < dim; ++d)
                v[i][d] = std::llround(cell->face(f)->vertex(i)[d] / scale * 1e9);
            std::sort(v.begin(), v.end());
            std::array<long long, 12> key;
            for (unsigned int i = 0; i < 4; ++i)
              for (unsigned int d = 0; d < dim; ++d)
                key[3 * i + d] = v[i][d];
            const auto [it, inserted] = faces.emplace(key, cell);
            if (!inserted)
              throw InputError(
                "Mesh: a face of a " + material_name(cell->material_id()) + " cell and a face of a " +
                material_name(it->second->material_id()) + " cell lie at the same place, centred at " +
                point_text(cell->face(f)->center()) + " m" +
                ", without sharing their nodes: the mesh is not conforming, and this face "
                "would be a joint face without a partner (or water not coupled to the "
                "solid). In Gmsh, make neighbouring volumes share their surfaces "
                "(BooleanFragments, or Coherence).");
          }

    check_dam_block_neighbours(conforming);
  }
} // namespace archdam::geometry
