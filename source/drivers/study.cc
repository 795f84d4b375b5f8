// The study's drivers, the mesh cycles and the states, and the steps of a
// state, each asked of the model.

#include <deal.II/base/timer.h>

#include <bilayer/core/progress.h>
#include <bilayer/drivers/resources.h>
#include <bilayer/drivers/study.h>
#include <bilayer/solvers/cohesive_newton.h>

#include <iomanip>
#include <sstream>

namespace bilayer
{
  using namespace dealii;


  Study::Study(const Scene        &scene,
               std::ostream       &out,
               const Distribution &distribution)
    : scene(scene)
    , out(out)
    , distribution(distribution)
    , pcout(out,
            scene.output.terminal == TerminalOutput::full &&
              distribution.is_root())
    , rout(out, distribution.is_root())
    , model(this->scene, distribution, pcout)
  {}


  // (Here, where the cohesive run's Newton method is a complete type.)
  Study::~Study() = default;


  bool
  Study::run()
  {
    if (scene.mesh.marking_spelled_fixed_fraction)
      pcout << "bilayer: note: Mesh/Marking = fixed fraction is the earlier "
               "spelling of fixed number (that fraction of the cells, "
               "deal.II's fixed number); deal.II's fixed fraction is bulk"
            << std::endl;
    if (!scene.geometry.gmsh_file.empty() && scene.mesh.fit_crack_tips)
      pcout << "bilayer: note: Mesh/Fit crack tips applies to the structured "
               "meshes of the rectangle only; a Gmsh scene meshes its crack "
               "tips as vertices of its own"
            << std::endl;
    // More layers than two go round at most four processes: a group of
    // processes shares only the subproblems of two layers.
    if (scene.materials.n_layers > Layout::min_layers &&
        distribution.n_processes() > Distribution::max_groups)
      throw CollectiveError(
        "Materials/Number of layers = " +
        std::to_string(scene.materials.n_layers) + " runs on at most " +
        std::to_string(Distribution::max_groups) + " MPI processes, got " +
        std::to_string(distribution.n_processes()));
    // So do more regions than two (Geometry/Interfaces above Sigma, or
    // the regions Region 3, ... of a Gmsh scene).
    if (model.topology().n_regions() > Layout::n_subdomains &&
        distribution.n_processes() > Distribution::max_groups)
      throw CollectiveError(
        std::string(scene.geometry.gmsh_file.empty() ?
                      "Geometry/Interfaces above Sigma" :
                      "Geometry/Gmsh file") +
        ": a scene of " + std::to_string(model.topology().n_regions()) +
        " regions runs on at most " + std::to_string(Distribution::max_groups) +
        " MPI processes, got " + std::to_string(distribution.n_processes()));
    const IterationClock clock;
    std::vector<double>  seconds, dofs;
    const bool           target = scene.mesh.target_accuracy > 0;
    for (unsigned int cycle = 0; cycle < scene.mesh.n_cycles; ++cycle)
      {
        const CycleRecord *done = nullptr;
        try
          {
            done = &run_cycle(cycle);
          }
        catch (const RunFailure &e)
          {
            // A mesh that does not fit before the target is met: the
            // accuracy reached so far is part of the failure.
            if (!target || cycle_records.empty())
              throw;
            std::ostringstream t;
            t << "Mesh/Target accuracy = " << scene.mesh.target_accuracy
              << " is not reached: " << e.what() << "; after cycle "
              << cycle_records.back().cycle << " "
              << target_estimate(cycle_records.back())
                   .text(scene.mesh.target_quantity);
            throw RunFailure(e.cycle, t.str());
          }
        const CycleRecord &record = *done;
        if (!record.accepted())
          return false;
        if (target && target_met(record))
          break;
        // The time left (progress.h): silent until it can be estimated.
        seconds.push_back(record.total_seconds);
        dofs.push_back(record.dofs);
        const unsigned int n_left = scene.mesh.n_cycles - cycle - 1;
        if (n_left > 0)
          {
            const TimeLeft left =
              time_left(seconds,
                        dofs,
                        n_left,
                        scene.mesh.refinement != Refinement::global);
            pcout << "  elapsed " << format_duration(clock.elapsed());
            if (left.seconds >= 0)
              {
                std::ostringstream growth;
                growth << std::setprecision(3) << left.growth;
                pcout << ", about " << format_duration(left.seconds)
                      << " left for " << n_left << " more cycle"
                      << (n_left > 1 ? "s" : "") << " (if the unknowns grow by "
                      << growth.str() << " per cycle)";
              }
            pcout << std::endl;
          }
      }
    if (scene.output.terminal == TerminalOutput::full && distribution.is_root())
      {
        out << "\n";
        write_tip_notes(out);
        table.write_text(out, TableHandler::org_mode_table);
      }
    return true;
  }


