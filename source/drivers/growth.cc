// The growth driver (Fracture/Crack growth, docs/fracture.md section 9):
// quasi-static Griffith growth of the crack along Sigma on one mesh, and
// the sweep of crack lengths. The subproblems are assembled and factorised
// once; each step sets the load factor and the crack, rebuilds the
// interface and solves on Sigma from the multipliers of the step before.

#include <deal.II/base/exceptions.h>

#include <bilayer/drivers/resources.h>
#include <bilayer/drivers/study.h>
#include <bilayer/postprocess/growth_law.h>

#include <algorithm>
#include <cmath>
#include <iomanip>
#include <limits>
#include <sstream>

namespace bilayer
{
  using namespace dealii;

  namespace
  {
    /// @p crack with the piece end at @p from moved to @p to; pieces that
    /// then touch or overlap are merged.
    CrackSet
    moved_end(const CrackSet &crack,
              const double    from,
              const double    to,
              const double    tolerance)
    {
      std::vector<CrackSet::Piece> pieces = crack.pieces();
      for (auto &piece : pieces)
        {
          if (std::abs(piece.start - from) <= tolerance)
            piece.start = to;
          else if (std::abs(piece.end - from) <= tolerance)
            piece.end = to;
        }
      std::sort(pieces.begin(), pieces.end(), [](const auto &a, const auto &b) {
        return a.start < b.start;
      });
      std::vector<CrackSet::Piece> merged;
      for (const auto &piece : pieces)
        if (!merged.empty() && piece.start <= merged.back().end + tolerance)
          merged.back().end = std::max(merged.back().end, piece.end);
        else
          merged.push_back(piece);
      return CrackSet(merged, tolerance);
    }

    /// The length of the crack piece that ends at @p s (0 if none).
    double
    piece_length(const CrackSet &crack, const double s, const double tolerance)
    {
      for (const auto &piece : crack.pieces())
        if (std::abs(piece.start - s) <= tolerance ||
            std::abs(piece.end - s) <= tolerance)
          return piece.end - piece.start;
      return 0;
    }

    double
    total_length(const CrackSet &crack)
    {
      double sum = 0;
      for (const auto &piece : crack.pieces())
        sum += piece.end - piece.start;
      return sum;
    }
  } // namespace


  bool
  Study::run_growth()
  {
    AssertThrow(cycle_records.empty(),
                ExcMessage("Study::run_growth: a study runs one driver"));
    const FractureParameters &fracture = scene.fracture;
    AssertThrow(fracture.growth != CrackGrowth::none,
                ExcMessage("Study::run_growth needs Fracture/Crack growth"));
    growth_run       = true;
    outputs.deferred = true;
    model.name_states_as_steps();
    const bool sweep = fracture.growth == CrackGrowth::sweep;

    // Subproblems shared by groups of processes (more than four) keep the
    // load of their set-up: refused before anything is built, by every
    // process together.
    bool scaled = false;
    for (const double lambda : scene.loads.load_factors)
      scaled = scaled || lambda != 1;
    if (scaled && distribution.n_processes() > Distribution::max_groups)
      throw CollectiveError(
        "Loads/Load factor other than 1 needs at most four MPI processes "
        "(a subproblem shared by a group keeps the load of its set-up), got " +
        std::to_string(distribution.n_processes()));

    // State 0: the meshes of the last cycle, the subproblems factorised
    // once for all steps.
    Timer       total;
    CycleRecord first;
    model.keep_meshes();
    set_up_cycle(first, scene.mesh.n_cycles - 1);
    onsets_exact = !sweep && fracture.exact_onsets && proportional_loading();
    start_growth();

    // Loading starts at 0. Under proportional loading the critical loads
    // of the crack below the next load factor are steps of their own, each
    // followed by the growth it starts; the first of them may lie below
    // the first load factor (found by a probe at that factor).
    const std::vector<double> &factors = scene.loads.load_factors;
    double                     lambda  = 0;
    const auto step = [&](const double load, const std::string &kind) {
      CycleRecord record;
      return solve_growth_step(growth_steps.empty() ? first : record,
                               load,
                               kind,
                               total);
    };
    try
      {
        for (unsigned int j = 0; j < factors.size(); ++j)
          {
            while (onsets_exact)
              {
                const double onset = growth_steps.empty() ?
                                       probe_onset(first, factors[0]) :
                                       next_onset();
                if (!(onset > lambda * (1 + 1e-12) &&
                      onset < factors[j] * (1 - 1e-12)))
                  break;
                lambda = onset;
                if (!step(lambda, "onset") || !grow_at_load(lambda, total))
                  return finish_growth(false);
                if (growth_stopped())
                  break;
              }
            lambda = factors[j];
            if (!step(lambda, "load") || !grow_at_load(lambda, total))
              return finish_growth(false);
          }
      }
    catch (const RunFailure &)
      {
        // A step that cannot go on: the records so far, in summary.json
        // too.
        write_growth(true);
        throw;
      }
    return finish_growth(true);
  }


