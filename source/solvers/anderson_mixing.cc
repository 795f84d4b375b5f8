#include <deal.II/lac/full_matrix.h>
#include <deal.II/lac/vector.h>

#include <bilayer/solvers/anderson_mixing.h>

#include <cmath>

namespace bilayer
{
  using namespace dealii;

  std::vector<double>
  AndersonMixing::next(const std::vector<double> &x,
                       const std::vector<double> &g)
  {
    xs.push_back(x);
    gs.push_back(g);
    if (xs.size() > depth + 1)
      {
        xs.pop_front();
        gs.pop_front();
      }
    const unsigned int m = xs.size() - 1, n = x.size();
    if (m == 0)
      return g;
    // dR(:, j) = r_(j+1) - r_j, dG(:, j) = g_(j+1) - g_j.
    const auto residual = [&](const unsigned int j, const unsigned int i) {
      return gs[j][i] - xs[j][i];
    };
    FullMatrix<double> normal(m, m);
    Vector<double>     rhs(m), gamma(m);
    for (unsigned int i = 0; i < n; ++i)
      for (unsigned int a = 0; a < m; ++a)
        {
          const double da = residual(a + 1, i) - residual(a, i);
          rhs(a) += da * residual(m, i);
          for (unsigned int b = 0; b < m; ++b)
            normal(a, b) += da * (residual(b + 1, i) - residual(b, i));
        }
    double trace = 0;
    for (unsigned int a = 0; a < m; ++a)
      trace += normal(a, a);
    if (!(trace > 0))
      return g;
    for (unsigned int a = 0; a < m; ++a)
      normal(a, a) += 1e-10 * trace;
    normal.gauss_jordan();
    normal.vmult(gamma, rhs);
    std::vector<double> result(g);
    for (unsigned int a = 0; a < m; ++a)
      if (std::isfinite(gamma(a)))
        for (unsigned int i = 0; i < n; ++i)
          result[i] -= gamma(a) * (gs[a + 1][i] - gs[a][i]);
    return result;
  }
} // namespace bilayer
