#ifndef bilayer_elastic_law_h
#define bilayer_elastic_law_h

#include <deal.II/base/symmetric_tensor.h>
#include <deal.II/base/tensor.h>
#include <deal.II/lac/full_matrix.h>

#include <array>
#include <map>
#include <memory>
#include <string>
#include <vector>

namespace bilayer
{
  /// Materials/Layer k/Law: the kind of Hooke's law of a layer.
  enum class MaterialLaw
  {
    /// Young's modulus and Poisson's ratio.
    isotropic,
    /// The 3-D orthotropic constants of the material axes 1, 2 (in the
    /// plane, axis 1 at the orientation angle) and 3 (= z).
    orthotropic,
    /// The in-plane stiffness of the plane problem, given as it is.
    anisotropic
  };


  /// Materials/Layer k/Plane state: what the plane problem assumes about z.
  enum class PlaneState
  {
    /// eps_zz = 0, sigma_zz the stress that keeps it so.
    plane_strain,
    /// sigma_zz = 0 (a thin plate), eps_zz free.
    plane_stress
  };


  /**
   * The 3-D orthotropic constants of a layer in its material axes 1, 2
   * (in the plane) and 3 (= z): Young's moduli E_i [stress], Poisson's
   * ratios nu_ij (the contraction along j of a tension along i: nu_ji =
   * nu_ij E_j / E_i) [-] and the in-plane shear modulus G_12 [stress].
   * Plane stress uses E_1, E_2, nu_12, G_12 alone. The defaults are the
   * isotropic constants E = 200, nu = 0.28, G = E / (2 (1 + nu)).
   */
  struct OrthotropicConstants
  {
    double E_1   = 200.0;
    double E_2   = 200.0;
    double E_3   = 200.0;
    double nu_12 = 0.28;
    double nu_13 = 0.28;
    double nu_23 = 0.28;
    double G_12  = 78.125;
  };


  /**
   * The entries of Materials/Layer k: the material of one layer. The law
   * selects which entries count: isotropic: Young's modulus [stress] and
   * Poisson's ratio; orthotropic: the OrthotropicConstants and the
   * orientation angle; anisotropic: the stiffness. The plane state counts
   * for isotropic and orthotropic layers (an anisotropic stiffness is the
   * plane law itself).
   */
  struct LayerMaterial
  {
    /// An isotropic plane-strain layer of Young's modulus @p E and
    /// Poisson's ratio @p nu (the other entries at their defaults).
    LayerMaterial(const double E = 200.0, const double nu = 0.28)
      : youngs_modulus(E)
      , poisson_ratio(nu)
    {}

    double      youngs_modulus;
    double      poisson_ratio;
    MaterialLaw law         = MaterialLaw::isotropic;
    PlaneState  plane_state = PlaneState::plane_strain;
    /// Orthotropic layers: the constants in the material axes.
    OrthotropicConstants orthotropic;
    /// Orthotropic layers: the angle from the x-axis to the material axis 1,
    /// counter-clockwise [degrees].
    double orientation_angle = 0.0;
    /**
     * Anisotropic layers: C11, C12, C16, C22, C26, C66 [stress], the
     * symmetric matrix of (s11, s22, s12) against (e11, e22, 2 e12) in the
     * x-y frame. The default is the isotropic stiffness of lambda = 100,
     * mu = 75.
     */
    std::array<double, 6> stiffness = {{250.0, 100.0, 0.0, 250.0, 0.0, 75.0}};
    /**
     * Materials/Layer k/Thermal expansion [1/K], three numbers whose
     * meaning the law gives: isotropic (alpha, alpha, alpha); orthotropic
     * (alpha_1, alpha_2, alpha_3) in the material axes; anisotropic
     * (alpha_11, alpha_22, alpha_12), the plane eigenstrain per kelvin in
     * the x-y frame (tensor shear). thermal_strain() reads them.
     */
    std::array<double, 3> thermal_expansion = {{0.0, 0.0, 0.0}};
  };


  /**
   * A 3-D eigenstrain without out-of-plane shears: its in-plane components
   * (x-y frame) and eps_zz.
   */
  struct Eigenstrain3D
  {
    dealii::SymmetricTensor<2, 2> in_plane;
    double                        zz = 0;
  };


  /**
   * The eigenstrain of the plane problem that a 3-D eigenstrain implies
   * under a plane state (ElasticLaw::plane_eigenstrain(), docs/problem.md
   * §1): the in-plane eigenstrain eps*_eff of sigma = C (eps - eps*_eff) and
   * the out-of-plane stress sigma_zz at eps = eps*_eff, so that
   * sigma_zz = Z : (eps - eps*_eff) + sigma_zz_offset.
   */
  struct PlaneEigenstrain
  {
    dealii::SymmetricTensor<2, 2> in_plane;
    double                        sigma_zz_offset = 0;
  };