  void
  Study::start_growth()
  {
    growth_steps.clear();
    followed.clear();
    const std::vector<CrackTip>       &tips = model.tips();
    const std::vector<InterfaceCurve> &curves =
      model.geometry().interface_curves();
    interface_vertices.clear();
    for (const unsigned int i : Layout::indices(curves.size()))
      interface_vertices.push_back(model.geometry().sigma_vertex_parameters(i));
    AssertThrow(!tips.empty(),
                ExcMessage("Fracture/Crack growth needs a crack with a tip "
                           "inside Omega (Geometry/Crack interval on Sigma, or "
                           "the crack groups of the Gmsh file)"));
    for (unsigned int t = 0; t < tips.size(); ++t)
      {
        FollowedTip tip;
        tip.number         = t + 1;
        tip.interface      = tips[t].interface;
        tip.s              = tips[t].s;
        tip.sign           = tips[t].sign;
        const double tol   = curves[tip.interface].tolerance();
        const auto  &on_it = interface_vertices[tip.interface];
        const bool   on_vertex =
          std::any_of(on_it.begin(), on_it.end(), [&](const double v) {
            return std::abs(v - tip.s) <= tol;
          });
        AssertThrow(on_vertex,
                    ExcMessage(
                      "Fracture/Crack growth: the crack tip at " +
                      tip_position(tips[t], scene.geometry.gmsh_file.empty()) +
                      " is not a vertex of its interface on both meshes "
                      "(non-matching traces): give both meshes a "
                      "vertex there"));
        followed.push_back(tip);
      }
    // The toughness, positive and finite at every vertex of every
    // interface where a tip may stand (off the crack: it never closes),
    // before the first step.
    for (const unsigned int i : Layout::indices(curves.size()))
      for (const double s : interface_vertices[i])
        if (!curves[i].crack().contains(s))
          {
            scene.fracture.toughness_at(curves[i].point(s), s);
            if (scene.fracture.mixed_mode_law != MixedModeLaw::mode_independent)
              scene.fracture.mode_ii_toughness_at(curves[i].point(s), s);
          }
    point_subproblems.clear();
    for (const Point<2> &p : scene.output.displacement_points)
      point_subproblems.push_back(model.point_subproblem(p));
    for (const unsigned int n : scene.fracture.growing_tips)
      AssertThrow(n <= tips.size(),
                  ExcMessage("Fracture/Growing tips: tip " + std::to_string(n) +
                             " does not exist, the crack has " +
                             std::to_string(tips.size()) + " tip(s)"));
  }


  double
  Study::next_onset()
  {
    double onset = std::numeric_limits<double>::infinity();
    for (FollowedTip &tip : followed)
      tip.onset = std::numeric_limits<double>::infinity();
    for (const GrowthTip &tip : growth_steps.back().tips)
      if (tip.present && tip_may_grow(tip.number) &&
          followed[tip.number - 1].stopped.empty())
        {
          followed[tip.number - 1].onset = tip.critical_load;
          onset                          = std::min(onset, tip.critical_load);
        }
    return onset;
  }


