#include <bilayer/physics/elastic_law.h>

#include <cmath>

namespace bilayer
{
  using namespace dealii;

  void
  ElasticLaw::add_stiffness(const std::vector<SymmetricTensor<2, 2>> &eps,
                            const double                              JxW,
                            FullMatrix<double> &cell_matrix) const
  {
    const unsigned int n = eps.size();
    for (unsigned int i = 0; i < n; ++i)
      for (unsigned int j = i; j < n; ++j)
        cell_matrix(i, j) += bilinear_form(eps[i], eps[j]) * JxW;
  }


  double
  ElasticLaw::von_mises(const SymmetricTensor<2, 2> &s, const double s_zz)
  {
    return std::sqrt(0.5 * ((s[0][0] - s[1][1]) * (s[0][0] - s[1][1]) +
                            (s[1][1] - s_zz) * (s[1][1] - s_zz) +
                            (s_zz - s[0][0]) * (s_zz - s[0][0])) +
                     3 * s[0][1] * s[0][1]);
  }


  IsotropicPlaneStrain::IsotropicPlaneStrain(const double youngs_modulus,
                                             const double poisson_ratio)
    : E(youngs_modulus)
    , nu(poisson_ratio)
    , mu(youngs_modulus / (2. * (1. + poisson_ratio)))
    , lambda(2. * poisson_ratio * mu / (1. - 2. * poisson_ratio))
  {}


  void
  IsotropicPlaneStrain::add_stiffness(
    const std::vector<SymmetricTensor<2, 2>> &eps,
    const double                              JxW,
    FullMatrix<double>                       &cell_matrix) const
  {
    // The traces once per shape function (the divergences of the shape
    // functions), then the same sum as bilinear_form().
    thread_local std::vector<double> div;
    const unsigned int               n = eps.size();
    div.resize(n);
    for (unsigned int i = 0; i < n; ++i)
      div[i] = trace(eps[i]);
    for (unsigned int i = 0; i < n; ++i)
      for (unsigned int j = i; j < n; ++j)
        cell_matrix(i, j) +=
          (2 * mu * scalar_product(eps[i], eps[j]) + lambda * div[i] * div[j]) *
          JxW;
  }


  SymmetricTensor<4, 2>
  IsotropicPlaneStrain::tangent() const
  {
    return 2 * mu * identity_tensor<2>() +
           lambda * outer_product(unit_symmetric_tensor<2>(),
                                  unit_symmetric_tensor<2>());
  }


  std::map<std::string, double>
  IsotropicPlaneStrain::load_constants() const
  {
    return {{"E", E}, {"nu", nu}, {"mu", mu}, {"lambda", lambda}};
  }


  Eigenstrain3D
  thermal_strain(const LayerMaterial &material)
  {
    const std::array<double, 3> &a = material.thermal_expansion;
    Eigenstrain3D                eps;
    if (material.law == MaterialLaw::isotropic)
      {
        eps.in_plane = a[0] * unit_symmetric_tensor<2>();
        eps.zz       = a[0];
      }
    else if (material.law == MaterialLaw::orthotropic)
      {
        // R diag(alpha_1, alpha_2) R^T: the material axis 1 is R e_x.
        const Tensor<2, 2> R = plane_laws::rotation(material.orientation_angle);
        Tensor<2, 2>       A;
        A[0][0]      = a[0];
        A[1][1]      = a[1];
        eps.in_plane = symmetrize(Tensor<2, 2>(R * A * transpose(R)));
        eps.zz       = a[2];
      }
    else
      {
        eps.in_plane[0][0] = a[0];
        eps.in_plane[1][1] = a[1];
        eps.in_plane[0][1] = a[2];
      }
    return eps;
  }


  bool
  has_thermal_expansion(const LayerMaterial &material)
  {
    for (const double a : material.thermal_expansion)
      if (a != 0)
        return true;
    return false;
  }


  std::unique_ptr<const ElasticLaw>
  make_elastic_law(const LayerMaterial &material)
  {
    switch (material.law)
      {
        case MaterialLaw::orthotropic:
          return plane_laws::orthotropic(material.orthotropic,
                                         material.plane_state,
                                         material.orientation_angle);
        case MaterialLaw::anisotropic:
          return plane_laws::anisotropic(material.stiffness);
        case MaterialLaw::isotropic:
          break;
      }
    if (material.plane_state == PlaneState::plane_stress)
      return plane_laws::isotropic_plane_stress(material.youngs_modulus,
                                                material.poisson_ratio);
    return std::make_unique<IsotropicPlaneStrain>(material.youngs_modulus,
                                                  material.poisson_ratio);
  }
} // namespace bilayer
