#ifndef bilayer_floating_parts_h
#define bilayer_floating_parts_h

#include <deal.II/base/conditional_ostream.h>
#include <deal.II/lac/block_vector.h>

#include <bilayer/solvers/dual_solve.h>
#include <bilayer/solvers/feti_preconditioner.h>
#include <bilayer/solvers/outer_solver.h>

#include <array>
#include <functional>
#include <memory>
#include <string>
#include <utility>
#include <vector>

/**
 * @file
 * Subproblems without a clamped side of their own (docs/floating.md): a
 * film held through its substrate, a part pulled through a neighbour, a free
 * specimen under self-balanced loads.
 *
 * A floating subproblem is solved with three anchor dofs held
 * (ElasticSubproblem::floating()); the anchors' displacements alpha are
 * unknowns of the coupled problem and their reactions r(alpha) (the
 * subproblem's out-of-balance force and moment) its equations: the coupled
 * solution is the one whose anchors carry no force. For a fixed alpha the
 * outer solvers (Uzawa, FISTA, active set, Coulomb fixed point) solve an
 * ordinary problem with every subproblem non-singular; r is affine in alpha
 * while the active set holds (piecewise affine and the gradient of a convex
 * function of alpha in all), so FloatingParts::balance() runs Newton's
 * method on r(alpha) = 0 around the outer solver, its Jacobian J = dr /
 * dalpha the coarse (rigid-motion) problem of FETI methods, G^T F^{-1} G
 * with the active set held: one linear solve with the held set
 * (solve_with_held_set()) per anchor, whose multiplier responses also
 * predict the multipliers of the next outer solve. A singular J means a
 * rigid motion that nothing holds, refused by name.
 *
 * A free specimen (nothing clamped) keeps the anchors of one subproblem at
 * zero, accepts loads whose resultant force and moment vanish to
 * free_specimen_tolerance, and is normalised at the end to zero mean
 * translation and rotation (the rigid motion nearest in L2 removed).
 */
namespace bilayer
{
  /// Loads of a free specimen are accepted when their resultant force and
  /// moment (the moment divided by the diameter) are at most this times the
  /// sum of the magnitudes of the nodal loads.
  constexpr double free_specimen_tolerance = 1e-8;

  /// The anchors of the floating subproblems are balanced when their
  /// largest reaction is at most this times the outer solver's tolerance
  /// times the load scale (the sum of the magnitudes of the nodal loads on
  /// the floating subproblems), and at least 1e-12 of it: finer than the
  /// multipliers the outer solver delivers is noise.
  constexpr double floating_balance_target = 1e-2;

  /// What balance() did.
  struct FloatingReport
  {
    /// The floating subproblems (names), and whether nothing is clamped.
    std::vector<std::string> subproblems;
    bool                     free_specimen = false;
    /// Outer solves and held-set linear solves (the Jacobian's columns).
    unsigned int  outer_solves = 0, jacobian_solves = 0;
    unsigned long subdomain_solves = 0;
    /// Wall time of the coarse matrices (the held-set solves) [s].
    double coarse_seconds = 0;
    /// The largest anchor reaction at the end over the load scale.
    double out_of_balance = 0;
    /// The free specimen's resultant force (x, y) and moment about the
    /// centre of the bounding box, and the sum of the magnitudes of the nodal
    /// loads.
    std::array<double, 3> resultant      = {{0, 0, 0}};
    double                load_magnitude = 0;
    /// The rigid motion removed by the normalisation (translation x, y and
    /// rotation about the centroid).
    std::array<double, 3> normalisation = {{0, 0, 0}};
  };

  class FloatingParts
  {
  public:
    /// The floating subproblems of @p subproblems (serial: owned, none
    /// shared).
    FloatingParts(const PerSubproblem<ElasticSubproblem *> &subproblems,
                  const Interface                          &interface);

    /// Whether any subproblem floats.
    bool
    any() const
    {
      return !floating.empty();
    }

    /// Whether nothing is clamped (every subproblem floats).
    bool
    free_specimen() const
    {
      return free;
    }

    /// The names of the floating subproblems.
    std::vector<std::string>
    names() const;

