#include <deal.II/base/timer.h>

#include <bilayer/interface/interface_diagnostics.h>
#include <bilayer/solvers/first_order_iteration.h>

#include <algorithm>
#include <cmath>
#include <iomanip>
#include <limits>
#include <sstream>

namespace bilayer
{
  using namespace dealii;

  double
  auto_step(const SolverParameters &parameters,
            const StepBound        &bound,
            const double            lambda_max)
  {
    return parameters.auto_theta_fraction * 2. / lambda_max * bound.factor;
  }


  unsigned long
  choose_auto_step(const SolverParameters   &parameters,
                   const StepBound          &bound,
                   const Subproblems        &subproblems,
                   const Interface          &interface,
                   const ConditionalOStream &pcout,
                   SolverResult             &result)
  {
    const SpectrumEstimate estimate =
      estimate_lambda_max(subproblems,
                          interface,
                          parameters.spectrum_iterations);
    result.lambda_max          = estimate.lambda_max;
    result.predicted_threshold = 2. / estimate.lambda_max;
    result.theta = auto_step(parameters, bound, estimate.lambda_max);
    pcout << "    theta = auto: lambda_max(S) = " << std::setprecision(6)
          << estimate.lambda_max << " after " << estimate.iterations
          << " power iterations, predicted threshold 2/lambda_max = "
          << result.predicted_threshold << ", theta = " << result.theta
          << std::defaultfloat << std::endl;
    return estimate.subdomain_solves;
  }


  void
  projected_step(const Interface           &interface,
                 const double               theta,
                 const BlockVector<double> &mu,
                 const BlockVector<double> &g,
                 BlockVector<double>       &next)
  {
    next = mu;
    next.add(theta, g);
    interface.space().project(next);
  }


  double
  relative_violation(const Interface           &interface,
                     const Solutions           &w,
                     const BlockVector<double> &g,
                     const BlockVector<double> &mu)
  {
    const double scale     = displacement_scale(interface, w);
    const double violation = interface.space().discrete_violation(g, mu);
    return scale > 0 ? violation / scale : violation;
  }


  double
  stopping_value(const SolverParameters    &parameters,
                 const Subproblems         &subproblems,
                 const Interface           &interface,
                 const Solutions           &w,
                 const Solutions           &w_old,
                 const BlockVector<double> &g,
                 const BlockVector<double> &mu,
                 const double               last_increment)
  {
    if (parameters.stopping_rule == StoppingRule::kkt)
      return kkt_residual(interface, w, g, mu).value();
    if (parameters.stopping_rule == StoppingRule::relative)
      {
        const double norm   = interface.space().weighted_norm(mu);
        const double change = norm > 0 ? last_increment / norm : last_increment;
        return std::max(change, relative_violation(interface, w, g, mu));
      }
    // Energy norms of whole solutions: each owner evaluates its own.
    Vector<double>              difference;
    const PerSubproblem<double> ratios =
      share_values(subproblems, [&](const unsigned int s) {
        difference = w[s];
        difference -= w_old[s];
        const double d =
          std::sqrt(subproblems[s]->energy_norm_squared(difference));
        const double n2 = subproblems[s]->energy_norm_squared(w[s]);
        const double denominator =
          parameters.stopping_rule == StoppingRule::paper ? n2 : std::sqrt(n2);
        return d == 0. ? 0. : d / denominator;
      });
    double value = 0;
    for (const double ratio : ratios)
      value = std::max(value, ratio);
    return value;
  }


  void
  print_progress(const OutputParameters    &output,
                 const ConditionalOStream  &pcout,
                 const unsigned int         k,
                 const double               value,
                 const double               last_increment,
                 const Interface           &interface,
                 const Solutions           &w,
                 const BlockVector<double> &g,
                 const BlockVector<double> &mu,
                 IterationClock            &clock,
                 const double               tolerance)
  {
    if (output.progress_interval > 0 && k > 0 &&
        k % output.progress_interval == 0)
      pcout << "    iteration " << std::setw(6) << k << "  stopping value "
            << std::scientific << std::setprecision(3) << value
            << "  multiplier change " << last_increment
            << "  relative violation "
            << relative_violation(interface, w, g, mu) << std::defaultfloat
            << "  (" << clock.report(k, value, tolerance) << ")" << std::endl;
  }


