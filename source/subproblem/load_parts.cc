// The load factor of a subproblem: the proportional part of the load and
// the preload kept apart from the one assembly, and the load at lambda
// made from them without a new factorisation.

#include <deal.II/base/exceptions.h>

#include <bilayer/subproblem/distributed_system.h>
#include <bilayer/subproblem/subproblem.h>

#include <cmath>

namespace bilayer
{
  using namespace dealii;

  void
  ElasticSubproblem::start_load_parts(const VolumeLoad *volume)
  {
    load_factor_    = 1;
    preload_factor_ = 1;
    has_preload_    = volume != nullptr && volume->has_eigenstrain();
    inhomogeneities.clear();
    for (const auto &line : constraints.get_lines())
      if (line.inhomogeneity != 0)
        inhomogeneities.emplace_back(line.index, line.inhomogeneity);
    // The parts that assemble() fills apart (an owner alone, with a
    // preload).
    const unsigned int n =
      owned() && has_preload_ && distribution.group_size(index()) == 1 ?
        dofs.n_dofs() :
        0;
    for (auto *v : {&unit_rhs, &preload_rhs, &unit_load, &preload_load})
      v->reinit(n);
    rhs_at_one.reinit(0);
    load_at_one.reinit(0);
  }


  void
  ElasticSubproblem::keep_load_at_one()
  {
    if (shared)
      return;
    if (has_preload_)
      {
        rhs_at_one  = system_rhs;
        load_at_one = load_vector;
      }
    else
      {
        // All of the load is proportional.
        unit_rhs  = system_rhs;
        unit_load = load_vector;
      }
  }


  void
  ElasticSubproblem::set_load_factor(const double lambda, const double preload)
  {
    AssertThrow(std::isfinite(lambda) && std::isfinite(preload),
                ExcMessage("the load factor of subproblem " + name() +
                           " must be a finite number"));
    AssertThrow((lambda == 1 && preload == 1) ||
                  distribution.group_size(index()) <= 1,
                ExcMessage("subproblem " + name() +
                           " is shared by a group of processes (more than "
                           "four processes): its load factor stays 1; run "
                           "with at most four processes to scale the load"));
    // (Without a preload, @p preload scales nothing.)
    const double p = has_preload_ ? preload : 1.;
    if (lambda == load_factor_ && p == preload_factor_)
      return;
    load_factor_    = lambda;
    preload_factor_ = p;
    for (const auto &[i, value] : inhomogeneities)
      constraints.set_inhomogeneity(i, lambda * value);
    if (!owned() || shared)
      return;
    if (has_preload_ && lambda == 1 && preload_factor_ == 1)
      {
        system_rhs  = rhs_at_one;
        load_vector = load_at_one;
      }
    else
      {
        system_rhs.equ(lambda, unit_rhs);
        load_vector.equ(lambda, unit_load);
        if (has_preload_)
          {
            system_rhs.add(preload_factor_, preload_rhs);
            load_vector.add(preload_factor_, preload_load);
          }
      }
    if (condensed())
      solve(Vector<double>(), particular);
  }


  void
  ElasticSubproblem::solve_load(const Vector<double> &load,
                                Vector<double>       &solution) const
  {
    solution = load;
    homogeneous_constraints.condense(solution);
    if (shared)
      shared->solve(solution, false);
    else
      factorisation.solve(solution);
    homogeneous_constraints.distribute(solution);
  }
} // namespace bilayer
