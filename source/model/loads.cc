// The loads of a model: the load factor (the proportional loads scaled, the
// preload kept, on the subproblems as they are factorised), the work of the
// loads and the displacement at a point; the error indicators that refine
// its meshes.

#include <deal.II/base/exceptions.h>
#include <deal.II/grid/grid_tools.h>
#include <deal.II/grid/grid_tools_cache.h>
#include <deal.II/numerics/vector_tools.h>

#include <bilayer/model/model.h>
#include <bilayer/parameters/expressions.h>
#include <bilayer/parameters/scene_checks.h>

#include <algorithm>
#include <cmath>
#include <sstream>

namespace bilayer
{
  using namespace dealii;

  void
  Model::set_load_factor(const double new_lambda)
  {
    AssertThrow(std::isfinite(new_lambda),
                ExcMessage("Study::set_load_factor: the load factor must be "
                           "a finite number"));
    // (Refused before anything changes, on every process alike.)
    for (const unsigned int s : Layout::indices(subproblems.size()))
      AssertThrow(new_lambda == 1 || subproblems[s] == nullptr ||
                    distribution.group_size(s) <= 1,
                  ExcMessage("Study::set_load_factor: subproblem " +
                             regions_and_layers.name(s) +
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
  Model::proportional_loading() const
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


  double
  Model::load_work() const
  {
    // Each subproblem's share from its owner, summed in the order of the
    // subproblems.
    PerSubproblem<double> work(subproblems.size(), 0.);
    for (const unsigned int s : Layout::indices(subproblems.size()))
      if (subproblems[s] && distribution.owns(s))
        work[s] = subproblems[s]->load_work(w[s]);
    distribution.share(work);
    double sum = 0;
    for (const double value : work)
      sum += value;
    return sum;
  }


  double
  Model::stiffness_scale() const
  {
    double largest = 0;
    for (const auto &sub : subproblems)
      if (sub)
        for (unsigned int j = 0; j < sub->laws().size(); ++j)
          largest = std::max(largest, sub->laws().law(j).tangent().norm());
    // (Every process holds the subproblems' laws; the largest of all
    // decides alike everywhere.)
    return distribution.max(largest);
  }


  Tensor<1, 2>
  Model::point_displacement(const Point<2> &p, const unsigned int s) const
  {
    Vector<double>        u(2);
    PerSubproblem<double> ux(subproblems.size(), 0.),
      uy(subproblems.size(), 0.);
    if (distribution.owns(s))
      {
        VectorTools::point_value(
          subproblems[s]->mapping(), subproblems[s]->dof_handler(), w[s], p, u);
        ux[s] = u[0];
        uy[s] = u[1];
      }
    distribution.share(ux);
    distribution.share(uy);
    return Tensor<1, 2>({ux[s], uy[s]});
  }


  unsigned int
  Model::point_subproblem(const Point<2> &p) const
  {
    // The regions from the bottom: a point on an interface is read in the
    // region below it.
    for (const unsigned int r : Layout::indices(regions_and_layers.n_regions()))
      {
        const unsigned int s = regions_and_layers.index(Layer::first, r);
        const GridTools::Cache<2, 2> cache(domain.triangulation(r),
                                           subproblems[s]->mapping());
        const auto found = GridTools::find_active_cell_around_point(cache, p);
        if (found.first.state() == IteratorState::valid)
          return s;
      }
    std::ostringstream msg;
    msg << "Output/Displacement points: (" << p[0] << ", " << p[1]
        << ") lies outside the domain";
    AssertThrow(false, ExcMessage(msg.str()));
    return 0;
  }


  void
  Model::set_indicators(const std::vector<Vector<double>> &new_indicators)
  {
    AssertThrow(new_indicators.size() == domain.n_regions(),
                ExcMessage("Study::set_indicators: one indicator per active "
                           "cell of each subdomain is needed"));
    for (const unsigned int r : Layout::indices(domain.n_regions()))
      AssertThrow(new_indicators[r].size() ==
                    domain.triangulation(r).n_active_cells(),
                  ExcMessage("Study::set_indicators: one indicator per active "
                             "cell of each subdomain is needed"));
    indicators = new_indicators;
  }
} // namespace bilayer
