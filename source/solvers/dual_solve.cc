#include <bilayer/solvers/active_set_iteration.h>
#include <bilayer/solvers/dual_solve.h>
#include <bilayer/solvers/feti_preconditioner.h>

#include <algorithm>

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
                      const unsigned int         max_iterations)
  {
    HeldSetSolution result;
    // The free set I of the state.
    const MultiplierSet &set = interface.space().set();
    BlockVector<double>  g, mask;
    interface.jumps(w, g);
    set.initialize(mask);
    for (unsigned int i = 0; i < mask.size(); ++i)
      mask(i) = set.held(i, mu(i), g(i)) ? 0. : 1.;

    // z0 = K^{-1} j, its jumps, F_II nu_I = (D g(z0))_I.
    Solutions z0(subproblems.size());
    double    largest = 0;
    for (const unsigned int s : Layout::indices(subproblems.size()))
      if (subproblems[s] != nullptr)
        {
          subproblems[s]->solve_load(j[s], z0[s]);
          largest = std::max(largest, z0[s].linfty_norm());
          ++result.subdomain_solves;
        }
    BlockVector<double> r;
    interface.jumps(z0, r);
    interface.space().scale_by_weights(r);
    r.scale(mask);
    FetiPreconditioner preconditioner(DualPreconditioner::lumped,
                                      subproblems,
                                      interface);
    preconditioner.reinit(mask);
    const double start  = active_set::largest_jump(interface, r);
    const double target = tolerance * std::max(largest, 1e-300);
    const active_set::ConjugateGradientOutcome outcome =
      active_set::conjugate_gradients_on_free_set(subproblems,
                                                  interface,
                                                  preconditioner,
                                                  mask,
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
