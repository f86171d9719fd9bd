// The mesh of the parametric arch dam in its canyon, with foundation rock and
// reservoir (doc/arch-dam-geometry.md; the shape is arch_dam_shape.h).
//
// The mesh is a structured grid in index space (i across the valley from
// y = +Y to y = -Y, k along the stream from the upstream end to the downstream
// end, j up from the foundation bottom to the crest level), mapped to physical
// space elevation by elevation:
//   - the grid levels j are horizontal planes z = z_j: the rock layers below the
//     dam base, then uniform layers from the base to the water level and from
//     the water level to the crest;
//   - at each elevation the plan (i, k) grid follows the arch: through the dam
//     the lines of constant i are the radial lines phi = u phi_a(z) and the
//     lines of constant k the arcs s = const; beside the abutments the arcs
//     continue as lines parallel to y out to the lateral truncation; upstream
//     and downstream of the dam the lines of constant i are straight lines from
//     the dam faces to the truncation planes, with the planes x = const of the
//     truncations as lines of constant k;
// and the cells that are neither dam, rock nor water (air in the canyon
// downstream and above the reservoir, and what lies beyond the rock's or the
// reservoir's extent) are left out. Joints are the radial grid surfaces
// u = u_k between blocks; every vertex is shared (the splitter duplicates
// joint and fluid-solid vertices later).

#include <archdam/base/input_error.h>
#include <archdam/base/number_text.h>
#include <archdam/geometry/arch_dam_mesh.h>
#include <archdam/geometry/arch_dam_shape.h>
#include <archdam/geometry/ids.h>

#include <deal.II/base/tensor.h>
#include <deal.II/grid/tria.h>
#include <deal.II/grid/tria_accessor.h>
#include <deal.II/grid/tria_iterator.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <sstream>
#include <string>
#include <vector>

namespace archdam::geometry
{
  using namespace dealii;

  namespace
  {
    /// Cells grow by at most this factor from one to the next away from the dam.
    constexpr double growth = 1.5;

    /**
     * Node fractions 0 = f_0 < ... < f_n = 1 of a segment of length @p L whose
     * cells start at about @p h0 at f = 0 and grow by @p growth up to @p hmax:
     * the capped geometric sequence is extended until it covers L and then
     * scaled to fit (with one cell fewer if that scales less), so that no cell
     * exceeds hmax on a segment of length L or shorter.
     */
    std::vector<double>
    graded_fractions(const double L, double h0, const double hmax)
    {
      if (!(L > 0))
        return {0.};
      if (!(hmax > 0) || L / hmax > 1e6)
        {
          std::ostringstream text;
          text << "Mesh/Arch dam: cells of at most " << hmax << " m over " << L
               << " m of rock or water would be more than a million along one line: the Rock "
               << "cell size or Water cell size is far too small (doc/arch-dam-geometry.md).";
          throw InputError(text.str());
        }
      h0 = std::min(h0, hmax);
      std::vector<double> sizes;
      double              total = 0, h = h0;
      while (total < L * (1 - 1e-12))
        {
          sizes.push_back(std::min(h, hmax));
          total += sizes.back();
          h *= growth;
        }
      if (sizes.size() > 1)
        {
          const double shorter = total - sizes.back();
          const double max_sh  = *std::max_element(sizes.begin(), sizes.end() - 1);
          if (L / shorter - 1 < 1 - L / total && max_sh * L / shorter <= hmax)
            {
              sizes.pop_back();
              total = shorter;
            }
        }
      std::vector<double> f(1, 0.);
      double              sum = 0;
      for (const double s : sizes)
        {
          sum += s;
          f.push_back(sum / total);
        }
      f.back() = 1.;
      return f;
    }

    enum class Region
    {
      dam,
      rock,
      water,
      air,     // inside the model's box, not meshed
      outside, // beyond the rock's or the reservoir's extent
      none     // beyond the index grid
    };

    /// One node line across the valley: in the canyon (u) or beside it
    /// (side = +1 at +y, -1 at -y; tau = 0 at the abutment, 1 at |y| = Y).
    /// Below its floor (the lowest foundation step of the blocks it bounds,
    /// or of the end block beside it) its plan position is the one at the
    /// floor: vertical prisms of rock.
    struct Column
    {
      bool   canyon;
      double u;
      int    side;
      double tau;
      double floor;
    };

