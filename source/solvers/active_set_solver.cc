#include <deal.II/base/timer.h>

#include <bilayer/core/progress.h>
#include <bilayer/interface/interface_diagnostics.h>
#include <bilayer/solvers/accelerated_solver.h>
#include <bilayer/solvers/active_set_iteration.h>
#include <bilayer/solvers/active_set_solver.h>
#include <bilayer/solvers/feti_preconditioner.h>

#include <cmath>
#include <iomanip>
#include <limits>
#include <sstream>

namespace bilayer
{
  using namespace dealii;

  namespace active_set
  {
    double
    largest_jump(const Interface &interface, const BlockVector<double> &x)
    {
      BlockVector<double> jump(x);
      interface.space().scale_by_weights(jump, true);
      return jump.linfty_norm();
    }


    // Why not deal.II's SolverCG: its arithmetic is the same, in the same
    // order (z = M^{-1} r, rz = r.z, p = z + (rz / rz_old) p, q = F p,
    // alpha = rz / p.q, delta += alpha p, r -= alpha q), but its stopping
    // test cannot be this one. SolverControl::check() receives only the
    // Euclidean norm |r|_2 that SolverCG computes, and the iteration_status
    // signal only the iterate delta; the largest jump is a weighted maximum
    // norm of r, no function of |r|_2, and r from delta would cost 4 more
    // solves per iteration. The only place where SolverCG hands out r is the
    // preconditioner, at the start of the next iteration: the test would
    // have to run there and end the solve by an exception, as would
    // p^T F p <= 0, which SolverCG only asserts to be nonzero (in debug
    // mode), and the unconditional first application of the preconditioner
    // would need a special case. (Built that way, SolverCG with a
    // SolverControl that never stops gives the same bits as this function
    // on every scene of scripts/compare_outputs: the arithmetic is not the
    // obstacle, the control flow is.)
    ConjugateGradientOutcome
    conjugate_gradients_on_free_set(const Subproblems         &subproblems,
                                    const Interface           &interface,
                                    const FetiPreconditioner  &preconditioner,
                                    const BlockVector<double> &mask,
                                    const BlockVector<double> &at,
                                    const double               start,
                                    const double               target,
                                    const unsigned int         max_iterations,
                                    BlockVector<double>       &r,
                                    BlockVector<double>       &delta)
    {
      ConjugateGradientOutcome outcome;
      BlockVector<double>      z, p, q;
      Solutions                homogeneous;
      delta.reinit(r);
      outcome.preconditioner_solves += preconditioner.vmult(z, r);
      p         = z;
      double rz = r * z;
      for (double jump = start; jump > target;)
        {
          if (outcome.iterations >= max_iterations)
            {
              outcome.limit_reached = true;
              outcome.jump          = jump;
              return outcome;
            }
          solve_homogeneous_subproblems(subproblems, interface, p, homogeneous);
          outcome.subdomain_solves += subproblems.size();
          interface.jumps(homogeneous, q);
          interface.space().scale_by_weights(q);
          q *= -1.; // F p
          interface.space().add_cohesive_operator(at, p, q);
          q.scale(mask);
          const double pq = p * q;
          if (!(pq > 0))
            break; // F_II is exhausted (semidefinite directions)
          const double alpha = rz / pq;
          delta.add(alpha, p);
          r.add(-alpha, q);
          ++outcome.iterations;
          jump = largest_jump(interface, r);
          if (jump <= target)
            break;
          outcome.preconditioner_solves += preconditioner.vmult(z, r);
          const double rz_new = r * z;
          p.sadd(rz_new / rz, 1., z);
          rz = rz_new;
        }
      return outcome;
    }


    NewtonIteration::NewtonIteration(const Subproblems        &subproblems,
                                     const Interface          &interface,
                                     const SolverParameters   &parameters,
                                     const OutputParameters   &output,
                                     const ConditionalOStream &pcout,
                                     const IterationClock     &clock,
                                     FetiPreconditioner       &preconditioner,
                                     BlockVector<double>      &mu,
                                     Solutions                &w,
                                     SolverResult             &result)
      : subproblems(subproblems)
      , interface(interface)
      , parameters(parameters)
      , output(output)
      , pcout(pcout)
      , clock(clock)
      , preconditioner(preconditioner)
      , mu(mu)
      , w(w)
      , result(result)
      , set(interface.space().set())
    {
      set.initialize(mask);
      previous_mask = mask;
      older_mask    = mask;
    }


