// Goal-oriented (dual-weighted residual) estimates of G at the tips and of
// the energy (docs/fracture.md §11): the dual loads, the dual solves with
// the active set held, and the sums of the weighted residuals.

#include <deal.II/base/timer.h>
#include <deal.II/fe/fe_values.h>

#include <bilayer/core/tasks.h>
#include <bilayer/postprocess/domain_integral.h>
#include <bilayer/postprocess/goal_estimate.h>
#include <bilayer/solvers/dual_solve.h>

#include <cmath>
#include <limits>

namespace bilayer
{
  using namespace dealii;

  namespace
  {
    /**
     * The derivative of the domain integral of G at @p tip in the
     * direction of each shape function of @p sub at the state @p u:
     *   J'(u)[phi] = int sigma(u) : (grad phi grad theta)
     *              + sigma(phi) : (grad u grad theta)
     *              - sigma(u) : eps(phi) div theta
     *              + sigma(phi) : ((grad eps*) theta)
     *              + (f . phi) div theta + ((grad f) theta) . phi dx,
     * sigma(u) = C (eps(u) - eps*) (energy_release_rate.cc, cell_integral()).
     */
    Vector<double>
    dual_load(const ElasticSubproblem &sub,
              const Vector<double>    &u,
              const CrackTip          &tip)
    {
      Vector<double>                       j(sub.n_dofs());
      const std::vector<CrackTip>          tips   = {tip};
      const std::vector<ThetaField>        fields = {ThetaField(tip)};
      const FEValuesExtractors::Vector     displacement(0);
      const VolumeLoad *const              volume = sub.volume_load();
      const unsigned int                   n      = sub.fe().n_dofs_per_cell();
      std::vector<Tensor<2, 2>>            grad_u;
      Vector<double>                       local(n);
      std::vector<types::global_dof_index> dofs(n);
      for_each_support_cell(
        sub,
        tips,
        fields,
        update_values | update_gradients | update_quadrature_points |
          update_JxW_values,
        [&](const FEValues<2>                         &fe_values,
            const DoFHandler<2>::active_cell_iterator &cell,
            const Point<2> &,
            const double) {
          grad_u.resize(fe_values.n_quadrature_points);
          fe_values[displacement].get_function_gradients(u, grad_u);
          const ElasticLaw &law = sub.law(*cell);
          const CellLoad    load =
            volume != nullptr ? volume->in(*cell) : CellLoad();
          const bool eigenstrain =
            volume != nullptr && volume->has_eigenstrain();
          const bool body_force = volume != nullptr && volume->has_body_force();
          local                 = 0;
          for (const unsigned int q : fe_values.quadrature_point_indices())
            {
              const Point<2>       &x          = fe_values.quadrature_point(q);
              const Tensor<2, 2>    grad_theta = fields[0].gradient(x);
              const Tensor<1, 2>    theta      = fields[0].value(x);
              const double          div_theta  = trace(grad_theta);
              SymmetricTensor<2, 2> elastic    = symmetrize(grad_u[q]);
              std::array<SymmetricTensor<2, 2>, 2> d_eps;
              if (eigenstrain)
                {
                  elastic -= load.eigenstrain(x);
                  d_eps = load.eigenstrain_gradient(x);
                }
              const Tensor<2, 2> stress(law.stress(elastic));
              const Tensor<2, 2> u_theta = grad_u[q] * grad_theta;
              for (unsigned int i = 0; i < n; ++i)
                {
                  const Tensor<2, 2> grad_phi =
                    fe_values[displacement].gradient(i, q);
                  const Tensor<1, 2> phi = fe_values[displacement].value(i, q);
                  const SymmetricTensor<2, 2> stress_phi =
                    law.stress(symmetrize(grad_phi));
                  double d =
                    scalar_product(stress, grad_phi * grad_theta) +
                    scalar_product(Tensor<2, 2>(stress_phi), u_theta) -
                    scalar_product(stress, Tensor<2, 2>(symmetrize(grad_phi))) *
                      div_theta;
                  if (eigenstrain)
                    d +=
                      stress_phi * (d_eps[0] * theta[0] + d_eps[1] * theta[1]);
                  if (body_force)
                    d += (load.body_force(x) * phi) * div_theta +
                         (load.body_force_gradient(x) * theta) * phi;
                  local(i) += d * fe_values.JxW(q);
                }
            }
          cell->get_dof_indices(dofs);
          for (unsigned int i = 0; i < n; ++i)
            j(dofs[i]) += local(i);
        });
      return j;
    }