    /// One node position along the stream.
    struct StreamNode
    {
      enum Kind
      {
        up_far,  // x = x_far + (x_near - x_far) f
        up_near, // x = x_near + (x_face - x_near) f
        dam,     // s = f
        down     // x = x_face + (x_end - x_face) f
      } kind;
      double f;
    };

    struct Layout
    {
      std::vector<Column>     across;
      std::vector<StreamNode> stream;
      std::vector<double>     levels; // z of the node levels (uniform in the dam)
      /// z of the node levels of each column: levels, with each foundation
      /// step moved to its block's floor in the block's columns.
      std::vector<std::vector<double>> column_levels;
      /// The first layer of each block's cells (j0 for a block on the floor).
      std::vector<unsigned int> block_layer;
      unsigned int            cells_across_block;
      unsigned int            i0, i1; // canyon cells: i0 <= i < i1
      unsigned int            k0, k1; // dam cells: k0 <= k < k1
      unsigned int            k_rock; // rock cells: k_rock <= k (when rock exists)
      unsigned int            k_water; // water cells: k_water <= k < k0
      unsigned int            j0;      // first cell layer above z = 0
      unsigned int            j_water; // first layer above the water level
      double                  x_far, x_near, x_down, y_side;
    };

    class Mapper
    {
    public:
      Mapper(const ArchDamGeometry &g, const Layout &l)
        : g(g)
        , l(l)
      {}

      /// Plan point of column c on the dam band (s in [0,1]) at elevation
      /// zz >= 0 (at its floor if zz is below).
      Point<2>
      band(const Column &c, const double s, const double zz) const
      {
        const double z = std::max(zz, c.floor);
        if (c.canyon)
          {
            const Point<3> q = g.column_point(c.u, s, z);
            return {q[0], q[1]};
          }
        const Point<3> a = g.column_point(c.side, s, z);
        return {a[0], a[1] + c.tau * (c.side * l.y_side - a[1])};
      }

      /// y of column c at the upstream and downstream truncations.
      double
      end_y(const Column &c, const double zz) const
      {
        const double b = g.canyon_half_width(std::max(zz, c.floor));
        return c.canyon ? c.u * b : c.side * (b + c.tau * (l.y_side - b));
      }

      /// The point at abscissa x on the straight line from s to (x_end, y_end).
      static Point<2>
      on_line(const Point<2> &s, const double x_end, const double y_end, const double x)
      {
        return {x, s[1] + (y_end - s[1]) * (x - s[0]) / (x_end - s[0])};
      }

      Point<3>
      operator()(const unsigned int i, const unsigned int k, const unsigned int j) const
      {
        const double      z  = l.column_levels[i][j];
        const double      zz = std::min(std::max(z, 0.), g.height());
        const Column     &c  = l.across[i];
        const StreamNode &n  = l.stream[k];
        Point<2>          p;
        switch (n.kind)
          {
            case StreamNode::dam:
              p = band(c, n.f, zz);
              break;
            case StreamNode::up_near:
            case StreamNode::up_far:
              {
                const Point<2> s = band(c, 0., zz);
                const double   x = n.kind == StreamNode::up_near ?
                                     l.x_near + (s[0] - l.x_near) * n.f :
                                     l.x_far + (l.x_near - l.x_far) * n.f;
                p = on_line(s, l.x_far, end_y(c, zz), x);
                break;
              }
            case StreamNode::down:
              {
                const Point<2> s = band(c, 1., zz);
                p = on_line(s, l.x_down, end_y(c, zz), s[0] + (l.x_down - s[0]) * n.f);
                break;
              }
          }
        return {p[0], p[1], z};
      }

    private:
      const ArchDamGeometry &g;
      const Layout          &l;
    };