    std::string
    NewtonIteration::run()
    {
      interface.space().project(mu);
      for (unsigned int k = 0;; ++k)
        {
          const KKTResidual     kkt    = evaluate_iterate(k);
          const bool            reject = rejects_step(k, kkt);
          const ActiveSetChange change = classify_active_set(k, reject);
          print_newton_step(k, kkt, change);
          std::string message = stopping_message(k, kkt, change, reject);
          if (!message.empty())
            return message;
          if (reject)
            {
              if (repeats_rejection(k) && stalled())
                {
                  // Back to the start of the rejected step, mu_{k-1}.
                  mu = previous_mu;
                  std::ostringstream msg;
                  msg << "the Newton step from the active set of step " << k - 1
                      << " was rejected " << max_repeated_rejections + 1
                      << " times in a row (steps "
                      << k - 2 * max_repeated_rejections << " to " << k
                      << ") with KKT residual " << std::setprecision(3)
                      << accepted_residual << " > Solver/Tolerance "
                      << parameters.tolerance << " at its start";
                  return msg.str();
                }
              replace_rejected_step(k);
              continue;
            }
          after_fallback = false;
          message        = solve_newton_system(k, change);
          if (!message.empty())
            return message;
          accepted_residual = kkt.value();
          take_newton_step(change);
        }
    }


    KKTResidual
    NewtonIteration::evaluate_iterate(const unsigned int k)
    {
      solve_subproblems(subproblems,
                        interface,
                        mu,
                        w,
                        parameters.iterates_on_sigma() ? SolveExtent::sigma :
                                                         SolveExtent::whole);
      result.subdomain_solves += subproblems.size();
      result.iterations = k;
      interface.jumps(w, g);
      interface.space().add_cohesive_jumps(mu, g);
      const KKTResidual kkt = kkt_residual(interface, w, g, mu);
      result.stopping_value = kkt.value();
      gradient              = g;
      interface.space().scale_by_weights(gradient);
      return kkt;
    }


    ActiveSetChange
    NewtonIteration::classify_active_set(const unsigned int k,
                                         const bool         reject)
    {
      // The active set at mu: components held at a bound (at a rejected
      // iterate the sets stay those of mu_k, to which it returns).
      if (!reject)
        {
          older_mask = previous_mask;
          previous_mask.swap(mask);
        }
      ActiveSetChange change;
      for (unsigned int i = 0; i < mu.size(); ++i)
        {
          const bool held = set.held(i, mu(i), g(i));
          if (held && set.free(i))
            ++change.n_active;
          const double free = held ? 0. : 1.;
          change.n_changed += (free != (reject ? mask(i) : previous_mask(i)));
          if (!reject)
            mask(i) = free;
        }
      change.settled =
        !reject && !after_fallback && k > 0 && change.n_changed == 0;
      // Cycling: the active set of two steps ago again (the inexact
      // steps of a changing set can alternate between two sets): the
      // next steps are solved as if the set had settled, and from the
      // third such return on they are halved (damped).
      change.cycling = !reject && k > 1 && change.n_changed > 0;
      for (unsigned int i = 0; change.cycling && i < mask.size(); ++i)
        change.cycling = mask(i) == older_mask(i);
      n_cycling += change.cycling;
      return change;
    }


    void
    NewtonIteration::print_newton_step(const unsigned int     k,
                                       const KKTResidual     &kkt,
                                       const ActiveSetChange &change) const
    {
      if (output.progress_interval > 0)
        pcout << "    Newton step " << std::setw(3) << k << "  KKT residual "
              << std::scientific << std::setprecision(3) << kkt.value()
              << " (violation " << kkt.primal << ", mu_c < 0 " << kkt.dual
              << ", complementarity " << kkt.complementarity << ")"
              << std::defaultfloat << "  active " << change.n_active
              << ", changed " << change.n_changed << ", CG iterations "
              << inner_iterations << ", elapsed "
              << format_duration(clock.elapsed()) << std::endl;
    }


