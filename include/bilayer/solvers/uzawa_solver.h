#ifndef bilayer_uzawa_solver_h
#define bilayer_uzawa_solver_h

#include <deal.II/base/conditional_ostream.h>
#include <deal.II/lac/block_vector.h>

#include <bilayer/interface/interface.h>
#include <bilayer/parameters/parameters.h>
#include <bilayer/solvers/first_order_iteration.h>
#include <bilayer/solvers/outer_solver.h>

namespace bilayer
{
  /**
   * The Uzawa algorithm of docs/problem.md §4:
   *   1. mu^0 given (zero, or a warm start);
   *   2. solve the subproblems with the multiplier loads of mu^k;
   *   3. mu^{k+1} = P(mu^k + theta g^k), g^k the jumps (Interface::jumps);
   *   4. stop when the stopping rule holds at step k (k >= 1), else repeat.
   * Iterations are counted as the k at which the rule holds, so the work is
   * 4 (k + 1) subdomain solves.
   *
   * The step is Solver/Uzawa step theta, or with theta = auto a fraction of
   * the stability threshold 2 / lambda_max(S) (choose_auto_step()); then a
   * converged run also reports the threshold of the final phase, on the
   * multipliers that the projection does not hold at a bound. The iteration
   * is stopped as divergent by the DivergenceTest.
   */
  class UzawaSolver : public FirstOrderSolver
  {
  public:
    UzawaSolver(const SolverParameters           &parameters,
                const OutputParameters           &output,
                const dealii::ConditionalOStream &pcout);

  private:
    /// Steps 2 to 4 from @p mu with the step and the set-up work recorded
    /// in @p result.
    void
    iterate(const Subproblems           &subproblems,
            const Interface             &interface,
            dealii::BlockVector<double> &mu,
            Solutions                   &w,
            SolverResult                &result) const override;

    /**
     * theta = auto with Solver/Auto theta steps = adaptive: the spectral
     * projected gradient iteration on the dual problem, mu^{k+1} = mu^k +
     * t_k d^k, d^k = P(mu^k + alpha_k g^k) - mu^k, alpha_0 = theta = auto,
     * alpha_k the Barzilai-Borwein step <s, S s>_D / <S s, S s>_D of the
     * last change s of the multipliers, t_k = 1 or the maximiser of the dual
     * objective on the segment (non-monotone line search). Every iterate is
     * feasible (a convex combination of feasible points), so the
     * projection still defines the iteration; four subdomain solves per
     * iteration (at mu^k + d^k, the solutions being affine in the
     * multipliers). The line search keeps the dual objective above its
     * lowest recent value, so only non-finite iterates count as divergence.
     */
    void
    iterate_adaptive(const Subproblems           &subproblems,
                     const Interface             &interface,
                     dealii::BlockVector<double> &mu,
                     Solutions                   &w,
                     SolverResult                &result) const;

    /// 2 / lambda_max of S restricted to the multipliers that the projected
    /// step from the solution @p mu with jumps @p g does not hold at a bound.
    void
    threshold_at_solution(const Subproblems                 &subproblems,
                          const Interface                   &interface,
                          const dealii::BlockVector<double> &mu,
                          const dealii::BlockVector<double> &g,
                          SolverResult                      &result) const;

    /**
     * Whether the iteration ends at step @p k with stopping value @p value:
     * the stopping rule met (then with theta = auto the threshold at the
     * solution) or the iteration limit reached (its message ends with
     * @p limit_advice); the message in @p result.
     */
    bool
    stopped(const unsigned int                 k,
            const double                       value,
            const Subproblems                 &subproblems,
            const Interface                   &interface,
            const dealii::BlockVector<double> &mu,
            const dealii::BlockVector<double> &g,
            const std::string                 &limit_advice,
            SolverResult                      &result) const;
  };
} // namespace bilayer

#endif
