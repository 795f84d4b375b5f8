#ifndef bilayer_feti_preconditioner_h
#define bilayer_feti_preconditioner_h

#include <deal.II/lac/block_vector.h>
#include <deal.II/lac/sparse_matrix.h>
#include <deal.II/lac/sparsity_pattern.h>

#include <bilayer/core/layout.h>
#include <bilayer/interface/interface.h>
#include <bilayer/parameters/parameters.h>
#include <bilayer/solvers/subdomain_solves.h>
#include <bilayer/subproblem/cholesky.h>
#include <bilayer/subproblem/interface_stiffness.h>

#include <memory>

namespace bilayer
{
  /**
   * The preconditioner of the conjugate gradients on F_II, the dual
   * operator restricted to the free multipliers I (ActiveSetSolver),
   * selected by Solver/Active set/Preconditioner:
   *  - dirichlet: M^{-1} = G^{-1} B S B^T G^{-1}, S the Schur complements
   *    of the subproblems on Sigma (InterfaceStiffness: one Dirichlet solve
   *    each) and G = B B^T restricted to I (Interface::coupling_gram()): the
   *    FETI Dirichlet preconditioner with the scaling (B B^T)^{-1} B, which
   *    bounds the condition number by C (1 + log(H/h))^2;
   *  - lumped: the same with K_{Sigma Sigma} for S (no solves);
   *  - none: D^{-1} (conjugate gradients in the metric of the Uzawa step).
   * Multiplier spaces with redundant constraints (mixed degrees,
   * non-matching traces) can make G singular: a Newton step whose G cannot
   * be factorised uses D^{-1} (a "degraded" step).
   */
  class FetiPreconditioner
  {
  public:
    /**
     * Builds the InterfaceStiffness of each subproblem this process owns
     * (the factorisations of the Dirichlet subproblems for dirichlet, as
     * parallel tasks; collective in the group of a shared subproblem).
     */
    FetiPreconditioner(const DualPreconditioner type,
                       const Subproblems       &subproblems,
                       const Interface         &interface);

    /// Restrict to the components with mask != 0 (factorises G again).
    void
    reinit(const dealii::BlockVector<double> &mask);

    /// Newton steps whose Gram matrix could not be factorised.
    unsigned int
    n_degraded_steps() const
    {
      return degraded_steps;
    }

    /// z = M^{-1} r; returns the Dirichlet solves spent.
    unsigned int
    vmult(dealii::BlockVector<double>       &z,
          const dealii::BlockVector<double> &r) const;

  private:
    /// x <- G^{-1} x.
    void
    solve_gram(dealii::BlockVector<double> &x) const;

    const DualPreconditioner type;
    const Subproblems       &subproblems;
    const Interface         &interface;
    /// The Sigma operators of the subproblems this process owns (nullptr
    /// elsewhere, and for none).
    PerSubproblem<std::unique_ptr<InterfaceStiffness>> stiffness;
    dealii::BlockVector<double>                        mask;
    dealii::SparsityPattern                            pattern;
    dealii::SparseMatrix<double>                       gram;
    SparseCholesky                                     gram_factorisation;
    bool                                               degraded       = false;
    unsigned int                                       degraded_steps = 0;
  };
} // namespace bilayer

#endif
