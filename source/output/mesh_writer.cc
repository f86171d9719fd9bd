#include <archdam/geometry/ids.h>
#include <archdam/output/atomic_file.h>
#include <archdam/output/mesh_writer.h>

#include <functional>
#include <iomanip>
#include <map>
#include <utility>
#include <vector>

namespace archdam::output
{
  using namespace dealii;

  namespace
  {
    /// One VTK unstructured grid of cells of one type, given by their corner
    /// points in VTK order, with integer cell data.
    struct Grid
    {
      unsigned int                                   vtk_type, corners;
      std::vector<Point<dim>>                        points;
      std::vector<std::pair<std::string, std::vector<int>>> data;

      void
      write(const std::string &filename) const
      {
        write_atomically(filename, [&](std::ostream &out) { write(out); });
      }

      void
      write(std::ostream &out) const
      {
        const auto n = points.size() / corners;
        out << std::setprecision(12)
            << "<?xml version=\"1.0\"?>\n"
               "<VTKFile type=\"UnstructuredGrid\" version=\"0.1\" byte_order=\"LittleEndian\">\n"
               "<UnstructuredGrid>\n<Piece NumberOfPoints=\""
            << points.size() << "\" NumberOfCells=\"" << n << "\">\n"
            << "<Points>\n<DataArray type=\"Float64\" NumberOfComponents=\"3\" format=\"ascii\">\n";
        for (const auto &p : points)
          out << p[0] << ' ' << p[1] << ' ' << p[2] << '\n';
        out << "</DataArray>\n</Points>\n<Cells>\n"
               "<DataArray type=\"Int64\" Name=\"connectivity\" format=\"ascii\">\n";
        for (std::size_t i = 0; i < points.size(); ++i)
          out << i << ((i + 1) % corners == 0 ? '\n' : ' ');
        out << "</DataArray>\n<DataArray type=\"Int64\" Name=\"offsets\" format=\"ascii\">\n";
        for (std::size_t c = 1; c <= n; ++c)
          out << c * corners << '\n';
        out << "</DataArray>\n<DataArray type=\"UInt8\" Name=\"types\" format=\"ascii\">\n";
        for (std::size_t c = 0; c < n; ++c)
          out << vtk_type << '\n';
        out << "</DataArray>\n</Cells>\n<CellData>\n";
        for (const auto &[name, values] : data)
          {
            out << "<DataArray type=\"Int32\" Name=\"" << name << "\" format=\"ascii\">\n";
            for (const int v : values)
              out << v << '\n';
            out << "</DataArray>\n";
          }
        out << "</CellData>\n</Piece>\n</UnstructuredGrid>\n</VTKFile>\n";
      }
    };
  } // namespace

  void
  write_mesh_vtu(const Triangulation<dim> &mesh, const std::string &basename)
  {
    // deal.II's lexicographic vertex order to VTK's (counter-clockwise).
    const unsigned int hex_order[8]  = {0, 1, 3, 2, 4, 5, 7, 6};
    const unsigned int quad_order[4] = {0, 1, 3, 2};

    Grid cells{12, 8, {}, {{"material id", {}}, {"region", {}}, {"block", {}}}};
    Grid faces{9, 4, {}, {{"boundary id", {}}, {"material id", {}}}};
    for (const auto &cell : mesh.active_cell_iterators())
      {
        const int m = cell->material_id();
        for (const unsigned int v : hex_order)
          cells.points.push_back(cell->vertex(v));
        cells.data[0].second.push_back(m);
        cells.data[1].second.push_back(m == ids::rock ? 1 : m == ids::water ? 2 : 3);
        cells.data[2].second.push_back(ids::is_dam(m) ? m - ids::first_dam_block : -1);
        for (const unsigned int f : cell->face_indices())
          if (cell->at_boundary(f))
            {
              for (const unsigned int v : quad_order)
                faces.points.push_back(cell->face(f)->vertex(v));
              faces.data[0].second.push_back(cell->face(f)->boundary_id());
              faces.data[1].second.push_back(m);
            }
      }
    cells.write(basename + ".vtu");
    faces.write(basename + "_boundary.vtu");
  }
} // namespace archdam::output
