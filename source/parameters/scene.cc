#include <deal.II/base/utilities.h>

#include <bilayer/parameters/scene.h>
#include <bilayer/parameters/scene_checks.h>

#include <algorithm>
#include <map>
#include <set>
#include <sstream>

namespace bilayer
{
  using namespace dealii;


  void
  Scene::declare_parameters(ParameterHandler    &prm,
                            const BoundaryParts &parts,
                            const PlyCounts     &n_plies)
  {
    GeometryParameters::declare_parameters(prm, parts);
    MeshParameters::declare_parameters(prm);
    MaterialParameters::declare_parameters(prm, n_plies);
    LoadParameters::declare_parameters(prm, parts, n_plies.size());
    ContactParameters::declare_parameters(prm);
    SolverParameters::declare_parameters(prm);
    FractureParameters::declare_parameters(prm);
    CohesiveParameters::declare_parameters(prm);
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
    cohesive.parse_parameters(prm);
    output.parse_parameters(prm);
    check_scene_relations(*this, parts);
    // Gmsh scenes: the loads are checked where they act, on the assembled
    // loads (ElasticSubproblem).
    if (!parts.gmsh)
      check_rectangle_loads(*this, parts);
  }


  namespace
  {
    /// Calls @p f(line, path) for each line of a short parameter file
    /// (path "Section/Subsection/Entry" for entries, "" for other lines).
    template <typename Function>
    void
    for_each_line(const std::string &short_prm, const Function &f)
    {
      std::vector<std::string> sections;
      std::istringstream       in(short_prm);
      for (std::string line; std::getline(in, line);)
        {
          const std::string trimmed = Utilities::trim(line);
          std::string       path;
          if (trimmed.rfind("subsection ", 0) == 0)
            sections.push_back(Utilities::trim(trimmed.substr(11)));
          else if (trimmed == "end" && !sections.empty())
            sections.pop_back();
          else if (trimmed.rfind("set ", 0) == 0)
            {
              const auto equal = trimmed.find('=');
              for (const auto &section : sections)
                path += section + "/";
              path += Utilities::trim(trimmed.substr(4, equal - 4));
            }
          f(line, path);
        }
    }


    /// Why the elastic-law entry @p path (Materials/Layer k/[side/]name) is
    /// not used: "" if it is or if it is no entry of a law. A layer's entry
    /// is used where a side without its own value reads it.
    std::string
    unused_law_entry(const std::string                        &path,
                     const std::map<std::string, std::string> &values)
    {
      const auto &names = MaterialParameters::law_entry_names();
      const auto  parts = Utilities::split_string_list(path, '/');
      if (parts.size() < 3 || parts.size() > 4 || parts[0] != "Materials" ||
          (std::find(names.begin(), names.end(), parts.back()) == names.end() &&
           parts.back() != "Plane state") ||
          parts.back() == "Law")
        return "";
      const std::string layer = parts[0] + "/" + parts[1] + "/";
      const std::string name  = parts.back();
      const auto        value = [&](const std::string &p) {
        const auto it = values.find(p);
        return it == values.end() ? std::string() : it->second;
      };
      if (name == "Thermal expansion")
        {
          const std::string dT = value("Loads/Temperature change");
          return (parts.size() == 4 && value(path).empty()) ||
                     !(dT.empty() || dT == "0") ?
                   "" :
                   "not used (Loads/Temperature change = 0)";
        }
      const std::string layer_law = value(layer + "Law");
      const std::string plane     = value(layer + "Plane state");
      const auto        side_law  = [&](const std::string &side) {
        const std::string own = value(layer + side + "/Law");
        return own.empty() ? layer_law : own;
      };
      if (parts.size() == 4)
        return value(path).empty() ||
                   MaterialParameters::law_reads(side_law(parts[2]),
                                                 plane,
                                                 name) ?
                 "" :
                 "not used by Law = " + side_law(parts[2]) + " on " + parts[2];
      bool read = false;
      for (const std::string side : {"Omega-", "Omega+"})
        read =
          read || (value(layer + side + "/" + name).empty() &&
                   MaterialParameters::law_reads(side_law(side), plane, name));
      if (read)
        return "";
      for (const std::string side : {"Omega-", "Omega+"})
        if (MaterialParameters::law_reads(side_law(side), plane, name) &&
            !value(layer + side + "/" + name).empty())
          return "given on each side where a law reads it";
      const std::string law = side_law("Omega-") == side_law("Omega+") ?
                                "Law = " + side_law("Omega-") :
                                "the laws of Omega- and Omega+";
      return "not used by " + law +
             (MaterialParameters::law_reads(side_law("Omega-"),
                                            "plane strain",
                                            name) ||
                  MaterialParameters::law_reads(side_law("Omega+"),
                                                "plane strain",
                                                name) ?
                " in " + plane :
                "");
    }
  } // namespace


