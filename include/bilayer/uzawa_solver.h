#ifndef bilayer_uzawa_solver_h
#define bilayer_uzawa_solver_h

#include <deal.II/base/conditional_ostream.h>
#include <deal.II/lac/block_vector.h>

#include <bilayer/first_order_iteration.h>
#include <bilayer/interface.h>
#include <bilayer/outer_solver.h>
#include <bilayer/parameters.h>

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

    /// 2 / lambda_max of S restricted to the multipliers that the projected
    /// step from the solution @p mu with jumps @p g does not hold at a bound.
    void
    threshold_at_solution(const Subproblems                 &subproblems,
                          const Interface                   &interface,
                          const dealii::BlockVector<double> &mu,
                          const dealii::BlockVector<double> &g,
                          SolverResult                      &result) const;
  };
} // namespace bilayer

#endif
