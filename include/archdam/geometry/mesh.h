#pragma once

#include <archdam/base/selection.h>
#include <archdam/geometry/arch_dam_parameters.h>
#include <archdam/geometry/box_mesh.h>

#include <deal.II/distributed/shared_tria.h>

#include <string>

namespace archdam::geometry
{
  /// `Mesh/Source`: where the model's mesh comes from.
  enum class MeshSource
  {
    box,      ///< a concrete block on a rock block (box_mesh.h)
    arch_dam, ///< the parametric arch dam in its canyon (arch_dam_mesh.h)
    gmsh      ///< a mesh read from Mesh/Gmsh/File (gmsh_mesh.h)
  };

  /// The names of MeshSource in the case file.
  inline const SelectionNames<MeshSource> &
  mesh_source_names()
  {
    static const SelectionNames<MeshSource> names{{"box", MeshSource::box},
                                                  {"arch dam", MeshSource::arch_dam},
                                                  {"gmsh", MeshSource::gmsh}};
    return names;
  }

  /// The `Mesh` subsection: where the model's mesh comes from.
  struct MeshParameters
  {
    MeshSource        source = MeshSource::box;
    BoxParameters     box;
    ArchDamParameters arch_dam;
    /// `Mesh/Gmsh/File`: the .msh file of `Source = gmsh` (relative to the
    /// case file's directory).
    std::string gmsh_file;

    void
    add_parameters(dealii::ParameterHandler &prm);
  };

  /**
   * Build the model mesh on every rank (a parallel::shared::Triangulation holds
   * the whole mesh everywhere and partitions the cells): generate or read the
   * conforming mesh, check that it carries the ids the physics needs, and
   * split joints and fluid-solid interfaces (splitter.h). Without
   * @p keep_water the water cells are left out (empty reservoir); the solid
   * faces they covered become traction-free (id 0).
   */
  void
  create_mesh(const MeshParameters                          &p,
              dealii::parallel::shared::Triangulation<dim> &tria,
              bool                                          keep_water = true,
              const std::string                            &base_directory = ".");

  /**
   * The whole model, water included, as a serial mesh: generate or read the
   * conforming mesh (a relative Gmsh file name is looked for in
   * @p base_directory, then in the data folder: find_input_file(),
   * base/data_files.h), check its cell shapes and ids (mesh_checks.h) and
   * split joints and fluid-solid interfaces (splitter.h).
   */
  /**
   * InputError, naming the parameters that set the mesh's size, when the
   * mesh of @p p (generated, not read) would not fit in this machine's
   * memory: counted before it is made, with its factorization for a run
   * that @p solves (elements of @p degree), the mesh alone otherwise.
   */
  void
  check_model_size(const MeshParameters &p, unsigned int degree, bool solves);

  void
  build_model_mesh(const MeshParameters       &p,
                   const std::string          &base_directory,
                   dealii::Triangulation<dim> &model);

  /// Leave the water cells out (empty reservoir): the solid faces they
  /// covered (id 7 after splitting, or interior before it) become
  /// traction-free (id 0); all other faces keep their ids.
  void
  remove_water(dealii::Triangulation<dim> &mesh);
} // namespace archdam::geometry
