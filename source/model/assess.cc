// The assessment of a state of a model: the energies, the residuals of
// the couplings, G with its mode split and error bar at every tip, and the
// error indicators of the next adaptive cycle.

#include <bilayer/model/model.h>
#include <bilayer/postprocess/boundary_forces.h>
#include <bilayer/postprocess/estimator.h>
#include <bilayer/postprocess/mode_split.h>
#include <bilayer/postprocess/stress_intensity.h>

#include <limits>

namespace bilayer
{
  using namespace dealii;

  void
  Model::assess(CycleRecord                    &record,
                const std::vector<CycleRecord> &history,
                const bool                      estimate)
  {
    // Energies (whole solutions: evaluated by the owners), summed in the
    // order of the subproblems as in a serial run.
    const PerSubproblem<double> energies =
      share_values(subproblem_views(), [&](const unsigned int s) {
        return subproblems[s]->energy(w[s]);
      });
    record.layer_energy.assign(Layout::n_slots(scene.materials.n_layers), 0.);
    for (const unsigned int s : Layout::indices(subproblems.size()))
      {
        record.energy += energies[s];
        record.layer_energy[static_cast<unsigned int>(
          regions_and_layers.layer(s))] += energies[s];
      }
    record.report = bilayer::assess(coupling, w, mu);
    record.forces = forces();
    if (!crack_tips_found.empty())
      assess_tips(record, history);
    // The indicators mark the next adaptive cycle; their global sum is
    // reported on every mesh (and must be finite, checked below).
    if (estimate)
      indicators = estimate_error(subproblem_views(),
                                  coupling,
                                  w,
                                  mu,
                                  scene.mesh.interface_terms,
                                  scene.mesh.contact_weight,
                                  &record.eta);
    else
      record.eta = std::numeric_limits<double>::quiet_NaN();
    if (scene.fracture.goal_oriented ||
        scene.mesh.refinement_goal != MeshParameters::Goal::estimator)
      estimate_goals(record);
  }


  ForceBalance
  Model::forces() const
  {
    const TractionFunctions tractions = traction_functions();
    return boundary_forces(subproblem_views(),
                           coupling,
                           w,
                           mu,
                           scene.geometry.parts.names,
                           scene.geometry.clamped,
                           tractions.by_layer,
                           Layout::n_slots(scene.materials.n_layers));
  }


  void
  Model::assess_tips(CycleRecord                    &record,
                     const std::vector<CycleRecord> &history)
  {
    record.release = energy_release_rates(
      subproblem_views(), coupling, w, mu, crack_tips_found);
    // A support with too few cells gives a wrong G: none is reported.
    for (unsigned int t = 0; t < record.release.size(); ++t)
      if (t < unresolved_tips.size() && !unresolved_tips[t].empty())
        {
          record.release[t].G = record.release[t].contact =
            std::numeric_limits<double>::quiet_NaN();
          record.release[t].unresolved = unresolved_tips[t];
        }
    // G_I + G_II = G (docs/fracture.md §7).
    mode_split(subproblem_views(),
               coupling,
               w,
               mu,
               tip_cell_sizes,
               scene.fracture.mode_split_length,
               record.release);
    // K by the interaction integral (docs/fracture.md §10).
    if (scene.fracture.stress_intensity)
      stress_intensity_factors(subproblem_views(),
                               coupling,
                               w,
                               mu,
                               scene.fracture.reference_length,
                               record.release);
    // The error bar: G once more with the support radius halved where
    // R/2 still holds enough cells (the same mesh: a single-mesh
    // indicator), and the sequence of G over the cycles.
    std::vector<CrackTip> halved = crack_tips_found;
    bool                  any    = false;
    for (unsigned int t = 0; t < halved.size(); ++t)
      {
        const bool resolved =
          crack_tips_found[t].defined() && unresolved_tips[t].empty() &&
          support_holds(0.5 * crack_tips_found[t].support_radius,
                        tip_cell_sizes[t]);
        halved[t].support_radius =
          resolved ? 0.5 * crack_tips_found[t].support_radius : 0.;
        any = any || resolved;
      }
    if (any)
      {
        const std::vector<EnergyReleaseRate> half =
          energy_release_rates(subproblem_views(), coupling, w, mu, halved);
        for (unsigned int t = 0; t < half.size(); ++t)
          if (halved[t].defined())
            record.release[t].G_half_support = half[t].G;
      }
    for (unsigned int t = 0; t < record.release.size(); ++t)
      {
        // G at this tip on this cycle and the consecutive ones before
        // it (the last four are used).
        std::vector<double> sequence = {record.release[t].G};
        unsigned int        expected = record.cycle;
        for (auto previous = history.rbegin();
             previous != history.rend() && expected > 0 &&
             previous->cycle + 1 == expected && t < previous->release.size() &&
             sequence.size() < 4;
             ++previous, --expected)
          sequence.insert(sequence.begin(), previous->release[t].G);
        set_g_error(record.release[t], g_error_from_cycles(sequence));
      }
  }
} // namespace bilayer
