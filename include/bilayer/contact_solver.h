#ifndef bilayer_contact_solver_h
#define bilayer_contact_solver_h

#include <deal.II/base/conditional_ostream.h>
#include <deal.II/lac/block_vector.h>

#include <bilayer/interface.h>
#include <bilayer/layout.h>
#include <bilayer/parameters.h>
#include <bilayer/subproblem.h>

#include <array>
#include <functional>
#include <string>

namespace bilayer
{
  using namespace dealii;

  /// The subproblems, indexed by Layout::index() (nullptr where a layer is
  /// absent). Solving reads them only: the factorisations are made by
  /// ElasticSubproblem::setup().
  using Subproblems = PerSubproblem<const ElasticSubproblem *>;

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
  };

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
   * iteration is four homogeneous subdomain solves; it stops when the
   * estimate changes by less than 1e-4 relative or after @p max_iterations.
   * The Rayleigh quotient approaches lambda_max from below. With @p mask
   * (1 or 0 per component) the operator is restricted further, e.g. to the
   * components that the projection does not hold at a bound at a solution.
   */
  SpectrumEstimate
  estimate_lambda_max(const Subproblems         &subproblems,
                      const Interface           &interface,
                      const unsigned int         max_iterations,
                      const BlockVector<double> *mask = nullptr);

  /**
   * Send the traces of the solutions from their owners to all processes
   * (ElasticSubproblem::share_trace(); nothing to do in a serial run).
   */
  void
  share_traces(const Subproblems &subproblems, Solutions &solutions);

  /**
   * value(s) evaluated by the owner of each present subproblem s, known to
   * every process afterwards (zero for absent subproblems): for quantities
   * of whole solutions, such as energies, that only the owner holds.
   */
  std::array<double, 4>
  share_values(const Subproblems                         &subproblems,
               const std::function<double(unsigned int)> &value);

  /**
   * The subdomain solves that every outer solver repeats: the multiplier
   * terms of the interface as loads, then the four independent solves (run
   * as parallel tasks; the factorisations are reused).
   */
  void
  solve_subproblems(const Subproblems         &subproblems,
                    const Interface           &interface,
                    const BlockVector<double> &multipliers,
                    Solutions                 &solutions);

  /// The four solves with the multiplier loads of @p multipliers only (no
  /// tractions, zero prescribed displacement): the linear part of the map
  /// from multipliers to solutions.
  void
  solve_homogeneous_subproblems(const Subproblems         &subproblems,
                                const Interface           &interface,
                                const BlockVector<double> &multipliers,
                                Solutions                 &solutions);

  /**
   * The Uzawa algorithm of paper.md §4:
   *   1. mu^0 given (zero, or a warm start);
   *   2. solve the four subproblems with the multiplier loads of mu^k;
   *   3. mu^{k+1} = P(mu^k + theta g^k), g^k the jumps (Interface::jumps);
   *   4. stop when the stopping rule holds at step k (k >= 1), else repeat.
   * Iterations are counted as the k at which the rule holds, so the work is
   * 4 (k + 1) subdomain solves.
   *
   * The iteration is stopped as divergent when the multipliers or solutions
   * stop being finite, or when the D-norm of the multiplier increment
   * exceeds its smallest value so far by Solver/Divergence growth factor:
   * for theta below the threshold 2 / lambda_max(D^{-1} C A^{-1} C^T) the
   * projected step is non-expansive, so the increments cannot grow.
   */
  class UzawaSolver
  {
  public:
    UzawaSolver(const SolverParameters   &parameters,
                const OutputParameters   &output,
                const ConditionalOStream &pcout);

    /// Run from the multipliers given in @p multipliers (sized by
    /// Interface::initialize()); on return they and @p solutions hold the
    /// last iterate.
    SolverResult
    solve(const Subproblems   &subproblems,
          const Interface     &interface,
          BlockVector<double> &multipliers,
          Solutions           &solutions) const;

  private:
    const SolverParameters    parameters;
    const OutputParameters    output;
    const ConditionalOStream &pcout;
  };
} // namespace bilayer

#endif
