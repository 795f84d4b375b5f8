#ifndef bilayer_distributed_system_h
#define bilayer_distributed_system_h

#include <deal.II/base/index_set.h>
#include <deal.II/base/mpi.h>
#include <deal.II/dofs/dof_handler.h>
#include <deal.II/lac/affine_constraints.h>
#include <deal.II/lac/trilinos_solver.h>
#include <deal.II/lac/trilinos_sparse_matrix.h>
#include <deal.II/lac/trilinos_vector.h>
#include <deal.II/lac/vector.h>

#include <memory>
#include <string>
#include <vector>

namespace bilayer
{
  /**
   * The linear system of one subproblem shared by a group of MPI processes
   * (more than four processes in all, see Distribution): the cells of the
   * (serial, replicated) mesh are split into one part per process by METIS
   * on the face connectivity of the cells, each process assembles its
   * cells, and the rows of the Trilinos matrices and vectors belong to the
   * process of the lowest part among the cells that share a dof. The matrix
   * is factorised once by a parallel direct solver of Trilinos' Amesos
   * (MUMPS by default) and the factorisation is reused for every solve.
   *
   * Vectors enter and leave as full (replicated) deal.II vectors, the same
   * on every process of the group: a solve takes the owned entries of the
   * right-hand side and returns the whole solution on every process of the
   * group (one reduction of a vector of the subproblem's size within the
   * group), so that the subproblem's callers need not know that it is
   * shared.
   */
  class DistributedSystem
  {
  public:
    /**
     * Partition the cells of @p dofs among the processes of @p group and
     * set up the sparsity of the matrices for the rows this process writes
     * (its cells' dofs and their constraints' masters in @p constraints).
     * With @p same_partition, take that system's partition (the same
     * subproblem under other constraints) instead of running METIS again.
     */
    DistributedSystem(const dealii::DoFHandler<2>             &dofs,
                      const dealii::AffineConstraints<double> &constraints,
                      const MPI_Comm                           group,
                      const std::string                       &solver_type,
                      const DistributedSystem *same_partition = nullptr);

    /// The part (process of the group) of each active cell.
    const std::vector<unsigned int> &
    cell_partition() const
    {
      return partition;
    }

    /// Whether this process assembles (and writes) the active cell with
    /// index @p active_cell_index.
    bool
    assembles(const unsigned int active_cell_index) const
    {
      return partition[active_cell_index] == part;
    }

    /// The system matrix (constraints condensed), its right-hand side, and
    /// optionally the unconstrained stiffness and load (with_stiffness).
    dealii::TrilinosWrappers::SparseMatrix matrix, stiffness;
    dealii::TrilinosWrappers::MPI::Vector  rhs, load;

    /// Exchange the entries written for other processes, then factorise.
    void
    finish_assembly();

    /**
     * @p v <- A^{-1} (v + rhs, if @p add_rhs) with @p v the same full
     * vector on every process of the group (collective in the group).
     */
    void
    solve(dealii::Vector<double> &v, const bool add_rhs) const;

    /// y = K x for full vectors (collective in the group).
    void
    vmult_stiffness(dealii::Vector<double>       &y,
                    const dealii::Vector<double> &x) const;

    /// x^T K x and load . x for a full vector x (collective in the group).
    double
    energy_norm_squared(const dealii::Vector<double> &x) const;
    double
    load_product(const dealii::Vector<double> &x) const;

  private:
    /// The owned entries of a full vector.
    void restrict(const dealii::Vector<double>          &full,
                  dealii::TrilinosWrappers::MPI::Vector &v) const;
    /// The full vector of owned entries from every process.
    void
    expand(const dealii::TrilinosWrappers::MPI::Vector &v,
           dealii::Vector<double>                      &full) const;

    /// rhs and load after assembly, without ghost entries.
    dealii::TrilinosWrappers::MPI::Vector owned_rhs, owned_load;

    const MPI_Comm                                          group;
    unsigned int                                            part = 0;
    std::vector<unsigned int>                               partition;
    dealii::IndexSet                                        owned, writable;
    std::string                                             solver_type;
    mutable dealii::SolverControl                           control;
    std::unique_ptr<dealii::TrilinosWrappers::SolverDirect> direct;
  };
} // namespace bilayer

#endif
