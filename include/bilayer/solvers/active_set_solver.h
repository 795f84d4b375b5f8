#ifndef bilayer_active_set_solver_h
#define bilayer_active_set_solver_h

#include <deal.II/base/conditional_ostream.h>
#include <deal.II/lac/block_vector.h>

#include <bilayer/interface/interface.h>
#include <bilayer/parameters/parameters.h>
#include <bilayer/solvers/outer_solver.h>

namespace bilayer
{
  /**
   * Primal-dual active set method (a semismooth Newton method) on the dual
   * problem of docs/problem.md §3, with FETI-type preconditioned conjugate
   * gradients through the subdomain solves.
   *
   * <h3>The dual problem</h3>
   * With the solution map w(mu) = K^{-1}(f - B^T mu) of the four factorised
   * subproblems (B the signed coupling, B w = D g with g the weighted jumps,
   * Interface::coupling_gram()), the multipliers minimise
   *   q(mu) = 1/2 mu^T F mu - mu^T d,   F = B K^{-1} B^T,  grad q = -D g(mu),
   * over the box lower <= mu <= upper (0 <= mu_c <= p at crack nodes,
   * |mu| <= p for the gluing multipliers). F is never formed: F x costs four
   * homogeneous subdomain solves.
   *
   * <h3>Newton step</h3>
   * At an iterate mu (in the box) with jumps g, a component at its lower
   * bound stays active if g <= 0 (the constraint pushes against the bound:
   * the crack is open there), one at its upper bound if g >= 0; all others
   * are inactive (the set I). This is the active-set prediction of the
   * semismooth Newton method for mu = P(mu + c g) in the limit of a small c.
   * The step solves the dual problem with the active components held:
   *   F_II delta_I = (D g)_I,   delta_A = 0,
   * so that the jumps vanish on I, and mu <- P(mu + delta). The iteration
   * stops when the relative KKT residual (kkt_residual() of
   * interface_diagnostics.h) of an iterate is below Solver/Tolerance; it is
   * evaluated after a full solve at every iterate, so the reported solution and
   * its residuals belong together.
   *
   * <h3>Globalisation</h3>
   * The dual function Phi = -q is a concave quadratic; its change over a
   * step is known exactly from the jumps at both ends. A Newton step must
   * increase it by 1e-4 times the increase its conjugate gradients predict;
   * the first inexact step that does not switches to exact steps, an exact
   * one that does not is rejected and replaced by the best of four kinds of
   * step from the previous iterate (a projected-gradient step with exact line
   * search, the segment to the rejected iterate, the Newton direction up to
   * its first bound, and reduced Newton steps: the exact Newton steps of
   * the faces on which the blocking multipliers, one more at a time, are
   * held at the bounds they cross, as in a primal active-set method). The
   * projected-gradient step bounds the increase from below by a positive
   * function of the projected gradient, hence the iterates approach the
   * solution set: docs/problem.md §4.3 gives the argument. Where no step is
   * rejected the iterates are those of the plain method.
   *
   * A Newton step rejected again from the active set of the rejected step
   * before it (a 2-cycle through a rejection: free contact multipliers a
   * round-off above 0 where the faces open, issue 45) makes the reduced
   * Newton steps hold every multiplier the step carries across a bound at
   * once; one rejected six times in a row ends the Newton steps, and the
   * AcceleratedSolver (theta = auto, the KKT rule) continues from the
   * multipliers where that step starts, as the terminal and the solver
   * message say.
   *
   * <h3>Linear solves</h3>
   * Conjugate gradients on F_II, preconditioned by the FetiPreconditioner
   * of Solver/Active set/Preconditioner (dirichlet, lumped or none), which
   * the solver builds for each solve (the Dirichlet factorisations: its
   * set-up time). While the active set still changes, the conjugate gradients
   * stop at a relative reduction Solver/Active set/Inner tolerance of the
   * largest jump on I (an inexact Newton step); once it stays the same, they
   * run until the largest jump is below Solver/Tolerance / 10 times the
   * displacement scale.
   *
   * Work: 4 subdomain solves per Newton step (the full solve at the iterate)
   * and per conjugate-gradient iteration; the Dirichlet preconditioner adds
   * 4 Dirichlet solves per application (counted as preconditioner_solves).
   */
  class ActiveSetSolver : public OuterSolver
  {
  public:
    ActiveSetSolver(const SolverParameters           &parameters,
                    const OutputParameters           &output,
                    const dealii::ConditionalOStream &pcout);

    /// Run from @p multipliers (projected onto the box first); on return
    /// they and @p solutions hold the last iterate.
    SolverResult
    solve(const Subproblems           &subproblems,
          const Interface             &interface,
          dealii::BlockVector<double> &multipliers,
          Solutions                   &solutions) const override;

  private:
  };

} // namespace bilayer

#endif
