#ifndef bilayer_dual_solve_h
#define bilayer_dual_solve_h

#include <deal.II/lac/block_vector.h>

#include <bilayer/solvers/feti_preconditioner.h>
#include <bilayer/solvers/subdomain_solves.h>

namespace bilayer
{
  /// The solution of a linear problem with the active set held
  /// (solve_with_held_set()) and the work spent on it.
  struct HeldSetSolution
  {
    /// The displacements z of the subproblems.
    Solutions z;
    /// The multipliers nu (zero on the held components).
    dealii::BlockVector<double> nu;
    unsigned int                iterations       = 0;
    unsigned long               subdomain_solves = 0;
    /// Whether the conjugate gradients reached the tolerance.
    bool converged = false;
  };

  /**
   * The linear problem of the state (@p w, @p mu) with its active set held:
   *   K z + B^T nu = j,   (B z)_I = 0,   nu_A = 0,
   * I the multiplier components that the solution does not hold at a bound
   * (MultiplierSet::held() of mu and the jumps of w: the crack in contact,
   * the glued parts, the stick part of friction), A the others (an open
   * crack, sliding). It is the last Newton step of ActiveSetSolver with the
   * load @p j (one vector per subproblem) for the tractions: the
   * factorisations of the subproblems are reused (substitutions only),
   * and conjugate gradients with the lumped FETI preconditioner solve for
   * nu_I until the largest jump on I is @p tolerance times the largest
   * |z0| of the solution without multipliers. The dual problems of the
   * goal-oriented error estimates (docs/fracture.md §11) are of this kind:
   * the operators are symmetric, so the dual of the linearised problem is
   * the problem itself with the derivative of the goal as the load.
   * With @p jump_offset, (B z + jump_offset)_I = 0 instead (the jumps of
   * a prescribed motion, e.g. of a floating subproblem's anchors), and the
   * tolerance is relative to the larger of |z0| and |jump_offset|. With
   * @p preconditioner, that one (built for @p subproblems and
   * @p interface; restricted to I here) instead of the lumped one.
   * Without @p whole_z only nu is computed (z stays empty).
   * Serial subproblems only (each owned by this process, none shared).
   */
  HeldSetSolution
  solve_with_held_set(const Subproblems                 &subproblems,
                      const Interface                   &interface,
                      const Solutions                   &w,
                      const dealii::BlockVector<double> &mu,
                      const Solutions                   &j,
                      const double                       tolerance,
                      const unsigned int                 max_iterations,
                      const dealii::BlockVector<double> *jump_offset = nullptr,
                      FetiPreconditioner *preconditioner             = nullptr,
                      const bool          whole_z                    = true);
} // namespace bilayer

#endif
