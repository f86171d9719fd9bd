// Fuzz target (libFuzzer) for the Gmsh route of the mesh: the bytes are saved
// as a .msh file and go the application's way, build_model_mesh() (read_gmsh,
// the cell shapes, the model ids, the dam cells, the splitter) and then the
// pairing of the joint faces the splitter made (pair_joint_faces). Every
// input, however malformed, must either give a model mesh or end in
// InputError with a message. Anything else (another exception, deal.II's
// own included, a failed deal.II assertion, a crash, a sanitizer report, a
// hang) is a finding. An accepted mesh must be what the checks promise:
// only material ids 1, 2 and 10 + k, and every joint face paired.
#include <archdam/base/input_error.h>
#include <archdam/geometry/ids.h>
#include <archdam/geometry/mesh.h>
#include <archdam/geometry/splitter.h>
#include <archdam/joints/joint_faces.h>

#include <cstdint>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <string>
#include <unistd.h>

namespace
{
  void
  check(const dealii::Triangulation<archdam::dim> &model)
  {
    namespace ids        = archdam::ids;
    unsigned int n_joint = 0;
    for (const auto &cell : model.active_cell_iterators())
      {
        const auto m = cell->material_id();
        if (m != ids::rock && m != ids::water && !ids::is_dam(m))
          std::abort();
        for (const unsigned int f : cell->face_indices())
          n_joint += cell->at_boundary(f) &&
                     archdam::geometry::is_joint_face(cell->face(f)->boundary_id());
      }
    if (2 * archdam::joints::pair_joint_faces(model).size() != n_joint)
      std::abort();
  }
} // namespace

extern "C" int
LLVMFuzzerTestOneInput(const std::uint8_t *data, const std::size_t size)
{
  static const std::string file = (std::filesystem::temp_directory_path() /
                                   ("archdam_fuzz_" + std::to_string(getpid()) + ".msh"))
                                    .string();
  std::ofstream(file, std::ios::binary).write(reinterpret_cast<const char *>(data), size);

  archdam::geometry::MeshParameters p;
  p.source    = archdam::geometry::MeshSource::gmsh;
  p.gmsh_file = file;
  try
    {
      dealii::Triangulation<archdam::dim> model;
      archdam::geometry::build_model_mesh(p, "/", model);
      check(model);
    }
  catch (const archdam::InputError &e)
    {
      if (std::string(e.what()).empty())
        std::abort();
    }
  std::filesystem::remove(file);
  return 0;
}
