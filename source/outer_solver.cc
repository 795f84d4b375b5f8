#include <bilayer/accelerated_solver.h>
#include <bilayer/active_set_solver.h>
#include <bilayer/outer_solver.h>
#include <bilayer/uzawa_solver.h>

#include <cmath>
#include <random>

namespace bilayer
{
  using namespace dealii;

  std::unique_ptr<OuterSolver>
  create_outer_solver(const SolverParameters   &parameters,
                      const OutputParameters   &output,
                      const ConditionalOStream &pcout)
  {
    switch (parameters.method)
      {
        case SolverMethod::active_set:
          return std::make_unique<ActiveSetSolver>(parameters, output, pcout);
        case SolverMethod::accelerated:
          return std::make_unique<AcceleratedSolver>(parameters, output, pcout);
        case SolverMethod::uzawa:
          break;
      }
    return std::make_unique<UzawaSolver>(parameters, output, pcout);
  }


  SpectrumEstimate
  estimate_lambda_max(const Subproblems         &subproblems,
                      const Interface           &interface,
                      const unsigned int         max_iterations,
                      const BlockVector<double> *mask)
  {
    SpectrumEstimate    estimate;
    BlockVector<double> x, g;
    interface.space().initialize(x);
    // A fixed pseudo-random start, so that runs are reproducible and the
    // start is not orthogonal to the top eigenvector.
    std::mt19937                           random(42);
    std::uniform_real_distribution<double> uniform(-1., 1.);
    for (unsigned int i = 0; i < x.size(); ++i)
      x(i) = uniform(random);
    interface.space().restrict_to_free(x);
    if (mask)
      x.scale(*mask);
    x /= interface.space().weighted_norm(x);

    Solutions w;
    for (unsigned int k = 0; k < max_iterations; ++k)
      {
        solve_homogeneous_subproblems(subproblems, interface, x, w);
        estimate.subdomain_solves += Layout::n_subproblems;
        estimate.iterations = k + 1;
        interface.jumps(w, g);
        g *= -1.; // S x
        if (mask)
          g.scale(*mask);

        // Rayleigh quotient <x, S x>_D with ||x||_D = 1.
        const double lambda = interface.space().weighted_dot(x, g);
        const bool   settled =
          k > 0 && std::abs(lambda - estimate.lambda_max) < 1e-4 * lambda;
        estimate.lambda_max = lambda;
        const double norm   = interface.space().weighted_norm(g);
        if (settled || norm == 0.)
          break;
        x = g;
        x /= norm;
      }
    return estimate;
  }
} // namespace bilayer
