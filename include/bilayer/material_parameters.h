#ifndef bilayer_material_parameters_h
#define bilayer_material_parameters_h

#include <deal.II/base/parameter_handler.h>

#include <bilayer/layout.h>

#include <array>

/**
 * The subsection Materials: the number of layers and each layer's
 * isotropic plane-strain constants.
 */
namespace bilayer
{
  /// Isotropic plane-strain material of one layer.
  struct LayerMaterial
  {
    double youngs_modulus = 200.0;
    double poisson_ratio  = 0.28;

    double
    mu() const
    {
      return youngs_modulus / (2. * (1. + poisson_ratio));
    }
    double
    lambda() const
    {
      return 2. * poisson_ratio * mu() / (1. - 2. * poisson_ratio);
    }
  };

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
