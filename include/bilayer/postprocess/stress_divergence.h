#ifndef bilayer_stress_divergence_h
#define bilayer_stress_divergence_h

#include <deal.II/base/symmetric_tensor.h>
#include <deal.II/base/tensor.h>

#include <bilayer/physics/elastic_law.h>

#include <array>

namespace bilayer
{
  /// div sigma = div C (eps(w) - eps*) at a point, from the Hessian @p H of
  /// the displacement (H[i][k][j] = d^2 w_i / dx_k dx_j) and the gradient
  /// of the eigenstrain (@p d_eps_star[j] = d eps* / d x_j).
  inline dealii::Tensor<1, 2>
  stress_divergence(
    const ElasticLaw                                   &law,
    const dealii::Tensor<3, 2>                         &H,
    const std::array<dealii::SymmetricTensor<2, 2>, 2> &d_eps_star)
  {
    dealii::Tensor<1, 2> div;
    for (unsigned int j = 0; j < 2; ++j)
      {
        dealii::SymmetricTensor<2, 2> d_eps;
        d_eps[0][0] = H[0][0][j];
        d_eps[1][1] = H[1][1][j];
        d_eps[0][1] = 0.5 * (H[0][1][j] + H[1][0][j]);
        d_eps -= d_eps_star[j];
        const dealii::SymmetricTensor<2, 2> d_sigma = law.stress(d_eps);
        div[0] += d_sigma[0][j];
        div[1] += d_sigma[1][j];
      }
    return div;
  }
} // namespace bilayer

#endif
