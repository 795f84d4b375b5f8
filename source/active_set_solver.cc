#include <deal.II/base/timer.h>

#include <bilayer/active_set_solver.h>
#include <bilayer/feti_preconditioner.h>
#include <bilayer/interface_diagnostics.h>
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


    /// F x = minus the weighted jumps of the homogeneous solutions with the
    /// multiplier loads of x (4 subdomain solves).
    void
    apply_dual_operator(const Subproblems         &subproblems,
                        const Interface           &interface,
                        const BlockVector<double> &x,
                        BlockVector<double>       &result)
    {
      Solutions homogeneous;
      solve_homogeneous_subproblems(subproblems, interface, x, homogeneous);
      interface.jumps(homogeneous, result);
      interface.space().scale_by_weights(result);
      result *= -1.;
    }


    /**
     * The projected-gradient candidate of a rejected Newton step, with exact
     * line search on the dual function Phi (concave quadratic, gradient
     * @p gradient = D g at @p mu, Hessian -F): s = P(mu + t D g) - mu and
     * @p step = a s with the maximiser a = min(1, D g . s / s^T F s) of Phi
     * on the segment (which lies in the box). The length @p t is the
     * Rayleigh quotient |x|^2 / x^T F x of the rejected Newton step x (a
     * Barzilai-Borwein length), that of D g where it is not a positive
     * number. Phi grows by the returned @p increase = a D g . s - a^2 / 2
     * s^T F s, at least |s|^2 / (2 t) min(1, 1 / (t lambda_max(F))) (as
     * D g . s >= |s|^2 / t, a property of the projection). Returns the
     * subdomain solves.
     */
    unsigned long
    projected_gradient_candidate(const Subproblems         &subproblems,
                                 const Interface           &interface,
                                 const BlockVector<double> &gradient,
                                 double                     t,
                                 const BlockVector<double> &mu,
                                 BlockVector<double>       &step,
                                 double                    &increase)
    {
      unsigned long       solves = 0;
      BlockVector<double> Fs;
      step     = gradient;
      increase = 0;
      interface.space().restrict_to_free(step);
      if (!(t > 0) || !std::isfinite(t))
        {
          apply_dual_operator(subproblems, interface, step, Fs);
          solves += Layout::n_subproblems;
          t = (step * step) / (step * Fs);
          if (!(t > 0) || !std::isfinite(t))
            {
              step = 0; // D g = 0 on the free components
              return solves;
            }
        }
      step.sadd(t, 1., mu);
      interface.space().project(step);
      step -= mu;
      apply_dual_operator(subproblems, interface, step, Fs);
      solves += Layout::n_subproblems;
      const double slope = gradient * step, curvature = step * Fs;
      const double a = curvature > 0 ? std::min(1., slope / curvature) : 1.;
      if (!(a > 0))
        {
          step = 0;
          return solves;
        }
      increase = a * slope - 0.5 * a * a * curvature;
      step *= a;
      return solves;
    }


    /// The maximiser a in [0, a_max] of Phi(mu + a x) - Phi(mu) =
    /// a slope - a^2 / 2 curvature, and that increase.
    std::pair<double, double>
    best_on_segment(const double slope,
                    const double curvature,
                    const double a_max)
    {
      if (!(slope > 0) || !(a_max > 0))
        return {0., 0.};
      const double a =
        curvature > 0 ? std::min(a_max, slope / curvature) : a_max;
      return {a, a * slope - 0.5 * a * a * curvature};
    }
  } // namespace


  ActiveSetSolver::ActiveSetSolver(const SolverParameters   &parameters,
                                   const OutputParameters   &output,
                                   const ConditionalOStream &pcout)
    : OuterSolver(parameters, output, pcout)
  {}


  namespace
  {
    /// A Newton step must increase the dual function by this fraction of
    /// the increase its quadratic model predicts (Armijo's constant).
    constexpr double sufficient_increase = 1e-4;
  } // namespace


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
    const MultiplierSet &set    = interface.space().set();
    const auto           finish = [&](const std::string &message) {
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
    BlockVector<double> g, mask, r, delta, gradient, previous_gradient,
      previous_mu;
    set.initialize(mask);
    BlockVector<double> previous_mask(mask), older_mask(mask);
    unsigned int        inner_iterations = 0, n_cycling = 0, n_stalled = 0;
    bool                exact_steps  = false;
    double              best_settled = std::numeric_limits<double>::infinity();
    // The globalisation: the increase of Phi that the conjugate gradients
    // predict for the last Newton step (0 after a replacement step, which is
    // not tested), that step's direction and its curvature d^T F d, and the
    // number of rejected Newton steps.
    double              predicted_increase = 0, newton_curvature = 0;
    BlockVector<double> newton_direction;
    unsigned int        n_replaced     = 0;
    bool                after_fallback = false, stale_preconditioner = false,
         no_ascent = false;
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
        //
        // Sufficient increase (globalisation): a Newton step must increase
        // Phi by at least sufficient_increase times the increase predicted
        // by its conjugate gradients, a (1 - a / 2) (D g)_I . delta_I for a
        // step a delta (the Galerkin property of CG: delta^T F delta =
        // (D g)_I . delta_I). An inexact step that does not switches to
        // exact steps (above); an exact step that does not is rejected: the
        // iterate returns to mu_k and takes the best of several steps from
        // there (below), one of them the projected-gradient step with exact
        // line search, which increases Phi by at least a positive function
        // of |P(mu + t D g) - mu|. So every step but one increases Phi by
        // that much, and the measure tends to zero: docs/problem.md §4.3.
        gradient = g;
        interface.space().scale_by_weights(gradient);
        bool reject = false;
        if (k > 0 && predicted_increase > 0 && std::isfinite(kkt.value()) &&
            kkt.value() > parameters.tolerance)
          {
            BlockVector<double> step(mu);
            step -= previous_mu;
            const double before = step * previous_gradient,
                         after  = step * gradient;
            const double change = 0.5 * (before + after);
            const double round_off =
              1e-12 * (std::abs(before) + std::abs(after));
            const bool sufficient =
              change >= sufficient_increase * predicted_increase - round_off;
            if (!exact_steps && !sufficient)
              {
                exact_steps = true;
                if (output.progress_interval > 0)
                  pcout << "    the inexact Newton step "
                        << (change < 0 ? "decreased" : "increased")
                        << " the dual function by " << std::scientific
                        << std::setprecision(3) << std::abs(change)
                        << std::defaultfloat
                        << ": the following steps are solved exactly"
                        << std::endl;
              }
            else if (!sufficient)
              {
                reject = true;
                if (output.progress_interval > 0)
                  pcout << "    Newton step " << k
                        << " changed the dual function by " << std::scientific
                        << std::setprecision(3) << change << " < "
                        << sufficient_increase << " x " << predicted_increase
                        << " (its model): rejected, the best of the "
                           "replacement steps from step "
                        << k - 1 << " instead" << std::defaultfloat
                        << std::endl;
              }
          }

        // The active set at mu: components held at a bound (at a rejected
        // iterate the sets stay those of mu_k, to which it returns).
        if (!reject)
          {
            older_mask = previous_mask;
            previous_mask.swap(mask);
          }
        unsigned int n_active = 0, n_changed = 0;
        for (unsigned int i = 0; i < mu.size(); ++i)
          {
            const bool held = set.held(i, mu(i), g(i));
            if (held && set.free(i))
              ++n_active;
            const double free = held ? 0. : 1.;
            n_changed += (free != (reject ? mask(i) : previous_mask(i)));
            if (!reject)
              mask(i) = free;
          }
        const bool settled =
          !reject && !after_fallback && k > 0 && n_changed == 0;
        // Cycling: the active set of two steps ago again (the inexact
        // steps of a changing set can alternate between two sets): the
        // next steps are solved as if the set had settled, and from the
        // third such return on they are halved (damped).
        bool cycling = !reject && k > 1 && n_changed > 0;
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
            if (n_replaced > 0)
              msg << " (" << n_replaced
                  << " of them in place of rejected Newton steps that did "
                     "not increase the dual function enough)";
            return finish(msg.str());
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
        else if (!settled && !reject)
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

        if (reject)
          {
            // Back to mu_k (its jumps: previous_gradient) and the best of
            // four kinds of step from there, each with its exact increase of
            // Phi (a concave quadratic on each segment):
            //  - the projected-gradient step, which needs F s (4 solves) and
            //    guarantees the increase of the convergence argument;
            //  - on the segment to the rejected iterate, x = mu_{k+1} - mu_k
            //    (x^T F x from the two gradients);
            //  - along the Newton direction d up to the first bound it meets
            //    (d^T F d from the conjugate gradients);
            //  - reduced Newton steps (below).
            BlockVector<double> x(mu), curvature(previous_gradient);
            x -= previous_mu;
            curvature -= gradient; // F x
            mu       = previous_mu;
            gradient = previous_gradient;
            BlockVector<double> best_step, best_face;
            double              best_increase = 0;
            result.subdomain_solves +=
              projected_gradient_candidate(subproblems,
                                           interface,
                                           gradient,
                                           (x * x) / (x * curvature),
                                           mu,
                                           best_step,
                                           best_increase);
            const auto on_segment =
              best_on_segment(gradient * x, x * curvature, 1.);
            const double a_max = set.step_to_boundary(mu, newton_direction, 1.);
            const auto truncated = best_on_segment(gradient * newton_direction,
                                                   newton_curvature,
                                                   a_max);
            // Reduced Newton steps (a primal active-set method from mu_k):
            // the free component that the direction d carries across a
            // bound first joins the set B of components moved onto their
            // bound (d_H = bound - mu_H), and the others J = I \ H take
            // the exact Newton step of that face,
            //   F_JJ d_J = (D g - F d_H)_J,
            // until d stays inside the box or max_reductions components are
            // held; then the best point of the segment mu + a d, a in
            // [0, a_max] inside the box (4 solves for F d_H and F d).
            constexpr unsigned int max_reductions = 8;
            BlockVector<double> reduced_mask(mask), face_step(mu), held(mu), Fd;
            held                              = 0;
            std::pair<double, double> on_face = {0., 0.};
            face_step                         = newton_direction;
            for (unsigned int reduction = 0;; ++reduction)
              {
                unsigned int first     = mu.size();
                double       first_hit = 1.;
                for (unsigned int i = 0; i < mu.size(); ++i)
                  if (reduced_mask(i) > 0 && face_step(i) != 0)
                    {
                      const double bound = set.bound_towards(i, face_step(i));
                      const double hit   = (bound - mu(i)) / face_step(i);
                      if (hit < first_hit)
                        first_hit = hit, first = i;
                    }
                if (reduction > 0)
                  {
                    // The line search of the face step of this reduction.
                    apply_dual_operator(subproblems, interface, face_step, Fd);
                    result.subdomain_solves += Layout::n_subproblems;
                    const auto candidate = best_on_segment(gradient * face_step,
                                                           face_step * Fd,
                                                           first_hit);
                    if (candidate.second > on_face.second)
                      {
                        on_face   = candidate;
                        best_face = face_step;
                      }
                  }
                if (first == mu.size() || reduction == max_reductions)
                  break;
                // Hold component first at the bound it crosses.
                reduced_mask(first) = 0;
                held(first) =
                  set.bound_towards(first, face_step(first)) - mu(first);
                BlockVector<double> rhs(gradient), face_delta;
                apply_dual_operator(subproblems, interface, held, Fd);
                result.subdomain_solves += Layout::n_subproblems;
                rhs -= Fd;
                rhs.scale(reduced_mask);
                preconditioner.reinit(reduced_mask);
                stale_preconditioner = true;
                const ConjugateGradientOutcome face_cg =
                  conjugate_gradients_on_free_set(
                    subproblems,
                    interface,
                    preconditioner,
                    reduced_mask,
                    largest_jump(interface, rhs),
                    0.1 * parameters.tolerance *
                      displacement_scale(interface, w),
                    parameters.max_inner_iterations,
                    rhs,
                    face_delta);
                result.subdomain_solves += face_cg.subdomain_solves;
                result.preconditioner_solves += face_cg.preconditioner_solves;
                result.linear_iterations += face_cg.iterations;
                face_step = held;
                face_step += face_delta;
              }
            const char *kind = "projected-gradient";
            if (on_face.second > best_increase)
              {
                best_step = best_face;
                best_step *= on_face.first;
                best_increase = on_face.second;
                kind          = "reduced Newton";
              }
            if (on_segment.second > best_increase &&
                on_segment.second >= truncated.second)
              {
                best_step = x;
                best_step *= on_segment.first;
                best_increase = on_segment.second;
                kind          = "segment";
              }
            else if (truncated.second > best_increase)
              {
                best_step = newton_direction;
                best_step *= truncated.first;
                best_increase = truncated.second;
                kind          = "truncated Newton";
              }
            no_ascent = !(best_increase > 0);
            if (output.progress_interval > 0)
              pcout << "    " << kind << " step from step " << k - 1
                    << ": dual function +" << std::scientific
                    << std::setprecision(3) << best_increase
                    << std::defaultfloat << std::endl;
            mu += best_step;
            interface.space().project(mu);
            ++n_replaced;
            predicted_increase = 0;
            after_fallback     = true;
            continue;
          }
        after_fallback = false;

        // Newton step: F_II delta_I = (D g)_I by preconditioned conjugate
        // gradients from delta = 0, to a relative reduction of the largest
        // jump while the active set changes, else to the tolerance.
        if (k == 0 || n_changed > 0 || stale_preconditioner)
          preconditioner.reinit(mask), stale_preconditioner = false;
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
        previous_mu         = mu;
        previous_gradient   = gradient;
        const double length = cycling && n_cycling > 2 ? 0.5 : 1.;
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
  }
} // namespace bilayer
