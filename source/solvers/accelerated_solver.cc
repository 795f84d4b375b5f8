#include <deal.II/base/timer.h>

#include <bilayer/interface/interface_diagnostics.h>
#include <bilayer/solvers/accelerated_solver.h>

#include <cmath>
#include <limits>
#include <sstream>

namespace bilayer
{
  using namespace dealii;

  AcceleratedSolver::AcceleratedSolver(const SolverParameters   &parameters,
                                       const OutputParameters   &output,
                                       const ConditionalOStream &pcout)
    : FirstOrderSolver(parameters,
                       output,
                       pcout,
                       "accelerated",
                       {0.5, " / lambda_max"})
  {}


  void
  AcceleratedSolver::iterate(const Subproblems   &subproblems,
                             const Interface     &interface,
                             BlockVector<double> &mu,
                             Solutions           &w,
                             SolverResult        &result) const
  {
    const double theta = result.theta;
    // Solves outside the iteration proper: the power iteration of theta =
    // auto and the checks of projected iterates.
    unsigned long  extra_solves = result.subdomain_solves;
    DivergenceTest divergence(parameters,
                              step_bound,
                              subproblems,
                              interface,
                              theta,
                              result.lambda_max,
                              DivergenceTest::accelerated_window);
    Solutions      w_old;
    // mu is the extrapolated point y_k, projected the last projected
    // iterate x_k, increment x_k - x_{k+1}.
    BlockVector<double> g, projected(mu), next, increment;
    double              t              = 1;
    double              last_increment = 0;

    for (unsigned int k = 0;; ++k)
      {
        const double value = evaluate(subproblems,
                                      interface,
                                      k,
                                      extra_solves,
                                      mu,
                                      w,
                                      w_old,
                                      g,
                                      last_increment,
                                      result);

        if (value < parameters.tolerance)
          {
            const bool accept = accept_projected(
              subproblems, interface, projected, mu, w, result);
            extra_solves += subproblems.size();
            if (accept)
              {
                result.converged = true;
                std::ostringstream msg;
                msg << "stopping rule met after " << k << " iterations";
                result.message = msg.str();
                return;
              }
          }
        if (k >= parameters.max_iterations)
          {
            result.message = iteration_limit_message(
              parameters,
              value,
              "; Solver/Method = active set needs far fewer "
              "iterations on ill-conditioned scenes");
            return;
          }

        // x_{k+1} = P(y_k + theta g(y_k)).
        projected_step(interface, theta, mu, g, next);
        increment = projected;
        increment -= next;
        last_increment = interface.space().weighted_norm(increment);
        result.message = divergence.check(k, value, last_increment, next);
        if (!result.message.empty())
          {
            result.diverged = true;
            return;
          }

        w_old.swap(w);
        // FISTA momentum; restart when the step goes against the gradient at
        // the extrapolated point (O'Donoghue and Candes' gradient restart):
        // <g(y_k), x_{k+1} - x_k>_D < 0.
        if (-interface.space().weighted_dot(g, increment) < 0)
          t = 1;
        const double t_new = 0.5 * (1. + std::sqrt(1. + 4. * t * t));
        // y_{k+1} = x_{k+1} + (t - 1) / t_new (x_{k+1} - x_k)
        mu = next;
        mu.add(-(t - 1.) / t_new, increment);
        t         = t_new;
        projected = next;
      }
  }


  bool
  AcceleratedSolver::accept_projected(const Subproblems         &subproblems,
                                      const Interface           &interface,
                                      const BlockVector<double> &x,
                                      BlockVector<double>       &mu,
                                      Solutions                 &w,
                                      SolverResult              &result) const
  {
    Solutions w_projected;
    solve_subproblems(subproblems,
                      interface,
                      x,
                      w_projected,
                      parameters.iterates_on_sigma() ? SolveExtent::sigma :
                                                       SolveExtent::whole);
    result.subdomain_solves += subproblems.size();
    bool accept = true;
    if (parameters.stopping_rule == StoppingRule::kkt)
      {
        BlockVector<double> g_projected;
        interface.jumps(w_projected, g_projected);
        accept = kkt_residual(interface, w_projected, g_projected, x).value() <
                 parameters.tolerance;
      }
    if (accept)
      {
        mu = x;
        w.swap(w_projected);
      }
    return accept;
  }
} // namespace bilayer