    /**
     * With free_specimen(): the resultant force and moment (about the
     * centre of the bounding box of the floating subproblems) of their loads at
     * their present load factors (the work of the load on the rigid motions
     * made of the anchor modes), and the sum of the magnitudes of the nodal
     * loads; refused in one line where the resultant exceeds
     * free_specimen_tolerance.
     */
    void
    check_free_loads(FloatingReport &report) const;

    /**
     * Solve the coupled problem: @p outer (an outer solver run from the
     * multipliers and solutions given) repeated with the anchors moved by
     * Newton steps until they carry no force (floating_balance_target times
     * @p solver_tolerance), or
     * until a step gains less than half (the outer solver's own accuracy).
     * Progress lines to @p pcout. Returns the last outer result, with the
     * counts of all solves and the balance in its message where it is not
     * reached.
     */
    SolverResult
    balance(const std::function<SolverResult(dealii::BlockVector<double> &,
                                             Solutions &)> &outer,
            const double                                    solver_tolerance,
            const double                      acceptance_tolerance,
            dealii::BlockVector<double>      &mu,
            Solutions                        &w,
            FloatingReport                   &report,
            const dealii::ConditionalOStream &pcout) const;

    /**
     * solve_with_held_set() with the floating subproblems balanced: the
     * linear problem K z + B^T nu = j, (B z)_I = 0, nu_A = 0 whose anchors
     * carry no force (exact: one more held-set solve per anchor).
     */
    HeldSetSolution
    solve_with_held_set(const Solutions                   &w,
                        const dealii::BlockVector<double> &mu,
                        const Solutions                   &j,
                        const double                       tolerance,
                        const unsigned int max_iterations) const;

    /// With free_specimen(): remove from @p w the rigid motion nearest to
    /// it in L2 over all subproblems (zero mean translation and rotation),
    /// moving the anchors along; the rigid motion goes to @p report.
    void
    normalise(Solutions &w, FloatingReport &report) const;

  private:
    const PerSubproblem<ElasticSubproblem *> targets;
    const Subproblems                        subproblems;
    const Interface                         &interface;
    /// The floating subproblems, and the anchors whose displacements are
    /// unknowns: (subproblem, anchor) of all, less the first subproblem's
    /// in a free specimen.
    std::vector<unsigned int>                          floating;
    std::vector<std::pair<unsigned int, unsigned int>> unknowns;
    bool                                               free = false;
    /// The Dirichlet preconditioner of the coarse matrices' solves (built
    /// at the first).
    mutable std::unique_ptr<FetiPreconditioner> preconditioner;

    /// The reactions at the unknown anchors of the anchored solutions with
    /// the anchors at @p alpha (by subproblem) under the loads @p b (one
    /// per subproblem; @p sigma_only: nonzero on the Sigma dofs alone), and
    /// their scale (the sum of |b| over the floating subproblems).
    std::vector<double>
    reactions(const std::function<std::array<double, 3>(unsigned int)> &alpha,
              const Solutions                                          &b,
              const bool sigma_only,
              double    &scale) const;

    /// The loads of the state: the subproblems' loads plus the multiplier
    /// terms of @p mu.
    Solutions
    state_loads(const dealii::BlockVector<double> &mu) const;

    /// The Jacobian: for each unknown anchor, the held-set response (z,
    /// nu) to its unit displacement, and the reactions it causes.
    struct Jacobian
    {
      std::vector<std::vector<double>>         columns;
      std::vector<dealii::BlockVector<double>> nu;
      std::vector<Solutions>                   z;
      unsigned long                            subdomain_solves = 0;
    };
    Jacobian
    jacobian(const Solutions                   &w,
             const dealii::BlockVector<double> &mu,
             const bool                         keep_z) const;

    /// The Newton step -J^{-1} r; refused naming the subproblem whose rigid
    /// motion J leaves free.
    std::vector<double>
    newton_step(const Jacobian &J, const std::vector<double> &r) const;

    /// The multipliers after the anchors' Newton @p step, as the coarse
    /// matrix's responses predict them (projected on their bounds).
    void
    predict_multipliers(const Jacobian              &J,
                        const std::vector<double>   &step,
                        dealii::BlockVector<double> &mu) const;

    /// Move the unknown anchors by @p step.
    void
    move_anchors(const std::vector<double> &step) const;
  };
} // namespace bilayer

#endif