  double
  Study::probe_onset(const CycleRecord &first, const double lambda)
  {
    if (!(lambda > 0))
      return std::numeric_limits<double>::infinity();
    // The state at lambda, solved and assessed but neither written nor
    // printed: its critical loads are those of the crack (G ~ lambda^2).
    CycleRecord probe = first;
    const bool  shown = pcout.is_active();
    pcout.set_condition(false);
    try
      {
        set_load_factor(lambda);
        model.set_up_interface(probe, nullptr);
        model.solve(probe);
        assess(probe);
      }
    catch (...)
      {
        pcout.set_condition(shown);
        throw;
      }
    pcout.set_condition(shown);
    double onset = std::numeric_limits<double>::infinity();
    if (!probe.result.converged)
      return onset;
    for (unsigned int t = 0; t < probe.release.size() && t < followed.size();
         ++t)
      {
        const EnergyReleaseRate &g = probe.release[t];
        if (!tip_may_grow(followed[t].number) || !g.tip.defined() ||
            !std::isfinite(g.G))
          continue;
        const GrowthCriterion f = criterion_at(g);
        if (f.undefined.empty())
          {
            followed[t].onset = critical_load_factor(f, lambda);
            onset             = std::min(onset, followed[t].onset);
          }
      }
    return onset;
  }


  EnergyReleaseRate
  Study::law_split(const EnergyReleaseRate &g) const
  {
    // The split of the stress intensity factors: G cos^2 psi, G sin^2 psi.
    EnergyReleaseRate split = g;
    if (scene.fracture.mode_mix_from_k)
      {
        const double psi = g.K_phase_angle * numbers::PI / 180;
        split.G_I        = g.G * std::cos(psi) * std::cos(psi);
        split.G_II       = g.G * std::sin(psi) * std::sin(psi);
        if (!std::isfinite(psi))
          split.mode_split_note =
            "no phase angle of K" +
            (g.K_note.empty() ? std::string() : ": " + g.K_note);
      }
    return split;
  }


  GrowthCriterion
  Study::criterion_at(const EnergyReleaseRate &g) const
  {
    const FractureParameters &fracture = scene.fracture;
    return growth_criterion(fracture.mixed_mode_law,
                            fracture.mixed_mode_exponent,
                            law_split(g),
                            fracture.toughness_at(g.tip.point, g.tip.s),
                            fracture.mode_ii_toughness_at(g.tip.point, g.tip.s),
                            split_resolution(
                              scene.solver.acceptance_tolerance));
  }


  bool
  Study::estimates_error(const CycleRecord &record) const
  {
    return !growth_run || record.cycle == 0;
  }


  bool
  Study::tip_may_grow(const unsigned int number) const
  {
    const auto &list = scene.fracture.growing_tips;
    return list.empty() ||
           std::find(list.begin(), list.end(), number) != list.end();
  }


  bool
  Study::growth_stopped() const
  {
    for (const FollowedTip &tip : followed)
      if (tip.present && tip.stopped.empty() && tip_may_grow(tip.number))
        return false;
    return true;
  }


