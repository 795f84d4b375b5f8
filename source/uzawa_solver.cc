#include <deal.II/base/timer.h>

#include <bilayer/uzawa_solver.h>

#include <algorithm>
#include <cmath>
#include <deque>
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
    if (parameters.auto_theta && parameters.adaptive_auto_steps)
      {
        iterate_adaptive(subproblems, interface, mu, w, result);
        return;
      }
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

        if (stopped(k,
                    value,
                    subproblems,
                    interface,
                    mu,
                    g,
                    "; first-order iterations slow down as the dual "
                    "operator's condition number grows (fine meshes, "
                    "material contrast): Solver/Method = accelerated or "
                    "active set",
                    result))
          return;

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
  UzawaSolver::iterate_adaptive(const Subproblems   &subproblems,
                                const Interface     &interface,
                                BlockVector<double> &mu,
                                Solutions           &w,
                                SolverResult        &result) const
  {
    const unsigned long spectrum_solves = result.subdomain_solves;
    const SolveExtent   extent =
      parameters.iterates_on_sigma() ? SolveExtent::sigma : SolveExtent::whole;
    DivergenceTest divergence(parameters,
                              step_bound,
                              subproblems,
                              interface,
                              result.theta,
                              result.lambda_max,
                              DivergenceTest::uzawa_window);
    // The Barzilai-Borwein steps lie in [alpha_min, alpha_max]; the first
    // one is theta = auto.
    const double alpha_min = 1e-3 * result.theta;
    const double alpha_max = 1e12 * result.theta;
    double       alpha     = result.theta;
    // The dual objective q(mu) = <mu, g(0)>_D - <mu, S mu>_D / 2 up to a
    // constant (its D-gradient is g(mu) = g(0) - S mu), relative to its
    // value at the first iterate, and its last values for the non-monotone
    // line search.
    double                 q = 0;
    std::deque<double>     recent_q(1, 0.);
    constexpr unsigned int memory              = 10;
    constexpr double       sufficient_increase = 1e-4;
    Solutions              w_old, w_trial;
    BlockVector<double>    g, g_trial, trial, direction, s_direction;
    double                 last_increment = 0;
    double                 value          = 0;

    for (unsigned int k = 0;; ++k)
      {
        if (k == 0)
          value = evaluate(subproblems,
                           interface,
                           0,
                           spectrum_solves,
                           mu,
                           w,
                           w_old,
                           g,
                           last_increment,
                           result);

        if (stopped(k,
                    value,
                    subproblems,
                    interface,
                    mu,
                    g,
                    "; first-order iterations slow down as the dual "
                    "operator's condition number grows (fine meshes, "
                    "material contrast): Solver/Method = active set",
                    result))
          return;

        // The projected direction d = P(mu + alpha g) - mu, an ascent
        // direction: <g, d>_D >= |d|_D^2 / alpha.
        projected_step(interface, alpha, mu, g, trial);
        direction = trial;
        direction -= mu;
        const double g_d = interface.space().weighted_dot(g, direction);
        const double d_d = interface.space().weighted_dot(direction, direction);
        // The solutions are affine in the multipliers: one solve at the
        // trial point gives S d = g(mu) - g(mu + d) and the whole segment.
        solve_subproblems(subproblems, interface, trial, w_trial, extent);
        interface.jumps(w_trial, g_trial);
        s_direction = g;
        s_direction -= g_trial;
        const double d_s_d =
          interface.space().weighted_dot(direction, s_direction);

        // Non-monotone line search (Grippo, Lampariello and Lucidi; the
        // spectral projected gradient of Birgin, Martinez and Raydan):
        // accept the trial point if q rises above the lowest of the last
        // values by a fraction of <g, d>_D, else take the maximiser of q on
        // the segment, t = <g, d>_D / <d, S d>_D < 1, which does.
        const double q_trial = q + g_d - 0.5 * d_s_d;
        const double q_low =
          *std::min_element(recent_q.begin(), recent_q.end());
        double t = 1.;
        if (!(q_trial >= q_low + sufficient_increase * g_d) && d_s_d > 0)
          t = std::min(1., g_d / d_s_d);
        last_increment = t * std::sqrt(d_d);
        result.message = divergence.check_finite(k, value, last_increment);
        if (!result.message.empty())
          {
            result.diverged = true;
            return;
          }

        w_old.swap(w);
        if (t == 1.)
          {
            mu.swap(trial);
            w.swap(w_trial);
            g.swap(g_trial);
          }
        else
          {
            mu.add(t, direction);
            g.add(-t, s_direction);
            for (const unsigned int s : Layout::subproblems)
              {
                w[s] = w_trial[s];
                w[s].sadd(t, 1. - t, w_old[s]);
              }
          }
        q += t * g_d - 0.5 * t * t * d_s_d;
        recent_q.push_back(q);
        if (recent_q.size() > memory)
          recent_q.pop_front();
        // Barzilai-Borwein (the second step): alpha = <s, S s>_D / <S s,
        // S s>_D for the step s = t d, a Rayleigh quotient of S^-1 weighted
        // by S, between 1 / lambda_max and 1 / lambda_min on the free
        // multipliers (it takes fewer iterations than <s, s>_D / <s, S s>_D
        // under strong contrast).
        const double sd_sd =
          interface.space().weighted_dot(s_direction, s_direction);
        if (d_s_d > 0 && sd_sd > 0)
          alpha = std::min(alpha_max, std::max(alpha_min, d_s_d / sd_sd));
        else
          alpha = alpha_max;

        // Bookkeeping of iteration k + 1 as in evaluate().
        result.iterations = k + 1;
        result.subdomain_solves =
          spectrum_solves + Layout::n_subproblems * (k + 2ul);
        value = stopping_value(
          parameters, subproblems, interface, w, w_old, g, mu, last_increment);
        result.stopping_value = value;
        print_progress(output,
                       pcout,
                       k + 1,
                       value,
                       last_increment,
                       interface,
                       w,
                       g,
                       clock,
                       parameters.tolerance);
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


  bool
  UzawaSolver::stopped(const unsigned int         k,
                       const double               value,
                       const Subproblems         &subproblems,
                       const Interface           &interface,
                       const BlockVector<double> &mu,
                       const BlockVector<double> &g,
                       const std::string         &limit_advice,
                       SolverResult              &result) const
  {
    if (value < parameters.tolerance)
      {
        result.converged = true;
        if (parameters.auto_theta)
          threshold_at_solution(subproblems, interface, mu, g, result);
        std::ostringstream msg;
        msg << "stopping rule met after " << k << " iterations";
        result.message = msg.str();
        return true;
      }
    if (k >= parameters.max_iterations)
      {
        result.message =
          iteration_limit_message(parameters, value, limit_advice);
        return true;
      }
    return false;
  }
} // namespace bilayer
