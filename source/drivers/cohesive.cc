// The cohesive driver: the softening curve of a cohesive zone traced step
// by step on one set of factorisations (docs/cohesive.md).

#include <deal.II/base/timer.h>

#include <bilayer/drivers/resources.h>
#include <bilayer/drivers/study.h>
#include <bilayer/interface/cohesive_zone.h>
#include <bilayer/parameters/parameter_entries.h>
#include <bilayer/physics/cohesive_law.h>
#include <bilayer/solvers/anderson_mixing.h>

#include <algorithm>
#include <cmath>
#include <iomanip>
#include <limits>
#include <memory>
#include <sstream>

namespace bilayer
{
  using namespace dealii;

  namespace
  {
    /// The depth of the Anderson acceleration of the secant iteration.
    constexpr unsigned int anderson_depth = 5;


    /// The crack @p crack with the pieces @p zone joined to it (pieces
    /// that touch or overlap merge into one).
    CrackSet
    join_zone(const CrackSet                           &crack,
              const std::vector<std::array<double, 2>> &zone,
              const double                              tolerance)
    {
      std::vector<CrackSet::Piece> pieces = crack.pieces();
      for (const auto &piece : zone)
        pieces.push_back({piece[0], piece[1]});
      std::sort(pieces.begin(), pieces.end(), [](const auto &a, const auto &b) {
        return a.start < b.start;
      });
      std::vector<CrackSet::Piece> joined;
      for (const auto &piece : pieces)
        if (!joined.empty() && piece.start <= joined.back().end + tolerance)
          joined.back().end = std::max(joined.back().end, piece.end);
        else
          joined.push_back(piece);
      return CrackSet(joined, tolerance);
    }


    /// Per boundary part (per region share where it has shares): the force
    /// on the body and the part's mean displacement.
    std::vector<std::pair<Tensor<1, 2>, Tensor<1, 2>>>
    part_pairs(const std::vector<PartForce> &parts)
    {
      std::vector<std::pair<Tensor<1, 2>, Tensor<1, 2>>> pairs;
      for (const PartForce &part : parts)
        if (!part.regions.empty())
          for (const auto &share : part.regions)
            pairs.emplace_back(share.force, share.mean_displacement);
        else
          for (unsigned int l = 0; l < part.layer_force.size(); ++l)
            pairs.emplace_back(part.layer_force[l],
                               part.layer_mean_displacement[l]);
      return pairs;
    }


    /// sum F . u over the pairs (NaN where a force is not computed: 0).
    double
    pairing(const std::vector<std::pair<Tensor<1, 2>, Tensor<1, 2>>> &pairs)
    {
      double sum = 0;
      for (const auto &[f, u] : pairs)
        if (std::isfinite(f.norm()) && std::isfinite(u.norm()))
          sum += f * u;
      return sum;
    }


    std::string
    format(const double x, const int digits = 6)
    {
      std::ostringstream out;
      out << std::setprecision(digits) << x;
      return out.str();
    }


    /// Path following: the factor of the load factor that makes the
    /// separations @p delta take the step (the first step: to the elastic
    /// limit), as CohesiveZone::scale_for_*() give it.
    double
    path_factor(const CohesiveParameters                    &parameters,
                const CohesiveZone                          &zone,
                const std::vector<CohesiveZone::Separation> &delta,
                const bool                                   to_onset,
                const double                                 fraction,
                const double                                 target,
                int                                         &control)
    {
      if (to_onset)
        return zone.scale_for_onset(delta);
      if (parameters.control == CohesiveControl::separation)
        return zone.scale_for_increment(
          delta, fraction * parameters.separation_increment, control);
      return zone.scale_for_dissipation(delta, target);
    }


    /// The line of a step at a prescribed load factor that does not settle.
    std::string
    not_settled(const unsigned int        step,
                const double              lambda,
                const double              change,
                const CohesiveParameters &parameters)
    {
      return "the secant iteration of step " + std::to_string(step) +
             " at load factor " + format(lambda, 8) +
             " did not settle in Cohesive/Maximum iterations = " +
             std::to_string(parameters.maximum_iterations) +
             " (damage still changes by " + format(change, 3) +
             "): the load factor may lie past a limit point of the "
             "curve; Cohesive/Control = dissipation traces it through";
    }
  } // namespace


