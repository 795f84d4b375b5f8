#ifndef bilayer_goal_estimate_h
#define bilayer_goal_estimate_h

#include <deal.II/base/function.h>
#include <deal.II/lac/block_vector.h>
#include <deal.II/lac/vector.h>

#include <bilayer/interface/interface.h>
#include <bilayer/postprocess/fracture.h>
#include <bilayer/solvers/floating_parts.h>
#include <bilayer/solvers/subdomain_solves.h>

#include <string>
#include <vector>

namespace bilayer
{
  /// The boundary loads of the subproblems, as the estimates read them:
  /// the clamped sides (Geometry) and the tractions of each subproblem's
  /// layer by side (at load factor 1; times the subproblem's load factor).
  struct BoundaryLoads
  {
    std::vector<bool>                                       clamped;
    PerSubproblem<std::vector<const dealii::Function<2> *>> traction;
  };

  /// What the goal-oriented refinement refines for (Mesh/Refinement goal).
  enum class RefinementGoal
  {
    /// The energy Pi.
    energy,
    /// G at every tip (each relative to its own G).
    all_tips,
    /// G at one tip (Mesh/Goal tip).
    one_tip
  };

  /**
   * The dual-weighted residual estimates of one state (docs/fracture.md
   * §11): of G at each tip and of the energy.
   */
  struct GoalEstimates
  {
    /// Signed estimate of G - G_h at each tip (NaN where none: see note).
    std::vector<double> G;
    /// sum_K |eta_K| of each tip (the estimate without cancellation).
    std::vector<double> G_absolute;
    /// The work of the loads on the dual solution of each tip, (F, z):
    /// equal to J'(w)[w] = 2 G where G is the quadratic domain integral
    /// alone (tractions only, zero prescribed displacement, a straight
    /// frictionless crack): the check of the dual load and solve.
    std::vector<double> dual_work;
    /// Signed estimate of Pi - Pi_h, and sum_K |eta_K| of it.
    double energy          = 0;
    double energy_absolute = 0;
    /// Cell indicators by region (active_cell_index()) for the goal asked
    /// for: |eta_K| summed over the layers of the region.
    std::vector<dealii::Vector<double>> indicators;
    /// The energy's indicators by region (those of a goal at tips on a
    /// state without a finite G).
    std::vector<dealii::Vector<double>> energy_indicators;
    /// By subproblem (active_cell_index()): the magnitudes of the cell
    /// terms of the energy's estimate, 1/2 |eta_K|, and of G's, |eta_K|
    /// summed over the tips with an estimate (empty where none) [energy,
    /// stress x length]: the fields dwr_energy and dwr_G of the VTU.
    PerSubproblem<dealii::Vector<double>> energy_terms, G_terms;
    /// Conjugate-gradient iterations and subdomain solves of the dual
    /// problems, and the wall time of all of it [s].
    unsigned int  dual_iterations  = 0;
    unsigned long subdomain_solves = 0;
    double        seconds          = 0;
    /// Why there is no estimate of G (empty where there is).
    std::string note;
  };

  /**
   * Dual-weighted residual estimates of the state (@p w, @p mu):
   *  - G at each defined tip of @p release: the dual problem is the
   *    problem linearised at the state with its active set held
   *    (solve_with_held_set()), the load its derivative of the domain
   *    integral of G, J'(w)[phi] (the interaction integral of w with phi,
   *    with the volume terms of the loads); the estimate is the residual
   *    of the state weighted by z~ - I z~, z~ the patchwise reconstruction
   *    of degree p + 1 of the dual solution z (a least-squares fit over the
   *    cell and its face neighbours, enriched on the cells at a tip by the
   *    tip's r^(1/2) functions), I the interpolation of the element;
   *  - the energy: -1/2 the residual weighted by the reconstruction of
   *    the state itself (no dual problem).
   * The residual: the cell residual f + div sigma(w), half the traction
   * jump on interior faces, g - sigma n on loaded sides, t - sigma n on
   * the interfaces (t the multipliers' traction). Not computed (note says
   * why): in a run with MPI, and for tips whose G carries contact or
   * friction face terms the dual load leaves out (the G estimate is still
   * computed: the note names the missing terms). With @p floating, the
   * dual problems balance its floating subproblems' anchors
   * (FloatingParts::solve_with_held_set()).
   */
  GoalEstimates
  goal_oriented_estimates(const Subproblems                    &subproblems,
                          const Interface                      &interface,
                          const Solutions                      &w,
                          const dealii::BlockVector<double>    &mu,
                          const std::vector<EnergyReleaseRate> &release,
                          const BoundaryLoads                  &loads,
                          const RefinementGoal                  goal,
                          const unsigned int                    goal_tip,
                          const FloatingParts *floating = nullptr);

  namespace goal
  {
    /// A crack tip as the reconstruction sees it: its point and the unit
    /// direction of growth (the crack lies behind it).
    struct TipFrame
    {
      dealii::Point<2>     point;
      dealii::Tensor<1, 2> direction;
    };

    /// Cells whose centre lies within this many of their diameters of a
    /// tip fit the near-tip functions r^(1/2) of the tip beside the
    /// polynomials (the weights of the cells at a tip see the singular
    /// part of the dual solution).
    constexpr double enrichment_radius = 0.8;

    /**
     * The residual of the state @p w of @p sub weighted by z~ - I z~ for
     * each field z of @p fields (its reconstruction of degree p + 1 on the
     * patch of each cell, with the near-tip functions of @p tips on the
     * cells at a tip): the cell contributions eta_K, by field, by
     * active_cell_index().
     */
    std::vector<dealii::Vector<double>>
    weighted_residuals(
      const ElasticSubproblem                           &sub,
      const unsigned int                                 s,
      const Interface                                   &interface,
      const dealii::Vector<double>                      &w,
      const dealii::BlockVector<double>                 &mu,
      const std::vector<bool>                           &clamped,
      const std::vector<const dealii::Function<2> *>    &traction,
      const std::vector<const dealii::Vector<double> *> &fields,
      const std::vector<TipFrame>                       &tips);
  } // namespace goal
} // namespace bilayer

#endif
