#include <deal.II/base/thread_management.h>
#include <deal.II/base/timer.h>

#include <bilayer/contact_solver.h>
#include <bilayer/tasks.h>

#include <cmath>
#include <iomanip>
#include <limits>
#include <random>
#include <sstream>

namespace bilayer
{
  namespace
  {
    /// The four solves with the multiplier loads of @p multipliers, as
    /// parallel tasks; @p homogeneous drops the tractions and the prescribed
    /// displacement (the linear part of the solution map).
    void
    solve_all(const Subproblems         &subproblems,
              const Interface           &interface,
              const BlockVector<double> &multipliers,
              Solutions                 &solutions,
              const bool                 homogeneous)
    {
      Solutions loads;
      interface.apply(multipliers, loads);
      Tasks tasks;
      for (unsigned int s = 0; s < 4; ++s)
        if (subproblems[s] != nullptr && subproblems[s]->owned())
          tasks.add([&, s]() {
            if (homogeneous)
              subproblems[s]->solve_homogeneous(loads[s], solutions[s]);
            else
              subproblems[s]->solve(loads[s], solutions[s]);
          });
      tasks.join_all();
      share_traces(subproblems, solutions);
    }
  } // namespace


  void
  share_traces(const Subproblems &subproblems, Solutions &solutions)
  {
    for (unsigned int s = 0; s < 4; ++s)
      if (subproblems[s] != nullptr)
        subproblems[s]->share_trace(solutions[s]);
  }


  std::array<double, 4>
  share_values(const Subproblems                         &subproblems,
               const std::function<double(unsigned int)> &value)
  {
    std::array<double, 4> values{};
    for (unsigned int s = 0; s < 4; ++s)
      if (subproblems[s] != nullptr && subproblems[s]->owned())
        values[s] = value(s);
    subproblems[0]->processes().share(values);
    return values;
  }


  void
  solve_subproblems(const Subproblems         &subproblems,
                    const Interface           &interface,
                    const BlockVector<double> &multipliers,
                    Solutions                 &solutions)
  {
    solve_all(subproblems, interface, multipliers, solutions, false);
  }


  void
  solve_homogeneous_subproblems(const Subproblems         &subproblems,
                                const Interface           &interface,
                                const BlockVector<double> &multipliers,
                                Solutions                 &solutions)
  {
    solve_all(subproblems, interface, multipliers, solutions, true);
  }


  SpectrumEstimate
  estimate_lambda_max(const Subproblems         &subproblems,
                      const Interface           &interface,
                      const unsigned int         max_iterations,
                      const BlockVector<double> *mask)
  {
    SpectrumEstimate    estimate;
    BlockVector<double> x, g;
    interface.initialize(x);
    // A fixed pseudo-random start, so that runs are reproducible and the
    // start is not orthogonal to the top eigenvector.
    std::mt19937                           random(42);
    std::uniform_real_distribution<double> uniform(-1., 1.);
    for (unsigned int i = 0; i < x.size(); ++i)
      x(i) = uniform(random);
    interface.restrict_to_free(x);
    if (mask)
      x.scale(*mask);
    x /= interface.weighted_norm(x);

    Solutions w;
    for (unsigned int k = 0; k < max_iterations; ++k)
      {
        solve_all(subproblems, interface, x, w, true);
        estimate.subdomain_solves += 4;
        estimate.iterations = k + 1;
        interface.jumps(w, g);
        g *= -1.; // S x
        if (mask)
          g.scale(*mask);

        // Rayleigh quotient <x, S x>_D with ||x||_D = 1.
        const double lambda = interface.weighted_dot(x, g);
        const bool   settled =
          k > 0 && std::abs(lambda - estimate.lambda_max) < 1e-4 * lambda;
        estimate.lambda_max = lambda;
        const double norm   = interface.weighted_norm(g);
        if (settled || norm == 0.)
          break;
        x = g;
        x /= norm;
      }
    return estimate;
  }


  UzawaSolver::UzawaSolver(const SolverParameters   &parameters,
                           const OutputParameters   &output,
                           const ConditionalOStream &pcout)
    : parameters(parameters)
    , output(output)
    , pcout(pcout)
  {}


