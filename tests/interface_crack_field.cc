// The auxiliary near-tip field of the interaction integral
// (InterfaceCrackField, include/bilayer/postprocess/stress_intensity.h)
// against the conditions that define it, for a crack between two
// isotropic materials (E = 1, nu = 0.3 above; E = 10, nu = 0.2 below,
// plane strain: eps = 0.0721) and for one material, at K = 1, i and
// 0.7 - 0.3 i:
// 1. the stress of the potentials is Hooke's law of the gradient, and the
//    gradient is the derivative of the displacement (central differences);
// 2. the crack faces (x1 < 0) are free of traction;
// 3. ahead (x1 > 0) the displacement and the traction are continuous and
//    sigma_22 + i sigma_12 = K r^(i eps) / sqrt(2 pi r);
// 4. the J-integral on circles of radius 0.5 and 2 equals |K|^2 /
//    modulus() (the energy release rate of the field, independent of the
//    closed form of the modulus);
// 5. one material: eps = 0, the opening behind the tip (kappa + 1) / mu
//    K_I sqrt(r / (2 pi)), the sliding the same with K_II, and modulus() =
//    E / (1 - nu^2).
// Each check to 1e-9 relative (1e-5 for the differences and the contour
// integrals).

#include <bilayer/postprocess/stress_intensity.h>

#include <cmath>
#include <complex>
#include <iostream>

#include "plane_strain.h"
#include "verdict.h"

using namespace bilayer;
using namespace dealii;
using Complex = std::complex<double>;

namespace
{
  using Material = PlaneStrain;

  /// The J-integral of the field on the circle of radius @p r.
  double
  contour_j(const InterfaceCrackField &f,
            const Material             m[2],
            const Complex             &K,
            const double               r)
  {
    const unsigned int n   = 20000;
    double             sum = 0;
    for (unsigned int k = 0; k < n; ++k)
      {
        // Midpoint rule in theta over (-pi, pi).
        const double   theta = -M_PI + (k + 0.5) * 2 * M_PI / n;
        const bool     upper = theta > 0;
        const Point<2> x(r * std::cos(theta), r * std::sin(theta));
        Tensor<1, 2>   u;
        Tensor<2, 2>   g;
        f.displacement(x, upper, K, u, g);
        const SymmetricTensor<2, 2> s = f.stress(x, upper, K);
        const Tensor<1, 2>          normal({std::cos(theta), std::sin(theta)});
        const double                W = 0.5 * (s * symmetrize(g));
        Tensor<1, 2>                du1;
        du1[0] = g[0][0];
        du1[1] = g[1][0];
        sum += (W * normal[0] - (s * normal) * du1) * r * 2 * M_PI / n;
      }
    return sum;
  }
} // namespace


