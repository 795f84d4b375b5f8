#ifndef bilayer_interface_stiffness_h
#define bilayer_interface_stiffness_h

#include <deal.II/base/types.h>
#include <deal.II/lac/affine_constraints.h>
#include <deal.II/lac/vector.h>

#include <bilayer/subproblem/cholesky.h>
#include <bilayer/subproblem/distributed_system.h>
#include <bilayer/subproblem/subproblem.h>

#include <memory>
#include <vector>

namespace bilayer
{
  /**
   * The stiffness of one subproblem seen from Sigma, the operators of the
   * FETI-type preconditioners of the dual problem (FetiPreconditioner):
   *  - the Schur complement S = K_SS - K_SI K_II^{-1} K_IS of the stiffness
   *    matrix on the Sigma dofs S (Steklov-Poincare operator), one solve of
   *    the "Dirichlet" subproblem (the Sigma dofs held at zero) each, or,
   *    for a condensed subproblem (ElasticSubproblem::condensed()), two
   *    dense triangular products with the factor of S that it holds;
   *  - its cheap stand-in K_SS (no solve).
   * Built from a subproblem that it only reads, by the processes that own
   * it; it holds its own factorisation, as large as the subproblem's, and
   * refers to the subproblem, which has to outlive it.
   */
  class InterfaceStiffness
  {
  public:
    /**
     * The Sigma dofs of @p subproblem (those not constrained) and, with
     * @p dirichlet, the factorisation of the Dirichlet subproblem: the
     * stiffness matrix with the Sigma dofs held at zero as well as those of
     * the homogeneous problem. A subproblem shared by a group of processes
     * (ElasticSubproblem::distributed()) is assembled again and factorised
     * by the group: then construction and apply_schur_complement() are
     * collective in the group.
     */
    InterfaceStiffness(const ElasticSubproblem &subproblem,
                       const bool               dirichlet);

    /**
     * y = S x: the reaction forces on Sigma of the displacement field that
     * takes the Sigma values of @p x, is zero on Gamma_D and is
     * discrete-harmonic inside. One Dirichlet solve; needs the
     * factorisation (@p dirichlet in the constructor). @p y is zero off
     * Sigma.
     */
    void
    apply_schur_complement(const dealii::Vector<double> &x,
                           dealii::Vector<double>       &y) const;

    /// y = K_SS x (no solve); zero off Sigma.
    void
    apply_interface_stiffness(const dealii::Vector<double> &x,
                              dealii::Vector<double>       &y) const;

  private:
    const ElasticSubproblem                     &subproblem;
    std::vector<dealii::types::global_dof_index> sigma_dofs;
    /// The constraints of the Dirichlet subproblem and its factorisation
    /// (dirichlet_factorisation, or dirichlet_system for a shared one).
    dealii::AffineConstraints<double>  dirichlet_constraints;
    std::unique_ptr<SparseCholesky>    dirichlet_factorisation;
    std::unique_ptr<DistributedSystem> dirichlet_system;
  };
} // namespace bilayer

#endif