  bool
  Study::solve_growth_step(CycleRecord       &record,
                           const double       lambda,
                           const std::string &kind,
                           const Timer       &total)
  {
    const unsigned int step = growth_steps.size();
    if (step >= scene.fracture.maximum_growth_steps)
      {
        const std::string limit =
          "Fracture/Maximum growth steps = " +
          std::to_string(scene.fracture.maximum_growth_steps);
        std::ostringstream at;
        at << std::setprecision(8) << lambda;
        throw RunFailure(step,
                         kind == "growth" ?
                           "the crack still grows (at load factor " + at.str() +
                             ") after " + limit + " steps" :
                           limit +
                             " steps reached before the load factors "
                             "are done (the next: " +
                             at.str() +
                             "): raise it, or give fewer Loads/Load factor");
      }
    Timer timer;
    set_load_factor(lambda);
    const bool warm = step > 0 && model.multipliers().size() > 0;
    const MultiplierSpace::Functions previous =
      warm ? model.multiplier_functions() : MultiplierSpace::Functions();
    record.cycle = step;
    if (step > 0)
      reuse_meshes(record);
    const bool accepted =
      solve_state(record, warm ? &previous : nullptr, step > 0 ? timer : total)
        .accepted();
    growth_steps.push_back(growth_step(cycle_records.back(), lambda, kind));
    write_growth(false);
    print_growth_step(growth_steps.back());
    return accepted;
  }


  GrowthStep
  Study::growth_step(const CycleRecord &record,
                     const double       lambda,
                     const std::string &kind)
  {
    const FractureParameters          &fracture = scene.fracture;
    const std::vector<InterfaceCurve> &curves =
      model.geometry().interface_curves();
    GrowthStep step;
    step.step         = record.cycle;
    step.load_factor  = lambda;
    step.kind         = kind;
    step.energy       = record.energy;
    step.parts        = record.forces.parts;
    step.crack_length = crack_length();
    measure_loading(step);
    for (FollowedTip &followed_tip : followed)
      {
        GrowthTip tip;
        tip.number = followed_tip.number;
        if (!followed_tip.present)
          {
            step.tips.push_back(tip);
            continue;
          }
        // The tip of this record at the followed position (none: the piece
        // merged with another, or reached an end of its interface).
        const CrackSet &crack      = curves[followed_tip.interface].crack();
        const double    tol        = curves[followed_tip.interface].tolerance();
        const EnergyReleaseRate *g = nullptr;
        for (const EnergyReleaseRate &candidate : record.release)
          if (candidate.tip.interface == followed_tip.interface &&
              std::abs(candidate.tip.s - followed_tip.s) <= 10 * tol &&
              candidate.tip.sign == followed_tip.sign)
            g = &candidate;
        if (!g)
          {
            followed_tip.present = false;
            step.tips.push_back(tip);
            continue;
          }
        tip.present                   = true;
        tip.s                         = g->tip.s;
        tip.point                     = g->tip.point;
        tip.G                         = g->G;
        const EnergyReleaseRate split = law_split(*g);
        tip.G_I                       = split.G_I;
        tip.G_II                      = split.G_II;
        tip.piece_length              = piece_length(crack, tip.s, 10 * tol);
        if (!g->tip.defined())
          followed_tip.stopped = "at a corner of Sigma";
        else if (!std::isfinite(g->G))
          followed_tip.stopped = "G not resolved: " + g->unresolved;
        else
          {
            const GrowthCriterion f = criterion_at(*g);
            if (!f.undefined.empty() && tip_may_grow(tip.number))
              throw RunFailure(step.step,
                               "Fracture/Mixed-mode law: tip " +
                                 std::to_string(tip.number) + ": " +
                                 f.undefined);
            tip.criterion = f.value;
            // At an onset step, the tips whose critical load it is are
            // critical by construction (G of the new solve differs from
            // the prediction by the solver's tolerance, not by physics).
            tip.critical =
              is_critical(f) ||
              (kind == "onset" &&
               std::abs(followed_tip.onset - lambda) <= 1e-12 * lambda);
            if (onsets_exact || fracture.growth == CrackGrowth::sweep)
              if (proportional_loading())
                tip.critical_load = critical_load_factor(f, lambda);
          }
        tip.status =
          !tip_may_grow(tip.number)     ? "held" :
          !followed_tip.stopped.empty() ? "stopped: " + followed_tip.stopped :
          tip.critical                  ? "critical" :
                                          "below critical";
        step.tips.push_back(tip);
      }
    return step;
  }


