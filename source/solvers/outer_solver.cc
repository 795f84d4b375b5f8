#include <deal.II/lac/precondition.h>
#include <deal.II/lac/solver_cg.h>
#include <deal.II/lac/solver_control.h>

#include <bilayer/solvers/accelerated_solver.h>
#include <bilayer/solvers/active_set_solver.h>
#include <bilayer/solvers/outer_solver.h>
#include <bilayer/solvers/uzawa_solver.h>

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
        estimate.subdomain_solves += subproblems.size();
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


  namespace
  {
    /**
     * D^{-1/2} C A^{-1} C^T D^{-1/2} on the free multiplier components, as
     * a matrix for SolverCG: one homogeneous solve per subproblem per
     * product.
     */
    class SymmetricDualOperator
    {
    public:
      SymmetricDualOperator(const Subproblems &subproblems,
                            const Interface   &interface)
        : subproblems(subproblems)
        , interface(interface)
      {
        interface.space().initialize(mu);
        BlockVector<double> weights(mu);
        weights = 1.;
        interface.space().scale_by_weights(weights);
        for (unsigned int i = 0; i < mu.size(); ++i)
          if (interface.space().free(i))
            {
              free_index.push_back(i);
              sqrt_weight.push_back(std::sqrt(weights(i)));
            }
      }

      unsigned int
      size() const
      {
        return free_index.size();
      }

      void
      vmult(Vector<double> &dst, const Vector<double> &src) const
      {
        mu = 0.;
        for (unsigned int k = 0; k < size(); ++k)
          mu(free_index[k]) = src(k) / sqrt_weight[k];
        solve_homogeneous_subproblems(subproblems, interface, mu, w);
        ++products;
        // C w = -C A^{-1} C^T mu (Layout's signs).
        g.reinit(mu);
        interface.coupling().differences(w, true, g);
        for (unsigned int k = 0; k < size(); ++k)
          dst(k) = -g(free_index[k]) / sqrt_weight[k];
      }

      mutable unsigned long products = 0;

    private:
      const Subproblems          &subproblems;
      const Interface            &interface;
      std::vector<unsigned int>   free_index;
      std::vector<double>         sqrt_weight;
      mutable BlockVector<double> mu, g;
      mutable Solutions           w;
    };
  } // namespace


  DualSpectrum
  estimate_dual_spectrum(const Subproblems &subproblems,
                         const Interface   &interface,
                         const unsigned int max_iterations)
  {
    DualSpectrum result;
    for (const unsigned int b : Layout::indices(interface.n_blocks()))
      {
        const auto &bp = interface.space().breakpoints(b);
        for (unsigned int e = 0; e + 1 < bp.size(); ++e)
          result.h = result.h == 0 ? bp[e + 1] - bp[e] :
                                     std::min(result.h, bp[e + 1] - bp[e]);
      }
    const SymmetricDualOperator op(subproblems, interface);
    if (op.size() == 0)
      return result;

    Vector<double>                         x(op.size()), b(op.size());
    std::mt19937                           random(42);
    std::uniform_real_distribution<double> uniform(-1., 1.);
    for (unsigned int k = 0; k < b.size(); ++k)
      b(k) = uniform(random);
    SolverControl            control(max_iterations, 1e-10 * b.l2_norm());
    SolverCG<Vector<double>> cg(control);
    std::vector<double>      eigenvalues;
    cg.connect_eigenvalues_slot(
      [&eigenvalues](const std::vector<double> &values) {
        eigenvalues = values;
      });
    try
      {
        cg.solve(op, x, b, PreconditionIdentity());
      }
    catch (const SolverControl::NoConvergence &)
      {
        // The Ritz values of the steps taken are estimates all the same.
      }
    if (!eigenvalues.empty())
      {
        result.lambda_min = eigenvalues.front();
        result.lambda_max = eigenvalues.back();
      }
    result.iterations       = control.last_step();
    result.subdomain_solves = op.products * subproblems.size();
    return result;
  }
} // namespace bilayer