  namespace
  {
    /// Why the friction entry @p path is not read (empty if it is): the
    /// bound only with Tresca, the coefficient and the iterations only with
    /// Coulomb friction.
    std::string
    unused_friction_entry(const std::string                        &path,
                          const std::map<std::string, std::string> &values)
    {
      const auto        it  = values.find("Contact/Friction");
      const std::string law = it == values.end() ? "none" : it->second;
      if ((path == "Contact/Friction bound" && law != "tresca") ||
          ((path == "Contact/Friction coefficient" ||
            path == "Contact/Friction iterations" ||
            path == "Contact/Coulomb method") &&
           law != "coulomb"))
        return "not used (Contact/Friction = " + law + ")";
      return "";
    }


    /// Why the growth entry @p path is not read (empty if it is): the
    /// entries of Fracture/Crack growth without growth, the mode II
    /// toughness, the exponent and the mode mix with the mode-independent
    /// law, Written
    /// cycles with growth.
    std::string
    unused_growth_entry(const std::string                        &path,
                        const std::map<std::string, std::string> &values)
    {
      const auto value = [&](const std::string &key, const std::string &def) {
        const auto it = values.find(key);
        return it == values.end() ? def : it->second;
      };
      const std::string growth = value("Fracture/Crack growth", "none");
      const std::set<std::string> growth_entries = {
        "Fracture/Toughness",
        "Fracture/Mode II toughness",
        "Fracture/Mixed-mode law",
        "Fracture/Mixed-mode exponent",
        "Fracture/Mode mix",
        "Fracture/Growth increment",
        "Fracture/Growing tips",
        "Fracture/Exact onsets",
        "Fracture/Maximum growth steps",
        "Output/Written steps",
        "Output/Displacement points"};
      if (growth == "none" && growth_entries.count(path) > 0)
        return "not used (Fracture/Crack growth = none)";
      if (growth != "none" && path == "Output/Written cycles")
        return "not used (Fracture/Crack growth = " + growth +
               ": Output/Written steps)";
      const std::string law =
        value("Fracture/Mixed-mode law", "mode independent");
      if (law == "mode independent" &&
          (path == "Fracture/Mode II toughness" ||
           path == "Fracture/Mixed-mode exponent" ||
           path == "Fracture/Mode mix"))
        return "not used (Fracture/Mixed-mode law = mode independent)";
      return "";
    }
  } // namespace


  std::string
  applicable_entries(const std::string &short_prm, const Scene &scene)
  {
    const std::set<std::string> gmsh_unused = {
      "Geometry/Lower left corner",
      "Geometry/Upper right corner",
      "Geometry/Height of Sigma",
      "Geometry/Crack interval on Sigma",
      "Mesh/Cells along Sigma",
      "Mesh/Cells across each subdomain",
      "Mesh/Cells along Sigma on the plus side",
      "Mesh/Fit crack tips",
      "Mesh/Mesh files"};
    const bool                         gmsh = !scene.geometry.gmsh_file.empty();
    std::map<std::string, std::string> values;
    for_each_line(short_prm,
                  [&](const std::string &line, const std::string &path) {
                    if (!path.empty())
                      values[path] =
                        Utilities::trim(line.substr(line.find('=') + 1));
                  });
    std::string result;
    for_each_line(short_prm,
                  [&](const std::string &line, const std::string &path) {
                    std::string why;
                    if (gmsh && gmsh_unused.count(path) > 0)
                      why = "not used by a Gmsh scene (Geometry/Gmsh file)";
                    else if (scene.materials.n_layers == 1 &&
                             (path.rfind("Materials/Layer 2/", 0) == 0 ||
                              path.rfind("Loads/Layer 2/", 0) == 0))
                      why = "not used (Materials/Number of layers = 1)";
                    else if (!path.empty())
                      why = unused_law_entry(path, values);
                    if (why.empty() && !path.empty())
                      why = unused_friction_entry(path, values);
                    if (why.empty() && !path.empty())
                      why = unused_growth_entry(path, values);
                    if (why.empty())
                      result += line + "\n";
                    else
                      result += line.substr(0, line.find_first_not_of(' ')) +
                                "# " + path + ": " + why + "\n";
                  });
    return result;
  }
} // namespace bilayer