  bool
  Study::run_cohesive()
  {
    AssertThrow(cycle_records.empty(),
                ExcMessage("Study::run_cohesive: a study runs one driver"));
    const CohesiveParameters &parameters = scene.cohesive;
    AssertThrow(parameters.active(),
                ExcMessage("Study::run_cohesive needs Cohesive/Law"));
    if (distribution.n_processes() > 1)
      throw CollectiveError(
        "Cohesive/Law runs in one process (the damage update reads the jumps "
        "of every subproblem), got " +
        std::to_string(distribution.n_processes()));
    growth_run       = true;
    outputs.deferred = true;
    model.name_states_as_steps();
    const std::unique_ptr<CohesiveLaw> law = make_cohesive_law(parameters.law);
    const bool  path = parameters.control != CohesiveControl::load_factor;
    Timer       total;
    CycleRecord first;
    const std::unique_ptr<CohesiveZone> zone =
      start_cohesive(first, *law, path);
    written_zone = zone.get();
    // (The zone lives until this function returns.)
    const std::shared_ptr<void> forget(nullptr, [this](void *) {
      written_zone = nullptr;
    });

    const unsigned int n_steps =
      path ? parameters.steps : scene.loads.load_factors.size();
    double      lambda = path ? 1. : scene.loads.load_factors[0];
    std::string stop;
    try
      {
        for (unsigned int step = 0; step < n_steps; ++step)
          {
            Timer        timer;
            CycleRecord  later;
            CycleRecord &record = step == 0 ? first : later;
            record.cycle        = step;
            if (step > 0)
              {
                reuse_meshes(record);
                record.multipliers = first.multipliers;
              }
            if (!path)
              lambda = scene.loads.load_factors[step];
            set_load_factor(lambda);
            const unsigned int   cracked_before = zone->summary().n_cracked;
            const CohesiveSettle settled        = settle_or_halve(
              record, *zone, lambda, path && step == 0 && zone->undamaged());
            if (settled.exhausted)
              {
                // (The state of the last step stands.)
                stop = "the zone has dissipated all it can (all but 1e-6 of "
                       "its toughness times its length)";
                break;
              }
            const double damage_growth = zone->largest_damage_growth();
            zone->commit();
            assess(record);
            write(record, step == 0 ? total : timer);
            print_report(record);
            distribution.barrier();
            record_cohesive_step(*zone, step, settled, lambda);
            // (The springs of the last trial damage act from the next step
            // on: the record is the state solved, checked with the springs
            // it was solved with.)
            model.set_cohesive_compliance(zone->compliance(),
                                          parameters.interface);
            if (!record.accepted())
              {
                stop = "a step failed its checks";
                break;
              }
            if (zone->fully_damaged())
              {
                // (A node whose damage jumps by more than a half to 1
                // within one step of a prescribed load factor: the load
                // factor lies past the limit point, and the rest of the
                // zone broke at once.)
                if (!path && zone->summary().n_cracked > cracked_before &&
                    damage_growth > 0.5)
                  throw RunFailure(
                    step,
                    "the cohesive zone broke completely within step " +
                      std::to_string(step) + " at load factor " +
                      format(lambda, 8) +
                      ": the load factor lies past the limit point of the "
                      "curve (its peak); Cohesive/Control = dissipation "
                      "traces the curve through it");
                // (Under prescribed load factors the run goes on: the
                // crack's faces touch and slide, with friction if asked.)
                if (path)
                  {
                    stop = "the whole zone is a crack";
                    break;
                  }
              }
          }
      }
    catch (const RunFailure &)
      {
        write_growth(true);
        write_cohesive(0, nullptr);
        throw;
      }
    finish_cohesive(stop, path, *zone);
    return stop != "a step failed its checks";
  }