  /**
   * The thermal strain of @p material per kelvin of temperature change
   * (alpha, a 3-D tensor in the x-y-z frame): isotropic alpha I;
   * orthotropic R diag(alpha_1, alpha_2) R^T in the plane (R the rotation
   * by the orientation angle), alpha_3 along z; anisotropic the given
   * in-plane tensor, eps_zz = 0 (the plane law says nothing about z: the
   * numbers are the plane eigenstrain per kelvin as it enters the law).
   */
  Eigenstrain3D
  thermal_strain(const LayerMaterial &material);

  /// Whether @p material expands (some coefficient not zero).
  bool
  has_thermal_expansion(const LayerMaterial &material);


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
     * estimator divides traction residuals by it (IsotropicPlaneStrain:
     * 2 mu; GeneralPlaneLaw: the smallest eigenvalue of C in Mandel
     * notation, which is 2 mu for an isotropic law with nu >= 0).
     */
    virtual double
    energy_norm_scale() const = 0;

    /**
     * The constants the law gives the load expressions of its layer,
     * without the layer number (an isotropic law: E, nu, mu, lambda); a
     * law that defines none of them gives none (orthotropic and
     * anisotropic laws).
     */
    virtual std::map<std::string, double>
    load_constants() const = 0;

    /**
     * The plane eigenstrain of the 3-D eigenstrain @p eps3 (a thermal
     * strain alpha dT), linear in it. Plane stress (sigma_zz = 0): the
     * in-plane part, sigma_zz_offset = 0. Plane strain (eps_zz = 0): from
     * the 3-D compliance S, eps_p = S_pp sigma_p + S_p3 sigma_zz + eps3_p
     * and 0 = S_3p sigma_p + S_33 sigma_zz + eps3_zz give
     *   eps*_eff = eps3_p - (S_p3 / S_33) eps3_zz,
     *   sigma_zz = -(S_3p / S_33) sigma_p - eps3_zz / S_33
     *            = Z : (eps - eps*_eff) - E_3 eps3_zz
     * (isotropic: eps*_eff = eps3_p + nu eps3_zz I, sigma_zz = nu (sigma_xx
     * + sigma_yy) - E eps3_zz). An anisotropic law: the in-plane part as
     * given (its sigma_zz is not defined).
     */
    virtual PlaneEigenstrain
    plane_eigenstrain(const Eigenstrain3D &eps3) const = 0;

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

    PlaneEigenstrain
    plane_eigenstrain(const Eigenstrain3D &eps3) const override
    {
      return {eps3.in_plane + nu * eps3.zz * dealii::unit_symmetric_tensor<2>(),
              -E * eps3.zz};
    }

