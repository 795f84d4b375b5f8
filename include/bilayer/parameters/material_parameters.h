#ifndef bilayer_material_parameters_h
#define bilayer_material_parameters_h

#include <deal.II/base/parameter_handler.h>

#include <bilayer/core/layout.h>
#include <bilayer/physics/elastic_law.h>
#include <bilayer/physics/plies.h>

#include <algorithm>
#include <array>
#include <optional>
#include <string>
#include <vector>

/**
 * The subsection Materials: the number of layers, each layer's entries
 * (LayerMaterial, elastic_law.h: the law's own parameters), in its
 * subsections Omega- and Omega+ the law entries that differ on one side of
 * Sigma (empty: as the layer), and its plies: the cell groups of the
 * regions, horizontal bands between the heights Ply heights (subsections
 * Ply 1, Ply 2, ... from the bottom) or the Gmsh physical surfaces Ply
 * groups (Ply 1 ... Ply n in their order, Ply n+1 the cells in none), each
 * with the law entries that differ in it.
 */
namespace bilayer
{
  /// The number of plies of each layer (the subsections Ply 1 ... Ply n
  /// that Materials/Layer k declares): one more than its ply heights or
  /// ply groups; one
  /// per layer slot (at least two: Layer 1 and Layer 2 are always
  /// declared), so its size also says how many Layer k subsections the
  /// Materials and Loads sections declare.
  using PlyCounts = std::vector<unsigned int>;

  struct MaterialParameters
  {
    /// The material of each layer slot (Materials/Layer k; layers k >= 3
    /// default to layer 2's material).
    std::vector<LayerMaterial> layer = {{200.0, 0.28}, {112.0, 0.32}};
    /**
     * side[l][s]: the material of layer l on the subdomain s (0: Omega-,
     * 1: Omega+) where Materials/Layer k/Omega- or Omega+ gives a law entry:
     * the layer's material with those entries; empty where the side gives
     * none (then the side has the layer's material, the very same object).
     */
    std::vector<std::array<std::optional<LayerMaterial>, 2>> side{2};
    /// 2: the two-layer structure; 1: layer 2 absent (a single body);
    /// N > 2: N layers stacked through the thickness, each glued along
    /// Sigma to the layer below it.
    unsigned int n_layers = 2;
    /// The most layers a scene may stack.
    static constexpr unsigned int max_layers = 64;
    /**
     * ply_heights[l]: Materials/Layer k/Ply heights, the heights
     * y_1 < ... < y_{n-1} at which the material of layer l changes. Ply j
     * (0-based; the entries' Ply j+1) is the band y_j < y < y_{j+1} of the
     * plane (y_0 = -inf, y_n = +inf), in either region it crosses. Empty:
     * one ply, the whole layer.
     */
    std::vector<std::vector<double>> ply_heights{2};
    /**
     * ply_groups[l]: Materials/Layer k/Ply groups, the names of Gmsh
     * physical surfaces inside the regions. Ply j (0-based; the entries'
     * Ply j+1) is the cells of group j; ply n (Ply n+1) the cells in none
     * of the n groups. Empty: plies by heights, or one ply.
     */
    std::vector<std::vector<std::string>> ply_groups{2};
    /**
     * ply[l][s][j]: the material of ply j of layer l on the subdomain s
     * where Materials/Layer k/Ply j+1 gives a law entry: the side's
     * material with those entries; empty where the ply gives none (then
     * the ply has the side's material, the very same object).
     */
    std::vector<std::array<std::vector<std::optional<LayerMaterial>>, 2>> ply{
      2};

    /// The material of the layer @p l on the subdomain @p s outside its
    /// plies' entries (the layer's with the side's entries).
    const LayerMaterial &
    material(const Layer l, const Subdomain s) const
    {
      const auto &m =
        side[static_cast<unsigned int>(l)][static_cast<unsigned int>(s)];
      return m ? *m : layer[static_cast<unsigned int>(l)];
    }

    /// The material of ply @p j of the layer @p l on the subdomain @p s.
    const LayerMaterial &
    material(const Layer l, const Subdomain s, const unsigned int j) const
    {
      const auto &plies =
        ply[static_cast<unsigned int>(l)][static_cast<unsigned int>(s)];
      return j < plies.size() && plies[j] ? *plies[j] : material(l, s);
    }

    /// The number of plies of the layer @p l (1: no Ply heights, no Ply
    /// groups).
    unsigned int
    n_plies(const Layer l) const
    {
      const unsigned int i = static_cast<unsigned int>(l);
      return std::max(ply_heights[i].size(), ply_groups[i].size()) + 1;
    }

    /// How the layer @p l is cut into plies (the material ids of the ply
    /// groups: all_ply_groups(), Geometry::ply_material_id()).
    PlyDivision
    division(const Layer l) const;

    /// The ply groups of the layers present, each once, in the order in
    /// which the layers name them: group k has the material id k + 1.
    std::vector<std::string>
    all_ply_groups() const;

    /// The materials of the layer @p l on the subdomain @p s, by ply.
    std::vector<LayerMaterial>
    ply_materials(const Layer l, const Subdomain s) const;

    /// The ply heights of the layers present, sorted, each once: the
    /// heights that the meshes fit.
    std::vector<double>
    all_ply_heights() const;

    bool
    has_layer(const Layer l) const
    {
      return l == Layer::first || static_cast<unsigned int>(l) < n_layers;
    }

    /// The layer slots (Layer 1, Layer 2, ... Layer max(2, N)): a scene
    /// with one layer keeps the slot of layer 2 (has_layer() false).
    std::vector<Layer>
    layers() const
    {
      std::vector<Layer> all;
      for (unsigned int l = 0; l < layer.size(); ++l)
        all.push_back(static_cast<Layer>(l));
      return all;
    }

    /// Declare the entries, with the subsections Layer 1 ... Layer n
    /// (n = n_plies.size() >= 2) and in layer l the subsections Ply 1 ...
    /// Ply n_plies[l].
    static void
    declare_parameters(dealii::ParameterHandler &prm,
                       const PlyCounts          &n_plies = {1, 1});

    /// The number of plies that the texts @p heights of a Ply heights entry
    /// and @p groups of a Ply groups entry state (one more than the items of
    /// the longer; 1 where both are empty or broken: the full parse reports
    /// it).
    static unsigned int
    count_plies(const std::string &heights, const std::string &groups);

    /// The heights of the entry @p entry (Ply heights) of the text
    /// @p text, checked to increase strictly.
    static std::vector<double>
    parse_ply_heights(const std::string &text, const std::string &entry);

    /// The names of the entry @p entry (Ply groups) of the text @p text:
    /// Gmsh physical surfaces, each once, none a region.
    static std::vector<std::string>
    parse_ply_groups(const std::string &text, const std::string &entry);

    /// The entries of a layer's law ("Law", "Young's modulus", ...,
    /// "Stiffness"), which its sides may override.
    static const std::vector<std::string> &
    law_entry_names();

    /// Whether a layer of Law = @p law ("isotropic", "orthotropic",
    /// "anisotropic") in @p plane_state ("plane strain", "plane stress")
    /// reads the entry @p name of Materials/Layer k (Plane state included).
    static bool
    law_reads(const std::string &law,
              const std::string &plane_state,
              const std::string &name);
    void
    parse_parameters(dealii::ParameterHandler &prm);
  };
} // namespace bilayer

#endif