  void
  Study::set_indicators(const std::vector<Vector<float>> &new_indicators)
  {
    std::vector<Vector<double>> converted(new_indicators.size());
    for (const unsigned int k : Layout::indices(new_indicators.size()))
      converted[k] = new_indicators[k];
    set_indicators(converted);
  }


  const CycleRecord &
  Study::run_cycle(const unsigned int cycle)
  {
    Timer       total;
    CycleRecord record;
    record.cycle = cycle;
    // The multipliers of the previous cycle, for a warm start (read before
    // the subproblems they live on are replaced).
    const bool warm = scene.solver.warm_start && !cycle_records.empty() &&
                      model.multipliers().size() > 0;
    const MultiplierSpace::Functions previous =
      warm ? model.multiplier_functions() : MultiplierSpace::Functions();
    set_up_cycle(record, cycle);
    return solve_state(record, warm ? &previous : nullptr, total);
  }


  const CycleRecord &
  Study::solve_state(CycleRecord                      &record,
                     const MultiplierSpace::Functions *previous,
                     const Timer                      &total)
  {
    model.set_up_interface(record, previous);
    record.setup_seconds = total.wall_time();
    model.solve(record);
    assess(record);
    write(record, total);
    print_report(record);
    // Every process's files are complete before the run may commit them.
    distribution.barrier();
    return cycle_records.back();
  }


  bool
  Study::run_states(const std::vector<CrackSet> &cracks,
                    const std::vector<double>   &load_factors)
  {
    AssertThrow(cycle_records.empty(),
                ExcMessage("Study::run_states: a study runs one driver"));
    AssertThrow(load_factors.empty() || load_factors.size() == cracks.size(),
                ExcMessage("Study::run_states: one load factor per state, "
                           "or none"));
    for (unsigned int k = 0; k < cracks.size(); ++k)
      {
        if (!load_factors.empty())
          set_load_factor(load_factors[k]);
        Timer       total;
        CycleRecord record;
        record.cycle = k;
        if (k == 0)
          set_up_cycle(record, 0, &cracks[0]);
        else
          {
            // The meshes and subproblems of state 0; the crack alone
            // changes, and with it the tips.
            model.set_crack(cracks[k]);
            reuse_meshes(record);
          }
        if (!solve_state(record, nullptr, total).accepted())
          return false;
      }
    return true;
  }


  void
  Study::set_up_cycle(CycleRecord       &record,
                      const unsigned int cycle,
                      const CrackSet    *crack)
  {
    build_meshes(record, cycle);
    if (crack != nullptr)
      {
        model.set_crack(*crack);
        model.update_tips(record);
      }
    check_memory(record);
    model.set_up_subproblems();
    model.count_dofs(record);
    model.count_set_up_times(record);
  }


  void
  Study::build_meshes(CycleRecord &record, const unsigned int cycle)
  {
    const bool refine =
      cycle > 0 && scene.mesh.refinement == Refinement::adaptive;
    if (refine)
      AssertThrow(!cycle_records.empty() &&
                    cycle_records.back().cycle + 1 == cycle,
                  ExcMessage("adaptive cycle " + std::to_string(cycle) +
                             " needs cycle " + std::to_string(cycle - 1) +
                             " of the same study first"));
    model.build_meshes(record, cycle, refine);
  }


  void
  Study::reuse_meshes(CycleRecord &record)
  {
    // The meshes and subproblems of the first record (its memory estimate:
    // the meshes are the same).
    model.describe_meshes(record);
    record.memory_estimate_mib = cycle_records.front().memory_estimate_mib;
    model.count_dofs(record);
    model.update_tips(record);
  }


  void
  Study::assess(CycleRecord &record)
  {
    model.assess(record, cycle_records, estimates_error(record));
    check(record);
  }
} // namespace bilayer
