#include <deal.II/base/timer.h>

#include <bilayer/active_set_solver.h>
#include <bilayer/feti_preconditioner.h>
#include <bilayer/progress.h>

#include <cmath>
#include <iomanip>
#include <limits>
#include <sstream>

namespace bilayer
{
  using namespace dealii;

  namespace
  {
    /// Largest |x_i| / D_i (the largest jump of a Euclidean residual).
    double
    largest_jump(const Interface &interface, const BlockVector<double> &x)
    {
      BlockVector<double> jump(x);
      interface.space().scale_by_weights(jump, true);
      return jump.linfty_norm();
    }


    /// How the conjugate gradients of a Newton step ended.
    struct ConjugateGradientOutcome
    {
      unsigned int  iterations            = 0;
      unsigned long subdomain_solves      = 0;
      unsigned long preconditioner_solves = 0;
      /// Stopped at the iteration limit with the largest jump @p jump still
      /// above the target.
      bool   limit_reached = false;
      double jump          = 0;
    };


    /**
     * Preconditioned conjugate gradients on F_II delta = r from delta = 0:
     * F p is minus the weighted jumps D g of the homogeneous solutions with
     * the multiplier loads of p (4 subdomain solves), restricted by @p mask
     * to the free components I. On entry @p r is the right-hand side (zero
     * off I) with largest jump @p start, on return the residual.
     *
     * The iteration stops when the largest jump of the residual,
     * max_i |r_i| / D_i, is at most @p target; when p^T F p is no longer
     * positive (F_II exhausted: its semidefinite directions), keeping the
     * iterate; or, as a failure, after @p max_iterations iterations. The
     * preconditioner is applied to the first residual and to every residual
     * that misses the target, the last one before the limit included.
     *
     * Why not deal.II's SolverCG: its arithmetic is the same, in the same
     * order (z = M^{-1} r, rz = r.z, p = z + (rz / rz_old) p, q = F p,
     * alpha = rz / p.q, delta += alpha p, r -= alpha q), but its stopping
     * test cannot be this one. SolverControl::check() receives only the
     * Euclidean norm |r|_2 that SolverCG computes, and the iteration_status
     * signal only the iterate delta; the largest jump is a weighted maximum
     * norm of r, no function of |r|_2, and r from delta would cost 4 more
     * solves per iteration. The only place where SolverCG hands out r is the
     * preconditioner, at the start of the next iteration: the test would
     * have to run there and end the solve by an exception, as would
     * p^T F p <= 0, which SolverCG only asserts to be nonzero (in debug
     * mode), and the unconditional first application of the preconditioner
     * would need a special case. (Built that way, SolverCG with a
     * SolverControl that never stops gives the same bits as this function
     * on every scene of scripts/compare_outputs: the arithmetic is not the
     * obstacle, the control flow is.)
     */
    ConjugateGradientOutcome
    conjugate_gradients_on_free_set(const Subproblems         &subproblems,
                                    const Interface           &interface,
                                    const FetiPreconditioner  &preconditioner,
                                    const BlockVector<double> &mask,
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
          outcome.subdomain_solves += Layout::n_subproblems;
          interface.jumps(homogeneous, q);
          interface.space().scale_by_weights(q);
          q *= -1.; // F p
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
  } // namespace


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
    const BlockVector<double> &lower  = interface.space().lower_bounds();
    const BlockVector<double> &upper  = interface.space().upper_bounds();
    const auto                 finish = [&](const std::string &message) {
      // The iterations solved on Sigma: the whole solutions of the last
      // multipliers.
      if (parameters.iterates_on_sigma())
        {
          solve_subproblems(subproblems, interface, mu, w);
          result.subdomain_solves += Layout::n_subproblems;
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
    BlockVector<double> g, mask(lower), previous_mask(lower), older_mask(lower),
      r, delta, gradient, previous_gradient, previous_mu;
    unsigned int inner_iterations = 0, n_cycling = 0, n_stalled = 0;
    bool         exact_steps  = false;
    double       best_settled = std::numeric_limits<double>::infinity();
    interface.space().project(mu);

    for (unsigned int k = 0;; ++k)
      {
        solve_subproblems(subproblems,
                          interface,
                          mu,
                          w,
                          parameters.iterates_on_sigma() ? SolveExtent::sigma :
                                                           SolveExtent::whole);
        result.subdomain_solves += Layout::n_subproblems;
        result.iterations = k;
        interface.jumps(w, g);
        const KKTResidual kkt = kkt_residual(interface, w, g, mu);
        result.stopping_value = kkt.value();

        // A Newton step must not decrease the dual function
        // Phi(mu) = min_w L(w, mu), a concave quadratic with gradient D g:
        // Phi(mu + s) - Phi(mu) = s . (D g(mu) + D g(mu + s)) / 2 exactly.
        // Inexact steps (conjugate gradients to Inner tolerance) on an
        // ill-conditioned F_II can decrease it and then cycle through a
        // chain of active sets (seen with Young's moduli 5e5 apart): after
        // the first decrease every following step is solved exactly.
        gradient = g;
        interface.space().scale_by_weights(gradient);
        if (k > 0 && !exact_steps && kkt.value() > parameters.tolerance)
          {
            BlockVector<double> step(mu);
            step -= previous_mu;
            const double before = step * previous_gradient,
                         after  = step * gradient;
            const double change = 0.5 * (before + after);
            if (change < -1e-12 * (std::abs(before) + std::abs(after)))
              {
                exact_steps = true;
                if (output.progress_interval > 0)
                  pcout << "    the inexact Newton step decreased the dual "
                           "function by "
                        << std::scientific << std::setprecision(3) << -change
                        << std::defaultfloat
                        << ": the following steps are solved exactly"
                        << std::endl;
              }
          }

        // The active set at mu: components held at a bound.
        older_mask = previous_mask;
        previous_mask.swap(mask);
        unsigned int n_active = 0, n_changed = 0;
        for (unsigned int i = 0; i < mu.size(); ++i)
          {
            const bool held = !(lower(i) < upper(i)) ||
                              (mu(i) <= lower(i) && g(i) <= 0) ||
                              (mu(i) >= upper(i) && g(i) >= 0);
            mask(i) = held ? 0. : 1.;
            if (held && lower(i) < upper(i))
              ++n_active;
            n_changed += (mask(i) != previous_mask(i));
          }
        const bool settled = k > 0 && n_changed == 0;
        // Cycling: the active set of two steps ago again (the inexact
        // steps of a changing set can alternate between two sets): the
        // next steps are solved as if the set had settled, and from the
        // third such return on they are halved (damped).
        bool cycling = k > 1 && n_changed > 0;
        for (unsigned int i = 0; cycling && i < mask.size(); ++i)
          cycling = mask(i) == older_mask(i);
        n_cycling += cycling;

        if (output.progress_interval > 0)
          pcout << "    Newton step " << std::setw(3) << k << "  KKT residual "
                << std::scientific << std::setprecision(3) << kkt.value()
                << " (violation " << kkt.primal << ", mu_c < 0 " << kkt.dual
                << ", complementarity " << kkt.complementarity << ")"
                << std::defaultfloat << "  active " << n_active << ", changed "
                << n_changed << ", CG iterations " << inner_iterations
                << ", elapsed " << format_duration(clock.elapsed())
                << std::endl;

        if (!std::isfinite(kkt.value()))
          {
            result.diverged = true;
            return finish(
              k == 0 ?
                "the first subdomain solutions are not finite: the loads and "
                "moduli (Loads, Materials) give displacements beyond the range "
                "of double; state them in other units" :
                "diverged: the multipliers of Newton step " +
                  std::to_string(k) + " are no longer finite");
          }
        if (kkt.value() <= parameters.tolerance)
          {
            result.converged = true;
            std::ostringstream msg;
            msg << "KKT residual " << std::setprecision(3) << kkt.value()
                << " <= " << parameters.tolerance << " after " << k
                << " Newton steps and " << result.linear_iterations
                << " conjugate-gradient iterations";
            return finish(msg.str());
          }
        // Round-off floor: with the active set settled every step is solved
        // exactly and should meet the tolerance. Five settled steps in a row
        // that do not halve the smallest residual seen mean the tolerance lies
        // below what the arithmetic resolves on this problem.
        if (settled && kkt.value() < 0.5 * best_settled)
          best_settled = kkt.value(), n_stalled = 0;
        else if (settled && ++n_stalled >= 5)
          {
            std::ostringstream msg;
            msg << "the KKT residual stagnates at " << std::setprecision(3)
                << best_settled << " > Solver/Tolerance "
                << parameters.tolerance << " with the active set settled (5 "
                << "exact Newton steps did not halve it, " << k
                << " steps in all): the tolerance is below the round-off "
                   "of this ill-conditioned problem (material contrast, "
                   "stretched cells); raise Solver/Tolerance";
            return finish(msg.str());
          }
        else if (!settled)
          best_settled = std::numeric_limits<double>::infinity(), n_stalled = 0;
        if (k >= parameters.max_newton_iterations)
          {
            std::ostringstream msg;
            msg << "Newton step limit " << parameters.max_newton_iterations
                << " reached (Solver/Active set/Maximum Newton iterations) "
                   "with KKT residual "
                << kkt.value() << " > Solver/Tolerance "
                << parameters.tolerance;
            return finish(msg.str());
          }

        // Newton step: F_II delta_I = (D g)_I by preconditioned conjugate
        // gradients from delta = 0, to a relative reduction of the largest
        // jump while the active set changes, else to the tolerance.
        if (k == 0 || n_changed > 0)
          preconditioner.reinit(mask);
        r = gradient;
        r.scale(mask);
        const double scale  = displacement_scale(interface, w);
        const double start  = largest_jump(interface, r);
        const double target = std::max(settled || n_cycling > 0 || exact_steps ?
                                         0. :
                                         parameters.inner_tolerance * start,
                                       0.1 * parameters.tolerance * scale);
        const ConjugateGradientOutcome cg =
          conjugate_gradients_on_free_set(subproblems,
                                          interface,
                                          preconditioner,
                                          mask,
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
            return finish(msg.str());
          }
        result.linear_iterations += inner_iterations;
        previous_mu       = mu;
        previous_gradient = gradient;
        mu.add(cycling && n_cycling > 2 ? 0.5 : 1., delta);
        interface.space().project(mu);
      }
  }
} // namespace bilayer
