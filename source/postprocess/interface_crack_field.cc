// The near-tip field of a crack between two isotropic materials from its
// Muskhelishvili potentials (include/bilayer/postprocess/stress_intensity.h).

#include <bilayer/postprocess/stress_intensity.h>

#include <cmath>

namespace bilayer
{
  using namespace dealii;
  using Complex = std::complex<double>;

  InterfaceCrackField::InterfaceCrackField(const double mu_upper,
                                           const double kappa_upper,
                                           const double mu_lower,
                                           const double kappa_lower)
    : mu_u(mu_upper)
    , kappa_u(kappa_upper)
    , mu_l(mu_lower)
    , kappa_l(kappa_lower)
    , a_u(kappa_upper / mu_upper + 1 / mu_lower)
    , a_l(kappa_lower / mu_lower + 1 / mu_upper)
    , eps(std::log(a_u / a_l) / (2 * M_PI))
  {}


  double
  InterfaceCrackField::modulus() const
  {
    return 16 * std::pow(std::cosh(M_PI * eps), 2) / (a_u + a_l);
  }


  InterfaceCrackField::Powers
  InterfaceCrackField::powers(const Point<2> &x, const bool upper) const
  {
    // The branch cut along the crack (x1 < 0): a point on x2 = 0 takes the
    // face of its own material (the sign of the zero picks the side).
    Powers w;
    w.z =
      Complex(x[0], upper ? (x[1] > 0 ? x[1] : +0.) : (x[1] < 0 ? x[1] : -0.));
    // z^p and conj(z)^p = exp(p conj(log z)): one logarithm, two
    // exponentials.
    const Complex p(-0.5, -eps);
    const Complex log_z = std::log(w.z);
    w.zp                = std::exp(p * log_z);
    w.zbp               = std::exp(p * std::conj(log_z));
    return w;
  }


  InterfaceCrackField::Potentials
  InterfaceCrackField::potentials(const Powers  &w,
                                  const bool     upper,
                                  const Complex &K) const
  {
    // h(z) = c z^p, its primitive H(z) = z h(z) / (p + 1).
    const Complex c =
      std::conj(K) / (std::sqrt(2 * M_PI) * (1 / a_u + 1 / a_l));
    const Complex p(-0.5, -eps);
    const Complex z = w.z, zb = std::conj(z);
    const Complex hz = c * w.zp, hzb = c * w.zbp;
    const Complex Hz = z * hz / (p + 1.), Hzb = zb * hzb / (p + 1.);
    const double  own = upper ? a_u : a_l, other = upper ? a_l : a_u;
    const Complex dh = p * hz / z;
    Potentials    f;
    f.z    = z;
    f.Phi  = hz / own;
    f.dPhi = dh / own;
    f.phi  = Hz / own;
    f.Psi  = std::conj(hzb) / other - (hz + z * dh) / own;
    f.psi  = std::conj(Hzb) / other - z * hz / own;
    return f;
  }


  void
  InterfaceCrackField::displacement(const Potentials &f,
                                    const bool        upper,
                                    Tensor<1, 2>     &u,
                                    Tensor<2, 2>     &grad) const
  {
    const double mu    = upper ? mu_u : mu_l;
    const double kappa = upper ? kappa_u : kappa_l;
    // 2 mu (u1 + i u2) = kappa phi - z conj(Phi) - conj(psi).
    const Complex w =
      (kappa * f.phi - f.z * std::conj(f.Phi) - std::conj(f.psi)) / (2 * mu);
    const Complex rest = f.z * std::conj(f.dPhi) + std::conj(f.Psi);
    const Complex dx   = (kappa * f.Phi - std::conj(f.Phi) - rest) / (2 * mu);
    const Complex dy =
      Complex(0, 1) * (kappa * f.Phi - std::conj(f.Phi) + rest) / (2 * mu);
    u[0]       = w.real();
    u[1]       = w.imag();
    grad[0][0] = dx.real();
    grad[1][0] = dx.imag();
    grad[0][1] = dy.real();
    grad[1][1] = dy.imag();
  }


  void
  InterfaceCrackField::displacement(const Point<2> &x,
                                    const bool      upper,
                                    const Complex  &K,
                                    Tensor<1, 2>   &u,
                                    Tensor<2, 2>   &grad) const
  {
    displacement(potentials(powers(x, upper), upper, K), upper, u, grad);
  }


  void
  InterfaceCrackField::unit_displacements(
    const Point<2>              &x,
    const bool                   upper,
    std::array<Tensor<1, 2>, 2> &u,
    std::array<Tensor<2, 2>, 2> &grad) const
  {
    // (The powers of z are those of every K.)
    const Powers w = powers(x, upper);
    displacement(potentials(w, upper, Complex(1, 0)), upper, u[0], grad[0]);
    displacement(potentials(w, upper, Complex(0, 1)), upper, u[1], grad[1]);
  }


  SymmetricTensor<2, 2>
  InterfaceCrackField::stress(const Point<2> &x,
                              const bool      upper,
                              const Complex  &K) const
  {
    const Potentials f = potentials(powers(x, upper), upper, K);
    // sigma_11 + sigma_22 = 4 Re Phi,
    // sigma_22 - sigma_11 + 2 i sigma_12 = 2 (conj(z) Phi' + Psi).
    const double          sum = 4 * f.Phi.real();
    const Complex         d   = 2. * (std::conj(f.z) * f.dPhi + f.Psi);
    SymmetricTensor<2, 2> s;
    s[0][0] = 0.5 * (sum - d.real());
    s[1][1] = 0.5 * (sum + d.real());
    s[0][1] = 0.5 * d.imag();
    return s;
  }
} // namespace bilayer
