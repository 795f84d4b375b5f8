#include <bilayer/solvers/active_set_iteration.h>

#include <algorithm>
#include <cmath>
#include <iomanip>
#include <utility>

namespace bilayer
{
  using namespace dealii;

  namespace active_set
  {
    namespace
    {
      /// A Newton step must increase the dual function by this fraction of
      /// the increase its quadratic model predicts (Armijo's constant).
      constexpr double sufficient_increase = 1e-4;


      /// F x = minus the weighted jumps of the homogeneous solutions with the
      /// multiplier loads of x (4 subdomain solves).
      void
      apply_dual_operator(const Subproblems         &subproblems,
                          const Interface           &interface,
                          const BlockVector<double> &at,
                          const BlockVector<double> &x,
                          BlockVector<double>       &result)
      {
        Solutions homogeneous;
        solve_homogeneous_subproblems(subproblems, interface, x, homogeneous);
        interface.jumps(homogeneous, result);
        interface.space().scale_by_weights(result);
        result *= -1.;
        interface.space().add_cohesive_operator(at, x, result);
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
            apply_dual_operator(subproblems, interface, mu, step, Fs);
            solves += subproblems.size();
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
        apply_dual_operator(subproblems, interface, mu, step, Fs);
        solves += subproblems.size();
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


      /**
       * The first component i with @p mask(i) > 0 that mu + a d crosses a
       * bound for, a in [0, @p first_hit], or mu.size() if there is none; on
       * return @p first_hit is its a (1 if none).
       */
      unsigned int
      first_bound_crossing(const MultiplierSet       &set,
                           const BlockVector<double> &mu,
                           const BlockVector<double> &mask,
                           const BlockVector<double> &d,
                           double                    &first_hit)
      {
        unsigned int first = mu.size();
        first_hit          = 1.;
        for (unsigned int i = 0; i < mu.size(); ++i)
          if (mask(i) > 0 && d(i) != 0)
            {
              const double bound = set.bound_towards(i, d(i));
              const double hit   = (bound - mu(i)) / d(i);
              if (hit < first_hit)
                first_hit = hit, first = i;
            }
        return first;
      }
    } // namespace


    bool
    NewtonIteration::rejects_step(const unsigned int k, const KKTResidual &kkt)
    {
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
      // there (replace_rejected_step()), one of them the projected-gradient
      // step with exact line search, which increases Phi by at least a
      // positive function of |P(mu + t D g) - mu|. So every step but one
      // increases Phi by that much, and the measure tends to zero:
      // docs/problem.md §4.3.
      bool reject = false;
      if (k > 0 && predicted_increase > 0 && std::isfinite(kkt.value()) &&
          kkt.value() > parameters.tolerance)
        {
          BlockVector<double> step(mu);
          step -= previous_mu;
          const double before    = step * previous_gradient,
                       after     = step * gradient;
          const double change    = 0.5 * (before + after);
          const double round_off = 1e-12 * (std::abs(before) + std::abs(after));
          const bool   sufficient =
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
                      << k - 1 << " instead" << std::defaultfloat << std::endl;
            }
        }
      return reject;
    }


    bool
    NewtonIteration::repeats_rejection(const unsigned int k)
    {
      // A 2-cycle that the test of classify_active_set() does not see: the
      // Newton step from an active set is rejected, the replacement step
      // from its start mu_{k-1} leads back to an iterate with the same
      // active set, and the same Newton step is rejected again. It happens
      // where crack faces touch with almost no pressure: free contact
      // multipliers a round-off above 0 whose jumps open the crack, which
      // the Newton step drives below 0 (clipped: Phi falls), while the
      // replacement steps, the reduced Newton steps among them (one more
      // held multiplier per reduction, at most eight), gain next to
      // nothing. (mask is the active set of mu_{k-1} at a rejected step.)
      bool same = last_rejection > 0 && last_rejection + 2 == k &&
                  accepted_residual > 0.1 * repeated_residual;
      for (unsigned int i = 0; same && i < mask.size(); ++i)
        same = mask(i) == rejected_start(i);
      if (same)
        ++n_repeated_rejections;
      else
        {
          n_repeated_rejections = 0;
          rejected_start        = mask;
          repeated_residual     = accepted_residual;
        }
      last_rejection = k;
      if (n_repeated_rejections == 1 && output.progress_interval > 0)
        pcout << "    Newton steps " << k - 2 << " and " << k
              << " start from the same active set and are both rejected: "
                 "the reduced Newton steps hold every multiplier the step "
                 "carries across a bound at once"
              << std::endl;
      return same;
    }


