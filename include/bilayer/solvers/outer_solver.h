#ifndef bilayer_outer_solver_h
#define bilayer_outer_solver_h

#include <deal.II/base/conditional_ostream.h>
#include <deal.II/lac/block_vector.h>

#include <bilayer/interface/interface.h>
#include <bilayer/parameters/parameters.h>
#include <bilayer/solvers/subdomain_solves.h>

#include <limits>
#include <memory>
#include <string>

/**
 * @file
 * The outer solvers on the multipliers of the dual problem (docs/problem.md
 * §3): one interface, OuterSolver, and the factory that picks the solver of
 * Solver/Method: UzawaSolver (the paper's projected Uzawa iteration,
 * uzawa_solver.h), AcceleratedSolver (FISTA with adaptive restart,
 * accelerated_solver.h), ActiveSetSolver (semismooth Newton with
 * FETI-preconditioned conjugate gradients, active_set_solver.h).
 */
namespace bilayer
{
  /// How an outer solve ended.
  struct SolverResult
  {
    std::string   solver;
    unsigned int  iterations       = 0;
    unsigned long subdomain_solves = 0;
    bool          converged        = false;
    bool          diverged         = false;
    /// Value of the stopping rule at the end [see StoppingRule].
    double stopping_value = 0;
    /// Why the solve ended, one line.
    std::string message;
    /// The step used.
    double theta = 0;
    /// Estimated lambda_max of S and the predicted stability threshold
    /// 2 / lambda_max (0 when not estimated).
    double lambda_max = 0, predicted_threshold = 0;
    /// 2 / lambda_max of S restricted to the multipliers that the
    /// projection does not hold at a bound at the solution: the threshold of
    /// the final phase of the iteration (0 when not estimated).
    double threshold_at_solution = 0;
    /// Solves with the Dirichlet subproblems of a preconditioner (counted
    /// apart from subdomain_solves).
    unsigned long preconditioner_solves = 0;
    /// Conjugate-gradient iterations of the active-set solver, in all.
    unsigned int linear_iterations = 0;
    /// Wall time of the solver's own set-up (spectrum estimates,
    /// preconditioner factorisations) and of its iterations [s].
    double setup_seconds = 0, iteration_seconds = 0;

    /// Add the work of @p other (iterations, solves, times), for a solve
    /// made of several outer solves.
    void
    add_work(const SolverResult &other)
    {
      iterations += other.iterations;
      subdomain_solves += other.subdomain_solves;
      preconditioner_solves += other.preconditioner_solves;
      linear_iterations += other.linear_iterations;
      setup_seconds += other.setup_seconds;
      iteration_seconds += other.iteration_seconds;
    }
  };

  /**
   * An outer solver: finds the multipliers of the dual problem and the
   * subproblem solutions they give. It reads the subproblems and the
   * interface and changes neither; whatever it builds for itself (a
   * preconditioner's factorisations) lives only for one solve().
   */
  class OuterSolver
  {
  public:
    virtual ~OuterSolver() = default;

    /// Run from the multipliers given in @p multipliers (sized by
    /// MultiplierSpace::initialize(): zero, or a warm start); on return
    /// they and @p solutions hold the last iterate.
    virtual SolverResult
    solve(const Subproblems           &subproblems,
          const Interface             &interface,
          dealii::BlockVector<double> &multipliers,
          Solutions                   &solutions) const = 0;

  protected:
    OuterSolver(const SolverParameters           &parameters,
                const OutputParameters           &output,
                const dealii::ConditionalOStream &pcout)
      : parameters(parameters)
      , output(output)
      , pcout(pcout)
    {}

    const SolverParameters            parameters;
    const OutputParameters            output;
    const dealii::ConditionalOStream &pcout;
  };

  /// The outer solver that Solver/Method selects. It prints its progress to
  /// @p pcout, which has to outlive it.
  std::unique_ptr<OuterSolver>
  create_outer_solver(const SolverParameters           &parameters,
                      const OutputParameters           &output,
                      const dealii::ConditionalOStream &pcout);

  /// Largest eigenvalue of the dual operator and the work spent on it.
  struct SpectrumEstimate
  {
    double        lambda_max       = 0;
    unsigned int  iterations       = 0;
    unsigned long subdomain_solves = 0;
  };

  /**
   * lambda_max of S = D^{-1} C A^{-1} C^T (multipliers -> jumps of the
   * homogeneous problem; symmetric positive semidefinite in the D inner
   * product) by the power iteration with Rayleigh quotients in the D inner
   * product, restricted to the components that carry multipliers. Each
   * iteration is one homogeneous solve per subproblem; it stops when the
   * estimate changes by less than 1e-4 relative or after
   * @p max_iterations. The Rayleigh quotient approaches lambda_max from
   * below. With @p mask (1 or 0 per component) the operator is restricted
   * further, e.g. to the components that the projection does not hold at a
   * bound at a solution.
   */
  SpectrumEstimate
  estimate_lambda_max(const Subproblems                 &subproblems,
                      const Interface                   &interface,
                      const unsigned int                 max_iterations,
                      const dealii::BlockVector<double> *mask = nullptr);

  /// Extreme eigenvalues of the dual operator and the work spent on them.
  struct DualSpectrum
  {
    double lambda_min = 0, lambda_max = 0;
    /// The shortest segment of the multiplier meshes [m].
    double h = 0;
    /// Lanczos steps (conjugate-gradient iterations).
    unsigned int  iterations       = 0;
    unsigned long subdomain_solves = 0;

    double
    condition_number() const
    {
      return lambda_min > 0 ? lambda_max / lambda_min :
                              std::numeric_limits<double>::infinity();
    }
  };

  /**
   * lambda_min and lambda_max of S = D^{-1} C A^{-1} C^T on the components
   * that carry multipliers, from the Lanczos process of the conjugate-
   * gradient method (deal.II's SolverCG and its eigenvalue estimates) on the
   * symmetric form D^{-1/2} C A^{-1} C^T D^{-1/2} with a fixed pseudo-random
   * right-hand side, run to a relative residual of 1e-10 or
   * @p max_iterations steps. Each step is one homogeneous solve per
   * subproblem. The multipliers are unique exactly when lambda_min > 0;
   * for a uniformly inf-sup stable choice of multipliers lambda_min / h is
   * bounded below under refinement (lambda_min >= beta^2 min |mu|^2_{-1/2} /
   * |mu|^2_{L2} and |mu|_{-1/2} >= c h^{1/2} |mu|_{L2} by the inverse
   * inequality), and lambda_max is bounded.
   */
  DualSpectrum
  estimate_dual_spectrum(const Subproblems &subproblems,
                         const Interface   &interface,
                         const unsigned int max_iterations);
} // namespace bilayer

#endif
