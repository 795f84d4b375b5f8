#ifndef bilayer_subdomain_solves_h
#define bilayer_subdomain_solves_h

#include <deal.II/lac/block_vector.h>

#include <bilayer/interface.h>
#include <bilayer/layout.h>
#include <bilayer/subproblem.h>

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

  /**
   * The subdomain solves that every outer solver repeats: the multiplier
   * terms of the interface as loads, then the independent solves of the
   * subproblems (run as parallel tasks; the factorisations are reused).
   */
  void
  solve_subproblems(const Subproblems                 &subproblems,
                    const Interface                   &interface,
                    const dealii::BlockVector<double> &multipliers,
                    Solutions                         &solutions);

  /// The solves with the multiplier loads of @p multipliers only (no
  /// tractions, zero prescribed displacement): the linear part of the map
  /// from multipliers to solutions.
  void
  solve_homogeneous_subproblems(const Subproblems                 &subproblems,
                                const Interface                   &interface,
                                const dealii::BlockVector<double> &multipliers,
                                Solutions                         &solutions);
} // namespace bilayer

#endif