    std::string
    NewtonIteration::stopping_message(const unsigned int     k,
                                      const KKTResidual     &kkt,
                                      const ActiveSetChange &change,
                                      const bool             reject)
    {
      if (!std::isfinite(kkt.value()))
        {
          result.diverged = true;
          return k == 0 ?
                   "the first subdomain solutions are not finite: the loads "
                   "and moduli (Loads, Materials) give displacements beyond "
                   "the range of double; state them in other units" :
                   "diverged: the multipliers of Newton step " +
                     std::to_string(k) + " are no longer finite";
        }
      if (kkt.value() <= parameters.tolerance)
        {
          result.converged = true;
          std::ostringstream msg;
          msg << "KKT residual " << std::setprecision(3) << kkt.value()
              << " <= " << parameters.tolerance << " after " << k
              << " Newton steps and " << result.linear_iterations
              << " conjugate-gradient iterations";
          if (n_replaced > 0)
            msg << " (" << n_replaced
                << " of them in place of rejected Newton steps that did "
                   "not increase the dual function enough)";
          return msg.str();
        }
      // No replacement step increases Phi at mu_k (to which the loop has
      // returned): mu_k is optimal to the round-off of Phi.
      if (no_ascent)
        {
          std::ostringstream msg;
          msg << "no step from Newton step " << k
              << " increases the dual function (the Newton step was "
                 "rejected, the projected-gradient step and the others "
                 "gain nothing) with KKT residual "
              << std::setprecision(3) << kkt.value() << " > Solver/Tolerance "
              << parameters.tolerance
              << ": the tolerance is below the round-off of this "
                 "ill-conditioned problem; raise Solver/Tolerance";
          return msg.str();
        }
      // Round-off floor: with the active set settled every step is solved
      // exactly and should meet the tolerance. Five settled steps in a row
      // that do not halve the smallest residual seen mean the tolerance lies
      // below what the arithmetic resolves on this problem.
      if (change.settled && kkt.value() < 0.5 * best_settled)
        best_settled = kkt.value(), n_stalled = 0;
      else if (change.settled && ++n_stalled >= 5)
        {
          std::ostringstream msg;
          msg << "the KKT residual stagnates at " << std::setprecision(3)
              << best_settled << " > Solver/Tolerance " << parameters.tolerance
              << " with the active set settled (5 "
              << "exact Newton steps did not halve it, " << k
              << " steps in all): the tolerance is below the round-off "
                 "of this ill-conditioned problem (material contrast, "
                 "stretched cells); raise Solver/Tolerance";
          return msg.str();
        }
      else if (!change.settled && !reject)
        best_settled = std::numeric_limits<double>::infinity(), n_stalled = 0;
      if (k >= parameters.max_newton_iterations)
        {
          std::ostringstream msg;
          msg << "Newton step limit " << parameters.max_newton_iterations
              << " reached (Solver/Active set/Maximum Newton iterations) "
                 "with KKT residual "
              << kkt.value() << " > Solver/Tolerance " << parameters.tolerance;
          return msg.str();
        }
      return "";
    }


    std::string
    NewtonIteration::solve_newton_system(const unsigned int     k,
                                         const ActiveSetChange &change)
    {
      // Newton step: F_II delta_I = (D g)_I by preconditioned conjugate
      // gradients from delta = 0, to a relative reduction of the largest
      // jump while the active set changes, else to the tolerance.
      if (k == 0 || change.n_changed > 0 || stale_preconditioner)
        preconditioner.reinit(mask), stale_preconditioner = false;
      r = gradient;
      r.scale(mask);
      const double scale = displacement_scale(interface, w);
      const double start = largest_jump(interface, r);
      const double target =
        std::max(change.settled || n_cycling > 0 || exact_steps ?
                   0. :
                   parameters.inner_tolerance * start,
                 0.1 * parameters.tolerance * scale);
      const ConjugateGradientOutcome cg =
        conjugate_gradients_on_free_set(subproblems,
                                        interface,
                                        preconditioner,
                                        mask,
                                        mu,
                                        start,
                                        target,
                                        parameters.max_inner_iterations,
                                        r,
                                        delta);
      result.subdomain_solves += cg.subdomain_solves;
      result.preconditioner_solves += cg.preconditioner_solves;
      inner_iterations = cg.iterations;
      if (cg.limit_reached)
        {
          std::ostringstream msg;
          msg << "conjugate gradients of Newton step " << k
              << " reached Solver/Active set/Maximum inner iterations = "
              << parameters.max_inner_iterations << " with largest jump "
              << cg.jump << " > " << target;
          return msg.str();
        }
      result.linear_iterations += inner_iterations;
      return "";
    }


