#ifndef bilayer_interface_diagnostics_h
#define bilayer_interface_diagnostics_h

#include <deal.II/base/point.h>
#include <deal.II/base/tensor.h>
#include <deal.II/lac/block_vector.h>

#include <bilayer/interface/interface.h>
#include <bilayer/interface/trace_coupling.h>

#include <algorithm>
#include <cmath>
#include <ostream>
#include <vector>

namespace bilayer
{

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
   * docs/problem.md §3, so its jump counts as no violation and no
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
   * Residuals of a computed solution (docs/problem.md §3 and the KKT conditions
   * of the discrete problem).
   */
  struct InterfaceReport
  {
    /// The integral (12) of docs/problem.md, Gauss quadrature on Sigma
    /// [length^2].
    double constraint_violation = 0;
    /// (12) divided by the integral of |u-|_1 + |u+|_1 + |v-|_1 + |v+|_1.
    double relative_constraint_violation = 0;
    /// Largest (u- - u+).nu on gamma_c at the Gauss points and nodes [length].
    double max_penetration = 0;
    /// Largest |trace| of the subproblems on Sigma [length].
    double displacement_scale = 0;
    /// Largest violation of the discrete constraints (jumps that must vanish,
    /// positive penetration at crack nodes) divided by displacement_scale.
    double relative_discrete_violation = 0;
    /// Largest |nodal jump| at the glued nodes that carry no multiplier
    /// (ends of Sigma on Gamma_D), where the Dirichlet data of both sides
    /// must close the jump, divided by displacement_scale [-].
    double relative_jump_without_multiplier = 0;
    /// Smallest contact multiplier mu_c (0 without crack nodes) [stress].
    double min_contact_multiplier = 0;
    /// sum m mu_c |jump| / (sum m mu_c * displacement_scale) [-].
    double complementarity = 0;
    /// Largest |multiplier| / p [-].
    double max_multiplier_over_bound = 0;
    /**
     * Friction on the crack faces (0 without): the complementarity of the
     * friction law, sum D (g |jump_t| - mu_t jump_t) / (sum D g *
     * displacement_scale) over the friction components (>= 0, 0 exactly
     * where the faces slip against the force and stick elsewhere) [-].
     */
    double friction_complementarity = 0;
    /// The frictional dissipation int s_tau [u].tau ds = sum D mu_t jump_t
    /// (>= 0) [energy per unit thickness].
    double friction_dissipation = 0;
    /// Largest |[u].tau| at the crack nodes with friction [length].
    double max_slip = 0;
    /// Crack nodes with friction that stick (|mu_t| < g) and slip
    /// (|mu_t| = g).
    unsigned int stick_nodes = 0, slip_nodes = 0;
    /// The relative KKT residual [-].
    KKTResidual kkt;
  };

  /// A segment [a, b] of the mesh of mu_1 on the crack with the value
  /// int_a^b mu_c [u].nu ds.
  struct ContactSegment
  {
    double a, b, complementarity;
  };

  /// Largest |trace value| of the present subproblems at the nodes of the
  /// blocks across the interfaces.
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
  /// the block across interface @p i (Sigma: mu_1).
  std::vector<double>
  normal_opening(const Interface   &interface,
                 const Solutions   &w,
                 const unsigned int i = 0);