  SolverResult
  UzawaSolver::solve(const Subproblems   &subproblems,
                     const Interface     &interface,
                     BlockVector<double> &mu,
                     Solutions           &w) const
  {
    SolverResult result;
    const bool   accelerated = parameters.method == SolverMethod::accelerated;
    result.solver            = accelerated ? "accelerated" : "uzawa";
    result.theta             = parameters.theta;
    unsigned long spectrum_solves = 0, extra_solves = 0;
    Timer         timer;
    // The step of theta = auto: projected gradient steps are stable below
    // 2 / lambda_max; the accelerated method needs a step below
    // 1 / lambda_max.
    const auto auto_step = [&](const double lambda_max) {
      return parameters.auto_theta_fraction * 2. / lambda_max *
             (accelerated ? 0.5 : 1.);
    };
    if (parameters.auto_theta)
      {
        const SpectrumEstimate estimate =
          estimate_lambda_max(subproblems,
                              interface,
                              parameters.spectrum_iterations);
        spectrum_solves            = estimate.subdomain_solves;
        result.lambda_max          = estimate.lambda_max;
        result.predicted_threshold = 2. / estimate.lambda_max;
        result.theta               = auto_step(estimate.lambda_max);
        pcout << "    theta = auto: lambda_max(S) = " << std::setprecision(6)
              << estimate.lambda_max << " after " << estimate.iterations
              << " power iterations, predicted threshold 2/lambda_max = "
              << result.predicted_threshold << ", theta = " << result.theta
              << std::defaultfloat << std::endl;
      }
    const double theta = result.theta;
    // After a divergence: the step that theta = auto takes, from a power
    // iteration on the dual operator (its solves are counted) unless one
    // was already run.
    const auto safe_step = [&]() -> std::string {
      double lambda_max = result.lambda_max;
      if (!(lambda_max > 0))
        {
          const SpectrumEstimate estimate =
            estimate_lambda_max(subproblems,
                                interface,
                                parameters.spectrum_iterations);
          extra_solves += estimate.subdomain_solves;
          lambda_max = estimate.lambda_max;
        }
      if (!std::isfinite(auto_step(lambda_max)) || !(lambda_max > 0))
        return std::string();
      std::ostringstream text;
      text << std::setprecision(4)
           << "; estimated safe step: theta <= " << auto_step(lambda_max)
           << " (" << parameters.auto_theta_fraction
           << (accelerated ? " / lambda_max" : " * 2 / lambda_max")
           << ", or theta = auto)";
      return text.str();
    };
    result.setup_seconds = timer.wall_time();
    timer.restart();
    // Every return below goes through this.
    const auto finish = [&]() {
      result.iteration_seconds = timer.wall_time();
      return result;
    };

    Solutions           w_old;
    BlockVector<double> g, mu_new, mu_old;
    // The accelerated method: the last projected iterate x_k and the
    // momentum parameter; mu is then the extrapolated point y_k.
    BlockVector<double> projected(mu);
    double              t = 1;
    Vector<double>      difference;
    double              min_increment  = std::numeric_limits<double>::max();
    double              last_increment = 0;

    for (unsigned int k = 0;; ++k)
      {
        solve_subproblems(subproblems, interface, mu, w);
        result.iterations = k;
        result.subdomain_solves =
          spectrum_solves + extra_solves + 4ul * (k + 1);
        interface.jumps(w, g);

        // Stopping rule at step k >= 1. The relative violation needs the
        // traces of all four solutions: evaluated only where it is used.
        const auto relative_violation = [&]() {
          const double scale     = interface.displacement_scale(w);
          const double violation = interface.discrete_violation(g);
          return scale > 0 ? violation / scale : violation;
        };
        double value = std::numeric_limits<double>::infinity();
        if (k >= 1)
          {
            if (parameters.stopping_rule == StoppingRule::kkt)
              value = interface.kkt_residual(w, g, mu).value();
            else if (parameters.stopping_rule == StoppingRule::relative)
              {
                const double norm = interface.weighted_norm(mu);
                const double change =
                  norm > 0 ? last_increment / norm : last_increment;
                value = std::max(change, relative_violation());
              }
            else
              {
                // Energy norms of whole solutions: each owner evaluates
                // its own.
                const std::array<double, 4> ratios =
                  share_values(subproblems, [&](const unsigned int s) {
                    difference = w[s];
                    difference -= w_old[s];
                    const double d = std::sqrt(
                      subproblems[s]->energy_norm_squared(difference));
                    const double n2 = subproblems[s]->energy_norm_squared(w[s]);
                    const double denominator =
                      parameters.stopping_rule == StoppingRule::paper ?
                        n2 :
                        std::sqrt(n2);
                    return d == 0. ? 0. : d / denominator;
                  });
                value = 0;
                for (const double ratio : ratios)
                  value = std::max(value, ratio);
              }
          }
        result.stopping_value = value;

        if (output.progress_interval > 0 && k > 0 &&
            k % output.progress_interval == 0)
          pcout << "    iteration " << std::setw(6) << k << "  stopping value "
                << std::scientific << std::setprecision(3) << value
                << "  multiplier change " << last_increment
                << "  relative violation " << relative_violation()
                << std::defaultfloat << std::endl;

        bool accept = value < parameters.tolerance;
        if (accept && accelerated)
          {
            // The result is the projected iterate x_k, which lies in the
            // multiplier sets, with its own solutions; under the KKT rule
            // it has to meet the rule itself.
            Solutions w_projected;
            solve_subproblems(subproblems, interface, projected, w_projected);
            extra_solves += 4;
            result.subdomain_solves += 4;
            if (parameters.stopping_rule == StoppingRule::kkt)
              {
                BlockVector<double> g_projected;
                interface.jumps(w_projected, g_projected);
                accept =
                  interface.kkt_residual(w_projected, g_projected, projected)
                    .value() < parameters.tolerance;
              }
            if (accept)
              {
                mu = projected;
                w.swap(w_projected);
              }
          }
        if (accept)
          {
            result.converged = true;
            if (parameters.auto_theta && !accelerated)
              {
                // Components held at a bound by the projection drop out of
                // the iteration near the solution.
                BlockVector<double> free_set(mu), trial(mu);
                trial.add(theta, g);
                interface.project(trial);
                for (unsigned int i = 0; i < mu.size(); ++i)
                  free_set(i) = trial(i) == mu(i) + theta * g(i) ? 1. : 0.;
                const SpectrumEstimate estimate =
                  estimate_lambda_max(subproblems,
                                      interface,
                                      parameters.spectrum_iterations,
                                      &free_set);
                result.subdomain_solves += estimate.subdomain_solves;
                result.threshold_at_solution = 2. / estimate.lambda_max;
                pcout << "    threshold 2/lambda_max on the free multipliers "
                         "at the solution: "
                      << std::setprecision(6) << result.threshold_at_solution
                      << std::defaultfloat << std::endl;
              }
            std::ostringstream msg;
            msg << "stopping rule met after " << k << " iterations";
            result.message = msg.str();
            return finish();
          }
        if (k >= parameters.max_iterations)
          {
            std::ostringstream msg;
            msg << "iteration limit " << parameters.max_iterations
                << " reached (Solver/Maximum iterations) with stopping value "
                << value << " > Solver/Tolerance " << parameters.tolerance
                << (parameters.stopping_rule == StoppingRule::paper ?
                      "; the paper's rule |w^k - w^k-1| / |w^k|^2 is not "
                      "scale invariant (it grows as the loads shrink): "
                      "Solver/Stopping rule = relative or kkt" :
                    accelerated ?
                      "; Solver/Method = active set needs far fewer "
                      "iterations on ill-conditioned scenes" :
                      "; first-order iterations slow down as the dual "
                      "operator's condition number grows (fine meshes, "
                      "material contrast): Solver/Method = accelerated or "
                      "active set");
            result.message = msg.str();
            return finish();
          }

        // Multiplier update, step 3: x_{k+1} = P(y_k + theta g(y_k)), with
        // y_k = mu^k for the paper's iteration.
        mu_new = mu;
        mu_new.add(theta, g);
        interface.project(mu_new);
        mu_old = accelerated ? projected : mu;
        mu_old -= mu_new; // x_k - x_{k+1}
        last_increment = interface.weighted_norm(mu_old);

        if (!std::isfinite(last_increment) || (k >= 1 && !std::isfinite(value)))
          {
            result.diverged = true;
            result.message =
              k == 0 ?
                "the first subdomain solutions or jumps are not finite: the "
                "loads and moduli (Loads, Materials) give displacements "
                "beyond the range of double; state them in other units" :
                "diverged: the iterates are no longer finite at iteration " +
                  std::to_string(k) + " (reduce Solver/Uzawa step theta" +
                  safe_step() + ")";
            return finish();
          }
        if (last_increment > parameters.divergence_factor * min_increment &&
            last_increment > 1e-12 * interface.weighted_norm(mu_new))
          {
            result.diverged = true;
            std::ostringstream msg;
            msg << "diverged at iteration " << k
                << ": the multiplier increment grew by more than "
                << parameters.divergence_factor
                << " (Solver/Divergence growth factor); theta = " << theta
                << " is above the stability threshold, reduce "
                   "Solver/Uzawa step theta"
                << safe_step();
            result.message = msg.str();
            return finish();
          }
        min_increment = std::min(min_increment, last_increment);

        w_old.swap(w);
        if (accelerated)
          {
            // FISTA momentum; restart when the step goes against the
            // gradient at the extrapolated point (O'Donoghue and Candes'
            // gradient restart): <g(y_k), x_{k+1} - x_k>_D < 0.
            if (-interface.weighted_dot(g, mu_old) < 0)
              t = 1;
            const double t_new = 0.5 * (1. + std::sqrt(1. + 4. * t * t));
            // y_{k+1} = x_{k+1} + (t - 1) / t_new (x_{k+1} - x_k)
            mu = mu_new;
            mu.add(-(t - 1.) / t_new, mu_old);
            t         = t_new;
            projected = mu_new;
          }
        else
          mu.swap(mu_new);
      }
  }
} // namespace bilayer
