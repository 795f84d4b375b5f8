#include <deal.II/base/exceptions.h>
#include <deal.II/lac/vector.h>

#include <bilayer/parameters/expression_volume_load.h>
#include <bilayer/parameters/expressions.h>

#include <cmath>
#include <sstream>

namespace bilayer
{
  using namespace dealii;

  ExpressionVolumeLoad::ExpressionVolumeLoad(
    const std::string                   &body_force,
    const std::string                   &eigenstrain,
    const std::map<std::string, double> &constants,
    const std::string                   &entry,
    const double                         length_scale)
    : force_entry(entry + "/Body force")
    , strain_entry(entry + "/Eigenstrain")
    , length(length_scale)
  {
    if (!expressions::is_zero(body_force))
      force = expressions::vector_function(body_force, constants, force_entry);
    if (!expressions::is_zero(eigenstrain))
      strain = expressions::function(
        eigenstrain, 3, "eps11; eps22; eps12", constants, strain_entry);
  }


  void
  ExpressionVolumeLoad::evaluate(const FunctionParser<2> &function,
                                 const std::string       &entry,
                                 const Point<2>          &p,
                                 double                  *values) const
  {
    const unsigned int n = function.n_components;
    for (unsigned int c = 0; c < n; ++c)
      {
        values[c] = function.value(p, c);
        if (!std::isfinite(values[c]))
          {
            std::ostringstream message;
            message.precision(6);
            message << entry << " is not finite at (x, y) = (" << p[0] << ", "
                    << p[1] << "): component " << c + 1 << " of " << n << " is "
                    << values[c];
            AssertThrow(false, ExcMessage(message.str()));
          }
      }
  }


  Tensor<1, 2>
  ExpressionVolumeLoad::body_force(const Point<2> &p) const
  {
    Tensor<1, 2> f;
    if (force)
      {
        double values[2];
        evaluate(*force, force_entry, p, values);
        f[0] = values[0];
        f[1] = values[1];
      }
    return f;
  }


  SymmetricTensor<2, 2>
  ExpressionVolumeLoad::eigenstrain(const Point<2> &p) const
  {
    SymmetricTensor<2, 2> eps;
    if (strain)
      {
        double values[3];
        evaluate(*strain, strain_entry, p, values);
        eps[0][0] = values[0];
        eps[1][1] = values[1];
        eps[0][1] = values[2];
      }
    return eps;
  }
} // namespace bilayer
