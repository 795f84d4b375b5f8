#ifndef bilayer_scene_checks_h
#define bilayer_scene_checks_h

#include <bilayer/parameters/scene.h>

namespace bilayer
{
  /**
   * The relations between entries of different subsections of a parsed
   * @p scene whose boundary parts are @p parts: the active-set method's
   * symmetric dual operator, degrees on triangles, a Gmsh file or mesh
   * files, no loads on an absent layer or a clamped part. Throws a message
   * that names the entry.
   */
  void
  check_scene_relations(const Scene &scene, const BoundaryParts &parts);

  /// Refuse ply heights outside Omega, or on a Gmsh scene or mesh files
  /// (whose meshes are not fitted to them).
  void
  check_plies(const Scene &scene, const BoundaryParts &parts);

  /// The entries of Fracture/Crack growth against the rest of the scene
  /// (Loads/Load factor, friction, refinement); part of
  /// check_scene_relations().
  void
  check_growth_relations(const Scene &scene);

  /// The scenes of several interfaces (Geometry/Interfaces above Sigma):
  /// one layer, the structured meshes of the rectangle, no crack growth.
  /// Part of check_scene_relations().
  void
  check_interfaces(const Scene &scene);

  /// Whether a present layer of @p scene has an eigenstrain, or a
  /// temperature change on a material that expands (the loads that
  /// Loads/Load factor scales = thermal scales).
  bool
  has_thermal_load(const Scene &scene);

  /// Whether a present layer of @p scene has a traction, a body force or a
  /// prescribed displacement (those of Loads/Load factor scales =
  /// mechanical).
  bool
  has_mechanical_load(const Scene &scene);

  /**
   * The loads of a rectangle scene sampled where they act (1001 points
   * along each side: the tractions on their sides, the prescribed
   * displacement on the clamped ones): finite, and with an energy whose
   * squares double precision represents. Throws a message that names the
   * entry, the side and the point.
   */
  void
  check_rectangle_loads(const Scene &scene, const BoundaryParts &parts);
} // namespace bilayer

#endif
