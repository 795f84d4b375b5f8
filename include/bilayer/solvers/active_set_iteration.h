#ifndef bilayer_active_set_iteration_h
#define bilayer_active_set_iteration_h

#include <deal.II/base/conditional_ostream.h>
#include <deal.II/lac/block_vector.h>

#include <bilayer/core/progress.h>
#include <bilayer/interface/interface.h>
#include <bilayer/interface/interface_diagnostics.h>
#include <bilayer/parameters/parameters.h>
#include <bilayer/solvers/feti_preconditioner.h>
#include <bilayer/solvers/outer_solver.h>
#include <bilayer/solvers/subdomain_solves.h>

#include <limits>
#include <string>
#include <utility>

/**
 * @file
 * The iteration of ActiveSetSolver (active_set_solver.h), shared by
 * active_set_solver.cc (the Newton steps: their linear solves, the active
 * sets, the stopping tests) and active_set_globalisation.cc (the
 * sufficient-increase test and the replacement steps of a rejected Newton
 * step). Only these two files include it.
 */
namespace bilayer
{
  namespace active_set
  {
    /// Largest |x_i| / D_i (the largest jump of a Euclidean residual).
    double
    largest_jump(const Interface                   &interface,
                 const dealii::BlockVector<double> &x);


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
     * to the free components I, plus D c' p of the cohesive springs at the
     * multipliers @p at (MultiplierSpace::add_cohesive_operator()). On
     * entry @p r is the right-hand side (zero off I) with largest jump
     * @p start, on return the residual.
     *
     * The iteration stops when the largest jump of the residual,
     * max_i |r_i| / D_i, is at most @p target; when p^T F p is no longer
     * positive (F_II exhausted: its semidefinite directions), keeping the
     * iterate; or, as a failure, after @p max_iterations iterations. The
     * preconditioner is applied to the first residual and to every residual
     * that misses the target, the last one before the limit included.
     */
    ConjugateGradientOutcome
    conjugate_gradients_on_free_set(const Subproblems        &subproblems,
                                    const Interface          &interface,
                                    const FetiPreconditioner &preconditioner,
                                    const dealii::BlockVector<double> &mask,
                                    const dealii::BlockVector<double> &at,
                                    const double                       start,
                                    const double                       target,
                                    const unsigned int           max_iterations,
                                    dealii::BlockVector<double> &r,
                                    dealii::BlockVector<double> &delta);


    /// The active set of an iterate compared with those before it.
    struct ActiveSetChange
    {
      /// Free components held at a bound, and components whose set changed.
      unsigned int n_active = 0, n_changed = 0;
      /// The set of the last Newton step again, with no step rejected or
      /// replaced in between.
      bool settled = false;
      /// The set of two steps ago again.
      bool cycling = false;
    };


    /**
     * The primal-dual active set iteration of ActiveSetSolver: the problem,
     * the preconditioner, the iterate (mu, w) and the SolverResult it
     * updates, and the state carried from one Newton step to the next (the
     * active sets, the globalisation, the guards against cycling and
     * stagnation).
     */
    class NewtonIteration
    {
    public:
      NewtonIteration(const Subproblems                &subproblems,
                      const Interface                  &interface,
                      const SolverParameters           &parameters,
                      const OutputParameters           &output,
                      const dealii::ConditionalOStream &pcout,
                      const IterationClock             &clock,
                      FetiPreconditioner               &preconditioner,
                      dealii::BlockVector<double>      &mu,
                      Solutions                        &w,
                      SolverResult                     &result);

      /// Newton steps from mu (projected onto the box first) until a
      /// stopping test holds; returns why the iteration ended.
      std::string
      run();

      /// Whether run() ended because the Newton step from one active set
      /// was rejected max_repeated_rejections + 1 times in a row (mu is
      /// then the iterate that step starts from): the caller continues
      /// with the accelerated method.
      bool
      stalled() const
      {
        return n_repeated_rejections >= max_repeated_rejections;
      }

      /// The rejections in a row, after the first, of the Newton step from
      /// one active set that end the Newton steps (stalled()).
      static constexpr unsigned int max_repeated_rejections = 5;

    private:
      /// The full solve at the iterate of step @p k, its jumps g, the
      /// gradient D g of the dual function and the KKT residual.
      KKTResidual
      evaluate_iterate(const unsigned int k);