    Layout
    make_layout(const ArchDamGeometry &g)
    {
      const ArchDamParameters &p    = g.parameters();
      const double             H    = p.height;
      const bool               rock = g.has_rock(), water = g.has_water();
      Layout                   l;
      l.y_side = rock ? g.rock_side_y() : 0.;
      l.x_down = rock ? g.rock_downstream_x() : 0.;

      // --- vertical levels: rock (graded), below water, above water ---
      const unsigned int nz = p.cells_over_height;
      unsigned int       n_air, n_wet;
      if (!water)
        n_air = nz, n_wet = 0;
      else if (p.water_level >= H)
        n_air = 0, n_wet = nz;
      else
        {
          n_air = std::max(1u, static_cast<unsigned int>(
                                 std::ceil(nz * (H - p.water_level) / H - 1e-9)));
          // a wet layer needs nz (H - level) / H <= nz - 1, so nz >= H / level
          if (n_air >= nz)
            arch_dam_input_error(
              "Cells over height (" + std::to_string(nz) +
              ") is too small to put a layer boundary at the water level " +
              number_text(p.water_level) + " m of a dam " + number_text(H) +
              " m high; use at least " +
              std::to_string(std::max(2u, static_cast<unsigned int>(
                                            std::ceil(H / p.water_level - 1e-9)))) +
              ".");
          n_wet = nz - n_air;
        }
      const double h_bottom_layer = n_wet > 0 ? p.water_level / n_wet : H / nz;
      if (rock)
        {
          const auto f = graded_fractions(-g.rock_bottom(), h_bottom_layer, p.rock_cell_size);
          for (auto it = f.rbegin(); it != f.rend(); ++it)
            l.levels.push_back(*it * g.rock_bottom());
          l.levels.back() = 0.;
        }
      else
        l.levels.push_back(0.);
      l.j0 = l.levels.size() - 1;
      for (unsigned int n = 1; n <= n_wet; ++n)
        l.levels.push_back(p.water_level * n / n_wet);
      l.j_water = l.levels.size() - 1;
      for (unsigned int n = 1; n <= n_air; ++n)
        l.levels.push_back(p.water_level + (H - p.water_level) * n / n_air);
      l.levels.back() = H;
      std::vector<double> dam_levels; // z >= 0 levels (the plan map at z < 0 is the one at 0)
      for (const double z : l.levels)
        if (z >= 0)
          dam_levels.push_back(z);

      // --- across the valley: side (+y), canyon, side (-y) ---
      const unsigned int n_canyon = p.n_blocks * p.cells_across_block;
      l.cells_across_block        = p.cells_across_block;
      // The blocks on either side of canyon column n (an index past the
      // blocks for none), and the lower of their floors, the column's.
      const auto blocks_beside = [&](const unsigned int n) {
        return std::array<unsigned int, 2>{
          {(n + p.cells_across_block - 1) / p.cells_across_block - 1, n / p.cells_across_block}};
      };
      const auto column_floor = [&](const unsigned int n) {
        double floor = std::numeric_limits<double>::max();
        for (const unsigned int k : blocks_beside(n))
          if (k < p.n_blocks)
            floor = std::min(floor, g.block_floor(k));
        return floor;
      };
      const double floor_left = column_floor(0), floor_right = column_floor(n_canyon);
      std::vector<double> tau{0.};
      if (rock)
        {
          double L = 0;
          for (const double z : dam_levels)
            for (const double s : {0., 1.})
              L = std::max(L, l.y_side - g.column_point(1., s, std::max(z, floor_left))[1]);
          tau = graded_fractions(L, p.crest_length / n_canyon, p.rock_cell_size);
        }
      for (unsigned int n = tau.size() - 1; n > 0; --n)
        l.across.push_back({false, 1., +1, tau[n], floor_left});
      l.i0 = l.across.size();
      for (unsigned int n = 0; n <= n_canyon; ++n)
        l.across.push_back({true, 1. - 2. * n / n_canyon, 0, 0., column_floor(n)});
      l.i1 = l.across.size() - 1;
      for (unsigned int n = 1; n < tau.size(); ++n)
        l.across.push_back({false, -1., -1, tau[n], floor_right});

      // --- foundation steps: each block's cells start at the level nearest
      // its floor (above the levels of lower neighbours, on the same side of
      // the water level), which its columns move to the floor exactly ---
      const unsigned int top = l.levels.size() - 1;
      l.block_layer.assign(p.n_blocks, l.j0);
      std::vector<unsigned int> by_floor(p.n_blocks);
      for (unsigned int k = 0; k < p.n_blocks; ++k)
        by_floor[k] = k;
      std::stable_sort(by_floor.begin(), by_floor.end(), [&](const unsigned int a, const unsigned int b) {
        return g.block_floor(a) < g.block_floor(b);
      });
      for (const unsigned int k : by_floor)
        {
          const double z_f = g.block_floor(k);
          if (z_f == 0.)
            continue;
          unsigned int J = l.j0 + 1;
          for (unsigned int j = l.j0 + 1; j < top; ++j)
            if (std::abs(l.levels[j] - z_f) < std::abs(l.levels[J] - z_f))
              J = j;
          if (water && z_f < p.water_level)
            J = std::min(J, l.j_water - 1);
          if (water && z_f > p.water_level)
            J = std::max(J, l.j_water + 1);
          for (const unsigned int nb : {k - 1, k + 1})
            if (nb < p.n_blocks && g.block_floor(nb) < z_f)
              J = std::max(J, l.block_layer[nb] + 1);
          if (J >= top || (water && z_f < p.water_level && J >= l.j_water))
            arch_dam_input_error(
              "Cells over height (" + std::to_string(nz) + ") is too small to give the "
              "foundation steps of the blocks (block " + std::to_string(k) + " at " +
              number_text(z_f) + " m) their own layers; use more.");
          l.block_layer[k] = J;
        }
      for (const Column &c : l.across)
        {
          // anchors (level index, z), the steps of the blocks the column bounds
          std::vector<std::pair<unsigned int, double>> anchors{{l.j0, 0.}, {top, H}};
          if (water && l.j_water < top)
            anchors.emplace_back(l.j_water, p.water_level);
          if (c.canyon)
            {
              const unsigned int n = &c - &l.across[l.i0];
              for (const unsigned int k : blocks_beside(n))
                if (k < p.n_blocks && l.block_layer[k] != l.j0)
                  anchors.emplace_back(l.block_layer[k], g.block_floor(k));
            }
          std::sort(anchors.begin(), anchors.end());
          anchors.erase(std::unique(anchors.begin(), anchors.end()), anchors.end());
          std::vector<double> z = l.levels;
          if (anchors.size() == (water && l.j_water < top ? 3u : 2u))
            {
              l.column_levels.push_back(z); // no step: the uniform levels
              continue;
            }
          for (unsigned int a = 0; a + 1 < anchors.size(); ++a)
            {
              const auto [j_a, z_a] = anchors[a];
              const auto [j_b, z_b] = anchors[a + 1];
              AssertThrow(j_b > j_a && z_b > z_a, ExcInternalError());
              for (unsigned int j = j_a; j <= j_b; ++j)
                z[j] = z_a + (z_b - z_a) * (j - j_a) / (j_b - j_a);
            }
          l.column_levels.push_back(z);
        }

      // --- along the stream ---
      const double x_r  = water ? g.reservoir_end_x() : 0.;
      const double x_ru = rock ? g.rock_upstream_x() : 0.;
      l.x_far           = g.model_upstream_x();
      l.x_near          = (rock && water) ? std::max(x_r, x_ru) : l.x_far;
      const Mapper map(g, l);
      const double h_dam_cell =
        0.5 * (p.crown_thickness_base + p.crown_thickness_crest) / p.cells_through;

      // far upstream segment: water only (reservoir longer than the rock) or
      // rock only (the other way round); uniform cells
      std::vector<double> f_far{0.};
      if (l.x_near > l.x_far)
        {
          const bool   water_only = x_r < x_ru;
          const double h          = water_only ? p.water_cell_size : p.rock_cell_size;
          double       L          = 0;
          for (const Column &c : l.across)
            for (const double z : dam_levels)
              {
                if (water_only ? !(c.canyon && z <= p.water_level) :
                                 (c.canyon && z > 0))
                  continue;
                const Point<2> s  = map.band(c, 0., z);
                const Point<2> a  = Mapper::on_line(s, l.x_far, map.end_y(c, z), l.x_near);
                const Point<2> e  = Mapper::on_line(s, l.x_far, map.end_y(c, z), l.x_far);
                L                 = std::max(L, a.distance(e));
              }
          const unsigned int n = std::max(1., std::ceil(L / h - 1e-9));
          for (unsigned int m = 1; m <= n; ++m)
            f_far.push_back(double(m) / n);
        }
      // near upstream segment: from the dam's upstream face to x_near
      double h_near = p.water_cell_size;
      if (rock)
        h_near = water ? std::min(p.rock_cell_size, p.water_cell_size) : p.rock_cell_size;
      // Only the lines that bound cells count: in the canyon, upstream of the
      // dam, the lines up to the water level (water) and at z <= 0 (rock);
      // downstream only those at z <= 0 (rock under the canyon floor); beside
      // the canyon all of them (rock up to the crest level).
      const auto relevant = [&](const Column &c, const double z, const bool upstream) {
        return !c.canyon || z == 0. || (upstream && water && z <= p.water_level);
      };
      double L_near = 0, L_down = 0;
      for (const Column &c : l.across)
        for (const double z : dam_levels)
          {
            const Point<2> s = map.band(c, 0., z);
            if ((rock || water) && relevant(c, z, true))
              L_near = std::max(
                L_near, s.distance(Mapper::on_line(s, l.x_far, map.end_y(c, z), l.x_near)));
            if (rock && relevant(c, z, false))
              {
                const Point<2> d = map.band(c, 1., z);
                L_down = std::max(L_down, d.distance(Point<2>(l.x_down, map.end_y(c, z))));
              }
          }
      const auto f_near = (rock || water) ? graded_fractions(L_near, h_dam_cell, h_near) :
                                            std::vector<double>{0.};
      const auto f_down =
        rock ? graded_fractions(L_down, h_dam_cell, p.rock_cell_size) : std::vector<double>{0.};

      for (unsigned int m = 0; m + 1 < f_far.size(); ++m)
        l.stream.push_back({StreamNode::up_far, f_far[m]});
      for (unsigned int m = f_near.size() - 1; m > 0; --m)
        l.stream.push_back({StreamNode::up_near, 1. - f_near[m]});
      l.k0 = l.stream.size();
      for (unsigned int m = 0; m <= p.cells_through; ++m)
        l.stream.push_back({StreamNode::dam, double(m) / p.cells_through});
      l.k1 = l.stream.size() - 1;
      for (unsigned int m = 1; m < f_down.size(); ++m)
        l.stream.push_back({StreamNode::down, f_down[m]});

      const unsigned int n_far = f_far.size() - 1;
      l.k_rock                 = (water && x_r < x_ru) ? n_far : 0;
      l.k_water                = (water && x_r < x_ru) ? 0 : n_far;
      return l;
    }

