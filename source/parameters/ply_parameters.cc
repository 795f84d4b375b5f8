// The plies of Materials/Layer k: the entries Ply heights and Ply groups
// read, the plies of each layer and the ply heights and groups of all.

#include <deal.II/base/exceptions.h>
#include <deal.II/base/utilities.h>

#include <bilayer/gmsh/gmsh_mesh.h>
#include <bilayer/parameters/material_parameters.h>
#include <bilayer/parameters/parameter_entries.h>

#include <algorithm>

namespace bilayer
{
  using namespace dealii;
  using namespace entries;

  std::vector<double>
  MaterialParameters::parse_ply_heights(const std::string &text,
                                        const std::string &entry)
  {
    std::vector<double> heights;
    if (Utilities::trim(text).empty())
      return heights;
    for (const std::string &item : Utilities::split_string_list(text, ','))
      heights.push_back(to_double(item, entry));
    for (unsigned int i = 1; i < heights.size(); ++i)
      AssertThrow(heights[i] > heights[i - 1],
                  ExcMessage(entry +
                             " must be a list of heights y that increase "
                             "strictly (the ply boundaries from the bottom), "
                             "got '" +
                             text + "'"));
    return heights;
  }


  std::vector<std::string>
  MaterialParameters::parse_ply_groups(const std::string &text,
                                       const std::string &entry)
  {
    std::vector<std::string> groups;
    if (Utilities::trim(text).empty())
      return groups;
    for (const std::string &item : Utilities::split_string_list(text, ','))
      {
        AssertThrow(!item.empty() &&
                      std::find(groups.begin(), groups.end(), item) ==
                        groups.end() &&
                      gmsh_region_number(item) == 0,
                    ExcMessage(entry +
                               " must be a list of the names of Gmsh "
                               "physical surfaces inside the regions, "
                               "each once (not the regions 'Omega-', "
                               "'Omega+', 'Region K' themselves), "
                               "got '" +
                               text + "'"));
        groups.push_back(item);
      }
    return groups;
  }


  unsigned int
  MaterialParameters::count_plies(const std::string &heights,
                                  const std::string &groups)
  {
    try
      {
        return std::max(parse_ply_heights(heights, "").size(),
                        parse_ply_groups(groups, "").size()) +
               1;
      }
    catch (...)
      {
        return 1;
      }
  }


  std::vector<LayerMaterial>
  MaterialParameters::ply_materials(const Layer l, const Subdomain s) const
  {
    std::vector<LayerMaterial> materials;
    for (unsigned int j = 0; j < n_plies(l); ++j)
      materials.push_back(material(l, s, j));
    return materials;
  }


  PlyDivision
  MaterialParameters::division(const Layer l) const
  {
    const unsigned int i = static_cast<unsigned int>(l);
    PlyDivision        division;
    division.heights = ply_heights[i];
    if (!ply_groups[i].empty())
      {
        // Material id 0 and the groups of the other layers: the last ply.
        const auto &groups = ply_groups[i];
        division.by_material_id.push_back(groups.size());
        for (const std::string &name : all_ply_groups())
          division.by_material_id.push_back(
            std::find(groups.begin(), groups.end(), name) - groups.begin());
      }
    return division;
  }


  std::vector<std::string>
  MaterialParameters::all_ply_groups() const
  {
    std::vector<std::string> groups;
    for (unsigned int l = 0; l < n_layers && l < ply_groups.size(); ++l)
      for (const std::string &name : ply_groups[l])
        if (std::find(groups.begin(), groups.end(), name) == groups.end())
          groups.push_back(name);
    return groups;
  }


  std::vector<double>
  MaterialParameters::all_ply_heights() const
  {
    std::vector<double> heights;
    for (unsigned int l = 0; l < n_layers; ++l)
      heights.insert(heights.end(),
                     ply_heights[l].begin(),
                     ply_heights[l].end());
    std::sort(heights.begin(), heights.end());
    heights.erase(std::unique(heights.begin(), heights.end()), heights.end());
    return heights;
  }


} // namespace bilayer