      /// Whether the Newton step to the iterate of step @p k is rejected
      /// for an insufficient increase of the dual function (the first such
      /// inexact step switches to exact steps instead).
      bool
      rejects_step(const unsigned int k, const KKTResidual &kkt);

      /// The active set at mu and how it differs from the last ones (at a
      /// rejected iterate the sets stay those of the previous one).
      ActiveSetChange
      classify_active_set(const unsigned int k, const bool reject);

      /// The progress line of Newton step @p k.
      void
      print_newton_step(const unsigned int     k,
                        const KKTResidual     &kkt,
                        const ActiveSetChange &change) const;

      /// Why the iteration ends at step @p k (diverged, converged, no
      /// ascent, stagnation, the step limit), or an empty string.
      std::string
      stopping_message(const unsigned int     k,
                       const KKTResidual     &kkt,
                       const ActiveSetChange &change,
                       const bool             reject);

      /// Whether the rejected Newton step @p k starts from the active set
      /// of the rejected step k - 2 (the replacement step led back to it)
      /// while the KKT residual there has not fallen tenfold: counts such
      /// repetitions in n_repeated_rejections (0 for a new rejection).
      bool
      repeats_rejection(const unsigned int k);

      /// Back to the previous iterate and the best of the replacement
      /// steps from there, in place of the rejected Newton step @p k.
      void
      replace_rejected_step(const unsigned int k);

      /// The best reduced Newton step from mu: its direction in
      /// @p best_face, its length and increase of the dual function. With
      /// @p all_at_once each reduction holds every free multiplier that the
      /// direction carries across a bound, not only the first.
      std::pair<double, double>
      best_reduced_newton_step(dealii::BlockVector<double> &best_face,
                               const bool                   all_at_once);

      /// Holds component @p first of the face step @p face_step at the
      /// bound it crosses and solves the Newton step of the smaller face.
      void
      hold_at_bound(const unsigned int           first,
                    dealii::BlockVector<double> &reduced_mask,
                    dealii::BlockVector<double> &held,
                    dealii::BlockVector<double> &face_step,
                    dealii::BlockVector<double> &Fd);

      /// The conjugate gradients of Newton step @p k on F_II delta_I =
      /// (D g)_I; why the iteration ends if they fail, else an empty string.
      std::string
      solve_newton_system(const unsigned int k, const ActiveSetChange &change);

      /// mu <- P(mu + length delta), with the prediction and curvature that
      /// the next step's sufficient-increase test needs.
      void
      take_newton_step(const ActiveSetChange &change);

      const Subproblems                &subproblems;
      const Interface                  &interface;
      const SolverParameters           &parameters;
      const OutputParameters           &output;
      const dealii::ConditionalOStream &pcout;
      const IterationClock             &clock;
      FetiPreconditioner               &preconditioner;
      dealii::BlockVector<double>      &mu;
      Solutions                        &w;
      SolverResult                     &result;
      const MultiplierSet              &set;

      dealii::BlockVector<double> g, mask, r, delta, gradient,
        previous_gradient, previous_mu;
      dealii::BlockVector<double> previous_mask, older_mask;
      unsigned int inner_iterations = 0, n_cycling = 0, n_stalled = 0;
      bool         exact_steps  = false;
      double       best_settled = std::numeric_limits<double>::infinity();
      // The globalisation: the increase of Phi that the conjugate gradients
      // predict for the last Newton step (0 after a replacement step, which
      // is not tested), that step's direction and its curvature d^T F d, and
      // the number of rejected Newton steps.
      double                      predicted_increase = 0, newton_curvature = 0;
      dealii::BlockVector<double> newton_direction;
      unsigned int                n_replaced = 0;
      // Repeated rejections (a 2-cycle between an accepted active set and a
      // rejected one): the active set that the last rejected Newton step
      // started from and the step of that rejection, the KKT residuals of
      // the last accepted iterate and of the first start of the
      // repetitions, and their number.
      dealii::BlockVector<double> rejected_start;
      unsigned int                last_rejection = 0, n_repeated_rejections = 0;
      double                      accepted_residual = 0, repeated_residual = 0;
      bool after_fallback = false, stale_preconditioner = false,
           no_ascent = false;
    };
  } // namespace active_set
} // namespace bilayer

#endif
