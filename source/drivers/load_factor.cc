// The load factor of a study: the proportional loads scaled, the preload
// kept, on the subproblems as they are factorised.

#include <deal.II/base/exceptions.h>

#include <bilayer/drivers/study.h>
#include <bilayer/parameters/expressions.h>
#include <bilayer/parameters/scene_checks.h>

#include <cmath>

namespace bilayer
{
  using namespace dealii;

  void
  Study::set_load_factor(const double new_lambda)
  {
    AssertThrow(std::isfinite(new_lambda),
                ExcMessage("Study::set_load_factor: the load factor must be "
                           "a finite number"));
    // (Refused before anything changes, on every process alike.)
    for (const unsigned int s : Layout::indices(subproblems.size()))
      AssertThrow(new_lambda == 1 || subproblems[s] == nullptr ||
                    distribution.group_size(s) <= 1,
                  ExcMessage("Study::set_load_factor: subproblem " +
                             topology.name(s) +
                             " is shared by a group of processes (more than "
                             "four processes): the load factor stays 1; run "
                             "with at most four processes to scale the load"));
    lambda                  = new_lambda;
    const double mechanical = scene.loads.mechanical_factor(lambda);
    const double thermal    = scene.loads.thermal_factor(lambda);
    for (const auto &load : volume_loads)
      if (load)
        load->set_load_factor(mechanical, thermal);
    for (const auto &sub : subproblems)
      if (sub)
        sub->set_load_factor(mechanical, thermal);
  }


  bool
  Study::proportional_loading() const
  {
    if (scene.contact.frictional())
      return false;
    // Every load present is scaled by lambda: the solution is lambda times
    // that at 1, G goes with lambda^2.
    switch (scene.loads.load_factor_scales)
      {
        case LoadParameters::Scaled::mechanical:
          return !has_thermal_load(scene);
        case LoadParameters::Scaled::thermal:
          return !has_mechanical_load(scene);
        default:
          return true;
      }
  }
} // namespace bilayer
