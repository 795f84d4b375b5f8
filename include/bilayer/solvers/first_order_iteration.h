#ifndef bilayer_first_order_iteration_h
#define bilayer_first_order_iteration_h

#include <deal.II/base/conditional_ostream.h>
#include <deal.II/lac/block_vector.h>

#include <bilayer/core/progress.h>
#include <bilayer/interface/interface.h>
#include <bilayer/parameters/parameters.h>
#include <bilayer/solvers/outer_solver.h>
#include <bilayer/solvers/subdomain_solves.h>

#include <deque>
#include <limits>
#include <string>

/**
 * @file
 * What the two first-order iterations on the dual problem, the paper's
 * projected Uzawa iteration (UzawaSolver) and its accelerated variant
 * (AcceleratedSolver), share: the step of theta = auto, the projected
 * gradient step, the stopping rules, the progress line, the message at the
 * iteration limit and the divergence test.
 */
namespace bilayer
{
  /**
   * The stable steps of a first-order iteration: theta below
   * factor * 2 / lambda_max(S), S = D^{-1} C A^{-1} C^T the dual operator.
   * The projected gradient step is non-expansive below 2 / lambda_max
   * (factor 1); the extrapolated steps of FISTA need theta below
   * 1 / lambda_max (factor 1/2).
   */
  struct StepBound
  {
    double factor;
    /// The step of theta = auto in words, after Solver/theta = auto
    /// fraction: " * 2 / lambda_max" or " / lambda_max".
    std::string in_words;
  };

  /// The step of theta = auto: the fraction Solver/theta = auto fraction of
  /// the bound.
  double
  auto_step(const SolverParameters &parameters,
            const StepBound        &bound,
            const double            lambda_max);

  /**
   * theta = auto: lambda_max(S) by the power iteration (estimate_lambda_max),
   * printed with the predicted threshold 2 / lambda_max and the step, and
   * recorded in @p result (lambda_max, predicted_threshold, theta). Returns
   * the subdomain solves spent.
   */
  unsigned long
  choose_auto_step(const SolverParameters           &parameters,
                   const StepBound                  &bound,
                   const Subproblems                &subproblems,
                   const Interface                  &interface,
                   const dealii::ConditionalOStream &pcout,
                   SolverResult                     &result);

  /**
   * Step 3 of the iteration: @p next = P(@p mu + theta g), g the jumps at
   * @p mu, P the projection onto the multiplier sets.
   */
  void
  projected_step(const Interface                   &interface,
                 const double                       theta,
                 const dealii::BlockVector<double> &mu,
                 const dealii::BlockVector<double> &g,
                 dealii::BlockVector<double>       &next);

  /// The largest violation of the jumps @p g at the multipliers @p mu
  /// relative to the displacement
  /// scale of @p w (absolute where the scale is zero). Needs the traces of
  /// all solutions.
  double
  relative_violation(const Interface                   &interface,
                     const Solutions                   &w,
                     const dealii::BlockVector<double> &g,
                     const dealii::BlockVector<double> &mu);

  /**
   * The value of Solver/Stopping rule at step k >= 1 of a first-order
   * iteration at the multipliers @p mu, with solutions @p w and jumps @p g,
   * @p w_old the solutions of the previous step and @p last_increment the
   * D-norm of the last multiplier increment:
   *  - kkt: the relative KKT residual;
   *  - relative: the larger of the relative multiplier change and the
   *    relative violation;
   *  - paper: max_s |w_s - w_s_old|_a / |w_s|_a^2 (energy norms);
   *  - paper with norm: max_s |w_s - w_s_old|_a / |w_s|_a.
   */
  double
  stopping_value(const SolverParameters            &parameters,
                 const Subproblems                 &subproblems,
                 const Interface                   &interface,
                 const Solutions                   &w,
                 const Solutions                   &w_old,
                 const dealii::BlockVector<double> &g,
                 const dealii::BlockVector<double> &mu,
                 const double                       last_increment);

  /// Every Output/Progress interval steps: the stopping value, the last
  /// multiplier change, the relative violation, the elapsed time and the
  /// time left to reach @p tolerance at the present rate (@p clock), one
  /// line.
  void
  print_progress(const OutputParameters            &output,
                 const dealii::ConditionalOStream  &pcout,
                 const unsigned int                 k,
                 const double                       value,
                 const double                       last_increment,
                 const Interface                   &interface,
                 const Solutions                   &w,
                 const dealii::BlockVector<double> &g,
                 const dealii::BlockVector<double> &mu,
                 IterationClock                    &clock,
                 const double                       tolerance);

  /**
   * The message of a first-order iteration stopped at Solver/Maximum
   * iterations with stopping value @p value: under the paper's stopping rule
   * why that rule may never hold, else @p advice (begins with "; ").
   */
  std::string
  iteration_limit_message(const SolverParameters &parameters,
                          const double            value,
                          const std::string      &advice);

  /**
   * Sustained growth of a sequence of positive values (the D-norms of the
   * multiplier increments): add() is true when the newest value exceeds the
   * smallest one so far by @p factor and each of the last w values exceeds
   * the largest of the w values before them, w = max(@p window, n / 10)
   * after n values (the oscillations of a converging iteration lengthen as
   * it slows down), or of half the values so far, at least 2, while fewer
   * than 2 w have been entered. A single non-monotone step, or a sequence that
   * oscillates but decreases from one window to the next, is never growth;
   * a geometric growth is, within 2 w values of exceeding the factor.
   */
  class GrowthWindow
  {
  public:
    GrowthWindow(const double factor, const unsigned int window);

