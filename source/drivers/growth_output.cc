// The outputs of the growth driver: growth.csv, appended to step by step,
// summary.json with its "growth" object, the tables and the collections
// (.pvd, .xdmf) at the end; the terminal's line per step and the end of the
// run.

#include <deal.II/base/utilities.h>

#include <bilayer/drivers/study.h>
#include <bilayer/output/output.h>

#include <cmath>
#include <iomanip>
#include <sstream>

namespace bilayer
{
  using namespace dealii;

  std::string
  Study::growth_mode() const
  {
    if (scene.cohesive.active())
      return "cohesive";
    return scene.fracture.growth == CrackGrowth::sweep ? "sweep" :
                                                         "quasi-static";
  }


  void
  Study::write_growth(const bool final)
  {
    const std::string &dir = scene.output.directory;
    std::string        failure;
    if (distribution.is_root())
      try
        {
          // growth.csv grows by the rows of the steps that no longer change
          // (all but the last until the end; a step is marked unstable when
          // the next one grows at its load): a constant number of bytes per
          // step. The rest is written once, at the end.
          const std::size_t  done     = final || growth_steps.empty() ?
                                          growth_steps.size() :
                                          growth_steps.size() - 1;
          const unsigned int n_tips   = followed.size();
          const unsigned int n_points = scene.output.displacement_points.size();
          const std::vector<PartForce>  none;
          const std::vector<PartForce> &parts =
            growth_steps.empty() ? none : growth_steps[0].parts;
          if (!growth_head_written || growth_rows_written < done)
            append_to(dir + "/growth.csv", [&](std::ostream &o) {
              if (!growth_head_written)
                write_growth_csv_head(o, n_tips, n_points, parts);
              for (std::size_t k = growth_rows_written; k < done; ++k)
                write_growth_csv_row(
                  o, growth_steps[k], n_tips, n_points, parts);
            });
          growth_head_written = true;
          growth_rows_written = done;
          if (final)
            {
              const std::string growth =
                growth_json(growth_mode(),
                            growth_steps,
                            unstable_runs(growth_steps),
                            growth_stop);
              write_atomically(dir + "/summary.json", [&](std::ostream &o) {
                write_summary_json(
                  o, scene.name, cycle_records, growth, scene.output.units);
              });
              write_tables();
              write_collections(dir, outputs);
            }
        }
      catch (const ExceptionBase &e)
        {
          failure = one_line_message(e);
        }
      catch (const std::exception &e)
        {
          failure = e.what();
        }
    const std::string error = distribution.first_error(failure);
    if (!error.empty())
      throw CollectiveError("writing growth.csv failed: " + error);
  }


  double
  Study::growth_step_time(const unsigned int step) const
  {
    switch (scene.output.growth_time)
      {
        case GrowthTime::step:
          return step;
        case GrowthTime::crack_length:
          return crack_length();
        default:
          return model.load_factor();
      }
  }


  std::string
  Study::state_name(const unsigned int cycle) const
  {
    return (growth_run ? "step " : "cycle ") + std::to_string(cycle);
  }


  void
  Study::print_growth_step(const GrowthStep &step) const
  {
    // (rout: also with Terminal output = checks.)
    rout << "step " << step.step << ": load factor " << std::setprecision(8)
         << step.load_factor << " (" << step.kind << "), crack length "
         << std::setprecision(6) << step.crack_length;
    for (const GrowthTip &tip : step.tips)
      if (tip.present)
        {
          rout << "; tip " << tip.number << " s = " << std::setprecision(6)
               << tip.s << " G = " << std::scientific << std::setprecision(4)
               << tip.G;
          if (std::isfinite(tip.criterion))
            rout << " f = " << std::defaultfloat << std::setprecision(4)
                 << tip.criterion;
          rout << std::defaultfloat << " [" << tip.status << "]";
        }
    rout << std::endl;
  }


  bool
  Study::finish_growth(const bool passed)
  {
    if (growth_stop.empty())
      {
        bool every_tip_stopped = true;
        for (const FollowedTip &tip : followed)
          if (tip.present && tip.stopped.empty() && tip_may_grow(tip.number))
            every_tip_stopped = false;
        growth_stop = !passed           ? "a step failed its checks" :
                      every_tip_stopped ? "every growing tip stopped" :
                                          "the load factors are done";
      }
    // The last step's fields where Output/Written steps = last (or every N
    // and the last is not a multiple of N).
    const unsigned int last =
      growth_steps.empty() ? 0 : growth_steps.size() - 1;
    if (passed && scene.output.written_steps_last &&
        !scene.output.writes_step(last) && !growth_steps.empty())
      write_step_fields(last);
    write_growth(true);
    const std::vector<UnstableRun> runs = unstable_runs(growth_steps);
    rout << "growth: " << growth_steps.size() << " steps, " << growth_stop;
    for (const UnstableRun &run : runs)
      rout << "; unstable growth at load factor " << std::setprecision(8)
           << run.load_factor << " from crack length " << std::setprecision(6)
           << run.from_length << " to " << run.to_length << " (steps "
           << run.first_step << " to " << run.last_step << ")";
    rout << std::endl;
    if (scene.output.growth_time == GrowthTime::load_factor &&
        scene.output.write_vtu && !runs.empty())
      rout << "growth: the steps of an unstable run share their load factor "
              "as their time in solution.pvd and interface.pvd (ParaView "
              "shows one of them); Output/Time of growth steps = step or "
              "crack length shows each"
           << std::endl;
    return passed;
  }
} // namespace bilayer
