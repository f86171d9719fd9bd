#include <archdam/base/input_error.h>
#include <archdam/geometry/gmsh_mesh.h>
#include <archdam/geometry/gmsh_structure.h>

#include <deal.II/grid/grid_in.h>

#include <fstream>
#include <sstream>

namespace archdam::geometry
{
  using namespace dealii;

  namespace
  {
    /// The first line of a deal.II exception's "Additional information" (the
    /// part a user can act on), or its whole text.
    std::string
    reason(const ExceptionBase &e)
    {
      const std::string text = e.what();
      const auto        info = text.find("Additional information:");
      if (info == std::string::npos)
        return text;
      std::istringstream rest(text.substr(info + 23));
      std::string        line, message;
      while (std::getline(rest, line))
        {
          const auto first = line.find_first_not_of(" \t");
          if (first == std::string::npos)
            {
              if (!message.empty())
                break;
              continue;
            }
          message += (message.empty() ? "" : " ") + line.substr(first);
        }
      return message;
    }

    /// The checks GridIn leaves to debug builds, or does not make: the header
    /// names an ASCII file of a version it reads, the element section is
    /// complete, and the whole file is well formed (gmsh_structure.h).
    /// Returns the file's text.
    std::string
    checked_text(const std::string &filename)
    {
      const std::string where = "Mesh/Gmsh/File: '" + filename + "'";
      std::ifstream     in(filename, std::ios::binary);
      if (!in)
        throw InputError(where + " cannot be opened.");
      std::ostringstream buffer;
      buffer << in.rdbuf();
      const std::string text = buffer.str();

      std::istringstream header(text);
      std::string        tag;
      double             version   = 0;
      int                file_type = -1, data_size = 0;
      header >> tag >> version >> file_type >> data_size;
      if (tag != "$MeshFormat")
        throw InputError(where + " is not a Gmsh .msh file (it does not start with "
                                 "$MeshFormat).");
      if (!((version >= 2. && version < 3.) || version == 4.1))
        throw InputError(where + " has .msh format " + std::to_string(version).substr(0, 3) +
                         "; ArchDam reads formats 2.x and 4.1 (gmsh -format msh22 or msh41).");
      if (file_type != 0 || data_size != sizeof(double))
        throw InputError(where + " is a binary .msh file; save it as ASCII (Gmsh option "
                                 "Mesh.Binary = 0, the default).");
      if (text.find("$EndElements") == std::string::npos)
        throw InputError(where + " is incomplete: it has no $EndElements (truncated file?).");
      check_gmsh_structure(text, where);
      return text;
    }
  } // namespace

  void
  read_gmsh(const std::string &filename, Triangulation<dim> &tria)
  {
    std::istringstream in(checked_text(filename));
    tria.clear();
    GridIn<dim> reader;
    reader.attach_triangulation(tria);
    try
      {
        reader.read_msh(in);
      }
    catch (const ExceptionBase &e)
      {
        const std::string message = reason(e);
        if (message.find("internal face") != std::string::npos)
          throw InputError("Mesh/Gmsh/File: '" + filename +
                           "' has surface or curve elements inside the model (" + message +
                           "). Physical surfaces must lie on the model's outer boundary, "
                           "and the file must not be saved with Mesh.SaveAll = 1: faces "
                           "between volumes (joints, the dam-water interface) are found by "
                           "ArchDam from the material ids.");
        throw InputError("Mesh/Gmsh/File: '" + filename + "' cannot be read: " + message);
      }
  }
} // namespace archdam::geometry
