#ifndef bilayer_tests_reference_h
#define bilayer_tests_reference_h

// Helpers shared by the tests: the plane-strain stiffness of the
// independent reference solvers (written without the library, so that
// they check it), and the yes/NO of an assertion line.

#include <deal.II/base/tensor.h>
#include <deal.II/fe/fe_values.h>
#include <deal.II/lac/full_matrix.h>

#include "verdict.h"

/// The loads of Example 1 (docs/problem.md §5) as a Loads subsection.
inline const char *const example1_loads =
  "subsection Loads\n set Constants = c = 1e-3*mu1\n"
  " subsection Layer 1\n"
  "  set Traction on bottom side = 0; c*x\n"
  "  set Traction on top side = 0; -c*x\n end\nend\n";

/// The materials of Example 1 (docs/problem.md §5, in GPa), written out here
/// rather than taken from the Scene, so that the references do not share the
/// library's parsing.
namespace example1_materials
{
  constexpr double E[2]       = {200., 112.};
  constexpr double poisson[2] = {0.28, 0.32};

  inline double
  lame_mu(const unsigned int l)
  {
    return E[l] / (2. * (1. + poisson[l]));
  }

  inline double
  lame_lambda(const unsigned int l)
  {
    return 2. * poisson[l] * lame_mu(l) / (1. - 2. * poisson[l]);
  }
} // namespace example1_materials

/// cell_matrix += int 2 mu eps(phi_i):eps(phi_j) + lambda div phi_i div phi_j
inline void
add_elasticity_matrix(const dealii::FEValues<2>                &fe_values,
                      const dealii::FEValuesExtractors::Vector &displacement,
                      const double                              mu,
                      const double                              lambda,
                      dealii::FullMatrix<double>               &cell_matrix)
{
  const unsigned int n = fe_values.dofs_per_cell;
  for (const unsigned int q : fe_values.quadrature_point_indices())
    for (unsigned int i = 0; i < n; ++i)
      for (unsigned int j = 0; j < n; ++j)
        cell_matrix(i, j) +=
          (2 * mu *
             scalar_product(fe_values[displacement].symmetric_gradient(i, q),
                            fe_values[displacement].symmetric_gradient(j, q)) +
           lambda * fe_values[displacement].divergence(i, q) *
             fe_values[displacement].divergence(j, q)) *
          fe_values.JxW(q);
}

#endif