  std::unique_ptr<CohesiveZone>
  Study::start_cohesive(CycleRecord       &first,
                        const CohesiveLaw &law,
                        const bool         path)
  {
    const CohesiveParameters &parameters = scene.cohesive;
    // The meshes of the last cycle, the subproblems factorised once; the
    // zone joins the crack of its interface.
    model.keep_meshes();
    set_up_cycle(first, scene.mesh.n_cycles - 1);
    const unsigned int i      = parameters.interface;
    const auto        &curves = model.geometry().interface_curves();
    AssertThrow(i < curves.size(),
                ExcMessage("Cohesive/Interface must be 1 to " +
                           std::to_string(curves.size()) + ", got " +
                           std::to_string(i + 1)));
    const double tolerance = curves[i].tolerance();
    try
      {
        model.set_crack(
          join_zone(curves[i].crack(), parameters.zone, tolerance), i, true);
      }
    catch (const ExceptionBase &e)
      {
        // (The crack joined with the zone: the zone's pieces are what the
        // user wrote.)
        AssertThrow(false,
                    ExcMessage("Cohesive/Zone: its pieces join the crack of "
                               "interface " +
                               std::to_string(i + 1) + ", and " +
                               one_line_message(e)));
      }
    model.update_tips(first);
    growth_steps.clear();
    followed.clear();
    cohesive_steps.clear();
    cohesive_newton.reset();
    cohesive_newton_skipped.clear();
    point_subproblems.clear();
    for (const Point<2> &p : scene.output.displacement_points)
      point_subproblems.push_back(model.point_subproblem(p));
    AssertThrow(!path || proportional_loading(),
                ExcMessage("Cohesive/Control = separation or dissipation needs "
                           "proportional loads (no preload, no friction): "
                           "the steps scale the load factor"));
    model.set_up_interface(first, nullptr);
    AssertThrow(!model.floating_parts().any(),
                ExcMessage("Cohesive/Law needs every subproblem held by a "
                           "clamped side (a floating subproblem's anchors "
                           "know no cohesive springs)"));
    auto zone = std::make_unique<CohesiveZone>(
      law, model.interface().space(), i, parameters.zone, tolerance);
    model.set_cohesive_compliance(zone->compliance(), i);
    rout << "cohesive zone: " << law.describe() << "; "
         << zone->summary().n_nodes << " nodes on interface " << i + 1
         << std::endl;
    return zone;
  }


  void
  Study::finish_cohesive(std::string        &stop,
                         const bool          path,
                         const CohesiveZone &zone)
  {
    if (stop.empty())
      stop = path ? "the steps are done" : "the load factors are done";
    growth_stop = stop;
    // The last step's fields and zone where Output/Written steps = last
    // (or every N and the last is not a multiple of N).
    const unsigned int last =
      cohesive_steps.empty() ? 0 : cohesive_steps.size() - 1;
    if (stop != "a step failed its checks" && scene.output.written_steps_last &&
        !scene.output.writes_step(last) && !cohesive_steps.empty())
      {
        write_step_fields(last);
        write_cohesive(last, &zone);
      }
    write_growth(true);
    rout << "cohesive: " << cohesive_steps.size() << " steps, " << stop
         << std::endl;
    // The process zone's resolution while the zone cracks (the median
    // over those steps: the zone's ends shorten it for a few): fewer
    // than 3 nodes in it and the curve follows the mesh node by node (a
    // saw tooth; docs/cohesive.md, choosing the mesh).
    std::vector<unsigned int> held;
    for (const CohesiveStep &r : cohesive_steps)
      if (r.cracked_nodes > 0 && r.cracked_nodes < zone.summary().n_nodes)
        held.push_back(r.process_nodes);
    std::sort(held.begin(), held.end());
    if (!held.empty() && held[held.size() / 2] < 3)
      rout << "cohesive: the process zone held " << held[held.size() / 2]
           << " node(s) while the zone cracked (the median over " << held.size()
           << " steps; fewer than 3): the curve follows the nodes one by "
              "one; a finer mesh along the zone or a longer cohesive length "
              "resolves it (docs/cohesive.md)"
           << std::endl;
  }