    /// The region of cell (i, k, j) of the index grid (none outside it).
    Region
    region_of(const Layout &l, const bool water, const long i, const long k, const long j)
    {
      const long ni = l.across.size() - 1, nk = l.stream.size() - 1, nj = l.levels.size() - 1;
      if (i < 0 || k < 0 || j < 0 || i >= ni || k >= nk || j >= nj)
        return Region::none;
      const bool canyon = i >= long(l.i0) && i < long(l.i1);
      if (canyon && j >= long(l.block_layer[(i - l.i0) / l.cells_across_block]))
        {
          if (k >= long(l.k0) && k < long(l.k1))
            return Region::dam;
          if (k < long(l.k0) && water && j < long(l.j_water) && k >= long(l.k_water))
            return Region::water;
          return Region::air;
        }
      return k >= long(l.k_rock) ? Region::rock : Region::outside;
    }

    /// Whether a cell of region @p r is in the mesh.
    bool
    kept_region(const Region r, const bool rock)
    {
      return r == Region::dam || r == Region::water || (r == Region::rock && rock);
    }
  } // namespace

  std::array<double, 2>
  arch_dam_cell_count(const ArchDamParameters &p)
  {
    const ArchDamGeometry g(p);
    const Layout          l     = make_layout(g);
    const bool            water = g.has_water(), rock = g.has_rock();
    std::array<double, 2> count{0., 0.};
    const double          n_grid = double(l.levels.size() - 1) * double(l.stream.size() - 1) *
                          double(l.across.size() - 1);
    if (n_grid > 1e9) // at least a tenth of it is kept
      return {n_grid / 10, 0.};
    for (long j = 0; j + 1 < long(l.levels.size()); ++j)
      for (long k = 0; k + 1 < long(l.stream.size()); ++k)
        for (long i = 0; i + 1 < long(l.across.size()); ++i)
          if (const Region r = region_of(l, water, i, k, j); kept_region(r, rock))
            count[r == Region::water] += 1.;
    return count;
  }

