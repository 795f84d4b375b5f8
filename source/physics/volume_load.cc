#include <bilayer/physics/volume_load.h>

namespace bilayer
{
  using namespace dealii;

  namespace
  {
    /// The fourth-order central difference of @p field at @p p along axis
    /// @p j with the step @p h.
    template <typename Value, typename Field>
    Value
    central_difference(const Field       &field,
                       const Point<2>    &p,
                       const unsigned int j,
                       const double       h)
    {
      Tensor<1, 2> step;
      step[j] = h;
      return (8. * (field(p + step) - field(p - step)) -
              (field(p + 2. * step) - field(p - 2. * step))) /
             (12. * h);
    }
  } // namespace


  Tensor<2, 2>
  VolumeLoad::body_force_gradient(const Point<2> &p) const
  {
    const double h     = gradient_step_fraction * length_scale();
    const auto   force = [this](const Point<2> &x) { return body_force(x); };
    Tensor<2, 2> gradient;
    for (unsigned int j = 0; j < 2; ++j)
      {
        const Tensor<1, 2> d = central_difference<Tensor<1, 2>>(force, p, j, h);
        for (unsigned int i = 0; i < 2; ++i)
          gradient[i][j] = d[i];
      }
    return gradient;
  }


  std::array<SymmetricTensor<2, 2>, 2>
  VolumeLoad::eigenstrain_gradient(const Point<2> &p) const
  {
    const double h      = gradient_step_fraction * length_scale();
    const auto   strain = [this](const Point<2> &x) { return eigenstrain(x); };
    return {{central_difference<SymmetricTensor<2, 2>>(strain, p, 0, h),
             central_difference<SymmetricTensor<2, 2>>(strain, p, 1, h)}};
  }
} // namespace bilayer


namespace bilayer
{
  using namespace dealii;

  Tensor<1, 2>
  CellLoad::body_force(const Point<2> &p) const
  {
    return load != nullptr ? factor * load->body_force(p) : Tensor<1, 2>();
  }


  SymmetricTensor<2, 2>
  CellLoad::eigenstrain(const Point<2> &p) const
  {
    if (load == nullptr)
      return SymmetricTensor<2, 2>();
    return preload == 1 ? load->eigenstrain(p) : preload * load->eigenstrain(p);
  }


  double
  CellLoad::eigenstress_zz(const Point<2> &p) const
  {
    return load != nullptr ? preload * load->eigenstress_zz(p) : 0.;
  }


  Tensor<2, 2>
  CellLoad::body_force_gradient(const Point<2> &p) const
  {
    return load != nullptr ? factor * load->body_force_gradient(p) :
                             Tensor<2, 2>();
  }


  std::array<SymmetricTensor<2, 2>, 2>
  CellLoad::eigenstrain_gradient(const Point<2> &p) const
  {
    if (load == nullptr)
      return std::array<SymmetricTensor<2, 2>, 2>();
    auto gradient = load->eigenstrain_gradient(p);
    if (preload != 1)
      for (auto &g : gradient)
        g *= preload;
    return gradient;
  }
} // namespace bilayer