  private:
    double E, nu, mu, lambda;
  };


  /**
   * A plane law with a constant general tangent C (docs/problem.md §1): the
   * isotropic plane-stress law, the orthotropic laws (plane strain and
   * plane stress, in the x-y frame at any orientation) and the anisotropic
   * law of a given in-plane stiffness. make_elastic_law() builds it;
   * isotropic plane strain stays IsotropicPlaneStrain.
   *
   * - sigma = C : eps, sigma_zz = Z : eps with a constant tensor Z (0 in
   *   plane stress; in orthotropic plane strain the stress that keeps
   *   eps_zz = 0). An anisotropic law has no sigma_zz: the plane law as
   *   given says nothing about z, and out_of_plane_stress() returns a quiet
   *   NaN (the outputs stress_zz and von_mises are NaN on such a layer).
   * - energy_norm_scale(): the smallest eigenvalue of C in Mandel notation
   *   (the 3x3 matrix of (s11, s22, sqrt(2) s12) against (e11, e22,
   *   sqrt(2) e12)), the largest s with C >= s I: 2 mu for an isotropic law
   *   with nu >= 0 (plane strain or plane stress).
   * - load_constants(): E, nu, mu, lambda for the isotropic plane-stress law
   *   (mu = E / (2 (1 + nu)) and lambda = 2 nu mu / (1 - 2 nu), the Lame
   *   constants of the 3-D material, not the plane-stress lambda*; lambda
   *   is left out for nu = 0.5, where it is infinite), none for the other
   *   laws.
   */
  class GeneralPlaneLaw : public ElasticLaw
  {
  public:
    /**
     * The law sigma = @p C : eps, sigma_zz = @p Z : eps (@p has_sigma_zz
     * false: sigma_zz is not defined, NaN) with the load constants
     * @p constants. @p C must be positive definite (refused otherwise).
     * The plane eigenstrain of a 3-D one (plane_eigenstrain()):
     * eps*_eff = eps3_p + @p P eps3_zz, sigma_zz_offset = -@p E_zz eps3_zz
     * (plane strain: P = -S_p3 / S_33 in the x-y frame, E_zz = 1 / S_33;
     * plane stress and anisotropic: 0).
     */
    GeneralPlaneLaw(const dealii::SymmetricTensor<4, 2> &C,
                    const dealii::SymmetricTensor<2, 2> &Z,
                    const bool                           has_sigma_zz,
                    std::map<std::string, double>        constants = {},
                    const dealii::SymmetricTensor<2, 2> &P         = {},
                    const double                         E_zz      = 0);

    dealii::SymmetricTensor<2, 2>
    stress(const dealii::SymmetricTensor<2, 2> &eps) const override
    {
      return C * eps;
    }

    double
    out_of_plane_stress(
      const dealii::SymmetricTensor<2, 2> &eps) const override;

    double
    bilinear_form(const dealii::SymmetricTensor<2, 2> &eps_a,
                  const dealii::SymmetricTensor<2, 2> &eps_b) const override
    {
      return (C * eps_a) * eps_b;
    }

    void
    add_stiffness(const std::vector<dealii::SymmetricTensor<2, 2>> &eps,
                  const double                                      JxW,
                  dealii::FullMatrix<double> &cell_matrix) const override;

    dealii::SymmetricTensor<4, 2>
    tangent() const override
    {
      return C;
    }

    double
    energy_norm_scale() const override
    {
      return smallest_eigenvalue;
    }

    std::map<std::string, double>
    load_constants() const override
    {
      return constants;
    }

    PlaneEigenstrain
    plane_eigenstrain(const Eigenstrain3D &eps3) const override
    {
      return {eps3.in_plane + eps3.zz * P, -E_zz * eps3.zz};
    }

  private:
    dealii::SymmetricTensor<4, 2> C;
    dealii::SymmetricTensor<2, 2> Z;
    bool                          has_sigma_zz;
    dealii::SymmetricTensor<2, 2> P;
    double                        E_zz;
    double                        smallest_eigenvalue;
    std::map<std::string, double> constants;
  };


  /**
   * The plane laws in matrices: the tangent of a 3x3 Voigt matrix D with
   * engineering shear, (s11, s22, s12) = D (e11, e22, 2 e12), the rotation
   * of the material frame, and the reductions of the 3-D laws
   * (docs/problem.md §1).
   */
  namespace plane_laws
  {
    /// The tangent C of the Voigt matrix @p D (symmetric 3x3).
    dealii::SymmetricTensor<4, 2>
    tangent_of_voigt(const std::array<std::array<double, 3>, 3> &D);

    /// The Voigt matrix of the six numbers C11, C12, C16, C22, C26, C66.
    std::array<std::array<double, 3>, 3>
    voigt_of_stiffness(const std::array<double, 6> &stiffness);

    /**
     * The rotation R by @p angle [degrees] counter-clockwise: the material
     * axis 1 is R e_x.
     */
    dealii::Tensor<2, 2>
    rotation(const double angle);

    /**
     * The tangent in the x-y frame of the tangent @p C_material of the
     * material frame rotated by @p R: C_xy(e) = R C_material(R^T e R) R^T.
     */
    dealii::SymmetricTensor<4, 2>
    rotate(const dealii::SymmetricTensor<4, 2> &C_material,
           const dealii::Tensor<2, 2>          &R);

    /// The smallest eigenvalue of @p C in Mandel notation.
    double
    smallest_mandel_eigenvalue(const dealii::SymmetricTensor<4, 2> &C);

    /// The isotropic plane-stress law E / (1 - nu^2) [...], sigma_zz = 0.
    std::unique_ptr<const ElasticLaw>
    isotropic_plane_stress(const double youngs_modulus,
                           const double poisson_ratio);

    /**
     * The orthotropic law of @p constants in @p state, the material axis 1
     * at @p angle [degrees] from x: plane strain reduces the 3-D compliance
     * by eps_zz = 0, plane stress by sigma_zz = 0.
     */
    std::unique_ptr<const ElasticLaw>
    orthotropic(const OrthotropicConstants &constants,
                const PlaneState            state,
                const double                angle);

    /// The anisotropic law of the stiffness C11, C12, C16, C22, C26, C66.
    std::unique_ptr<const ElasticLaw>
    anisotropic(const std::array<double, 6> &stiffness);
  } // namespace plane_laws


  /**
   * The law that @p material describes: IsotropicPlaneStrain for isotropic
   * plane strain (the default), a GeneralPlaneLaw otherwise.
   */
  std::unique_ptr<const ElasticLaw>
  make_elastic_law(const LayerMaterial &material);
} // namespace bilayer

#endif
