#include <deal.II/base/exceptions.h>
#include <deal.II/base/utilities.h>

#include <bilayer/gmsh/gmsh_mesh.h>
#include <bilayer/parameters/parameter_entries.h>
#include <bilayer/parameters/parameter_includes.h>
#include <bilayer/parameters/parameter_overrides.h>
#include <bilayer/parameters/scene.h>
#include <bilayer/parameters/suggestions.h>

#include <filesystem>
#include <functional>

namespace bilayer
{
  using namespace dealii;

  namespace
  {
    /**
     * The boundary parts of the scene: the rectangle's sides, or the named
     * curves of Geometry/Gmsh file, read from the parameter file (or text)
     * and the overrides before the other entries are declared (they name
     * the Loads entries). Relative paths are relative to @p base.
     */
    BoundaryParts
    boundary_parts(const std::function<void(ParameterHandler &)> &parse,
                   const std::vector<std::string>                &overrides,
                   const std::filesystem::path                   &base,
                   std::string                                   &gmsh_file,
                   const bool allow_gmsh_commands,
                   PlyCounts &n_plies)
    {
      ParameterHandler first;
      first.enter_subsection("Geometry");
      first.declare_entry("Gmsh file", "", Patterns::Anything());
      first.leave_subsection();
      first.enter_subsection("Mesh");
      first.declare_entry("Gmsh time limit", "600", Patterns::Anything());
      first.leave_subsection();
      first.enter_subsection("Materials");
      first.declare_entry("Number of layers", "2", Patterns::Anything());
      for (unsigned int l = 0; l < MaterialParameters::max_layers; ++l)
        {
          first.enter_subsection(entries::layer_subsection(l));
          first.declare_entry("Ply heights", "", Patterns::Anything());
          first.declare_entry("Ply groups", "", Patterns::Anything());
          first.leave_subsection();
        }
      first.leave_subsection();
      n_plies = {1, 1};
      try
        {
          parse(first);
        }
      catch (...)
        {
          // A broken file: the full parse reports it.
          return BoundaryParts();
        }
      // The layers name the subsections Materials/Layer k and Loads/Layer
      // k, the plies Materials/Layer k/Ply j (a number of layers out of
      // range: the full parse reports it).
      first.enter_subsection("Materials");
      const std::string layers =
        Utilities::trim(overridden_value(overrides,
                                         {"Materials", "Number of layers"},
                                         first.get("Number of layers")));
      first.leave_subsection();
      unsigned int n_layers = 2;
      try
        {
          std::size_t end = 0;
          const int   n   = std::stoi(layers, &end);
          if (end == layers.size() && n >= 1 &&
              n <= static_cast<int>(MaterialParameters::max_layers))
            n_layers = n;
        }
      catch (...)
        {}
      n_plies.assign(Layout::n_slots(n_layers), 1);
      for (unsigned int l = 0; l < n_plies.size(); ++l)
        {
          first.enter_subsection("Materials");
          first.enter_subsection(entries::layer_subsection(l));
          n_plies[l] = MaterialParameters::count_plies(
            overridden_value(
              overrides,
              {"Materials", entries::layer_subsection(l), "Ply heights"},
              first.get("Ply heights")),
            overridden_value(
              overrides,
              {"Materials", entries::layer_subsection(l), "Ply groups"},
              first.get("Ply groups")));
          first.leave_subsection();
          first.leave_subsection();
        }
      first.enter_subsection("Geometry");
      gmsh_file = Utilities::trim(first.get("Gmsh file"));
      first.leave_subsection();
      first.enter_subsection("Mesh");
      std::string time_limit = first.get("Gmsh time limit");
      first.leave_subsection();
      gmsh_file = Utilities::trim(
        overridden_value(overrides, {"Geometry", "Gmsh file"}, gmsh_file));
      time_limit =
        overridden_value(overrides, {"Mesh", "Gmsh time limit"}, time_limit);
      if (gmsh_file.empty())
        return BoundaryParts();
      if (std::filesystem::path(gmsh_file).is_relative())
        gmsh_file = (base / gmsh_file).string();
      // The full parse checks the limit; gmsh runs within it already now.
      GmshOptions options;
      options.allow_commands = allow_gmsh_commands;
      try
        {
          const double limit = std::stod(Utilities::trim(time_limit));
          if (limit >= 1 && limit <= 1e6)
            options.time_limit = limit;
        }
      catch (const std::exception &)
        {}
      const auto names = gmsh_group_names(gmsh_file, options);
      return BoundaryParts::of_gmsh(gmsh_file, names);
    }
  } // namespace


  Scene
  read_scene(ParameterHandler               &prm,
             const std::string              &filename,
             const std::vector<std::string> &overrides,
             const bool                      allow_gmsh_commands)
  {
    const std::vector<std::string> files = parameter_files(filename);
    const auto    base = std::filesystem::path(filename).parent_path();
    std::string   gmsh_file;
    PlyCounts     n_plies;
    BoundaryParts parts = boundary_parts(
      [&](ParameterHandler &first) {
        first.parse_input(filename, "", true, false);
      },
      overrides,
      base,
      gmsh_file,
      allow_gmsh_commands,
      n_plies);
    Scene::declare_parameters(prm, parts, n_plies);
    try
      {
        prm.parse_input(filename, "", false, true);
      }
    catch (const ExceptionBase &e)
      {
        AssertThrow(false, ExcMessage(with_suggestion(prm, e)));
      }

    apply_overrides(prm, overrides);

    Scene scene;
    scene.parse_parameters(prm, parts);
    scene.name = std::filesystem::path(filename).stem().string();
    for (auto &file : scene.mesh.mesh_files)
      if (std::filesystem::path(file).is_relative())
        file = (base / file).string();
    scene.geometry.gmsh_file           = gmsh_file;
    scene.geometry.allow_gmsh_commands = allow_gmsh_commands;
    scene.input_files                  = files;
    return scene;
  }


  Scene
  scene_from_string(const std::string &text, const std::string &name)
  {
    std::string         gmsh_file;
    PlyCounts           n_plies;
    const BoundaryParts parts = boundary_parts(
      [&](ParameterHandler &first) {
        first.parse_input_from_string(text, "", true);
      },
      {},
      "",
      gmsh_file,
      false,
      n_plies);
    ParameterHandler prm;
    Scene::declare_parameters(prm, parts, n_plies);
    prm.parse_input_from_string(text);
    Scene scene;
    scene.parse_parameters(prm, parts);
    scene.geometry.gmsh_file = gmsh_file;
    scene.name               = name;
    return scene;
  }
} // namespace bilayer