  Study::CohesiveSettle
  Study::settle_or_halve(CycleRecord  &record,
                         CohesiveZone &zone,
                         double       &lambda,
                         const bool    to_onset)
  {
    const CohesiveParameters &parameters = scene.cohesive;
    const unsigned int        step       = record.cycle;
    // A path-following step that does not settle is taken again
    // from its start with half the increment, down to 1/64.
    const double                      start             = lambda;
    const dealii::BlockVector<double> start_multipliers = model.multipliers();
    CohesiveSettle                    settled;
    if (parameters.control == CohesiveControl::dissipation && !to_onset &&
        zone.exhausted())
      {
        settled.exhausted = true;
        return settled;
      }
    for (double fraction = 1;; fraction /= 2)
      {
        settled =
          settle_cohesive_step(record, zone, lambda, to_onset, fraction);
        if (settled.converged)
          break;
        if (fraction <= 1. / 64)
          throw RunFailure(
            step,
            "the secant iteration of step " + std::to_string(step) +
              " did not settle in Cohesive/Maximum iterations = " +
              std::to_string(parameters.maximum_iterations) +
              " even with 1/64 of the increment (" +
              (std::isinf(settled.change) ?
                 std::string("an iterate's separations could not carry "
                             "the increment") :
                 "its damage or load factor still changes by " +
                   format(settled.change, 3)) +
              "): a larger Damage tolerance or a finer mesh may let it");
        rout << "step " << step
             << ": the secant iteration did not settle; the "
                "increment halved to "
             << fraction / 2 << " of its value" << std::endl;
        zone.reset_trial();
        lambda = start;
        set_load_factor(lambda);
        model.set_multipliers(start_multipliers);
        model.set_cohesive_compliance(zone.compliance(), parameters.interface);
      }
    return settled;
  }


