// The goal-oriented estimates of a state (docs/fracture.md §11): G at the
// tips and the energy, and the indicators of a Mesh/Refinement goal.

#include <bilayer/model/model.h>
#include <bilayer/postprocess/goal_estimate.h>

#include <algorithm>
#include <cmath>

namespace bilayer
{
  using namespace dealii;

  void
  Model::estimate_goals(CycleRecord &record)
  {
    // The tractions of each layer's sides (their functions live here).
    BoundaryLoads                                   loads;
    std::vector<std::unique_ptr<FunctionParser<2>>> owners;
    loads.clamped = scene.geometry.clamped;
    loads.traction.resize(subproblems.size());
    for (const unsigned int s : Layout::indices(subproblems.size()))
      if (subproblems[s])
        for (unsigned int part = 0; part < scene.geometry.parts.size(); ++part)
          {
            owners.push_back(
              scene.loads.traction_function(regions_and_layers.layer(s), part));
            loads.traction[s].push_back(owners.back().get());
          }
    using Goal           = MeshParameters::Goal;
    const Goal     asked = scene.mesh.refinement_goal;
    RefinementGoal goal  = RefinementGoal::energy;
    if (asked == Goal::G)
      goal = RefinementGoal::all_tips;
    else if (asked == Goal::G_at_tip)
      goal = RefinementGoal::one_tip;
    AssertThrow(
      asked != Goal::G_at_tip || scene.mesh.goal_tip < record.release.size(),
      ExcMessage("Mesh/Refinement goal = G at tip " +
                 std::to_string(scene.mesh.goal_tip + 1) + ": the scene has " +
                 std::to_string(record.release.size()) + " tips (1 to " +
                 std::to_string(record.release.size()) + ")"));
    const FloatingParts floating  = floating_parts();
    const GoalEstimates estimates = goal_oriented_estimates(subproblem_views(),
                                                            coupling,
                                                            w,
                                                            mu,
                                                            record.release,
                                                            loads,
                                                            goal,
                                                            scene.mesh.goal_tip,
                                                            &floating);
    goal_fields.names             = {"dwr_energy"};
    goal_fields.values            = {estimates.energy_terms};
    if (std::any_of(estimates.G_terms.begin(),
                    estimates.G_terms.end(),
                    [](const Vector<double> &v) { return v.size() > 0; }))
      {
        goal_fields.names.emplace_back("dwr_G");
        goal_fields.values.push_back(estimates.G_terms);
      }
    record.energy_dwr     = estimates.energy;
    record.dwr_iterations = estimates.dual_iterations;
    record.dwr_seconds    = estimates.seconds;
    record.dwr_note       = estimates.note;
    bool any_tip          = false;
    for (unsigned int t = 0; t < record.release.size(); ++t)
      {
        EnergyReleaseRate &g = record.release[t];
        g.G_dwr              = estimates.G[t];
        g.G_dwr_absolute     = estimates.G_absolute[t];
        g.dual_work          = estimates.dual_work[t];
        if (!std::isfinite(g.G_dwr))
          continue;
        any_tip = any_tip || goal == RefinementGoal::all_tips ||
                  t == scene.mesh.goal_tip;
        // The bar takes the sum of the cell terms' magnitudes: the signed
        // sum cancels where the error of G changes sign between regions
        // (docs/fracture.md §11).
        if (!std::isfinite(g.error) || g.G_dwr_absolute > g.error)
          {
            g.error          = g.G_dwr_absolute;
            g.error_estimate = "DWR";
          }
      }
    if (asked == Goal::estimator || estimates.indicators.empty())
      return;
    // A goal at tips without a finite estimate refines for the energy.
    // The marking (bulk: the fewest cells whose squared indicators make up
    // the Refinement fraction of the total) reads energy-norm indicators,
    // whose squares add up to the error; the terms |eta_K| of a goal add
    // up themselves, so it gets their square roots.
    indicators = goal != RefinementGoal::energy && !any_tip ?
                   estimates.energy_indicators :
                   estimates.indicators;
    for (Vector<double> &region : indicators)
      for (double &value : region)
        value = std::sqrt(value);
  }
} // namespace bilayer
