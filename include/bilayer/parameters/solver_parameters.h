#ifndef bilayer_solver_parameters_h
#define bilayer_solver_parameters_h

#include <deal.II/base/parameter_handler.h>

#include <string>

/**
 * The subsection Solver (with Solver/Active set): the outer solver on the
 * multipliers, its step, stopping rule and tolerances.
 */
namespace bilayer
{
  /**
   * Stopping rules of the Uzawa iteration.
   * - `paper`: max over the four subproblems of
   *   ||w^k - w^{k-1}|| / ||w^k||^2 < tol (energy norms), as printed in the
   *   paper (docs/problem.md §5); not scale invariant.
   * - `paper_norm`: the same with ||w^k|| in the denominator.
   * - `relative`: the relative change of the multipliers and the relative
   *   violation of the discrete constraints both below tol.
   * - `kkt`: the relative KKT residual (KKTResidual in interface_diagnostics.h)
   * below tol; the active-set solver always stops on it.
   */
  enum class StoppingRule
  {
    paper,
    paper_norm,
    relative,
    kkt
  };

  /// Preconditioners of the linear dual solves of the active-set solver.
  enum class DualPreconditioner
  {
    /// None: conjugate gradients on the dual operator itself.
    none,
    /// G^-1 B K_{Sigma Sigma} B^T G^-1 (no solves).
    lumped,
    /// G^-1 B S B^T G^-1, S the Schur complements (one Dirichlet solve per
    /// subproblem).
    dirichlet
  };

  /// Outer solvers on the multipliers.
  enum class SolverMethod
  {
    /// The paper's projected Uzawa iteration.
    uzawa,
    /// The same projected gradient step with Nesterov/FISTA momentum and
    /// adaptive (gradient) restart.
    accelerated,
    /// Primal-dual active set (semismooth Newton) on the dual problem with
    /// preconditioned conjugate gradients through the subdomain solves.
    active_set
  };

  struct SolverParameters
  {
    SolverMethod method = SolverMethod::uzawa;
    /// The Uzawa step; ignored when auto_theta is set.
    double theta = 65.0;
    /// theta = auto_theta_fraction * 2 / lambda_max(S), S estimated.
    bool   auto_theta          = false;
    double auto_theta_fraction = 0.9;
    /// Method = uzawa with theta = auto: Barzilai-Borwein steps with a
    /// non-monotone line search (UzawaSolver) instead of the constant step.
    bool         adaptive_auto_steps = true;
    unsigned int spectrum_iterations = 30;
    /// Lanczos steps for the extreme eigenvalues of the dual operator
    /// reported per cycle (0: none).
    unsigned int dual_spectrum_steps = 0;
    unsigned int max_iterations      = 100000;
    StoppingRule stopping_rule       = StoppingRule::paper;
    /// Amesos solver of subproblems shared by a group of processes.
    std::string shared_solver = "Amesos_Mumps";
    double      tolerance     = 1e-6;
    /// Divergence: the multiplier increment grew by this factor over its
    /// smallest value so far.
    double divergence_factor = 1e3;
    /// Tolerance of the acceptance checks of the final solution.
    double acceptance_tolerance = 1e-6;
    /// Start each cycle from the previous cycle's multipliers.
    bool warm_start = false;
    /// Iterate on Sigma alone (Schur complements, SolveExtent::sigma).
    bool solve_on_sigma = true;
    /// Solver/Ordering: the fill-reducing ordering of the factorisations
    /// with the Sigma dofs last (SparseCholesky::OrderingChoice's codes:
    /// 0 minimum degree, 1 nested dissection, 2 fewest flops).
    unsigned int ordering = 0;

    /// Whether the outer solver's iterations need the solutions on Sigma
    /// only (with solve_on_sigma): the active set method, and the
    /// first-order methods with a stopping rule that reads no energy norm.
    bool
    iterates_on_sigma() const
    {
      return solve_on_sigma && (method == SolverMethod::active_set ||
                                stopping_rule == StoppingRule::kkt ||
                                stopping_rule == StoppingRule::relative);
    }
    /// Solver/Active set: preconditioner, relative tolerance of the linear
    /// solves while the active set changes, limit of their iterations.
    DualPreconditioner preconditioner        = DualPreconditioner::dirichlet;
    double             inner_tolerance       = 1e-2;
    unsigned int       max_newton_iterations = 50;
    unsigned int       max_inner_iterations  = 1000;

    static void
    declare_parameters(dealii::ParameterHandler &prm);
    void
    parse_parameters(dealii::ParameterHandler &prm);
  };
} // namespace bilayer

#endif