  std::string
  iteration_limit_message(const SolverParameters &parameters,
                          const double            value,
                          const std::string      &advice)
  {
    std::ostringstream msg;
    msg << "iteration limit " << parameters.max_iterations
        << " reached (Solver/Maximum iterations) with stopping value " << value
        << " > Solver/Tolerance " << parameters.tolerance
        << (parameters.stopping_rule == StoppingRule::paper ?
              "; the paper's rule |w^k - w^k-1| / |w^k|^2 is not "
              "scale invariant (it grows as the loads shrink): "
              "Solver/Stopping rule = relative or kkt" :
              advice);
    return msg.str();
  }


  GrowthWindow::GrowthWindow(const double factor, const unsigned int window)
    : factor(factor)
    , window(std::max(window, 2u))
    , min_value(std::numeric_limits<double>::max())
    , count(0)
  {}


  bool
  GrowthWindow::add(const double value)
  {
    const bool above_min = value > factor * min_value;
    min_value            = std::min(min_value, value);
    recent.push_back(value);
    ++count;
    // The window grows with the run (a tenth of the values so far): the
    // oscillations of a converging iteration lengthen as it slows down.
    const std::size_t full = std::max<std::size_t>(window, count / 10);
    while (recent.size() > 2 * full)
      recent.pop_front();
    // The first values: windows of half of them, at least 2 values each.
    const std::size_t width = std::min(full, recent.size() / 2);
    if (!above_min || width < 2)
      return false;
    const auto   middle      = recent.end() - width;
    const double earlier_max = *std::max_element(middle - width, middle);
    const double later_min   = *std::min_element(middle, recent.end());
    return later_min > earlier_max;
  }


  DivergenceTest::DivergenceTest(const SolverParameters &parameters,
                                 const StepBound        &bound,
                                 const Subproblems      &subproblems,
                                 const Interface        &interface,
                                 const double            theta,
                                 const double            lambda_max,
                                 const unsigned int      window)
    : parameters(parameters)
    , bound(bound)
    , subproblems(subproblems)
    , interface(interface)
    , theta(theta)
    , lambda_max(lambda_max)
    , growth(parameters.divergence_factor, window)
  {}


  std::string
  DivergenceTest::check(const unsigned int         k,
                        const double               value,
                        const double               increment,
                        const BlockVector<double> &next)
  {
    const std::string finite = check_finite(k, value, increment);
    if (!finite.empty())
      return finite;
    if (k >= 1 && increment < smallest_increment)
      {
        smallest_increment = increment;
        value_at_smallest  = value;
      }
    // Increments at round-off level of the multipliers do not count, nor
    // do increments that grew while a scale-invariant stopping value (kkt,
    // relative) fell to half; the paper's ratios of solution norms fall
    // under divergence too.
    const bool scale_invariant =
      parameters.stopping_rule == StoppingRule::kkt ||
      parameters.stopping_rule == StoppingRule::relative;
    if (growth.add(increment) &&
        increment > 1e-12 * interface.space().weighted_norm(next) &&
        !(scale_invariant && value <= 0.5 * value_at_smallest))
      {
        std::ostringstream msg;
        msg << "diverged at iteration " << k
            << ": the multiplier increment grew by more than "
            << parameters.divergence_factor
            << " (Solver/Divergence growth factor) and over each of the last "
               "windows; theta = "
            << theta;
        const std::string advice = safe_step_advice();
        if (advice.empty() || advice[0] == ';')
          msg << " is above the stability threshold, reduce "
                 "Solver/Uzawa step theta"
              << advice;
        else
          msg << advice;
        return msg.str();
      }
    return std::string();
  }


