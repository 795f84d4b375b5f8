#ifndef bilayer_material_parameters_h
#define bilayer_material_parameters_h

#include <deal.II/base/parameter_handler.h>

#include <bilayer/core/layout.h>
#include <bilayer/physics/elastic_law.h>

#include <array>

/**
 * The subsection Materials: the number of layers and each layer's entries
 * (LayerMaterial, elastic_law.h: the law's own parameters).
 */
namespace bilayer
{
  struct MaterialParameters
  {
    std::array<LayerMaterial, 2> layer = {{{200.0, 0.28}, {112.0, 0.32}}};
    /// 2: the two-layer structure; 1: layer 2 absent (a single body).
    unsigned int n_layers = 2;

    bool
    has_layer(const Layer l) const
    {
      return l == Layer::first || n_layers == 2;
    }

    static void
    declare_parameters(dealii::ParameterHandler &prm);
    void
    parse_parameters(dealii::ParameterHandler &prm);
  };
} // namespace bilayer

#endif