int
main()
{
  const Material two[2] = {{1, 0.3}, {10, 0.2}};
  const Material one[2] = {{1, 0.3}, {1, 0.3}};
  for (const auto *m : {two, one})
    {
      const bool                same = m == one;
      const InterfaceCrackField f(m[0].mu(),
                                  m[0].kappa(),
                                  m[1].mu(),
                                  m[1].kappa());
      const double              eps = f.epsilon();
      std::cout << (same ? "one material" : "two materials") << ": eps "
                << (same ? "0" : "0.0721") << ": "
                << yes(same ?
                         eps == 0 :
                         std::abs(
                           eps - std::log(
                                   (m[0].kappa() / m[0].mu() + 1 / m[1].mu()) /
                                   (m[1].kappa() / m[1].mu() + 1 / m[0].mu())) /
                                   (2 * M_PI)) < 1e-15 &&
                           std::abs(eps - 0.0721) < 1e-4)
                << std::endl;
      bool hooke = true, derivative = true, faces = true, ahead = true,
           traction = true, contour = true, opening = true;
      for (const Complex K : {Complex(1, 0), Complex(0, 1), Complex(0.7, -0.3)})
        {
          for (const double r : {1e-3, 0.1, 1., 7.})
            {
              for (const double theta : {-3.0, -2.0, -0.5, 0.3, 1.7, 3.1})
                {
                  const bool     upper = theta > 0;
                  const Point<2> x(r * std::cos(theta), r * std::sin(theta));
                  Tensor<1, 2>   u;
                  Tensor<2, 2>   g;
                  f.displacement(x, upper, K, u, g);
                  const SymmetricTensor<2, 2> s = f.stress(x, upper, K);
                  const SymmetricTensor<2, 2> h =
                    m[upper ? 0 : 1].hooke(symmetrize(g));
                  hooke          = hooke && (s - h).norm() <= 1e-9 * s.norm();
                  const double d = 1e-6 * r;
                  for (unsigned int j = 0; j < 2; ++j)
                    {
                      Point<2> xp = x, xm = x;
                      xp[j] += d;
                      xm[j] -= d;
                      Tensor<1, 2> up, um;
                      Tensor<2, 2> unused;
                      f.displacement(xp, upper, K, up, unused);
                      f.displacement(xm, upper, K, um, unused);
                      for (unsigned int i = 0; i < 2; ++i)
                        derivative =
                          derivative && std::abs((up[i] - um[i]) / (2 * d) -
                                                 g[i][j]) <= 1e-5 * g.norm();
                    }
                }
              // Faces and the interface, x2 = +-0.
              for (const bool upper : {true, false})
                {
                  const SymmetricTensor<2, 2> s =
                    f.stress(Point<2>(-r, 0), upper, K);
                  faces = faces && std::abs(s[0][1]) + std::abs(s[1][1]) <=
                                     1e-9 * std::abs(K) / std::sqrt(r);
                }
              Tensor<1, 2> uu, ul;
              Tensor<2, 2> gu, gl;
              f.displacement(Point<2>(r, 0), true, K, uu, gu);
              f.displacement(Point<2>(r, 0), false, K, ul, gl);
              const SymmetricTensor<2, 2> su =
                                            f.stress(Point<2>(r, 0), true, K),
                                          sl =
                                            f.stress(Point<2>(r, 0), false, K);
              ahead =
                ahead && (uu - ul).norm() <= 1e-9 * uu.norm() &&
                std::abs(gu[0][0] - gl[0][0]) + std::abs(gu[1][0] - gl[1][0]) <=
                  1e-9 * gu.norm();
              const Complex expected = K *
                                       std::exp(Complex(0, eps * std::log(r))) /
                                       std::sqrt(2 * M_PI * r);
              traction =
                traction &&
                std::abs(su[1][1] - sl[1][1]) + std::abs(su[0][1] - sl[0][1]) <=
                  1e-9 * su.norm() &&
                std::abs(Complex(su[1][1], su[0][1]) - expected) <=
                  1e-9 * std::abs(expected);
              if (same)
                {
                  // Opening and sliding behind the tip.
                  f.displacement(Point<2>(-r, 0), true, K, uu, gu);
                  f.displacement(Point<2>(-r, 0), false, K, ul, gl);
                  const double c =
                    (m[0].kappa() + 1) / m[0].mu() * std::sqrt(r / (2 * M_PI));
                  opening =
                    opening &&
                    std::abs(uu[1] - ul[1] - c * K.real()) <= 1e-9 * c &&
                    std::abs(uu[0] - ul[0] - c * K.imag()) <= 1e-9 * c;
                }
            }
          for (const double r : {0.5, 2.})
            {
              const double J = contour_j(f, m, K, r);
              contour = contour && std::abs(J - std::norm(K) / f.modulus()) <=
                                     1e-5 * std::norm(K) / f.modulus();
            }
        }
      std::cout << "  Hooke's law of the gradient: " << yes(hooke) << std::endl
                << "  the gradient of the displacement: " << yes(derivative)
                << std::endl
                << "  traction-free faces: " << yes(faces) << std::endl
                << "  continuous displacement ahead: " << yes(ahead)
                << std::endl
                << "  continuous traction ahead, K r^(i eps) / sqrt(2 pi r): "
                << yes(traction) << std::endl
                << "  J on circles = |K|^2 / modulus: " << yes(contour)
                << std::endl;
      if (same)
        {
          const double Eprime = m[0].E / (1 - m[0].nu * m[0].nu);
          std::cout
            << "  opening and sliding (kappa + 1) / mu K sqrt(r / 2 pi): "
            << yes(opening) << std::endl
            << "  modulus E / (1 - nu^2): "
            << yes(std::abs(f.modulus() - Eprime) <= 1e-12 * Eprime)
            << std::endl;
        }
    }
}