    /// Enter @p value; true if the sequence now grows.
    bool
    add(const double value);

  private:
    const double       factor;
    const unsigned int window;
    double             min_value;
    std::size_t        count;
    /// The last 2 w values, the newest last.
    std::deque<double> recent;
  };

  /**
   * The divergence test of the first-order iterations: stop when the
   * multipliers or solutions stop being finite, or when the D-norm of the
   * multiplier increment grows (GrowthWindow with Solver/Divergence growth
   * factor and the window of the method): for theta below the threshold
   * 2 / lambda_max(D^{-1} C A^{-1} C^T) the projected Uzawa step is
   * non-expansive, so its increments cannot grow; the accelerated iteration
   * is not monotone, hence the window. A growth of the increments over a
   * span of iterations in which a scale-invariant stopping value
   * (Solver/Stopping rule = kkt or relative) fell to half or less
   * (since the iteration of the smallest increment) is no divergence: on a
   * nearly singular dual operator the iterates of a converging accelerated
   * iteration drift along a flat direction with growing momentum while the
   * stopping value keeps falling, with plateaus of many thousand
   * iterations; a diverging iteration's relative stopping value does not
   * fall. Its message ends with the step that theta = auto would take
   * (safe_step_advice()), unless theta is already that small.
   */
  class DivergenceTest
  {
  public:
    /// @p lambda_max: the estimate of theta = auto, or 0 if none was made.
    DivergenceTest(const SolverParameters &parameters,
                   const StepBound        &bound,
                   const Subproblems      &subproblems,
                   const Interface        &interface,
                   const double            theta,
                   const double            lambda_max,
                   const unsigned int      window);

    /// The window of the Uzawa iteration (monotone increments below the
    /// threshold).
    static constexpr unsigned int uzawa_window = 5;
    /// The window of the accelerated iteration (increments oscillate with
    /// the momentum between restarts).
    static constexpr unsigned int accelerated_window = 20;

    /**
     * At step k, with stopping value @p value (infinite at k = 0) and the
     * increment @p increment = |x_k - x_{k+1}|_D to the next iterate
     * @p next: why the iteration diverged, or an empty string, and then the
     * increment enters the smallest one so far.
     */
    std::string
    check(const unsigned int                 k,
          const double                       value,
          const double                       increment,
          const dealii::BlockVector<double> &next);

    /**
     * The first part of check(): why the iteration diverged if the
     * increment, or the stopping value at k >= 1, is not finite, else an
     * empty string. The iterations whose line search keeps the dual
     * objective from decreasing (Uzawa with adaptive steps) need no more:
     * their increments may grow and shrink with the step.
     */
    std::string
    check_finite(const unsigned int k,
                 const double       value,
                 const double       increment) const;

  private:
    /**
     * "; estimated safe step: theta <= ... (...)", the step of theta = auto
     * from lambda_max, estimated now by a power iteration unless theta =
     * auto already did (its solves are not added to
     * SolverResult::subdomain_solves); empty without a usable estimate.
     */
    std::string
    safe_step_advice() const;

    const SolverParameters &parameters;
    const StepBound        &bound;
    const Subproblems      &subproblems;
    const Interface        &interface;
    const double            theta, lambda_max;
    GrowthWindow            growth;
    /// The smallest increment from iteration 1 on and the stopping value
    /// at its iteration.
    double smallest_increment = std::numeric_limits<double>::infinity();
    double value_at_smallest  = std::numeric_limits<double>::infinity();
  };
  /**
   * The frame of the two first-order iterations: theta = auto (the power
   * iteration, with the iteration's own StepBound) as the solver's set-up,
   * then iterate(), both timed.
   */
  class FirstOrderSolver : public OuterSolver
  {
  public:
    SolverResult
    solve(const Subproblems           &subproblems,
          const Interface             &interface,
          dealii::BlockVector<double> &multipliers,
          Solutions                   &solutions) const override;

  protected:
    FirstOrderSolver(const SolverParameters           &parameters,
                     const OutputParameters           &output,
                     const dealii::ConditionalOStream &pcout,
                     const std::string                &name,
                     const StepBound                  &step_bound)
      : OuterSolver(parameters, output, pcout)
      , name(name)
      , step_bound(step_bound)
    {}

    /// Iterate from @p mu with the step result.theta.
    virtual void
    iterate(const Subproblems           &subproblems,
            const Interface             &interface,
            dealii::BlockVector<double> &mu,
            Solutions                   &w,
            SolverResult                &result) const = 0;

    /**
     * The part of iteration @p k that both iterations share: the four
     * solves with the loads of @p mu, the work so far (@p extra_solves
     * besides 4 per iteration), the jumps @p g, the stopping value
     * (infinite at k = 0; @p w_old and @p last_increment are the previous
     * iterate and the D-norm of the last multiplier increment) and the
     * progress line. Returns the stopping value.
     */
    double
    evaluate(const Subproblems                 &subproblems,
             const Interface                   &interface,
             const unsigned int                 k,
             const unsigned long                extra_solves,
             const dealii::BlockVector<double> &mu,
             Solutions                         &w,
             const Solutions                   &w_old,
             dealii::BlockVector<double>       &g,
             const double                       last_increment,
             SolverResult                      &result) const;

    /// SolverResult::solver.
    const std::string name;
    const StepBound   step_bound;
    /// The time of the iteration for the progress lines (started by
    /// solve()).
    mutable IterationClock clock;
  };
} // namespace bilayer

#endif
