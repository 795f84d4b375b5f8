#ifndef bilayer_thermal_volume_load_h
#define bilayer_thermal_volume_load_h

#include <deal.II/base/function_parser.h>

#include <bilayer/physics/elastic_law.h>
#include <bilayer/physics/volume_load.h>

#include <memory>
#include <string>

namespace bilayer
{
  /**
   * The volume load of one subproblem with a temperature change dT(x, y)
   * (Loads/Temperature change) on a material that expands
   * (Materials/Layer k/Thermal expansion): the layer's own volume load
   * (body force and Eigenstrain entries, @p base, may be null) plus the
   * plane eigenstrain that the subproblem's law gives the 3-D thermal
   * strain alpha dT (ElasticLaw::plane_eigenstrain(), linear in dT:
   * computed once per kelvin):
   *
   *   eps*(p) = eps*_base(p) + dT(p) eps*_eff,1K,
   *   sigma_zz offset(p) = dT(p) sigma_zz,1K
   *
   * (isotropic plane strain: eps*_eff,1K = (1 + nu) alpha I, sigma_zz,1K =
   * -E alpha; plane stress: alpha I, 0). Each value of dT is checked: one
   * that is not finite throws "Loads/Temperature change is not finite at
   * (x, y) = (...)". The gradients are VolumeLoad's fourth-order
   * differences of eigenstrain() with the step 1e-3 of @p length_scale.
   */
  class ThermalVolumeLoad : public VolumeLoad
  {
  public:
    ThermalVolumeLoad(std::unique_ptr<VolumeLoad>                base,
                      std::unique_ptr<dealii::FunctionParser<2>> temperature,
                      const LayerMaterial                       &material,
                      const double                               length_scale);

    dealii::Tensor<1, 2>
    body_force(const dealii::Point<2> &p) const override;

    dealii::SymmetricTensor<2, 2>
    eigenstrain(const dealii::Point<2> &p) const override;

    double
    eigenstress_zz(const dealii::Point<2> &p) const override;

    bool
    has_body_force() const override
    {
      return base != nullptr && base->has_body_force();
    }

    bool
    has_eigenstrain() const override
    {
      return true;
    }

    double
    length_scale() const override
    {
      return length;
    }

    /// The temperature change at @p p [K], checked finite.
    double
    temperature_change(const dealii::Point<2> &p) const;

  private:
    std::unique_ptr<VolumeLoad>                base;
    std::unique_ptr<dealii::FunctionParser<2>> temperature;
    /// The plane eigenstrain of 1 K.
    PlaneEigenstrain per_kelvin;
    const double     length;
  };
} // namespace bilayer

#endif
