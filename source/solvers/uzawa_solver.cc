#include <deal.II/base/timer.h>

#include <bilayer/solvers/uzawa_solver.h>

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


  namespace
  {
    /**
     * The dual objective q(mu) = <mu, g(0)>_D - <mu, S mu>_D / 2 up to a
     * constant (its D-gradient is g(mu) = g(0) - S mu), relative to its
     * value at the first iterate, and its last values for the non-monotone
     * line search (Grippo, Lampariello and Lucidi; the spectral projected
     * gradient of Birgin, Martinez and Raydan).
     */
    class NonmonotoneLineSearch
    {
    public:
      NonmonotoneLineSearch()
        : recent_q(1, 0.)
      {}

      /**
       * The step t along the ascent direction d with <g, d>_D = @p g_d and
       * <d, S d>_D = @p d_s_d: accept the trial point (t = 1) if q rises
       * above the lowest of the last values by a fraction of <g, d>_D, else
       * take the maximiser of q on the segment, t = <g, d>_D / <d, S d>_D <
       * 1, which does.
       */
      double
      step_length(const double g_d, const double d_s_d) const
      {
        const double q_trial = q + g_d - 0.5 * d_s_d;
        const double q_low =
          *std::min_element(recent_q.begin(), recent_q.end());
        double t = 1.;
        if (!(q_trial >= q_low + sufficient_increase * g_d) && d_s_d > 0)
          t = std::min(1., g_d / d_s_d);
        return t;
      }

      /// Records q after the step t d (q is quadratic along the segment).
      void
      record(const double t, const double g_d, const double d_s_d)
      {
        q += t * g_d - 0.5 * t * t * d_s_d;
        recent_q.push_back(q);
        if (recent_q.size() > memory)
          recent_q.pop_front();
      }

    private:
      static constexpr unsigned int memory              = 10;
      static constexpr double       sufficient_increase = 1e-4;
      double                        q                   = 0;
      std::deque<double>            recent_q;
    };


    /// The projected direction of one step, its trial point with the
    /// solutions and jumps there, and the products the line search needs.
    struct ProjectedDirection
    {
      Solutions           w_trial;
      BlockVector<double> g_trial, trial, direction, s_direction;
      /// <g, d>_D, <d, d>_D and <d, S d>_D.
      double g_d = 0, d_d = 0, d_s_d = 0;
    };


    /**
     * The projected direction d = P(mu + @p alpha g) - mu at @p mu with
     * jumps @p g, and S d from one solve at the trial point mu + d.
     */
    void
    compute_projected_direction(const Subproblems         &subproblems,
                                const Interface           &interface,
                                const SolveExtent          extent,
                                const double               alpha,
                                const BlockVector<double> &mu,
                                const BlockVector<double> &g,
                                ProjectedDirection        &step)
    {
      // The projected direction d = P(mu + alpha g) - mu, an ascent
      // direction: <g, d>_D >= |d|_D^2 / alpha.
      projected_step(interface, alpha, mu, g, step.trial);
      step.direction = step.trial;
      step.direction -= mu;
      step.g_d = interface.space().weighted_dot(g, step.direction);
      step.d_d = interface.space().weighted_dot(step.direction, step.direction);
      // The solutions are affine in the multipliers: one solve at the
      // trial point gives S d = g(mu) - g(mu + d) and the whole segment.
      solve_subproblems(
        subproblems, interface, step.trial, step.w_trial, extent);
      interface.jumps(step.w_trial, step.g_trial);
      step.s_direction = g;
      step.s_direction -= step.g_trial;
      step.d_s_d =
        interface.space().weighted_dot(step.direction, step.s_direction);
    }


    /**
     * The iterate mu + @p t d with its solutions and jumps (those of the
     * trial point for t = 1, else the affine combinations); the present
     * solutions move to @p w_old.
     */
    void
    move_along_segment(const double         t,
                       ProjectedDirection  &step,
                       BlockVector<double> &mu,
                       Solutions           &w,
                       Solutions           &w_old,
                       BlockVector<double> &g)
    {
      w_old.swap(w);
      if (t == 1.)
        {
          mu.swap(step.trial);
          w.swap(step.w_trial);
          g.swap(step.g_trial);
        }
      else
        {
          mu.add(t, step.direction);
          g.add(-t, step.s_direction);
          for (const unsigned int s : Layout::indices(w.size()))
            {
              w[s] = step.w_trial[s];
              w[s].sadd(t, 1. - t, w_old[s]);
            }
        }
    }


    /**
     * Barzilai-Borwein (the second step): alpha = <s, S s>_D / <S s,
     * S s>_D for the step s = t d, a Rayleigh quotient of S^-1 weighted
     * by S, between 1 / lambda_max and 1 / lambda_min on the free
     * multipliers (it takes fewer iterations than <s, s>_D / <s, S s>_D
     * under strong contrast), within [@p alpha_min, @p alpha_max].
     */
    double
    barzilai_borwein_step(const Interface          &interface,
                          const ProjectedDirection &step,
                          const double              alpha_min,
                          const double              alpha_max)
    {
      const double sd_sd =
        interface.space().weighted_dot(step.s_direction, step.s_direction);
      if (step.d_s_d > 0 && sd_sd > 0)
        return std::min(alpha_max, std::max(alpha_min, step.d_s_d / sd_sd));
      else
        return alpha_max;
    }
  } // namespace


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
    const double          alpha_min = 1e-3 * result.theta;
    const double          alpha_max = 1e12 * result.theta;
    double                alpha     = result.theta;
    NonmonotoneLineSearch line_search;
    Solutions             w_old;
    BlockVector<double>   g;
    ProjectedDirection    step;
    double                last_increment = 0;
    double                value          = 0;

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

        compute_projected_direction(
          subproblems, interface, extent, alpha, mu, g, step);
        const double t = line_search.step_length(step.g_d, step.d_s_d);
        last_increment = t * std::sqrt(step.d_d);
        result.message = divergence.check_finite(k, value, last_increment);
        if (!result.message.empty())
          {
            result.diverged = true;
            return;
          }

        move_along_segment(t, step, mu, w, w_old, g);
        line_search.record(t, step.g_d, step.d_s_d);
        alpha = barzilai_borwein_step(interface, step, alpha_min, alpha_max);

        // Bookkeeping of iteration k + 1 as in evaluate().
        result.iterations = k + 1;
        result.subdomain_solves =
          spectrum_solves + subproblems.size() * (k + 2ul);
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
                       mu,
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
