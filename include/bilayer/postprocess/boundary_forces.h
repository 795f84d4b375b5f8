#ifndef bilayer_boundary_forces_h
#define bilayer_boundary_forces_h

#include <deal.II/base/function.h>
#include <deal.II/base/tensor.h>
#include <deal.II/lac/block_vector.h>

#include <bilayer/interface/interface.h>
#include <bilayer/subproblem/subproblem.h>

#include <cmath>
#include <limits>
#include <string>
#include <vector>

/**
 * @file
 * The forces on the named parts of the outer boundary and their mean
 * displacements: the reactions of the clamps from the residual of the
 * equilibrium equations, the resultants of the tractions, and the check
 * that they balance (docs/user-guide.md, "Forces and displacements").
 */
namespace bilayer
{
  /// The imbalance of forces a run accepts beyond the round-off bound
  /// ForceBalance::roundoff, relative to the forces.
  constexpr double force_balance_tolerance = 1e-10;

  /// One named part of the outer boundary in one state (per unit
  /// thickness, as all forces of the plane problem).
  struct PartForce
  {
    std::string name;
    /// Whether the part belongs to Gamma_D (its force is the reaction).
    bool clamped = false;
    /// Per layer slot: the force that the support (clamped) or the
    /// traction (not clamped) exerts on the layer through this part
    /// [stress x length]; NaN where not computed.
    std::vector<dealii::Tensor<1, 2>> layer_force;
    /// Per layer slot: the mean displacement of the layer on the part,
    /// int w ds / int ds [length].
    std::vector<dealii::Tensor<1, 2>> layer_mean_displacement;
    /// The length of the part (both regions) [length].
    double length = 0;

    /// The part's share in one region (where it has faces there).
    struct RegionShare
    {
      unsigned int region = 0;
      double       length = 0;
      /// Summed over the layers.
      dealii::Tensor<1, 2> force;
      /// Averaged over the layers.
      dealii::Tensor<1, 2> mean_displacement;
    };
    std::vector<RegionShare> regions;

    /// The sum of layer_force over the layers (NaN where not computed).
    dealii::Tensor<1, 2>
    force() const;

    /// The mean of layer_mean_displacement over the layers (NaN where not
    /// computed).
    dealii::Tensor<1, 2>
    mean_displacement() const;
  };

  /// The forces of a state and their balance.
  struct ForceBalance
  {
    std::vector<PartForce> parts;
    /// The resultant of every applied load (tractions and body forces of
    /// all layers) and of every reaction of the clamps and of the anchors
    /// of floating subproblems (ElasticSubproblem::floating()).
    dealii::Tensor<1, 2> applied, reactions;
    /// The resultant of the anchors' reactions alone (in reactions): the
    /// out-of-balance force left on the floating subproblems.
    dealii::Tensor<1, 2> anchors;
    /// |applied + reactions| [force].
    double residual = std::numeric_limits<double>::quiet_NaN();
    /// The sum of the norms of the forces on the parts, by region and
    /// layer, and of the applied resultant [force].
    double force_scale = 0;
    /// The round-off of the sums: machine epsilon times
    /// sum_i (sum_j |K_ij| |w_j| + |F_i| + |c_i|) over the subproblems
    /// [force].
    double roundoff = std::numeric_limits<double>::quiet_NaN();

    /// Whether the forces were computed (not where a subproblem is shared
    /// by a group of processes).
    bool
    computed() const
    {
      return std::isfinite(residual);
    }

    /// residual / force_scale (residual where force_scale is 0); NaN where
    /// not computed.
    double
    imbalance() const
    {
      return force_scale > 0 ? residual / force_scale : residual;
    }

    /// Whether the forces balance: residual <= roundoff + the tolerance
    /// times force_scale.
    bool
    balanced() const
    {
      return !computed() ||
             residual <= roundoff + force_balance_tolerance * force_scale;
    }
  };

  /**
   * The forces on the boundary parts @p names (boundary ids 0, 1, ...;
   * @p clamped: which form Gamma_D) of the state @p w, @p mu of
   * @p subproblems coupled by @p interface.
   *
   * The reaction on a clamped part is the consistent one, from the
   * residual r = K w - F - B^T mu of each subproblem (K the unconstrained
   * stiffness, F its load vector at the present load factor, B^T mu the
   * multiplier terms): the residuals of hanging nodes moved to their
   * masters, r summed component by component over the clamped dofs of the
   * part (a dof on two clamped parts counts to the first). It is the force
   * of the support on the body: it balances the loads exactly, since
   * every free dof has r = 0 to the direct solves' round-off, K annihilates
   * the translations and the multiplier terms of the interface sum to zero
   * (action and reaction). On a part that is not clamped the force is the
   * resultant of the traction @p traction[layer][part] times the
   * subproblem's load factor, by quadrature on the part's faces.
   *
   * A subproblem shared by a group of processes (more than four) holds no
   * assembled matrix on one process: the forces are then NaN (not
   * computed). Collective: every process gets the result.
   */
  ForceBalance
  boundary_forces(
    const PerSubproblem<const ElasticSubproblem *>              &subproblems,
    const Interface                                             &interface,
    const Solutions                                             &w,
    const dealii::BlockVector<double>                           &mu,
    const std::vector<std::string>                              &names,
    const std::vector<bool>                                     &clamped,
    const std::vector<std::vector<const dealii::Function<2> *>> &traction,
    const unsigned int                                           n_slots);
} // namespace bilayer

#endif