  Study::CohesiveSettle
  Study::settle_cohesive_step(CycleRecord  &record,
                              CohesiveZone &zone,
                              double       &lambda,
                              const bool    to_onset,
                              const double  fraction)
  {
    const CohesiveParameters &parameters = scene.cohesive;
    const unsigned int        i          = parameters.interface;
    const unsigned int        step       = record.cycle;
    const bool   path   = parameters.control != CohesiveControl::load_factor;
    const double target = zone.committed_dissipation() +
                          fraction * parameters.dissipation_increment;
    // The secant iteration: solve with the springs of the trial damage,
    // new trial damage from the separations (and, with path following,
    // the load factor of the step's increment), until nothing changes.
    CohesiveSettle      settled;
    SolverResult        work;
    AndersonMixing      mixing(anderson_depth);
    int                 control = -1;
    std::vector<double> iterate;
    unsigned int        solved_cracked = 0;
    const auto          solve          = [&](const std::string &what) {
      solved_cracked = zone.summary().n_cracked;
      model.solve(record);
      work.add_work(record.result);
      if (!record.result.converged)
        throw RunFailure(step,
                         "the outer solve of " + what +
                           " did not converge: " + record.result.message);
    };
    // The first iterate: the Newton method's solution (Method = newton)
    // where it converges, else the histories extrapolated from the last
    // two steps by the fraction of this one (from the third step: the
    // first's increment, from the unloaded state, is no tangent).
    settled.newton_iterations =
      !to_onset && parameters.newton ?
        newton_first_iterate(zone, lambda, fraction, target, control, work) :
        -1;
    if (settled.newton_iterations < 0 && !to_onset && step >= 2)
      {
        iterate = zone.predicted_histories(fraction);
        zone.set_trial_histories(iterate);
        model.set_cohesive_compliance(zone.compliance(), i);
      }
    for (settled.iterations = 1;; ++settled.iterations)
      {
        solve("secant iteration " + std::to_string(settled.iterations));
        const auto delta =
          zone.separations(model.interface(), model.solutions());
        double factor = 1;
        if (path)
          {
            factor = path_factor(
              parameters, zone, delta, to_onset, fraction, target, control);
            // (An iterate whose separations cannot carry the step, or
            // whose mixities leave the zone less to dissipate than the
            // step asks: the step is taken again with a smaller
            // increment.)
            if ((std::isnan(factor) && settled.iterations > 1) ||
                (std::isinf(factor) && !to_onset &&
                 parameters.control == CohesiveControl::dissipation))
              {
                settled.converged = false;
                settled.change    = std::numeric_limits<double>::infinity();
                return settled;
              }
            if (!std::isfinite(factor) || !(factor > 0))
              throw RunFailure(step,
                               "Cohesive/Control: no node of the zone opens "
                               "under the loads; they cannot drive it");
          }
        // (The iterate x of the fixed point, unclipped: the zone clips it
        // to the committed histories.)
        if (iterate.empty())
          iterate = zone.trial_histories();
        const double change        = zone.try_separations(delta, factor);
        const double lambda_change = std::abs(factor - 1);
        if (scene.output.progress_interval > 0)
          pcout << "  secant iteration " << settled.iterations
                << ": damage change " << std::scientific << std::setprecision(3)
                << change << ", load factor change " << lambda_change
                << std::defaultfloat << std::endl;
        if (change <= parameters.damage_tolerance &&
            lambda_change <= parameters.damage_tolerance)
          break;
        if (settled.iterations >= parameters.maximum_iterations)
          {
            if (path)
              {
                // (The caller takes the step again with a smaller
                // increment.)
                settled.converged = false;
                settled.change    = std::max(change, lambda_change);
                return settled;
              }
            throw RunFailure(step,
                             not_settled(step, lambda, change, parameters));
          }
        if (path)
          {
            lambda *= factor;
            set_load_factor(lambda);
            model.scale_multipliers(factor);
          }
        // Anderson acceleration of the fixed point x = G(x), x the trial
        // histories (G: the histories of the separations solved with the
        // springs of x's damage).
        iterate = mixing.next(iterate, zone.trial_histories());
        zone.set_trial_histories(iterate);
        model.set_cohesive_compliance(zone.compliance(), i);
      }
    // A node that broke in the last update is a crack face from now on
    // (contact, friction): the step's state is solved again with it, so
    // that the record holds the tractions of the crack.
    if (zone.summary().n_cracked != solved_cracked)
      {
        model.set_cohesive_compliance(zone.compliance(), i);
        solve("the step with its broken nodes as crack faces");
      }
    record.result.iterations       = work.iterations;
    record.result.subdomain_solves = work.subdomain_solves;
    return settled;
  }


  void
  Study::record_cohesive_step(const CohesiveZone   &zone,
                              const unsigned int    step,
                              const CohesiveSettle &settled,
                              const double          lambda)
  {
    growth_steps.push_back(
      growth_step(cycle_records.back(), lambda, "cohesive"));
    // The zone, the path's work and the balance of energy.
    const CohesiveZone::Summary s = zone.summary();
    CohesiveStep                row;
    row.step                   = step;
    row.iterations             = settled.iterations;
    row.newton_iterations      = settled.newton_iterations;
    row.load_factor            = lambda;
    row.conjugate_displacement = growth_steps.back().conjugate_displacement;
    // The work of the boundary forces along the path (trapezoidal rule per
    // part: exact where each part's force and displacement are uniform on
    // it, as a prescribed displacement or a uniform traction), less the
    // stored energy, half the present forces' work (Clapeyron).
    const auto now = part_pairs(growth_steps.back().parts);
    const auto old =
      growth_steps.size() > 1 ?
        part_pairs(growth_steps[growth_steps.size() - 2].parts) :
        std::vector<std::pair<Tensor<1, 2>, Tensor<1, 2>>>(now.size());
    double increment = 0;
    for (unsigned int p = 0; p < now.size() && p < old.size(); ++p)
      if (std::isfinite(now[p].first.norm()) &&
          std::isfinite(old[p].first.norm()))
        increment +=
          0.5 * (now[p].first + old[p].first) * (now[p].second - old[p].second);
    row.external_work =
      (cohesive_steps.empty() ? 0. : cohesive_steps.back().external_work) +
      increment;
    row.dissipated_balance = row.external_work - 0.5 * pairing(now);
    row.dissipated         = s.dissipated;
    row.cracked_length     = s.cracked_length;
    row.process_length     = s.process_length;
    row.process_start      = s.process_start;
    row.process_end        = s.process_end;
    row.process_nodes      = s.n_process;
    row.cracked_nodes      = s.n_cracked;
    row.largest_damage     = s.largest_damage;
    row.largest_separation = s.largest_separation;
    cohesive_steps.push_back(row);
    write_growth(false);
    write_cohesive(step, scene.output.writes_step(step) ? &zone : nullptr);
    rout << "step " << step << ": load factor " << std::setprecision(8)
         << lambda << ", largest separation " << std::setprecision(6)
         << s.largest_separation << ", cracked " << s.cracked_length
         << ", process zone " << s.process_length;
    if (s.n_process > 0)
      rout << " (s " << s.process_start << " to " << s.process_end << ")";
    rout << ", dissipated " << s.dissipated << ", " << settled.iterations
         << " secant iterations";
    if (settled.newton_iterations >= 0)
      rout << " from " << settled.newton_iterations
           << " Newton iterations on the interface";
    rout << std::endl;
  }


