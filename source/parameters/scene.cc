#include <deal.II/base/utilities.h>

#include <bilayer/parameters/scene.h>
#include <bilayer/parameters/scene_checks.h>

#include <set>
#include <sstream>

namespace bilayer
{
  using namespace dealii;


  void
  Scene::declare_parameters(ParameterHandler &prm, const BoundaryParts &parts)
  {
    GeometryParameters::declare_parameters(prm, parts);
    MeshParameters::declare_parameters(prm);
    MaterialParameters::declare_parameters(prm);
    LoadParameters::declare_parameters(prm, parts);
    ContactParameters::declare_parameters(prm);
    SolverParameters::declare_parameters(prm);
    FractureParameters::declare_parameters(prm);
    OutputParameters::declare_parameters(prm);
  }


  void
  Scene::parse_parameters(ParameterHandler &prm, const BoundaryParts &parts)
  {
    geometry.parse_parameters(prm, parts);
    mesh.parse_parameters(prm);
    materials.parse_parameters(prm);
    loads.parse_parameters(prm, materials, parts);
    contact.parse_parameters(prm);
    solver.parse_parameters(prm);
    fracture.parse_parameters(prm);
    output.parse_parameters(prm);
    check_scene_relations(*this, parts);
    // Gmsh scenes: the loads are checked where they act, on the assembled
    // loads (ElasticSubproblem).
    if (!parts.gmsh)
      check_rectangle_loads(*this, parts);
  }


  std::string
  applicable_entries(const std::string &short_prm, const Scene &scene)
  {
    if (scene.geometry.gmsh_file.empty())
      return short_prm;
    const std::set<std::string> unused = {
      "Geometry/Lower left corner",
      "Geometry/Upper right corner",
      "Geometry/Height of Sigma",
      "Geometry/Crack interval on Sigma",
      "Mesh/Cells along Sigma",
      "Mesh/Cells across each subdomain",
      "Mesh/Cells along Sigma on the plus side",
      "Mesh/Fit crack tips",
      "Mesh/Mesh files"};
    std::vector<std::string> sections;
    std::string              result;
    std::istringstream       in(short_prm);
    for (std::string line; std::getline(in, line);)
      {
        const std::string trimmed = Utilities::trim(line);
        if (trimmed.rfind("subsection ", 0) == 0)
          sections.push_back(Utilities::trim(trimmed.substr(11)));
        else if (trimmed == "end" && !sections.empty())
          sections.pop_back();
        else if (trimmed.rfind("set ", 0) == 0)
          {
            const auto  equal = trimmed.find('=');
            std::string path;
            for (const auto &section : sections)
              path += section + "/";
            path += Utilities::trim(trimmed.substr(4, equal - 4));
            if (unused.count(path) > 0)
              {
                result += line.substr(0, line.find_first_not_of(' ')) + "# " +
                          path +
                          ": not used by a Gmsh scene (Geometry/Gmsh file)\n";
                continue;
              }
          }
        result += line + "\n";
      }
    return result;
  }
} // namespace bilayer
