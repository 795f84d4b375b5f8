#ifndef bilayer_stress_intensity_h
#define bilayer_stress_intensity_h

#include <deal.II/base/point.h>
#include <deal.II/base/symmetric_tensor.h>
#include <deal.II/base/tensor.h>
#include <deal.II/lac/block_vector.h>

#include <bilayer/core/layout.h>
#include <bilayer/interface/interface.h>
#include <bilayer/postprocess/fracture.h>
#include <bilayer/subproblem/subproblem.h>

#include <array>
#include <complex>
#include <vector>

/**
 * @file
 * The stress intensity factors of the crack tips (docs/fracture.md §10) by
 * the interaction integral: the part of the domain integral of G that is
 * bilinear in the computed field and an auxiliary near-tip field of known
 * K, with the velocity field theta of G.
 */
namespace bilayer
{
  /**
   * The near-tip field of a crack along the interface of two isotropic
   * materials (the homogeneous crack where they agree), in the tip's frame:
   * x1 along the direction of growth (the crack behind, x1 < 0), x2 turned
   * by +90 degrees; "upper" is the material at x2 > 0. With
   * a_u = kappa_u / mu_u + 1 / mu_l, a_l = kappa_l / mu_l + 1 / mu_u and
   * the oscillation index eps = ln(a_u / a_l) / (2 pi), the Muskhelishvili
   * potentials are Phi = h / a (own a), Psi(z) = conj(h(conj z)) / a_other
   * - (h(z) + z h'(z)) / a_own with h(z) = c z^(-1/2 - i eps),
   * c = conj(K) / (sqrt(2 pi) (1 / a_u + 1 / a_l)): traction-free faces,
   * continuous tractions and displacements ahead, and the traction ahead
   * sigma_22 + i sigma_12 = K r^(i eps) / sqrt(2 pi r) (Rice 1988). The
   * energy release rate of the field is |K|^2 / modulus(), modulus() =
   * E* cosh^2(pi eps), 1 / E* = (a_u + a_l) / 16. kappa is
   * (lambda + 3 mu) / (lambda + mu) of the plane law's Lame constants.
   */
  class InterfaceCrackField
  {
  public:
    InterfaceCrackField(const double mu_upper,
                        const double kappa_upper,
                        const double mu_lower,
                        const double kappa_lower);

    double
    epsilon() const
    {
      return eps;
    }

    double
    modulus() const;

    /// The displacement @p u (up to a rigid motion) and its gradient
    /// @p grad (grad[i][j] = d u_i / d x_j) at @p x of the material
    /// @p upper for the complex stress intensity factor @p K. Points on
    /// x2 = 0 behind the tip take the face of that material.
    void
    displacement(const dealii::Point<2>     &x,
                 const bool                  upper,
                 const std::complex<double> &K,
                 dealii::Tensor<1, 2>       &u,
                 dealii::Tensor<2, 2>       &grad) const;

    /// displacement() for K = 1 (entry 0) and K = i (entry 1) at once.
    void
    unit_displacements(const dealii::Point<2>              &x,
                       const bool                           upper,
                       std::array<dealii::Tensor<1, 2>, 2> &u,
                       std::array<dealii::Tensor<2, 2>, 2> &grad) const;

    /// The stress of the potentials at @p x (for the checks of the field).
    dealii::SymmetricTensor<2, 2>
    stress(const dealii::Point<2>     &x,
           const bool                  upper,
           const std::complex<double> &K) const;

  private:
    double mu_u, kappa_u, mu_l, kappa_l, a_u, a_l, eps;

    /// z (on the side of its material) and z^p, conj(z)^p, p = -1/2 -
    /// i eps: what the potentials of every K share.
    struct Powers
    {
      std::complex<double> z, zp, zbp;
    };

    struct Potentials
    {
      std::complex<double> z, phi, Phi, dPhi, psi, Psi;
    };

    Powers
    powers(const dealii::Point<2> &x, const bool upper) const;

    Potentials
    potentials(const Powers               &w,
               const bool                  upper,
               const std::complex<double> &K) const;

    void
    displacement(const Potentials     &f,
                 const bool            upper,
                 dealii::Tensor<1, 2> &u,
                 dealii::Tensor<2, 2> &grad) const;
  };


  /**
   * Fill K_I, K_II, K_magnitude, K_phase_angle, oscillation_index,
   * reference_length, G_from_K and K_note of every entry of @p release
   * (G already computed; collective like energy_release_rates()). Per tip:
   * the layers on each side of its interface isotropic at the tip and
   * proportional to each other (one Poisson's ratio per side), so that the
   * singular field is that of one isotropic material per side with the
   * layers' summed stiffness; the interaction integral
   *   I(K_aux) = sum over the subproblems of int sigma(w) : (grad a grad
   *     theta) + sigma(a) : (grad w grad theta) - sigma(w) : eps(a) div
   *     theta (+ the volume loads' terms) dx
   *     - int_{gamma_c} psi mu_c d/dx1 (a_upper - a_lower).e2 ds
   * of the auxiliary fields a of K_aux = 1 and i gives
   * I = 2 Re(K conj(K_aux)) / modulus(). K L^(i eps) = K_I + i K_II at
   * @p reference_length L (Fracture/Reference length; where eps = 0 any
   * length; where eps != 0 and L = 0, K_I, K_II and the phase angle are NaN
   * and the note says to set it). NaN with a note where G is NaN, on a
   * curved interface, with friction on the faces, with anisotropic or
   * non-proportional layers, or where the support holds another material
   * than the one at the tip.
   */
  void
  stress_intensity_factors(
    const PerSubproblem<const ElasticSubproblem *> &subproblems,
    const Interface                                &interface,
    const Solutions                                &w,
    const dealii::BlockVector<double>              &mu,
    const double                                    reference_length,
    std::vector<EnergyReleaseRate>                 &release);
} // namespace bilayer

#endif