  void
  Study::write_cohesive(const unsigned int step, const CohesiveZone *zone)
  {
    if (!distribution.is_root())
      return;
    const std::string &dir = scene.output.directory;
    write_atomically(dir + "/cohesive.csv", [&](std::ostream &o) {
      o << "# the cohesive driver's steps (docs/cohesive.md): q is the work-"
           "conjugate displacement of the load factor (the work of the unit "
           "loads on the solution); work the boundary forces' work along the "
           "path (trapezoidal rule per part, exact for forces and "
           "displacements uniform on each part); "
           "dissipated the zone's dissipated energy by the law at each node, "
           "dissipated_balance the work less the stored energy lambda q / 2; "
           "lengths per unit width; iterations the secant iteration's, "
           "newton_iterations those of the Newton method on the interface "
           "that gave its first iterate (-1: not used)\n";
      o << "step,load_factor,q,iterations,largest_separation,largest_damage,"
           "cracked_length,process_length,process_start,process_end,"
           "dissipated,work,dissipated_balance,process_nodes,"
           "newton_iterations\n";
      o << std::setprecision(12);
      for (const CohesiveStep &r : cohesive_steps)
        o << r.step << ',' << r.load_factor << ',' << r.conjugate_displacement
          << ',' << r.iterations << ',' << r.largest_separation << ','
          << r.largest_damage << ',' << r.cracked_length << ','
          << r.process_length << ',' << r.process_start << ',' << r.process_end
          << ',' << r.dissipated << ',' << r.external_work << ','
          << r.dissipated_balance << ',' << r.process_nodes << ','
          << r.newton_iterations << '\n';
    });
    if (zone == nullptr)
      return;
    const MultiplierSpace &space = model.interface().space();
    const unsigned int     b     = zone->block();
    std::ostringstream     name;
    name << dir << "/cohesive-" << std::setw(4) << std::setfill('0') << step
         << ".csv";
    const auto &mu = model.multipliers();
    write_atomically(name.str(), [&](std::ostream &o) {
      o << "# the zone's nodes at step " << step
        << ": s, damage, largest equivalent separation, mixity B = G_II / G, "
           "normal and tangential traction (the multipliers: compressive "
           "normal > 0)\n";
      o << "s,damage,history,mixity,traction_normal,traction_tangential\n";
      o << std::setprecision(12);
      for (unsigned int a = 0; a < space.n_nodes(b); ++a)
        if (zone->in_zone(a))
          o << space.node_position(a, b) << ',' << zone->damage(a) << ','
            << zone->history(a) << ',' << zone->mixity(a) << ','
            << mu.block(b)(Layout::entry(a, Layout::normal)) << ','
            << mu.block(b)(Layout::entry(a, Layout::tangential)) << '\n';
    });
  }
} // namespace bilayer