  /// The subproblems whose traces the nodes of interface @p i report
  /// (InterfaceNode::trace): every subproblem of a two-region scene (u-,
  /// u+, v-, v+, ...), else layer 1 below and above the interface.
  std::vector<unsigned int>
  trace_subproblems(const Topology &topology, const unsigned int i);

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
                   const dealii::BlockVector<double> &mu,
                   const unsigned int                 i = 0);

  /// The state of Sigma at a node of the mesh of mu_1.
  enum class ContactState
  {
    /// A crack node with an open gap.
    open = 0,
    /// A crack node in contact: mu_c > 0, or the normal jump within the
    /// tolerance (relative to the displacement scale) of zero.
    closed = 1,
    /// A node of the glued part (the crack tips included).
    glued = 2
  };

  /// The tangential state of a node of the mesh of mu_1 under friction.
  enum class FrictionState
  {
    /// A crack node without a friction bound (frictionless there).
    free = 0,
    /// A crack node whose tangential force is below its bound: [u].tau = 0.
    stick = 1,
    /// A crack node whose tangential force is at its bound.
    slip = 2,
    /// A node of the glued part.
    glued = 3
  };

  /// The state of a crack node whose tangential multiplier is @p mu_t and
  /// friction bound @p bound: free without a bound, slip at it, else stick.
  inline FrictionState
  friction_state(const double bound, const double mu_t)
  {
    return bound == 0              ? FrictionState::free :
           std::abs(mu_t) >= bound ? FrictionState::slip :
                                     FrictionState::stick;
  }

  /**
   * What is reported at one node of the mesh of mu_1 (the multiplier
   * across Sigma). Vectors are in the node's frame: component 0 along the
   * tangent tangent_of(normal), component 1 along the normal nu (x and y on
   * the rectangle).
   */
  struct InterfaceNode
  {
    /// Parameter s on Sigma, the point and the node's normal nu.
    double               s;
    dealii::Point<2>     point;
    dealii::Tensor<1, 2> normal;
    bool                 on_crack;
    /// A node of the glued part next to a crack node.
    bool         crack_tip;
    ContactState state;
    /// [u].nu and [u].tau of layer 1, u+ - u- [length].
    double jump_normal, jump_tangential;
    /// The contact multiplier (0 off the crack) and the gluing multiplier
    /// across Sigma (0 on the crack) [stress].
    double               mu_c;
    dealii::Tensor<1, 2> mu_g;
    /// The multipliers between the layers on each side at the node.
    dealii::Tensor<1, 2> mu_minus, mu_plus;
    /// The gaps u - v between layers 1 and 2 on each side [length].
    std::array<dealii::Tensor<1, 2>, 2> layer_gap;
    /// Traces of trace_subproblems() (u-, u+, v-, v+, ...) [length].
    std::vector<dealii::Tensor<1, 2>> trace;
    /**
     * The normal traction transmitted across Sigma, compression positive
     * [stress]: mu_c on the crack, the normal component of the gluing
     * multiplier on the glued part.
     */
    double normal_traction;
    /**
     * The pressure between the crack faces [stress]: mu_c on the crack; at
     * a crack tip, where the constraint is the gluing one and mu_c is not
     * defined, the compressive part max(normal_traction, 0) (the pressure
     * the faces transmit as they meet at the tip, not a drop to zero); 0 on
     * the rest of the glued part.
     */
    double contact_pressure;
    /// Whether the scene has friction on the crack faces (the CSV then has
    /// the three columns below).
    bool frictional = false;
    /// The tangential force s_tau = -mu_t that Omega+ exerts on Omega- at a
    /// crack node with friction (0 elsewhere) [stress], its bound g and the
    /// tangential state.
    double        tangential_force = 0, friction_bound = 0;
    FrictionState friction_state = FrictionState::glued;
    /// Whether the interface carries a cohesive zone (the CSV then has the
    /// column below, the VTU the field damage).
    bool cohesive = false;
    /// The damage of the cohesive law at a node of the zone (1: a crack
    /// face; -1 off the zone).
    double damage = -1;
  };

  /**
   * Every node of the mesh of the block across interface @p i (Sigma:
   * mu_1), in the order of its numbering; a crack node is closed when
   * mu_c > 0 or its normal jump is at most @p closed_tolerance times the
   * displacement scale.
   */
  std::vector<InterfaceNode>
  interface_nodes(const Interface                   &interface,
                  const Solutions                   &w,
                  const dealii::BlockVector<double> &mu,
                  const double                       closed_tolerance = 1e-6,
                  const unsigned int                 i                = 0);

  /**
   * One row per node of mu_1: x, jumps, multipliers, gaps, traces (frame
   * components), s, y, the normal, the contact pressure, the normal traction
   * and the state (0 open, 1 closed, 2 glued) of interface_nodes(); with
   * friction also the tangential force, its bound and the friction state
   * (0 free, 1 stick, 2 slip, 3 glued). Each
   * of @p notes goes before the header as a line starting with "# ". The
   * traces' columns are named by @p trace_names (Topology::field_name() of
   * trace_subproblems()).
   */
  void
  write_interface_csv(std::ostream                     &out,
                      const std::vector<InterfaceNode> &nodes,
                      const std::vector<std::string>   &trace_names,
                      const std::vector<std::string>   &notes = {});
} // namespace bilayer

#endif
