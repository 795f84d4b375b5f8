#include <deal.II/grid/grid_tools.h>
#include <deal.II/lac/dynamic_sparsity_pattern.h>
#include <deal.II/lac/sparsity_pattern.h>
#include <deal.II/lac/sparsity_tools.h>
#include <deal.II/lac/trilinos_sparsity_pattern.h>

#include <bilayer/subproblem/distributed_system.h>

#include <algorithm>

namespace bilayer
{
  using namespace dealii;

  DistributedSystem::DistributedSystem(
    const DoFHandler<2>             &dofs,
    const AffineConstraints<double> &constraints,
    const MPI_Comm                   group,
    const std::string               &solver_type,
    const DistributedSystem         *same_partition)
    : group(group)
    , part(Utilities::MPI::this_mpi_process(group))
    , solver_type(solver_type)
  {
    const unsigned int n_parts = Utilities::MPI::n_mpi_processes(group);
    const auto        &tria    = dofs.get_triangulation();

    // METIS (GridTools::partition_triangulation) on a copy of the mesh,
    // which other subproblems share; the first process's partition is
    // everybody's.
    partition.resize(tria.n_active_cells());
    if (same_partition != nullptr)
      partition = same_partition->cell_partition();
    else if (part == 0)
      {
        Triangulation<2> copy;
        copy.copy_triangulation(tria);
        GridTools::partition_triangulation(n_parts,
                                           copy,
                                           SparsityTools::Partitioner::metis);
        for (const auto &cell : copy.active_cell_iterators())
          partition[cell->active_cell_index()] = cell->subdomain_id();
      }
    if (same_partition == nullptr)
      partition = Utilities::MPI::broadcast(group, partition, 0);

    // A dof belongs to the lowest part among its cells.
    std::vector<unsigned int>            owner(dofs.n_dofs(), n_parts);
    std::vector<types::global_dof_index> local_dofs(
      dofs.get_fe().n_dofs_per_cell());
    for (const auto &cell : dofs.active_cell_iterators())
      {
        cell->get_dof_indices(local_dofs);
        for (const auto i : local_dofs)
          owner[i] = std::min(owner[i], partition[cell->active_cell_index()]);
      }
    owned.set_size(dofs.n_dofs());
    writable.set_size(dofs.n_dofs());
    for (types::global_dof_index i = 0; i < dofs.n_dofs(); ++i)
      if (owner[i] == part)
        owned.add_index(i);
    owned.compress();

    // Rows this process writes: its cells' dofs and their masters.
    std::vector<types::global_dof_index> rows;
    for (const auto &cell : dofs.active_cell_iterators())
      if (assembles(cell->active_cell_index()))
        {
          cell->get_dof_indices(local_dofs);
          for (const auto i : local_dofs)
            {
              rows.push_back(i);
              if (const auto *line = constraints.get_constraint_entries(i))
                for (const auto &entry : *line)
                  rows.push_back(entry.first);
            }
        }
    std::sort(rows.begin(), rows.end());
    rows.erase(std::unique(rows.begin(), rows.end()), rows.end());
    writable.add_indices(rows.begin(), rows.end());
    writable.add_indices(owned);
    writable.compress();

    TrilinosWrappers::SparsityPattern pattern(owned, owned, writable, group);
    for (const auto &cell : dofs.active_cell_iterators())
      if (assembles(cell->active_cell_index()))
        {
          cell->get_dof_indices(local_dofs);
          constraints.add_entries_local_to_global(local_dofs, pattern, true);
        }
    pattern.compress();
    matrix.reinit(pattern);
    stiffness.reinit(pattern);
    IndexSet ghosts = writable;
    ghosts.subtract_set(owned);
    rhs.reinit(owned, ghosts, group, true);
    load.reinit(owned, ghosts, group, true);
  }


  void
  DistributedSystem::finish_assembly()
  {
    matrix.compress(VectorOperation::add);
    stiffness.compress(VectorOperation::add);
    rhs.compress(VectorOperation::add);
    load.compress(VectorOperation::add);
    owned_rhs.reinit(owned, group);
    owned_load.reinit(owned, group);
    for (const auto i : owned)
      {
        owned_rhs(i)  = rhs(i);
        owned_load(i) = load(i);
      }
    owned_rhs.compress(VectorOperation::insert);
    owned_load.compress(VectorOperation::insert);
    direct = std::make_unique<TrilinosWrappers::SolverDirect>(
      control,
      TrilinosWrappers::SolverDirect::AdditionalData(false, solver_type));
    direct->initialize(matrix);
  }


  void DistributedSystem::restrict(const Vector<double>          &full,
                                   TrilinosWrappers::MPI::Vector &v) const
  {
    v.reinit(owned, group);
    for (const auto i : owned)
      v(i) = full(i);
    v.compress(VectorOperation::insert);
  }


  void
  DistributedSystem::expand(const TrilinosWrappers::MPI::Vector &v,
                            Vector<double>                      &full) const
  {
    full.reinit(owned.size());
    for (const auto i : owned)
      full(i) = v(i);
    // Exactly one process contributes each entry: the sum is exact.
    Utilities::MPI::sum(ArrayView<const double>(full.begin(), full.size()),
                        group,
                        ArrayView<double>(full.begin(), full.size()));
  }


  void
  DistributedSystem::solve(Vector<double> &v, const bool add_rhs) const
  {
    TrilinosWrappers::MPI::Vector b, x(owned, group);
    restrict(v, b);
    if (add_rhs)
      b += owned_rhs;
    direct->solve(x, b);
    expand(x, v);
  }


  void
  DistributedSystem::vmult_stiffness(Vector<double>       &y,
                                     const Vector<double> &x) const
  {
    TrilinosWrappers::MPI::Vector in, out(owned, group);
    restrict(x, in);
    stiffness.vmult(out, in);
    expand(out, y);
  }


  double
  DistributedSystem::energy_norm_squared(const Vector<double> &x) const
  {
    TrilinosWrappers::MPI::Vector in, out(owned, group);
    restrict(x, in);
    stiffness.vmult(out, in);
    return out * in;
  }


  double
  DistributedSystem::load_product(const Vector<double> &x) const
  {
    TrilinosWrappers::MPI::Vector in;
    restrict(x, in);
    return owned_load * in;
  }
} // namespace bilayer
