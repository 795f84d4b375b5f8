#ifndef bilayer_material_h
#define bilayer_material_h

#include <deal.II/base/symmetric_tensor.h>

#include <bilayer/parameters.h>

#include <cmath>

namespace bilayer
{
  /**
   * The plane-strain linear elastic law of one layer (docs/problem.md §1):
   *   sigma(w) = 2 mu eps(w) + lambda tr(eps(w)) I,
   *   sigma_zz = lambda tr(eps(w))   (eps_zz = 0),
   * with the Lame constants of LayerMaterial. The one place where stresses
   * and the energy density are computed from strains: the stiffness
   * assembly, the error estimator and the stress output use it.
   */
  class PlaneStrainLaw
  {
  public:
    explicit PlaneStrainLaw(const LayerMaterial &material)
      : mu(material.mu())
      , lambda(material.lambda())
    {}

    /// The in-plane stress of the strain @p eps.
    dealii::SymmetricTensor<2, 2>
    stress(const dealii::SymmetricTensor<2, 2> &eps) const
    {
      return 2 * mu * eps +
             lambda * dealii::trace(eps) * dealii::unit_symmetric_tensor<2>();
    }

    /// The out-of-plane stress sigma_zz of the strain @p eps.
    double
    out_of_plane_stress(const dealii::SymmetricTensor<2, 2> &eps) const
    {
      return lambda * dealii::trace(eps);
    }

    /**
     * sigma(eps_a) : eps_b written with the divergences div_a = tr(eps_a),
     * div_b = tr(eps_b): the integrand of the bilinear form a(., .).
     */
    double
    energy_density(const dealii::SymmetricTensor<2, 2> &eps_a,
                   const double                         div_a,
                   const dealii::SymmetricTensor<2, 2> &eps_b,
                   const double                         div_b) const
    {
      return 2 * mu * dealii::scalar_product(eps_a, eps_b) +
             lambda * div_a * div_b;
    }

    /// The von Mises stress of the in-plane stress @p s and sigma_zz.
    static double
    von_mises(const dealii::SymmetricTensor<2, 2> &s, const double s_zz)
    {
      return std::sqrt(0.5 * ((s[0][0] - s[1][1]) * (s[0][0] - s[1][1]) +
                              (s[1][1] - s_zz) * (s[1][1] - s_zz) +
                              (s_zz - s[0][0]) * (s_zz - s[0][0])) +
                       3 * s[0][1] * s[0][1]);
    }

    /// The shear modulus mu [stress].
    double
    shear_modulus() const
    {
      return mu;
    }

  private:
    double mu, lambda;
  };
} // namespace bilayer

#endif
