#include <bilayer/core/tasks.h>
#include <bilayer/solvers/feti_preconditioner.h>

namespace bilayer
{
  using namespace dealii;

  FetiPreconditioner::FetiPreconditioner(const DualPreconditioner type,
                                         const Subproblems       &subproblems,
                                         const Interface         &interface)
    : type(type)
    , subproblems(subproblems)
    , interface(interface)
  {
    if (type == DualPreconditioner::none)
      return;
    stiffness.resize(subproblems.size());
    Tasks tasks;
    for (const unsigned int s : Layout::indices(subproblems.size()))
      if (subproblems[s] != nullptr && subproblems[s]->owned())
        tasks.add([&, s]() {
          stiffness[s] = std::make_unique<InterfaceStiffness>(
            *subproblems[s], type == DualPreconditioner::dirichlet);
        });
    tasks.join_all();
  }


  void
  FetiPreconditioner::reinit(const BlockVector<double> &new_mask)
  {
    mask = new_mask;
    if (type == DualPreconditioner::none)
      return;
    interface.coupling_gram(mask, pattern, gram);
    degraded = !gram_factorisation.try_initialize(gram);
    if (degraded)
      ++degraded_steps;
  }


  unsigned int
  FetiPreconditioner::vmult(BlockVector<double>       &z,
                            const BlockVector<double> &r) const
  {
    z = r;
    if (type == DualPreconditioner::none || degraded)
      {
        interface.space().scale_by_weights(z, true);
        z.scale(mask);
        return 0;
      }
    solve_gram(z);
    Solutions loads, reactions(subproblems.size());
    interface.apply(z, loads); // -B^T G^{-1} r
    Tasks tasks;
    for (const unsigned int s : Layout::indices(stiffness.size()))
      if (stiffness[s] != nullptr)
        tasks.add([&, s]() {
          if (type == DualPreconditioner::dirichlet)
            stiffness[s]->apply_schur_complement(loads[s], reactions[s]);
          else
            stiffness[s]->apply_interface_stiffness(loads[s], reactions[s]);
        });
    tasks.join_all();
    share_traces(subproblems, reactions);
    interface.jumps(reactions, z);
    interface.space().scale_by_weights(z); // B S (-B^T G^{-1} r)
    z *= -1.;
    z.scale(mask);
    solve_gram(z);
    return type == DualPreconditioner::dirichlet ?
             static_cast<unsigned int>(subproblems.size()) :
             0;
  }


  void
  FetiPreconditioner::solve_gram(BlockVector<double> &x) const
  {
    Vector<double> flat(x.size());
    for (unsigned int i = 0; i < x.size(); ++i)
      flat(i) = x(i);
    gram_factorisation.solve(flat);
    for (unsigned int i = 0; i < x.size(); ++i)
      x(i) = flat(i);
  }
} // namespace bilayer
