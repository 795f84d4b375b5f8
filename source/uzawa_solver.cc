#include <deal.II/base/timer.h>

#include <bilayer/uzawa_solver.h>

#include <cmath>
#include <iomanip>
#include <limits>
#include <sstream>

namespace bilayer
{
  using namespace dealii;

  UzawaSolver::UzawaSolver(const SolverParameters   &parameters,
                           const OutputParameters   &output,
                           const ConditionalOStream &pcout)
    : FirstOrderSolver(parameters,
                       output,
                       pcout,
                       "uzawa",
                       {1., " * 2 / lambda_max"})
  {}


  void
  UzawaSolver::iterate(const Subproblems   &subproblems,
                       const Interface     &interface,
                       BlockVector<double> &mu,
                       Solutions           &w,
                       SolverResult        &result) const
  {
    const double        theta           = result.theta;
    const unsigned long spectrum_solves = result.subdomain_solves;
    DivergenceTest      divergence(parameters,
                              step_bound,
                              subproblems,
                              interface,
                              theta,
                              result.lambda_max,
                              DivergenceTest::uzawa_window);
    Solutions           w_old;
    BlockVector<double> g, mu_new, increment;
    double              last_increment = 0;

    for (unsigned int k = 0;; ++k)
      {
        const double value = evaluate(subproblems,
                                      interface,
                                      k,
                                      spectrum_solves,
                                      mu,
                                      w,
                                      w_old,
                                      g,
                                      last_increment,
                                      result);

        if (value < parameters.tolerance)
          {
            result.converged = true;
            if (parameters.auto_theta)
              threshold_at_solution(subproblems, interface, mu, g, result);
            std::ostringstream msg;
            msg << "stopping rule met after " << k << " iterations";
            result.message = msg.str();
            return;
          }
        if (k >= parameters.max_iterations)
          {
            result.message = iteration_limit_message(
              parameters,
              value,
              "; first-order iterations slow down as the dual "
              "operator's condition number grows (fine meshes, "
              "material contrast): Solver/Method = accelerated or "
              "active set");
            return;
          }

        // Step 3: mu^{k+1} = P(mu^k + theta g^k).
        projected_step(interface, theta, mu, g, mu_new);
        increment = mu;
        increment -= mu_new;
        last_increment = interface.space().weighted_norm(increment);
        result.message = divergence.check(k, value, last_increment, mu_new);
        if (!result.message.empty())
          {
            result.diverged = true;
            return;
          }

        w_old.swap(w);
        mu.swap(mu_new);
      }
  }


  void
  UzawaSolver::threshold_at_solution(const Subproblems         &subproblems,
                                     const Interface           &interface,
                                     const BlockVector<double> &mu,
                                     const BlockVector<double> &g,
                                     SolverResult              &result) const
  {
    // Components held at a bound by the projection drop out of the
    // iteration near the solution.
    const double        theta = result.theta;
    BlockVector<double> free_set(mu), trial(mu);
    trial.add(theta, g);
    interface.space().project(trial);
    for (unsigned int i = 0; i < mu.size(); ++i)
      free_set(i) = trial(i) == mu(i) + theta * g(i) ? 1. : 0.;
    const SpectrumEstimate estimate = estimate_lambda_max(
      subproblems, interface, parameters.spectrum_iterations, &free_set);
    result.subdomain_solves += estimate.subdomain_solves;
    result.threshold_at_solution = 2. / estimate.lambda_max;
    pcout << "    threshold 2/lambda_max on the free multipliers "
             "at the solution: "
          << std::setprecision(6) << result.threshold_at_solution
          << std::defaultfloat << std::endl;
  }
} // namespace bilayer
