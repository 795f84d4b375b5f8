#include <bilayer/solvers/active_set_iteration.h>
#include <bilayer/solvers/dual_solve.h>
#include <bilayer/solvers/feti_preconditioner.h>

#include <algorithm>
#include <memory>

namespace bilayer
{
  using namespace dealii;

  HeldSetSolution
  solve_with_held_set(const Subproblems         &subproblems,
                      const Interface           &interface,
                      const Solutions           &w,
                      const BlockVector<double> &mu,
                      const Solutions           &j,
                      const double               tolerance,
                      const unsigned int         max_iterations,
                      const BlockVector<double> *jump_offset,
                      FetiPreconditioner        *given,
                      const bool                 whole_z)
  {
    HeldSetSolution result;
    // The free set I of the state.
    const MultiplierSet &set = interface.space().set();
    BlockVector<double>  g, mask;
    interface.jumps(w, g);
    interface.space().add_cohesive_jumps(mu, g);
    set.initialize(mask);
    for (unsigned int i = 0; i < mask.size(); ++i)
      mask(i) = set.held(i, mu(i), g(i)) ? 0. : 1.;

    // z0 = K^{-1} j, its jumps, F_II nu_I = (D g(z0))_I.
    Solutions z0(subproblems.size());
    double    largest = 0;
    for (const unsigned int s : Layout::indices(subproblems.size()))
      if (subproblems[s] != nullptr)
        {
          // (No solve for a zero load.)
          if (j[s].linfty_norm() == 0)
            {
              z0[s].reinit(subproblems[s]->n_dofs());
              continue;
            }
          subproblems[s]->solve_load(j[s], z0[s]);
          largest = std::max(largest, z0[s].linfty_norm());
          ++result.subdomain_solves;
        }
    BlockVector<double> r;
    interface.jumps(z0, r);
    if (jump_offset != nullptr)
      {
        r += *jump_offset;
        largest = std::max(largest, jump_offset->linfty_norm());
      }
    interface.space().scale_by_weights(r);
    r.scale(mask);
    std::unique_ptr<FetiPreconditioner> lumped;
    if (given == nullptr)
      lumped = std::make_unique<FetiPreconditioner>(DualPreconditioner::lumped,
                                                    subproblems,
                                                    interface);
    FetiPreconditioner &preconditioner = given ? *given : *lumped;
    preconditioner.reinit(mask);
    const double start  = active_set::largest_jump(interface, r);
    const double target = tolerance * std::max(largest, 1e-300);
    const active_set::ConjugateGradientOutcome outcome =
      active_set::conjugate_gradients_on_free_set(subproblems,
                                                  interface,
                                                  preconditioner,
                                                  mask,
                                                  mu,
                                                  start,
                                                  target,
                                                  max_iterations,
                                                  r,
                                                  result.nu);
    result.iterations = outcome.iterations;
    result.subdomain_solves += outcome.subdomain_solves;
    result.converged = !outcome.limit_reached;
    if (result.nu.size() == 0)
      set.initialize(result.nu);

    if (!whole_z)
      return result;
    // z = K^{-1} (j - B^T nu), whole.
    Solutions loads;
    interface.apply(result.nu, loads);
    result.z.resize(subproblems.size());
    for (const unsigned int s : Layout::indices(subproblems.size()))
      if (subproblems[s] != nullptr)
        {
          Vector<double> load = j[s];
          if (loads[s].size() == load.size())
            load += loads[s];
          subproblems[s]->solve_load(load, result.z[s]);
          ++result.subdomain_solves;
        }
    return result;
  }
} // namespace bilayer
