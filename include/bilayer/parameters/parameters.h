#ifndef bilayer_parameters_h
#define bilayer_parameters_h

#include <bilayer/parameters/parameter_entries.h>
#include <bilayer/parameters/scene.h>

/**
 * The scene: every entry of a parameter file, typed.
 *
 * One struct per subsection of the .prm file, each with
 * `declare_parameters()` and `parse_parameters()`, in a header of its own
 * (geometry_parameters.h, mesh_parameters.h, material_parameters.h,
 * load_parameters.h, contact_parameters.h, solver_parameters.h,
 * fracture_parameters.h, output_parameters.h); Scene (scene.h) holds them
 * all. Selections are mapped to `enum class` values once, there.
 * Consistency checks that involve several entries (the crack inside Sigma,
 * Sigma inside Omega, ...) are done in Scene::parse_parameters()
 * (scene_checks.h) and end with an ExcMessage that names the entry and the
 * allowed range.
 */

#endif
