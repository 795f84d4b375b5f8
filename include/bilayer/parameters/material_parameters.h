#ifndef bilayer_material_parameters_h
#define bilayer_material_parameters_h

#include <deal.II/base/parameter_handler.h>

#include <bilayer/core/layout.h>
#include <bilayer/physics/elastic_law.h>

#include <array>
#include <optional>
#include <string>
#include <vector>

/**
 * The subsection Materials: the number of layers, each layer's entries
 * (LayerMaterial, elastic_law.h: the law's own parameters) and, in its
 * subsections Omega- and Omega+, the law entries that differ on one side of
 * Sigma (empty: as the layer).
 */
namespace bilayer
{
  struct MaterialParameters
  {
    std::array<LayerMaterial, 2> layer = {{{200.0, 0.28}, {112.0, 0.32}}};
    /**
     * side[l][s]: the material of layer l on the subdomain s (0: Omega-,
     * 1: Omega+) where Materials/Layer k/Omega- or Omega+ gives a law entry:
     * the layer's material with those entries; empty where the side gives
     * none (then the side has the layer's material, the very same object).
     */
    std::array<std::array<std::optional<LayerMaterial>, 2>, 2> side;
    /// 2: the two-layer structure; 1: layer 2 absent (a single body).
    unsigned int n_layers = 2;

    /// The material of the layer @p l on the subdomain @p s.
    const LayerMaterial &
    material(const Layer l, const Subdomain s) const
    {
      const auto &m =
        side[static_cast<unsigned int>(l)][static_cast<unsigned int>(s)];
      return m ? *m : layer[static_cast<unsigned int>(l)];
    }

    bool
    has_layer(const Layer l) const
    {
      return l == Layer::first || n_layers == 2;
    }

    static void
    declare_parameters(dealii::ParameterHandler &prm);

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