  bool
  Study::grow_at_load(const double lambda, const Timer &total)
  {
    const bool sweep = scene.fracture.growth == CrackGrowth::sweep;
    bool       first = true;
    while (true)
      {
        // The tips that grow now: every free tip of a sweep, the critical
        // ones of quasi-static growth.
        std::vector<unsigned int> growing;
        for (const GrowthTip &tip : growth_steps.back().tips)
          {
            const FollowedTip &f = followed[tip.number - 1];
            if (tip.present && f.stopped.empty() && tip_may_grow(tip.number) &&
                (sweep || tip.critical))
              growing.push_back(tip.number - 1);
          }
        if (growing.empty() || !advance_tips(growing))
          return true;
        // Growth at this load that goes on after its first step.
        if (!sweep && !first)
          growth_steps.back().unstable = true;
        first = false;
        CycleRecord record;
        if (!solve_growth_step(record, lambda, "growth", total))
          return false;
      }
  }


  bool
  Study::advance_tips(const std::vector<unsigned int> &growing)
  {
    const std::vector<InterfaceCurve> &curves =
      model.geometry().interface_curves();
    std::vector<CrackSet> cracks;
    for (const InterfaceCurve &curve : curves)
      cracks.push_back(curve.crack());
    std::vector<bool> moved(curves.size(), false);
    for (const unsigned int i : growing)
      {
        FollowedTip          &tip      = followed[i];
        const InterfaceCurve &curve    = curves[tip.interface];
        const auto           &vertices = interface_vertices[tip.interface];
        CrackSet             &crack    = cracks[tip.interface];
        const double          tol      = curve.tolerance();
        auto                  at =
          std::lower_bound(vertices.begin(), vertices.end(), tip.s - tol);
        int         index = at - vertices.begin();
        double      s     = tip.s;
        std::string stop;
        // Sigma, or interface K >= 2 by its number.
        const std::string name =
          tip.interface == 0 ? std::string("Sigma") :
                               "interface " + std::to_string(tip.interface + 1);
        for (unsigned int k = 0; k < scene.fracture.growth_increment; ++k)
          {
            const int next = index + (tip.sign > 0 ? 1 : -1);
            if (next < 0 || next >= static_cast<int>(vertices.size()))
              {
                stop = "at the end of " + name;
                break;
              }
            const double   candidate_s = vertices[next];
            const CrackSet candidate   = moved_end(crack, s, candidate_s, tol);
            std::string    refusal     = curve.crack_refusal(candidate);
            if (refusal.empty())
              refusal = model.support_refusal(candidate, tip.interface);
            if (!refusal.empty())
              {
                stop = refusal;
                break;
              }
            crack = candidate;
            s     = candidate_s;
            index = next;
            Tensor<1, 2> before, after;
            if (crack.contains(s) || crack.mouth(s))
              {
                stop = crack.mouth(s) ? "reached the end of " + name :
                                        "merged with the next crack piece";
                break;
              }
            if (curve.corner(s, before, after))
              {
                stop = "at a corner of " + name;
                break;
              }
          }
        if (s != tip.s)
          {
            moved[tip.interface] = true;
            tip.s                = s;
          }
        if (!stop.empty())
          tip.stopped = stop;
      }
    bool any = false;
    for (const unsigned int i : Layout::indices(curves.size()))
      if (moved[i])
        {
          model.set_crack(cracks[i], i);
          any = true;
        }
    return any;
  }


  double
  Study::crack_length() const
  {
    double length = 0;
    for (const InterfaceCurve &curve : model.geometry().interface_curves())
      length += total_length(curve.crack());
    return length;
  }


  void
  Study::measure_loading(GrowthStep &step) const
  {
    // The work of the unit proportional loads, and layer 1's displacement
    // at the named points, each from the owner of its subproblem.
    step.conjugate_displacement = model.load_work();
    const auto &points          = scene.output.displacement_points;
    for (unsigned int i = 0; i < points.size(); ++i)
      step.point_displacements.push_back(
        model.point_displacement(points[i], point_subproblems[i]));
  }


} // namespace bilayer
