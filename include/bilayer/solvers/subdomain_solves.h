#ifndef bilayer_subdomain_solves_h
#define bilayer_subdomain_solves_h

#include <deal.II/lac/block_vector.h>

#include <bilayer/core/layout.h>
#include <bilayer/interface/interface.h>
#include <bilayer/subproblem/subproblem.h>

#include <functional>

/**
 * @file
 * The subdomain solves that every outer solver repeats, and the exchange of
 * their results between the processes of an MPI job.
 */
namespace bilayer
{
  /// The subproblems, indexed by Layout::index() (nullptr where a layer is
  /// absent). Solving reads them only: the factorisations are made by
  /// ElasticSubproblem::setup().
  using Subproblems = PerSubproblem<const ElasticSubproblem *>;

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
  PerSubproblem<double>
  share_values(const Subproblems                         &subproblems,
               const std::function<double(unsigned int)> &value);

  /// What a solve computes.
  enum class SolveExtent
  {
    /// The whole solutions.
    whole,
    /// Only their values on the dofs of the Sigma faces, which is all that
    /// the interface reads, where a subproblem is
    /// ElasticSubproblem::condensed() (two dense triangular solves); the
    /// whole solutions elsewhere.
    sigma
  };

  /**
   * The subdomain solves that every outer solver repeats: the multiplier
   * terms of the interface as loads, then the independent solves of the
   * subproblems (run as parallel tasks; the factorisations are reused).
   */
  void
  solve_subproblems(const Subproblems                 &subproblems,
                    const Interface                   &interface,
                    const dealii::BlockVector<double> &multipliers,
                    Solutions                         &solutions,
                    const SolveExtent extent = SolveExtent::whole);

  /// The solves with the multiplier loads of @p multipliers only (no
  /// tractions, zero prescribed displacement): the linear part of the map
  /// from multipliers to solutions, on Sigma only where a subproblem is
  /// condensed (SolveExtent::sigma): every user reads the traces only.
  void
  solve_homogeneous_subproblems(const Subproblems                 &subproblems,
                                const Interface                   &interface,
                                const dealii::BlockVector<double> &multipliers,
                                Solutions                         &solutions);

  /// solve_homogeneous_subproblems() for each of @p multipliers: the
  /// condensed subproblems solve all of them at once (blocked dense
  /// triangular solves), the others one by one.
  void
  solve_homogeneous_subproblems(
    const Subproblems                              &subproblems,
    const Interface                                &interface,
    const std::vector<dealii::BlockVector<double>> &multipliers,
    std::vector<Solutions>                         &solutions);
} // namespace bilayer

#endif