    void
    NewtonIteration::take_newton_step(const ActiveSetChange &change)
    {
      previous_mu         = mu;
      previous_gradient   = gradient;
      const double length = change.cycling && n_cycling > 2 ? 0.5 : 1.;
      // r0 . delta with r0 = (D g)_I = the masked gradient.
      BlockVector<double> masked_gradient(gradient);
      masked_gradient.scale(mask);
      predicted_increase =
        length * (1. - 0.5 * length) * (masked_gradient * delta);
      // The step direction and its curvature d^T F d (F delta = r0 - r).
      newton_direction = delta;
      newton_direction *= length;
      masked_gradient -= r;
      newton_curvature = length * length * (delta * masked_gradient);
      mu.add(length, delta);
      interface.space().project(mu);
    }
  } // namespace active_set


  ActiveSetSolver::ActiveSetSolver(const SolverParameters   &parameters,
                                   const OutputParameters   &output,
                                   const ConditionalOStream &pcout)
    : OuterSolver(parameters, output, pcout)
  {}


  SolverResult
  ActiveSetSolver::solve(const Subproblems   &subproblems,
                         const Interface     &interface,
                         BlockVector<double> &mu,
                         Solutions           &w) const
  {
    SolverResult result;
    result.solver = "active set";
    Timer                timer;
    const IterationClock clock;
    FetiPreconditioner   preconditioner(parameters.preconditioner,
                                      subproblems,
                                      interface);
    result.setup_seconds = timer.wall_time();
    timer.restart();
    const auto finish = [&](const std::string &message,
                            const bool         whole_solutions) {
      // The iterations solved on Sigma: the whole solutions of the last
      // multipliers.
      if (parameters.iterates_on_sigma() && !whole_solutions)
        {
          solve_subproblems(subproblems, interface, mu, w);
          result.subdomain_solves += subproblems.size();
        }
      result.message = message;
      if (preconditioner.n_degraded_steps() > 0)
        result.message +=
          "; the preconditioner's Gram matrix of the free multipliers was "
          "singular (redundant multiplier constraints) in " +
          std::to_string(preconditioner.n_degraded_steps()) +
          " Newton steps, which used the diagonal scaling instead";
      result.iteration_seconds = timer.wall_time();
      return result;
    };
    active_set::NewtonIteration iteration(subproblems,
                                          interface,
                                          parameters,
                                          output,
                                          pcout,
                                          clock,
                                          preconditioner,
                                          mu,
                                          w,
                                          result);

    const std::string message = iteration.run();
    // (Cohesive springs: the accelerated method's step sizes do not know
    // them; the failure is reported instead.)
    if (!iteration.stalled() || interface.space().set().has_cohesive())
      return finish(message, false);
    // The same Newton step rejected again and again (a degenerate contact
    // zone, issue 45): the accelerated method from the multipliers where it
    // starts, with theta = auto and the KKT rule of this method; it
    // converges on the dual problem whatever its active sets. Its final
    // solve gives the whole solutions.
    SolverParameters accelerated = parameters;
    accelerated.method           = SolverMethod::accelerated;
    accelerated.auto_theta       = true;
    accelerated.stopping_rule    = StoppingRule::kkt;
    pcout << "    " << message
          << ": continuing with the accelerated method (theta = auto, "
             "stopping rule kkt) from there"
          << std::endl;
    const SolverResult first_order =
      AcceleratedSolver(accelerated, output, pcout)
        .solve(subproblems, interface, mu, w);
    result.converged      = first_order.converged;
    result.diverged       = first_order.diverged;
    result.stopping_value = first_order.stopping_value;
    result.subdomain_solves += first_order.subdomain_solves;
    result.theta               = first_order.theta;
    result.lambda_max          = first_order.lambda_max;
    result.predicted_threshold = first_order.predicted_threshold;
    result.setup_seconds += first_order.setup_seconds;
    return finish(message + "; then the accelerated method (theta = " +
                    "auto, stopping rule kkt) from there: " +
                    first_order.message,
                  true);
  }
} // namespace bilayer