    void
    NewtonIteration::replace_rejected_step(const unsigned int k)
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
      //  - reduced Newton steps (best_reduced_newton_step()).
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
      const auto on_segment = best_on_segment(gradient * x, x * curvature, 1.);
      const double a_max    = set.step_to_boundary(mu, newton_direction, 1.);
      const auto   truncated =
        best_on_segment(gradient * newton_direction, newton_curvature, a_max);
      const std::pair<double, double> on_face =
        best_reduced_newton_step(best_face, n_repeated_rejections > 0);
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
              << ": dual function +" << std::scientific << std::setprecision(3)
              << best_increase << std::defaultfloat << std::endl;
      mu += best_step;
      interface.space().project(mu);
      ++n_replaced;
      predicted_increase = 0;
      after_fallback     = true;
    }


    std::pair<double, double>
    NewtonIteration::best_reduced_newton_step(BlockVector<double> &best_face,
                                              const bool           all_at_once)
    {
      // Reduced Newton steps (a primal active-set method from mu_k):
      // the free component that the direction d carries across a
      // bound first joins the set B of components moved onto their
      // bound (d_H = bound - mu_H), and the others J = I \ H take
      // the exact Newton step of that face,
      //   F_JJ d_J = (D g - F d_H)_J,
      // until d stays inside the box or max_reductions components are
      // held; then the best point of the segment mu + a d, a in
      // [0, a_max] inside the box (4 solves for F d_H and F d).
      // With all_at_once (the same Newton step rejected again) a reduction
      // holds every free component that d carries across a bound, so that
      // a contact zone whose many multipliers lie a round-off above 0 is
      // released in a few reductions rather than one node per reduction.
      constexpr unsigned int max_reductions = 8;
      BlockVector<double>    reduced_mask(mask), face_step(mu), held(mu), Fd;
      held                              = 0;
      std::pair<double, double> on_face = {0., 0.};
      face_step                         = newton_direction;
      for (unsigned int reduction = 0;; ++reduction)
        {
          double             first_hit = 1.;
          const unsigned int first =
            first_bound_crossing(set, mu, reduced_mask, face_step, first_hit);
          if (reduction > 0)
            {
              // The line search of the face step of this reduction.
              apply_dual_operator(subproblems, interface, mu, face_step, Fd);
              result.subdomain_solves += subproblems.size();
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
          for (unsigned int i = 0; all_at_once && i < mu.size(); ++i)
            if (i != first && reduced_mask(i) > 0 && face_step(i) != 0)
              {
                const double bound = set.bound_towards(i, face_step(i));
                if ((bound - mu(i)) / face_step(i) < 1.)
                  {
                    reduced_mask(i) = 0;
                    held(i)         = bound - mu(i);
                  }
              }
          hold_at_bound(first, reduced_mask, held, face_step, Fd);
        }
      return on_face;
    }


    void
    NewtonIteration::hold_at_bound(const unsigned int   first,
                                   BlockVector<double> &reduced_mask,
                                   BlockVector<double> &held,
                                   BlockVector<double> &face_step,
                                   BlockVector<double> &Fd)
    {
      // Hold component first at the bound it crosses.
      reduced_mask(first) = 0;
      held(first) = set.bound_towards(first, face_step(first)) - mu(first);
      BlockVector<double> rhs(gradient), face_delta;
      apply_dual_operator(subproblems, interface, mu, held, Fd);
      result.subdomain_solves += subproblems.size();
      rhs -= Fd;
      rhs.scale(reduced_mask);
      preconditioner.reinit(reduced_mask);
      stale_preconditioner = true;
      const ConjugateGradientOutcome face_cg =
        conjugate_gradients_on_free_set(subproblems,
                                        interface,
                                        preconditioner,
                                        reduced_mask,
                                        mu,
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
  } // namespace active_set
} // namespace bilayer
