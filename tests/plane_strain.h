#ifndef bilayer_tests_plane_strain_h
#define bilayer_tests_plane_strain_h

// An isotropic plane-strain material from its engineering constants, as
// the tests compute it independently of the program's laws.

#include <deal.II/base/symmetric_tensor.h>

struct PlaneStrain
{
  double E, nu;

  double
  mu() const
  {
    return E / (2 * (1 + nu));
  }
  double
  lambda() const
  {
    return E * nu / ((1 + nu) * (1 - 2 * nu));
  }
  /// Kolosov's constant 3 - 4 nu.
  double
  kappa() const
  {
    return 3 - 4 * nu;
  }
  /// The plane-strain compliances b11 = b22 and b12.
  double
  b11() const
  {
    return (1 - nu * nu) / E;
  }
  double
  b12() const
  {
    return -nu * (1 + nu) / E;
  }
  dealii::SymmetricTensor<2, 2>
  hooke(const dealii::SymmetricTensor<2, 2> &e) const
  {
    return lambda() * dealii::trace(e) * dealii::unit_symmetric_tensor<2>() +
           2 * mu() * e;
  }
};

#endif
