#include <deal.II/base/exceptions.h>

#include <bilayer/parameters/expressions.h>
#include <bilayer/parameters/parameter_entries.h>
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
    if (scene.cohesive.active())
      {
        AssertThrow(solver.method == SolverMethod::active_set,
                    ExcMessage("Cohesive/Law needs Solver/Method = active set "
                               "(the step sizes of the first-order methods do "
                               "not know the cohesive springs)"));
        AssertThrow(scene.fracture.growth == CrackGrowth::none,
                    ExcMessage("Cohesive/Law and Fracture/Crack growth exclude "
                               "each other (two models of one delamination): "
                               "set Crack growth = none"));
        AssertThrow(contact.non_penetration,
                    ExcMessage("Cohesive/Law needs Contact/Non-penetration on "
                               "the crack = true (the zone's faces touch "
                               "exactly under pressure)"));
        AssertThrow(mesh.refinement != Refinement::adaptive ||
                      mesh.n_cycles == 1,
                    ExcMessage("Cohesive/Law runs on the meshes of one "
                               "cycle: Mesh/Refinement = adaptive needs "
                               "Mesh/Number of cycles = 1 with it, got " +
                               std::to_string(mesh.n_cycles)));
        AssertThrow(!scene.fracture.goal_oriented,
                    ExcMessage("Cohesive/Law does not take Fracture/"
                               "Goal-oriented estimate = true (the estimates "
                               "know no cohesive springs)"));
      }
    for (const Layer layer : materials.layers())
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
      AssertThrow(materials.n_layers != 1 ||
                    loads.traction_is_zero(Layer::second, i),
                  ExcMessage("Loads/Layer 2/" + parts.traction_entry(i) +
                             " must be '0; 0': layer 2 is absent "
                             "(Materials/Number of layers = 1)"));
    AssertThrow(materials.n_layers != 1 ||
                  expressions::is_zero(loads.prescribed[1]),
                ExcMessage("Loads/Layer 2/Prescribed displacement must be "
                           "'0; 0': layer 2 is absent (Materials/Number of "
                           "layers = 1)"));
    AssertThrow(materials.n_layers != 1 ||
                  !loads.has_volume_load(Layer::second),
                ExcMessage("Loads/Layer 2/Body force and Loads/Layer "
                           "2/Eigenstrain must be zero ('0; 0', '0; 0; 0'): "
                           "layer 2 is absent (Materials/Number of layers = "
                           "1)"));
    for (const Layer layer : materials.layers())
      for (unsigned int i = 0; i < parts.size(); ++i)
        AssertThrow(
          !geometry.clamped[i] || loads.traction_is_zero(layer, i),
          ExcMessage(
            "Loads/Layer " + std::to_string(static_cast<int>(layer) + 1) + "/" +
            parts.traction_entry(i) + " must be '0; 0': " +
            (parts.gmsh ? parts.names[i] : "the " + parts.names[i] + " side") +
            " is clamped (Geometry/Clamped sides)"));
    check_plies(scene, parts);
    check_interfaces(scene);
    check_growth_relations(scene);
  }


  void
  check_interfaces(const Scene &scene)
  {
    // (The layers are glued along every interface; a Gmsh scene's regions
    // come with its own meshes.)
    if (scene.geometry.further_interfaces.empty())
      return;
    const std::string entry = "Geometry/Interfaces above Sigma";
    AssertThrow(scene.mesh.mesh_files.empty(),
                ExcMessage(entry + " cuts the rectangle's structured meshes "
                                   "into regions: Mesh/Mesh files must be "
                                   "empty"));
  }


  void
  check_plies(const Scene &scene, const BoundaryParts &parts)
  {
    const auto &geometry = scene.geometry;
    for (unsigned int l = 0; l < scene.materials.n_layers; ++l)
      {
        AssertThrow(scene.materials.ply_groups[l].empty() ||
                      (parts.gmsh && scene.mesh.mesh_files.empty()),
                    ExcMessage("Materials/Layer " + std::to_string(l + 1) +
                               "/Ply groups names physical surfaces of a "
                               "Gmsh scene; without Geometry/Gmsh file (or "
                               "with Mesh/Mesh files) it must be empty: the "
                               "rectangle scene states plies by Ply "
                               "heights"));
        const auto &heights = scene.materials.ply_heights[l];
        if (heights.empty())
          continue;
        const std::string entry =
          "Materials/Layer " + std::to_string(l + 1) + "/Ply heights";
        AssertThrow(!parts.gmsh && scene.mesh.mesh_files.empty(),
                    ExcMessage(entry +
                               " states plies of the rectangle scene, whose "
                               "meshes fit them; with Geometry/Gmsh file or "
                               "Mesh/Mesh files it must be empty"));
        for (const double y : heights)
          AssertThrow(y > geometry.y_min && y < geometry.y_max,
                      ExcMessage(entry + " must lie strictly inside Omega, " +
                                 entries::number(geometry.y_min) + " < y < " +
                                 entries::number(geometry.y_max) + ", got " +
                                 entries::number(y)));
      }
  }


  void
  check_growth_relations(const Scene &scene)
  {
    const auto &fracture = scene.fracture;
    const auto &factors  = scene.loads.load_factors;
    const bool  growth   = fracture.growth != CrackGrowth::none;
    if (scene.mesh.target_accuracy > 0)
      {
        AssertThrow(!growth,
                    ExcMessage("Mesh/Target accuracy applies to the mesh "
                               "cycles of a static run, not to Fracture/Crack "
                               "growth (its steps run on one mesh)"));
        AssertThrow(scene.mesh.n_cycles >= 2,
                    ExcMessage("Mesh/Target accuracy needs Mesh/Number of "
                               "cycles >= 2 (the most cycles to reach it), "
                               "got 1"));
        AssertThrow(scene.mesh.target_quantity != TargetQuantity::G ||
                      fracture.energy_release_rate,
                    ExcMessage("Mesh/Target quantity = G needs Fracture/Energy "
                               "release rate = true (or Mesh/Target quantity = "
                               "energy)"));
      }
    AssertThrow(growth || scene.cohesive.active() ||
                  (factors.size() == 1 && factors[0] == 1),
                ExcMessage("Loads/Load factor must be 1 without "
                           "Fracture/Crack growth or Cohesive/Law (it sets "
                           "the loads of their steps)"));
    if (!growth)
      return;
    AssertThrow(fracture.energy_release_rate,
                ExcMessage("Fracture/Crack growth needs Fracture/Energy "
                           "release rate = true"));
    AssertThrow(!scene.contact.frictional(),
                ExcMessage("Fracture/Crack growth needs Contact/Friction = "
                           "none: with friction the growth depends on the "
                           "path of the slip, which is not tracked"));
    AssertThrow(scene.mesh.refinement == Refinement::global,
                ExcMessage("Fracture/Crack growth needs Mesh/Refinement = "
                           "global: the tips move along Sigma on the meshes "
                           "of the last cycle"));
    AssertThrow(fracture.growth != CrackGrowth::sweep || factors.size() == 1,
                ExcMessage("Fracture/Crack growth = sweep needs one Loads/Load "
                           "factor (the load of every crack length)"));
    // Factors that scale no load would repeat one state.
    bool scaled = false;
    for (const double lambda : factors)
      scaled = scaled || lambda != 1;
    const auto scales     = scene.loads.load_factor_scales;
    const bool mechanical = has_mechanical_load(scene);
    const bool thermal    = has_thermal_load(scene);
    const bool nothing =
      scales == LoadParameters::Scaled::mechanical ? !mechanical :
      scales == LoadParameters::Scaled::thermal    ? !thermal :
                                                     !mechanical && !thermal;
    AssertThrow(!scaled || !nothing,
                ExcMessage(
                  std::string("Loads/Load factor scales = ") +
                  (scales == LoadParameters::Scaled::mechanical ? "mechanical" :
                   scales == LoadParameters::Scaled::thermal    ? "thermal" :
                                                                  "all") +
                  ": the scene has no such load, so the load factors change "
                  "nothing; " +
                  (scales == LoadParameters::Scaled::mechanical && thermal ?
                     "set Loads/Load factor scales = thermal to scale the "
                     "temperature change and eigenstrains" :
                     "give the scene a load or choose what the factors "
                     "scale")));
    for (unsigned int k = 1; k < factors.size(); ++k)
      AssertThrow(factors[k] > factors[k - 1],
                  ExcMessage("Loads/Load factor must increase with "
                             "Fracture/Crack growth = quasi-static, got " +
                             std::to_string(factors[k - 1]) + " then " +
                             std::to_string(factors[k])));
  }


  bool
  has_thermal_load(const Scene &scene)
  {
    for (const Layer layer : scene.materials.layers())
      if (scene.materials.has_layer(layer))
        {
          const unsigned int l = static_cast<unsigned int>(layer);
          if (!expressions::is_zero(scene.loads.eigenstrain[l]))
            return true;
          for (const Subdomain sd : {Subdomain::minus, Subdomain::plus})
            for (const LayerMaterial &m :
                 scene.materials.ply_materials(layer, sd))
              if (scene.loads.has_thermal_load(m))
                return true;
        }
    return false;
  }


  bool
  has_mechanical_load(const Scene &scene)
  {
    const LoadParameters &loads = scene.loads;
    for (const Layer layer : scene.materials.layers())
      if (scene.materials.has_layer(layer))
        {
          const unsigned int l = static_cast<unsigned int>(layer);
          if (!expressions::is_zero(loads.body_force[l]) ||
              !expressions::is_zero(loads.prescribed[l]))
            return true;
          for (unsigned int i = 0; i < loads.parts.size(); ++i)
            if (!loads.traction_is_zero(layer, i))
              return true;
        }
    return false;
  }
} // namespace bilayer
