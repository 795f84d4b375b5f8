#ifndef bilayer_scene_h
#define bilayer_scene_h

#include <deal.II/base/parameter_handler.h>

#include <bilayer/parameters/cohesive_parameters.h>
#include <bilayer/parameters/contact_parameters.h>
#include <bilayer/parameters/fracture_parameters.h>
#include <bilayer/parameters/geometry_parameters.h>
#include <bilayer/parameters/load_parameters.h>
#include <bilayer/parameters/material_parameters.h>
#include <bilayer/parameters/mesh_parameters.h>
#include <bilayer/parameters/output_parameters.h>
#include <bilayer/parameters/solver_parameters.h>

#include <string>
#include <vector>

/**
 * The scene: all subsections together (Scene), read from a parameter file
 * with its includes and the --set overrides (read_scene.cc).
 */
namespace bilayer
{
  /**
   * All subsections together. parse_parameters() also checks the
   * relations between entries.
   */
  struct Scene
  {
    std::string        name = "scene";
    GeometryParameters geometry;
    MeshParameters     mesh;
    MaterialParameters materials;
    LoadParameters     loads;
    ContactParameters  contact;
    SolverParameters   solver;
    FractureParameters fracture;
    CohesiveParameters cohesive;
    OutputParameters   output;
    /// The parameter file and the files it includes (not the mesh files).
    std::vector<std::string> input_files;

    /// Declare every entry; a Gmsh scene's boundary @p parts give the
    /// entries of the Loads section, @p n_plies the subsections Ply j of
    /// each layer.
    static void
    declare_parameters(dealii::ParameterHandler &prm,
                       const BoundaryParts      &parts   = BoundaryParts(),
                       const PlyCounts          &n_plies = {1, 1});
    void
    parse_parameters(dealii::ParameterHandler &prm,
                     const BoundaryParts      &parts = BoundaryParts());
  };

  /**
   * Declare, read a parameter file and parse it into a Scene. The Scene's
   * name is the file name without directory and extension. With
   * @p allow_gmsh_commands a .geo scene may run programs and write files
   * (--allow-gmsh-commands; docs/geometry.md).
   */
  Scene
  read_scene(dealii::ParameterHandler       &prm,
             const std::string              &filename,
             const std::vector<std::string> &overrides           = {},
             const bool                      allow_gmsh_commands = false);

  /// Parse a Scene from parameter-file text (entries not given keep their
  /// defaults).
  Scene
  scene_from_string(const std::string &text, const std::string &name);

  /**
   * The entries @p short_prm (ParameterHandler::ShortPRM) without those that
   * the scene does not use, each replaced by a comment line that names it:
   * for a Gmsh scene (Geometry/Gmsh file) the rectangle's corners, Height
   * of Sigma and Crack interval, and the structured mesh's cell counts,
   * Fit crack tips and Mesh files; the material entries that no side's
   * elastic law reads (an isotropic layer's E_1 ... Stiffness, an
   * orthotropic one's E_3, nu_13, nu_23 in plane stress, a layer's entry
   * that both sides give themselves, a side's entry its law does not read,
   * the thermal expansion without a temperature change);
   * every entry of layer 2 in a one-layer scene.
   */
  std::string
  applicable_entries(const std::string &short_prm, const Scene &scene);
} // namespace bilayer

#endif