  void
  generate_arch_dam(const ArchDamParameters &p, Triangulation<3> &tria)
  {
    const ArchDamGeometry g(p);
    const Layout          l = make_layout(g);
    const Mapper          map(g, l);
    const bool            rock = g.has_rock(), water = g.has_water();

    const unsigned int ni = l.across.size() - 1, nk = l.stream.size() - 1,
                       nj = l.levels.size() - 1;

    const auto region = [&](const long i, const long k, const long j) {
      return region_of(l, water, i, k, j);
    };
    const auto kept = [&](const Region r) { return kept_region(r, rock); };

    // Cells in index order, their vertices, and the vertex positions.
    const auto node = [&](const unsigned int i, const unsigned int k, const unsigned int j) {
      return (std::size_t(j) * (nk + 1) + k) * (ni + 1) + i;
    };
    std::vector<unsigned int>          vertex_of_node((ni + 1) * std::size_t(nk + 1) * (nj + 1),
                                             numbers::invalid_unsigned_int);
    std::vector<Point<3>>              vertices;
    std::vector<CellData<3>>           cells;
    std::vector<std::array<long, 3>>   cell_index;
    for (unsigned int j = 0; j < nj; ++j)
      for (unsigned int k = 0; k < nk; ++k)
        for (unsigned int i = 0; i < ni; ++i)
          {
            const Region r = region(i, k, j);
            if (!kept(r))
              continue;
            CellData<3> cell;
            for (unsigned int v = 0; v < 8; ++v)
              {
                const unsigned int ii = i + (v & 1), kk = k + ((v >> 1) & 1),
                                   jj = j + ((v >> 2) & 1);
                unsigned int &vi = vertex_of_node[node(ii, kk, jj)];
                if (vi == numbers::invalid_unsigned_int)
                  {
                    vi = vertices.size();
                    vertices.push_back(map(ii, kk, jj));
                  }
                cell.vertices[v] = vi;
              }
            cell.material_id = r == Region::dam ? types::material_id(
                                                    ids::first_dam_block +
                                                    (i - l.i0) / p.cells_across_block) :
                               r == Region::water ? ids::water : ids::rock;

            // Every corner must have a positive Jacobian (edges in the order
            // xi, eta, zeta; xi runs towards -y, eta downstream, zeta up).
            for (unsigned int v = 0; v < 8; ++v)
              {
                Tensor<1, 3> e[3];
                for (unsigned int d = 0; d < 3; ++d)
                  {
                    const unsigned int w = v ^ (1u << d);
                    e[d] = vertices[cell.vertices[std::max(v, w)]] -
                           vertices[cell.vertices[std::min(v, w)]];
                  }
                if (!(scalar_product(e[0], cross_product_3d(e[1], e[2])) > 0))
                  {
                    const Point<3> c = vertices[cell.vertices[0]];
                    arch_dam_input_error(
                      "the parameters give an inverted or degenerate cell near (" +
                      number_text(c[0]) + ", " + number_text(c[1]) + ", " + number_text(c[2]) +
                      ") m; check the arch radii, thicknesses, overhang and canyon width.");
                  }
              }
            cells.push_back(cell);
            cell_index.push_back({{long(i), long(k), long(j)}});
          }

    tria.clear();
    tria.create_triangulation(vertices, cells, SubCellData());

    // Boundary ids from the region beyond each boundary face.
    static const long offset[6][3] = {{-1, 0, 0}, {1, 0, 0}, {0, -1, 0},
                                      {0, 1, 0},  {0, 0, -1}, {0, 0, 1}};
    unsigned int n = 0;
    for (const auto &cell : tria.active_cell_iterators())
      {
        const auto &[i, k, j] = cell_index[n];
        AssertThrow(cell->vertex_index(0) == cells[n].vertices[0] &&
                      cell->vertex_index(7) == cells[n].vertices[7],
                    ExcInternalError());
        ++n;
        const Region r = region(i, k, j);
        for (unsigned int f = 0; f < 6; ++f)
          {
            const Region nb = region(i + offset[f][0], k + offset[f][1], j + offset[f][2]);
            AssertThrow(cell->face(f)->at_boundary() == !kept(nb), ExcInternalError());
            if (kept(nb))
              continue;
            types::boundary_id id = ids::free_surface_solid;
            if (r == Region::dam)
              // without rock the base (zeta-) and the abutments (xi+-) are fixed
              id = (!rock && (f == 0 || f == 1 || f == 4)) ? ids::foundation_bottom :
                                                             ids::free_surface_solid;
            else if (r == Region::water)
              id = f == 5 ? ids::reservoir_surface :
                   f == 2 ? ids::reservoir_truncation :
                            ids::reservoir_bottom;
            else if (nb == Region::air || f == 5)
              id = ids::free_surface_solid; // ground surface and canyon walls
            else
              id = f == 4 ? ids::foundation_bottom : ids::foundation_sides;
            cell->face(f)->set_boundary_id(id);
          }
      }
  }
} // namespace archdam::geometry
