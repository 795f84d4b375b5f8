#include <deal.II/base/exceptions.h>

#include <bilayer/parameters/scene_checks.h>

#include <string>

namespace bilayer
{
  using namespace dealii;


  void
  check_scene_relations(const Scene &scene, const BoundaryParts &parts)
  {
    const auto &geometry  = scene.geometry;
    const auto &mesh      = scene.mesh;
    const auto &materials = scene.materials;
    const auto &loads     = scene.loads;
    const auto &contact   = scene.contact;
    const auto &solver    = scene.solver;
    AssertThrow(solver.method != SolverMethod::active_set ||
                  contact.sampling == JumpSampling::weighted ||
                  contact.coupling == MultiplierCoupling::lumped,
                ExcMessage("Solver/Method = active set needs a symmetric "
                           "dual operator: Contact/Jump sampling = weighted, "
                           "or Contact/Multiplier coupling = lumped (where "
                           "both samplings agree)"));
    AssertThrow(solver.method != SolverMethod::active_set ||
                  contact.friction != Friction::coulomb ||
                  contact.coulomb_method == CoulombMethod::fixed_point,
                ExcMessage("Contact/Coulomb method = direct needs "
                           "Solver/Method = uzawa or accelerated (the "
                           "active set solves Coulomb friction by the fixed "
                           "point over Tresca problems)"));
    for (const Layer layer : {Layer::first, Layer::second})
      AssertThrow(mesh.shape == ElementShape::quadrilateral ||
                    mesh.degree(layer) <= 2,
                  ExcMessage("Mesh/Polynomial degree of layer " +
                             std::to_string(static_cast<int>(layer) + 1) +
                             " must be 1 or 2 on triangles, got " +
                             std::to_string(mesh.degree(layer))));
    AssertThrow(geometry.gmsh_file.empty() || mesh.mesh_files.empty(),
                ExcMessage("Mesh/Mesh files and Geometry/Gmsh file exclude "
                           "each other: give the specimen by one of them"));
    for (unsigned int i = 0; i < parts.size(); ++i)
      AssertThrow(materials.n_layers == 2 ||
                    loads.traction_is_zero(Layer::second, i),
                  ExcMessage("Loads/Layer 2/" + parts.traction_entry(i) +
                             " must be '0; 0': layer 2 is absent "
                             "(Materials/Number of layers = 1)"));
    AssertThrow(materials.n_layers == 2 ||
                  !loads.has_volume_load(Layer::second),
                ExcMessage("Loads/Layer 2/Body force and Loads/Layer "
                           "2/Eigenstrain must be zero ('0; 0', '0; 0; 0'): "
                           "layer 2 is absent (Materials/Number of layers = "
                           "1)"));
    for (const Layer layer : {Layer::first, Layer::second})
      for (unsigned int i = 0; i < parts.size(); ++i)
        AssertThrow(
          !geometry.clamped[i] || loads.traction_is_zero(layer, i),
          ExcMessage(
            "Loads/Layer " + std::to_string(static_cast<int>(layer) + 1) + "/" +
            parts.traction_entry(i) + " must be '0; 0': " +
            (parts.gmsh ? parts.names[i] : "the " + parts.names[i] + " side") +
            " is clamped (Geometry/Clamped sides)"));
  }
} // namespace bilayer
