#ifndef bilayer_interface_diagnostics_h
#define bilayer_interface_diagnostics_h

#include <deal.II/lac/block_vector.h>

#include <bilayer/trace_coupling.h>

#include <algorithm>
#include <ostream>
#include <vector>

namespace bilayer
{
  class Interface;

  /**
   * The relative residual of the KKT conditions of the discrete dual
   * problem at multipliers mu with jumps g (stationarity of the primal
   * variables holds exactly: the subproblems are solved directly). All
   * three parts are scale invariant:
   *  - primal: largest violation of the discrete constraints (|g| where a
   *    jump must vanish, max(g, 0) = penetration at crack nodes) divided by
   *    the displacement scale;
   *  - dual: largest max(-mu_c, 0) divided by max |mu|;
   *  - complementarity: largest |mu_c g| at crack nodes divided by
   *    max |mu| times the displacement scale.
   * A multiplier held at a bound by a jump pushing it outward (at +-p, or
   * mu_c = 0 with an open gap) is optimal for the bounded problem of
   * paper.md §3, so its jump counts as no violation and no
   * complementarity: the residual measures the solution of the problem
   * with the bound p. Whether p is active is checked separately (the
   * constraints are then violated, estimate (12)).
   */
  struct KKTResidual
  {
    double primal = 0, dual = 0, complementarity = 0;

    double
    value() const
    {
      return std::max(primal, std::max(dual, complementarity));
    }
  };

  /**
   * Residuals of a computed solution (paper.md §3 and the KKT conditions of
   * the discrete problem).
   */
  struct InterfaceReport
  {
    /// The integral (12) of paper.md, Gauss quadrature on Sigma [length^2].
    double constraint_violation = 0;
    /// (12) divided by the integral of |u-|_1 + |u+|_1 + |v-|_1 + |v+|_1.
    double relative_constraint_violation = 0;
    /// Largest (u- - u+).nu on gamma_c at the Gauss points and nodes [length].
    double max_penetration = 0;
    /// Largest |trace| of the four subproblems on Sigma [length].
    double displacement_scale = 0;
    /// Largest violation of the discrete constraints (jumps that must vanish,
    /// positive penetration at crack nodes) divided by displacement_scale.
    double relative_discrete_violation = 0;
    /// Smallest contact multiplier mu_c (0 without crack nodes) [stress].
    double min_contact_multiplier = 0;
    /// sum m mu_c |jump| / (sum m mu_c * displacement_scale) [-].
    double complementarity = 0;
    /// Largest |multiplier| / p [-].
    double max_multiplier_over_bound = 0;
    /// The relative KKT residual [-].
    KKTResidual kkt;
  };

  /// A segment [a, b] of the mesh of mu_1 on the crack with the value
  /// int_a^b mu_c [u].nu ds.
  struct ContactSegment
  {
    double a, b, complementarity;
  };

  /// Largest |trace value| at the nodes of mu_1 of the present subproblems.
  double
  displacement_scale(const Interface &interface, const Solutions &w);

  /// The relative KKT residual of multipliers @p mu with solutions @p w and
  /// their jumps @p g.
  KKTResidual
  kkt_residual(const Interface                   &interface,
               const Solutions                   &w,
               const dealii::BlockVector<double> &g,
               const dealii::BlockVector<double> &mu);

  /// The normal opening [u].nu = (u+ - u-).nu of layer 1 at every node of
  /// mu_1.
  std::vector<double>
  normal_opening(const Interface &interface, const Solutions &w);

  /// Every residual of InterfaceReport.
  InterfaceReport
  assess(const Interface                   &interface,
         const Solutions                   &w,
         const dealii::BlockVector<double> &mu);

  /**
   * The complementarity density of the contact pair per segment of the
   * mu_1 mesh that touches the crack, int mu_c [u].nu over the segment by
   * Gauss-Lobatto quadrature of the product of the two nodal
   * interpolants (exact for their product). The discrete constraints hold
   * at the nodes, so mu_c [u].nu vanishes at every node; between nodes it
   * does not where the contact zone ends inside a segment (mu_c > 0 at one
   * end, an open gap at the other): the term marks the end of the contact
   * zone for refinement.
   */
  std::vector<ContactSegment>
  contact_residual(const Interface                   &interface,
                   const Solutions                   &w,
                   const dealii::BlockVector<double> &mu);

  /// One row per node of mu_1: x, jumps, gaps, multipliers, traces.
  void
  write_interface_csv(std::ostream                      &out,
                      const Interface                   &interface,
                      const Solutions                   &w,
                      const dealii::BlockVector<double> &mu);
} // namespace bilayer

#endif
