#include <deal.II/base/exceptions.h>

#include <bilayer/parameters/thermal_volume_load.h>

#include <cmath>
#include <sstream>

namespace bilayer
{
  using namespace dealii;

  ThermalVolumeLoad::ThermalVolumeLoad(
    std::unique_ptr<VolumeLoad>        base,
    std::unique_ptr<FunctionParser<2>> temperature,
    const LayerMaterial               &material,
    const double                       length_scale)
    : base(std::move(base))
    , temperature(std::move(temperature))
    , per_kelvin(
        make_elastic_law(material)->plane_eigenstrain(thermal_strain(material)))
    , length(length_scale)
  {}


  double
  ThermalVolumeLoad::temperature_change(const Point<2> &p) const
  {
    const double dT = temperature->value(p);
    if (!std::isfinite(dT))
      {
        std::ostringstream message;
        message.precision(6);
        message << "Loads/Temperature change is not finite at (x, y) = ("
                << p[0] << ", " << p[1] << "): it is " << dT;
        AssertThrow(false, ExcMessage(message.str()));
      }
    return dT;
  }


  Tensor<1, 2>
  ThermalVolumeLoad::body_force(const Point<2> &p) const
  {
    return base != nullptr ? base->body_force(p) : Tensor<1, 2>();
  }


  SymmetricTensor<2, 2>
  ThermalVolumeLoad::eigenstrain(const Point<2> &p) const
  {
    SymmetricTensor<2, 2> eps = temperature_change(p) * per_kelvin.in_plane;
    if (base != nullptr && base->has_eigenstrain())
      eps += base->eigenstrain(p);
    return eps;
  }


  double
  ThermalVolumeLoad::eigenstress_zz(const Point<2> &p) const
  {
    return temperature_change(p) * per_kelvin.sigma_zz_offset;
  }
} // namespace bilayer
