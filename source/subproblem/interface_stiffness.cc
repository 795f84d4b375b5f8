#include <deal.II/dofs/dof_tools.h>
#include <deal.II/lac/sparse_matrix.h>

#include <bilayer/core/boundary_ids.h>
#include <bilayer/subproblem/interface_stiffness.h>

namespace bilayer
{
  using namespace dealii;

  InterfaceStiffness::InterfaceStiffness(const ElasticSubproblem &subproblem,
                                         const bool               dirichlet)
    : subproblem(subproblem)
  {
    const AffineConstraints<double> &homogeneous =
      subproblem.zero_displacement_constraints();
    for (const auto i : subproblem.trace_dofs())
      if (!homogeneous.is_constrained(i))
        sigma_dofs.push_back(i);
    // A condensed subproblem holds S already (its factor on Sigma).
    if (!dirichlet || subproblem.condensed())
      return;

    dirichlet_constraints.merge(homogeneous);
    for (const auto i : sigma_dofs)
      dirichlet_constraints.add_line(i);
    dirichlet_constraints.close();
    if (subproblem.distributed())
      // Assembled again by the group with the Sigma dofs held.
      dirichlet_system = subproblem.factorise_in_group(dirichlet_constraints);
    else
      {
        // The sparsity pattern already holds the fill of the hanging-node
        // condensation; holding more dofs at zero adds none.
        const SparseMatrix<double> &stiffness = subproblem.stiffness_matrix();
        SparseMatrix<double>        matrix(stiffness.get_sparsity_pattern());
        matrix.copy_from(stiffness);
        dirichlet_constraints.condense(matrix);
        dirichlet_factorisation = std::make_unique<SparseCholesky>();
        dirichlet_factorisation->initialize(
          matrix,
          "the Dirichlet preconditioner matrix of subproblem " +
            subproblem.name());
      }
  }


  void
  InterfaceStiffness::apply_schur_complement(const Vector<double> &x,
                                             Vector<double>       &y) const
  {
    if (subproblem.condensed())
      {
        subproblem.apply_schur_complement(x, y);
        return;
      }
    Assert(dirichlet_factorisation || dirichlet_system, ExcInternalError());
    const unsigned int n = subproblem.n_dofs();
    // The Sigma values of x, extended by zero ...
    Vector<double> extension(n);
    for (const auto i : sigma_dofs)
      extension(i) = x(i);
    // ... then discrete-harmonically into the interior: K_II z = -K_I. x.
    Vector<double> interior(n);
    subproblem.multiply_stiffness(interior, extension);
    interior *= -1.;
    dirichlet_constraints.condense(interior);
    if (dirichlet_system)
      dirichlet_system->solve(interior, false);
    else
      dirichlet_factorisation->solve(interior);
    dirichlet_constraints.distribute(interior);
    extension += interior;
    Vector<double> reaction(n);
    subproblem.multiply_stiffness(reaction, extension);
    y.reinit(n);
    for (const auto i : sigma_dofs)
      y(i) = reaction(i);
  }


  void
  InterfaceStiffness::apply_interface_stiffness(const Vector<double> &x,
                                                Vector<double>       &y) const
  {
    const unsigned int n = subproblem.n_dofs();
    Vector<double>     extension(n), reaction(n);
    for (const auto i : sigma_dofs)
      extension(i) = x(i);
    subproblem.multiply_stiffness(reaction, extension);
    y.reinit(n);
    for (const auto i : sigma_dofs)
      y(i) = reaction(i);
  }
} // namespace bilayer