  std::string
  DivergenceTest::check_finite(const unsigned int k,
                               const double       value,
                               const double       increment) const
  {
    if (!std::isfinite(increment) || (k >= 1 && !std::isfinite(value)))
      {
        if (k == 0)
          return "the first subdomain solutions or jumps are not finite: the "
                 "loads and moduli (Loads, Materials) give displacements "
                 "beyond the range of double; state them in other units";
        const std::string  advice = safe_step_advice();
        std::ostringstream msg;
        msg << "diverged: the iterates are no longer finite at iteration " << k;
        if (advice.empty() || advice[0] == ';')
          msg << " (reduce Solver/Uzawa step theta" << advice << ")";
        else
          msg << "; theta = " << theta << advice;
        return msg.str();
      }
    return std::string();
  }


  std::string
  DivergenceTest::safe_step_advice() const
  {
    double estimate = lambda_max;
    if (!(estimate > 0))
      estimate = estimate_lambda_max(subproblems,
                                     interface,
                                     parameters.spectrum_iterations)
                   .lambda_max;
    const double step = auto_step(parameters, bound, estimate);
    if (!std::isfinite(step) || !(estimate > 0))
      return std::string();
    std::ostringstream text;
    text << std::setprecision(4);
    // A step the run already uses is no advice: the estimate of lambda_max
    // is then too small for this scene (or the growth is not the step's).
    if (theta <= step * (1. + 1e-3))
      text << " is within the estimated safe step theta <= " << step << " ("
           << parameters.auto_theta_fraction << bound.in_words
           << "); the estimate of lambda_max is too small for this scene: "
              "take a smaller Solver/Uzawa step theta, raise "
              "Solver/Divergence growth factor, or Solver/Method = active set";
    else
      text << "; estimated safe step: theta <= " << step << " ("
           << parameters.auto_theta_fraction << bound.in_words
           << ", or theta = auto)";
    return text.str();
  }


  SolverResult
  FirstOrderSolver::solve(const Subproblems   &subproblems,
                          const Interface     &interface,
                          BlockVector<double> &mu,
                          Solutions           &w) const
  {
    SolverResult result;
    result.solver = name;
    result.theta  = parameters.theta;
    Timer timer;
    if (parameters.auto_theta)
      result.subdomain_solves = choose_auto_step(
        parameters, step_bound, subproblems, interface, pcout, result);
    result.setup_seconds = timer.wall_time();
    timer.restart();
    clock = IterationClock();
    iterate(subproblems, interface, mu, w, result);
    // The iterations solved on Sigma: the whole solutions of the last
    // multipliers.
    if (parameters.iterates_on_sigma())
      {
        solve_subproblems(subproblems, interface, mu, w);
        result.subdomain_solves += subproblems.size();
      }
    result.iteration_seconds = timer.wall_time();
    return result;
  }


  double
  FirstOrderSolver::evaluate(const Subproblems         &subproblems,
                             const Interface           &interface,
                             const unsigned int         k,
                             const unsigned long        extra_solves,
                             const BlockVector<double> &mu,
                             Solutions                 &w,
                             const Solutions           &w_old,
                             BlockVector<double>       &g,
                             const double               last_increment,
                             SolverResult              &result) const
  {
    solve_subproblems(subproblems,
                      interface,
                      mu,
                      w,
                      parameters.iterates_on_sigma() ? SolveExtent::sigma :
                                                       SolveExtent::whole);
    result.iterations       = k;
    result.subdomain_solves = extra_solves + subproblems.size() * (k + 1ul);
    interface.jumps(w, g);
    const double value =
      k >= 1 ?
        stopping_value(
          parameters, subproblems, interface, w, w_old, g, mu, last_increment) :
        std::numeric_limits<double>::infinity();
    result.stopping_value = value;
    print_progress(output,
                   pcout,
                   k,
                   value,
                   last_increment,
                   interface,
                   w,
                   g,
                   mu,
                   clock,
                   parameters.tolerance);
    return value;
  }
} // namespace bilayer