    /**
     * The sums of the cell terms @p eta (by subproblem: the energy's, then
     * those of the tips @p estimated) into @p result: the estimates, their
     * absolute sums, the indicators of @p goal by region and the cell
     * terms by subproblem.
     */
    void
    collect(const Subproblems                                &subproblems,
            const Topology                                   &topology,
            const PerSubproblem<std::vector<Vector<double>>> &eta,
            const std::vector<unsigned int>                  &estimated,
            const std::vector<EnergyReleaseRate>             &release,
            const RefinementGoal                              goal,
            const unsigned int                                goal_tip,
            GoalEstimates                                    &result)
    {
      for (unsigned int k = 0; k < estimated.size(); ++k)
        result.G[estimated[k]] = result.G_absolute[estimated[k]] = 0;
      result.indicators.resize(topology.n_regions());
      result.energy_indicators.resize(topology.n_regions());
      result.energy_terms.resize(subproblems.size());
      result.G_terms.resize(subproblems.size());
      for (const unsigned int s : Layout::indices(subproblems.size()))
        if (subproblems[s] != nullptr)
          {
            const auto &e = eta[s];
            result.energy += -0.5 * e[0].mean_value() * e[0].size();
            result.energy_absolute += 0.5 * e[0].l1_norm();
            for (unsigned int k = 0; k < estimated.size(); ++k)
              {
                result.G[estimated[k]] +=
                  e[k + 1].mean_value() * e[k + 1].size();
                result.G_absolute[estimated[k]] += e[k + 1].l1_norm();
              }
            Vector<double> &indicator =
              result.indicators[subproblems[s]->region()];
            Vector<double> &energy_indicator =
              result.energy_indicators[subproblems[s]->region()];
            if (indicator.size() == 0)
              {
                indicator.reinit(e[0].size());
                energy_indicator.reinit(e[0].size());
              }
            result.energy_terms[s].reinit(e[0].size());
            if (!estimated.empty())
              result.G_terms[s].reinit(e[0].size());
            for (unsigned int c = 0; c < e[0].size(); ++c)
              {
                energy_indicator(c) += 0.5 * std::abs(e[0](c));
                result.energy_terms[s](c) = 0.5 * std::abs(e[0](c));
                for (unsigned int k = 0; k < estimated.size(); ++k)
                  result.G_terms[s](c) += std::abs(e[k + 1](c));
                double value = 0;
                if (goal == RefinementGoal::energy)
                  value = 0.5 * std::abs(e[0](c));
                for (unsigned int k = 0; k < estimated.size(); ++k)
                  if (goal == RefinementGoal::all_tips ||
                      (goal == RefinementGoal::one_tip &&
                       estimated[k] == goal_tip))
                    value += std::abs(e[k + 1](c)) /
                             std::max(std::abs(release[estimated[k]].G),
                                      std::numeric_limits<double>::min());
                indicator(c) += value;
              }
          }
    }
  } // namespace


  GoalEstimates
  goal_oriented_estimates(const Subproblems                    &subproblems,
                          const Interface                      &interface,
                          const Solutions                      &w,
                          const BlockVector<double>            &mu,
                          const std::vector<EnergyReleaseRate> &release,
                          const BoundaryLoads                  &loads,
                          const RefinementGoal                  goal,
                          const unsigned int                    goal_tip,
                          const FloatingParts                  *floating)
  {
    Timer              timer;
    GoalEstimates      result;
    const unsigned int n   = release.size();
    const double       nan = std::numeric_limits<double>::quiet_NaN();
    result.G.assign(n, nan);
    result.G_absolute.assign(n, nan);
    result.dual_work.assign(n, nan);
    for (const ElasticSubproblem *sub : subproblems)
      if (sub != nullptr && (!sub->owned() || sub->distributed()))
        {
          result.note   = "not computed in a run with MPI";
          result.energy = result.energy_absolute = nan;
          return result;
        }

    // The tips (defined or not) whose near-tip functions enrich the
    // reconstructions (those with a direction of growth).
    std::vector<goal::TipFrame> frames;
    for (const EnergyReleaseRate &g : release)
      if (std::isfinite(g.tip.point.norm()) &&
          std::abs(g.tip.direction.norm() - 1) < 1e-6)
        frames.push_back({g.tip.point, g.tip.direction});

    // The dual solutions, by tip.
    std::vector<unsigned int> estimated;
    std::vector<Solutions>    duals;
    for (unsigned int t = 0; t < n; ++t)
      if (release[t].tip.defined() && std::isfinite(release[t].G))
        {
          Solutions j(subproblems.size());
          Tasks     tasks;
          for (const unsigned int s : Layout::indices(subproblems.size()))
            if (subproblems[s] != nullptr)
              tasks.add([&, s]() {
                j[s] = dual_load(*subproblems[s], w[s], release[t].tip);
              });
          tasks.join_all();
          HeldSetSolution dual =
            floating != nullptr && floating->any() ?
              floating->solve_with_held_set(w, mu, j, 1e-10, 2000) :
              solve_with_held_set(
                subproblems, interface, w, mu, j, 1e-10, 2000);
          result.dual_iterations += dual.iterations;
          result.subdomain_solves += dual.subdomain_solves;
          if (!dual.converged)
            result.note = "the dual problem of a tip did not converge";
          result.dual_work[t] = 0;
          for (const unsigned int s : Layout::indices(subproblems.size()))
            if (subproblems[s] != nullptr)
              result.dual_work[t] += subproblems[s]->load_factor() *
                                     subproblems[s]->load_work(dual.z[s]);
          estimated.push_back(t);
          duals.push_back(std::move(dual.z));
          if (release[t].tip.curved() || release[t].friction != 0)
            result.note = "the dual load leaves out the face terms of G "
                          "(curved crack, friction)";
        }

    // The weighted residuals of each subproblem: field 0 the state itself
    // (the energy), then the dual solution of each estimated tip.
    PerSubproblem<std::vector<Vector<double>>> eta(subproblems.size());
    Tasks                                      tasks;
    for (const unsigned int s : Layout::indices(subproblems.size()))
      if (subproblems[s] != nullptr)
        tasks.add([&, s]() {
          std::vector<const Vector<double> *> fields = {&w[s]};
          for (const Solutions &z : duals)
            fields.push_back(&z[s]);
          eta[s] = goal::weighted_residuals(*subproblems[s],
                                            s,
                                            interface,
                                            w[s],
                                            mu,
                                            loads.clamped,
                                            loads.traction[s],
                                            fields,
                                            frames);
        });
    tasks.join_all();

    collect(subproblems,
            interface.topology(),
            eta,
            estimated,
            release,
            goal,
            goal_tip,
            result);
    result.seconds = timer.wall_time();
    return result;
  }
} // namespace bilayer
