#ifndef bilayer_coulomb_fixed_point_h
#define bilayer_coulomb_fixed_point_h

#include <deal.II/base/conditional_ostream.h>
#include <deal.II/lac/block_vector.h>

#include <bilayer/interface/interface.h>
#include <bilayer/parameters/parameters.h>
#include <bilayer/solvers/outer_solver.h>
#include <bilayer/solvers/subdomain_solves.h>

/**
 * @file
 * Coulomb friction as a fixed point over Tresca problems
 * (Contact/Coulomb method = fixed point; docs/problem.md §3): a solver that
 * wraps the outer solver of Solver/Method and owns the friction bounds of
 * the admissible set, which it sets on the interface before each Tresca
 * solve.
 */
namespace bilayer
{
  /// How the fixed point ended: its iterations and the last relative
  /// change of the bounds.
  struct FixedPointRecord
  {
    unsigned int iterations   = 0;
    double       bound_change = 0;
  };


  class CoulombFixedPoint
  {
  public:
    /// The fixed point of the friction coefficient and iteration limit of
    /// @p contact over the outer solver of @p parameters; progress to
    /// @p pcout, which has to outlive it.
    CoulombFixedPoint(const SolverParameters           &parameters,
                      const ContactParameters          &contact,
                      const OutputParameters           &output,
                      const dealii::ConditionalOStream &pcout);

    /**
     * The bound of each crack node is F mu_c of the last solve (of the
     * start multipliers first: zero, or a warm start), until the bounds
     * change by at most max(Solver/Tolerance, 1e-12) relative to the
     * largest one, or stop contracting within 100 times that (the accuracy
     * of the Tresca solves). The work of all Tresca solves is summed into
     * the result; @p record gets the iterations and the last change. On
     * return @p interface holds the last bounds.
     */
    SolverResult
    solve(const Subproblems           &subproblems,
          Interface                   &interface,
          dealii::BlockVector<double> &multipliers,
          Solutions                   &solutions,
          FixedPointRecord            &record) const;

  private:
    const SolverParameters             parameters;
    const double                       coefficient;
    const unsigned int                 max_iterations;
    const dealii::ConditionalOStream  &pcout;
    const std::unique_ptr<OuterSolver> tresca;
  };
} // namespace bilayer

#endif
