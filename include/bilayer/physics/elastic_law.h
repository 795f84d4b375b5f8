#ifndef bilayer_elastic_law_h
#define bilayer_elastic_law_h

#include <deal.II/base/symmetric_tensor.h>
#include <deal.II/lac/full_matrix.h>

#include <map>
#include <memory>
#include <string>
#include <vector>

namespace bilayer
{
  /**
   * The entries of Materials/Layer k: the material of one layer (today
   * isotropic: Young's modulus [stress] and Poisson's ratio).
   */
  struct LayerMaterial
  {
    double youngs_modulus = 200.0;
    double poisson_ratio  = 0.28;
  };


  /**
   * The linear elastic law of one layer on one subdomain (docs/problem.md
   * §1): sigma(w) = C eps(w) with a constant tangent C, in-plane (2-D
   * tensors), and the out-of-plane stress sigma_zz that the plane state
   * implies. The one code that knows the material: the stiffness assembly,
   * the volume loads, the error estimator, the stress output and the energy
   * release rate ask the law, never the moduli.
   *
   * Adding a law is one class derived from this one plus its entries in
   * LayerMaterial and a case in make_elastic_law().
   */
  class ElasticLaw
  {
  public:
    virtual ~ElasticLaw() = default;

    /// The in-plane stress sigma = C eps of the strain @p eps.
    virtual dealii::SymmetricTensor<2, 2>
    stress(const dealii::SymmetricTensor<2, 2> &eps) const = 0;

    /// The out-of-plane stress sigma_zz of the strain @p eps.
    virtual double
    out_of_plane_stress(const dealii::SymmetricTensor<2, 2> &eps) const = 0;

    /// sigma(eps_a) : eps_b, the integrand of the bilinear form a(., .).
    virtual double
    bilinear_form(const dealii::SymmetricTensor<2, 2> &eps_a,
                  const dealii::SymmetricTensor<2, 2> &eps_b) const = 0;

    /**
     * The cell stiffness of one quadrature point: adds
     * sigma(eps[i]) : eps[j] * JxW to @p cell_matrix(i, j) for j >= i
     * (the upper triangle; the caller mirrors it). @p eps are the
     * symmetric gradients of the shape functions at the point.
     */
    virtual void
    add_stiffness(const std::vector<dealii::SymmetricTensor<2, 2>> &eps,
                  const double                                      JxW,
                  dealii::FullMatrix<double> &cell_matrix) const;

    /// The energy density sigma(eps) : eps / 2 [energy per unit volume].
    double
    energy_density(const dealii::SymmetricTensor<2, 2> &eps) const
    {
      return 0.5 * (stress(eps) * eps);
    }

    /// The tangent C: sigma = C : eps.
    virtual dealii::SymmetricTensor<4, 2>
    tangent() const = 0;

    /**
     * A stiffness [stress] that makes the error indicators energies: the
     * estimator divides traction residuals by it (an isotropic law:
     * 2 mu).
     */
    virtual double
    energy_norm_scale() const = 0;

    /**
     * The constants the law gives the load expressions of its layer,
     * without the layer number (an isotropic law: E, nu, mu, lambda); a
     * law that defines none of them gives none.
     */
    virtual std::map<std::string, double>
    load_constants() const = 0;

    /// The von Mises stress of the in-plane stress @p s and sigma_zz @p s_zz.
    static double
    von_mises(const dealii::SymmetricTensor<2, 2> &s, const double s_zz);
  };


  /**
   * The isotropic plane-strain law (eps_zz = 0):
   *   sigma(w) = 2 mu eps(w) + lambda tr(eps(w)) I,
   *   sigma_zz = lambda tr(eps(w)),
   * with the Lame constants mu = E / (2 (1 + nu)) and
   * lambda = 2 nu mu / (1 - 2 nu) of Young's modulus E and Poisson's
   * ratio nu.
   */
  class IsotropicPlaneStrain : public ElasticLaw
  {
  public:
    IsotropicPlaneStrain(const double youngs_modulus,
                         const double poisson_ratio);

    dealii::SymmetricTensor<2, 2>
    stress(const dealii::SymmetricTensor<2, 2> &eps) const override
    {
      return 2 * mu * eps +
             lambda * dealii::trace(eps) * dealii::unit_symmetric_tensor<2>();
    }

    double
    out_of_plane_stress(const dealii::SymmetricTensor<2, 2> &eps) const override
    {
      return lambda * dealii::trace(eps);
    }

    double
    bilinear_form(const dealii::SymmetricTensor<2, 2> &eps_a,
                  const dealii::SymmetricTensor<2, 2> &eps_b) const override
    {
      return 2 * mu * dealii::scalar_product(eps_a, eps_b) +
             lambda * dealii::trace(eps_a) * dealii::trace(eps_b);
    }

    void
    add_stiffness(const std::vector<dealii::SymmetricTensor<2, 2>> &eps,
                  const double                                      JxW,
                  dealii::FullMatrix<double> &cell_matrix) const override;

    dealii::SymmetricTensor<4, 2>
    tangent() const override;

    double
    energy_norm_scale() const override
    {
      return 2 * mu;
    }

    std::map<std::string, double>
    load_constants() const override;

  private:
    double E, nu, mu, lambda;
  };


  /// The law that @p material describes.
  std::unique_ptr<const ElasticLaw>
  make_elastic_law(const LayerMaterial &material);
} // namespace bilayer

#endif
