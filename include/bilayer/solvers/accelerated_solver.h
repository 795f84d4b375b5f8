#ifndef bilayer_accelerated_solver_h
#define bilayer_accelerated_solver_h

#include <deal.II/base/conditional_ostream.h>
#include <deal.II/lac/block_vector.h>

#include <bilayer/interface/interface.h>
#include <bilayer/parameters/parameters.h>
#include <bilayer/solvers/first_order_iteration.h>
#include <bilayer/solvers/outer_solver.h>

namespace bilayer
{
  /**
   * The projected gradient step of the Uzawa iteration with Nesterov/FISTA
   * momentum and adaptive restart (Beck and Teboulle; O'Donoghue and
   * Candes):
   *   x_{k+1} = P(y_k + theta g(y_k)),
   *   t_{k+1} = (1 + sqrt(1 + 4 t_k^2)) / 2,
   *   y_{k+1} = x_{k+1} + (t_k - 1) / t_{k+1} (x_{k+1} - x_k),
   * from y_0 = x_0 = mu^0, t_0 = 1; t restarts at 1 when the step goes
   * against the gradient at the extrapolated point,
   * <g(y_k), x_{k+1} - x_k>_D < 0. The subproblems are solved at y_k; the
   * stopping rule is evaluated there, and when it holds, the result is the
   * projected iterate x_k (which lies in the multiplier sets) with its own
   * solutions, which under the KKT rule has to meet the rule itself (4 more
   * solves, counted).
   *
   * The step is Solver/Uzawa step theta, or with theta = auto a fraction of
   * 1 / lambda_max(S) (choose_auto_step()). The iteration is stopped as
   * divergent by the DivergenceTest.
   */
  class AcceleratedSolver : public FirstOrderSolver
  {
  public:
    AcceleratedSolver(const SolverParameters           &parameters,
                      const OutputParameters           &output,
                      const dealii::ConditionalOStream &pcout);

  private:
    /// The iteration from @p mu with the step and the set-up work recorded
    /// in @p result.
    void
    iterate(const Subproblems           &subproblems,
            const Interface             &interface,
            dealii::BlockVector<double> &mu,
            Solutions                   &w,
            SolverResult                &result) const override;

    /**
     * Whether the projected iterate @p x meets the stopping rule: its
     * solutions (4 solves, counted in @p result) and, under the KKT rule,
     * its own KKT residual. If so, @p mu and @p w become @p x and its
     * solutions.
     */
    bool
    accept_projected(const Subproblems                 &subproblems,
                     const Interface                   &interface,
                     const dealii::BlockVector<double> &x,
                     dealii::BlockVector<double>       &mu,
                     Solutions                         &w,
                     SolverResult                      &result) const;
  };
} // namespace bilayer

#endif
