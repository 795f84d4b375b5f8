// The study's drivers and the steps of a state: the meshes, the
// subproblems, the interface, the outer solve and the assessment.

#include <deal.II/base/thread_management.h>
#include <deal.II/base/timer.h>
#include <deal.II/base/utilities.h>
#include <deal.II/fe/fe_values.h>
#include <deal.II/grid/grid_tools.h>

#include <bilayer/core/progress.h>
#include <bilayer/core/tasks.h>
#include <bilayer/drivers/study.h>
#include <bilayer/parameters/expressions.h>
#include <bilayer/parameters/parameter_entries.h>
#include <bilayer/parameters/thermal_volume_load.h>
#include <bilayer/postprocess/estimator.h>
#include <bilayer/postprocess/mode_split.h>
#include <bilayer/solvers/coulomb_fixed_point.h>
#include <bilayer/solvers/outer_solver.h>

#include <cmath>
#include <iomanip>
#include <limits>
#include <sstream>

namespace bilayer
{
  using namespace dealii;

  namespace
  {
    /// The diameter of the bounding box of both meshes: the length over
    /// which the volume loads vary (the step of their gradients).
    double
    domain_diameter(const Geometry &domain)
    {
      Point<2> lower, upper;
      for (const unsigned int r : Layout::indices(domain.n_regions()))
        {
          const auto box =
            GridTools::compute_bounding_box(domain.triangulation(r));
          for (unsigned int d = 0; d < 2; ++d)
            {
              const double low  = box.get_boundary_points().first[d],
                           high = box.get_boundary_points().second[d];
              lower[d]          = r == 0 ? low : std::min(lower[d], low);
              upper[d]          = r == 0 ? high : std::max(upper[d], high);
            }
        }
      return lower.distance(upper);
    }


    /**
     * Loads/Temperature change at the vertices and at the Gauss points of
     * the assembly of the subproblem @p sub (its material @p material),
     * each checked finite (ThermalVolumeLoad::temperature_change(): "Loads/
     * Temperature change is not finite at (x, y) = (...)"). Done for every
     * subproblem wherever dT is not "0": a material that does not expand
     * builds no thermal load and never evaluates dT, yet a dT that is not
     * finite must be refused there as where a material expands (whose
     * assembly evaluates dT at these Gauss points and whose stress output
     * at the vertices), on the rectangle and on Gmsh scenes alike.
     */
    void
    check_temperature_change(const ElasticSubproblem &sub,
                             const LoadParameters    &loads,
                             const LayerMaterial     &material,
                             const double             length)
    {
      const ThermalVolumeLoad dT(
        nullptr,
        expressions::function(loads.temperature_change,
                              1,
                              "dT",
                              loads.constant_values,
                              "Loads/Temperature change"),
        material,
        length);
      FEValues<2> fe_values(
        sub.mapping(),
        sub.fe(),
        sub.fe().reference_cell().get_gauss_type_quadrature<2>(sub.fe().degree +
                                                               1),
        update_quadrature_points);
      for (const auto &cell : sub.dof_handler().active_cell_iterators())
        {
          fe_values.reinit(cell);
          for (const Point<2> &x : fe_values.get_quadrature_points())
            dT.temperature_change(x);
          for (const unsigned int v : cell->vertex_indices())
            dT.temperature_change(cell->vertex(v));
        }
    }
  } // namespace


  Study::Study(const Scene        &scene,
               std::ostream       &out,
               const Distribution &distribution)
    : scene(scene)
    , out(out)
    , distribution(distribution)
    , topology(scene.geometry.n_regions(), scene.materials.n_layers)
    , volume_loads(topology.n_subproblems())
    , pcout(out,
            scene.output.terminal == TerminalOutput::full &&
              distribution.is_root())
    , rout(out, distribution.is_root())
    , domain(scene.geometry,
             scene.mesh,
             scene.materials.all_ply_heights(),
             scene.materials.all_ply_groups())
    , subproblems(topology.n_subproblems())
    , coupling(scene.contact)
  {}


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
    if (topology.n_regions() > Layout::n_subdomains &&
        distribution.n_processes() > Distribution::max_groups)
      throw CollectiveError(
        std::string(scene.geometry.gmsh_file.empty() ?
                      "Geometry/Interfaces above Sigma" :
                      "Geometry/Gmsh file") +
        ": a scene of " + std::to_string(topology.n_regions()) +
        " regions runs on at most " + std::to_string(Distribution::max_groups) +
        " MPI processes, got " + std::to_string(distribution.n_processes()));
    const IterationClock clock;
    std::vector<double>  seconds, dofs;
    for (unsigned int cycle = 0; cycle < scene.mesh.n_cycles; ++cycle)
      {
        const CycleRecord &record = run_cycle(cycle);
        if (!record.accepted())
          return false;
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


  void
  Study::set_indicators(const std::vector<Vector<double>> &new_indicators)
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


  const CycleRecord &
  Study::run_cycle(const unsigned int cycle)
  {
    Timer       total;
    CycleRecord record;
    record.cycle = cycle;
    // The multipliers of the previous cycle, for a warm start (read before
    // the subproblems they live on are replaced).
    const bool warm =
      scene.solver.warm_start && !cycle_records.empty() && mu.size() > 0;
    const MultiplierSpace::Functions previous =
      warm ? coupling.space().functions(mu) : MultiplierSpace::Functions();

    build_meshes(record, cycle);
    check_memory(record);
    set_up_subproblems();
    count_subproblems(record);
    return solve_state(record, warm ? &previous : nullptr, total);
  }


  const CycleRecord &
  Study::solve_state(CycleRecord                      &record,
                     const MultiplierSpace::Functions *previous,
                     const Timer                      &total)
  {
    set_up_interface(record, previous);
    record.setup_seconds = total.wall_time();
    solve(record);
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
          {
            build_meshes(record, 0);
            set_crack(cracks[0]);
            update_tips(record);
            check_memory(record);
            set_up_subproblems();
            count_subproblems(record);
          }
        else
          {
            // The meshes and subproblems of state 0; the crack alone
            // changes, and with it the tips.
            set_crack(cracks[k]);
            reuse_meshes(record);
          }
        if (!solve_state(record, nullptr, total).accepted())
          return false;
      }
    return true;
  }


  PerSubproblem<const ElasticSubproblem *>
  Study::subproblem_views() const
  {
    PerSubproblem<const ElasticSubproblem *> views(subproblems.size());
    for (const unsigned int s : Layout::indices(subproblems.size()))
      views[s] = subproblems[s].get();
    return views;
  }


  void
  Study::build_meshes(CycleRecord &record, const unsigned int cycle)
  {
    for (auto &sub : subproblems)
      sub.reset();
    if (cycle > 0 && scene.mesh.refinement == Refinement::adaptive)
      {
        AssertThrow(!cycle_records.empty() &&
                      cycle_records.back().cycle + 1 == cycle,
                    ExcMessage("adaptive cycle " + std::to_string(cycle) +
                               " needs cycle " + std::to_string(cycle - 1) +
                               " of the same study first"));
        // The cells at a tip whose support of theta holds too few of them
        // (support_holds()) are refined as well (G is asked for at every
        // tip).
        std::vector<PointResolution> resolve;
        for (const CrackTip &tip : tips)
          if (tip.defined())
            resolve.push_back(
              {tip.point, tip.support_radius / min_cells_per_support_radius});
        domain.refine(indicators, resolve);
      }
    else
      {
        domain.create_meshes(cycle);
        if (cycle == 0)
          for (const std::string &name : domain.unread_surfaces())
            pcout << "bilayer: note: the physical surface '" << name
                  << "' of Geometry/Gmsh file is not among Materials/Layer "
                     "k/Ply groups: its cells take their region's law\n";
      }
    record.minus = domain.statistics(Subdomain::minus);
    // Above Sigma: every region there together.
    record.plus = domain.statistics(Subdomain::plus);
    for (unsigned int r = 2; r < domain.n_regions(); ++r)
      {
        const MeshStatistics more = domain.statistics(r);
        record.plus.vertices += more.vertices;
        record.plus.cells += more.cells;
        record.plus.h_min = std::min(record.plus.h_min, more.h_min);
        record.plus.h_max = std::max(record.plus.h_max, more.h_max);
      }
    record.P = domain.n_sigma_vertices();
    record.M = domain.n_outer_vertices();
    update_tips(record);
  }


  void
  Study::set_crack(const CrackSet &crack, const unsigned int i)
  {
    domain.set_crack(crack, i);
    tips_found = false;
  }


  void
  Study::reuse_meshes(CycleRecord &record)
  {
    const CycleRecord &front   = cycle_records.front();
    record.minus               = front.minus;
    record.plus                = front.plus;
    record.P                   = front.P;
    record.M                   = front.M;
    record.memory_estimate_mib = front.memory_estimate_mib;
    for (const auto &sub : subproblems)
      if (sub)
        record.dofs += sub->n_dofs();
    update_tips(record);
  }


  void
  Study::update_tips(const CycleRecord &record)
  {
    // The tips (and a refusal of Fracture/Support radius) before anything
    // is computed or written.
    if (!tips_found && scene.fracture.energy_release_rate)
      {
        // The tips of each interface in turn; the other interfaces are
        // obstacles of its supports.
        const std::vector<InterfaceCurve> &curves = domain.interface_curves();
        const std::vector<Segment>         material_faces = ply_boundaries();
        tips.clear();
        for (const unsigned int i : Layout::indices(curves.size()))
          {
            std::vector<InterfaceCurve> others;
            for (const unsigned int j : Layout::indices(curves.size()))
              if (j != i)
                others.push_back(curves[j]);
            const std::vector<CrackTip> on_i =
              crack_tips(curves[i],
                         {{&domain.triangulation(i),
                           &domain.triangulation(i + 1)}},
                         scene.fracture.support_radius,
                         i,
                         others,
                         material_faces);
            tips.insert(tips.end(), on_i.begin(), on_i.end());
          }
        tips_found = true;
      }
    if (!tips.empty())
      check_supports(record);
  }


  void
  Study::set_up_subproblems()
  {
    // The loads of each layer, then the set-ups (assembly and
    // factorisation) as parallel tasks.
    const unsigned int n_slots = Layout::n_slots(scene.materials.n_layers);
    std::vector<decltype(scene.loads.prescribed_function(Layer::first))>
      prescribed(n_slots);
    std::vector<std::vector<std::unique_ptr<FunctionParser<2>>>>
                                                  traction_owners(n_slots);
    std::vector<std::vector<const Function<2> *>> traction(n_slots);
    Tasks                                         setups;
    for (const Layer layer : scene.materials.layers())
      if (scene.materials.has_layer(layer))
        {
          const unsigned int l = static_cast<unsigned int>(layer);
          prescribed[l]        = scene.loads.prescribed_function(layer);
          for (unsigned int part = 0; part < scene.geometry.parts.size();
               ++part)
            {
              traction_owners[l].push_back(
                scene.loads.traction_function(layer, part));
              traction[l].push_back(traction_owners[l].back().get());
            }
          for (const unsigned int r : Layout::indices(topology.n_regions()))
            {
              const unsigned int i = topology.index(layer, r);
              // The regions above Sigma take the material of Omega+.
              const Subdomain side = Topology::material_side(r);
              // (The subproblem of the previous cycle, which referred to
              // it, is gone.)
              const std::vector<LayerMaterial> plies =
                scene.materials.ply_materials(layer, side);
              auto load =
                scene.loads.volume_load(layer,
                                        plies,
                                        scene.materials.division(layer),
                                        domain_diameter(domain));
              volume_loads[i] =
                load ? std::make_unique<ScaledVolumeLoad>(std::move(load)) :
                       nullptr;
              auto &sub = subproblems[i];
              sub =
                std::make_unique<ElasticSubproblem>(layer,
                                                    static_cast<Subdomain>(r),
                                                    domain.triangulation(r),
                                                    scene.mesh.degree(layer),
                                                    plies,
                                                    scene.materials.division(
                                                      layer),
                                                    distribution,
                                                    topology.n_regions());
              ElasticSubproblem *const target = sub.get();
              setups.add([&, target, l, i]() {
                target->setup(scene.geometry.clamped,
                              *prescribed[l],
                              traction[l],
                              scene.solver.shared_solver,
                              scene.solver.iterates_on_sigma(),
                              volume_loads[i].get());
              });
            }
        }
    setups.join_all();
    // (Collective: every process knows, the first reports in one line.)
    std::string problem;
    if (!expressions::is_zero(scene.loads.temperature_change))
      try
        {
          for (const Layer layer : scene.materials.layers())
            for (const unsigned int r : Layout::indices(topology.n_regions()))
              if (scene.materials.has_layer(layer) &&
                  subproblems[topology.index(layer, r)])
                check_temperature_change(
                  *subproblems[topology.index(layer, r)],
                  scene.loads,
                  scene.materials.material(layer, Topology::material_side(r)),
                  domain_diameter(domain));
        }
      catch (const ExceptionBase &e)
        {
          problem = one_line_message(e);
        }
    problem = distribution.first_error(problem);
    if (!problem.empty())
      throw CollectiveError(problem);
    // The load factor of the study (setup() assembles at 1).
    if (lambda != 1)
      set_load_factor(lambda);
  }


  void
  Study::count_subproblems(CycleRecord &record) const
  {
    for (const auto &sub : subproblems)
      if (sub)
        record.dofs += sub->n_dofs();
    for (const auto &sub : subproblems)
      if (sub != nullptr && sub->owned())
        {
          record.assembly_seconds += sub->assembly_seconds;
          record.factorisation_seconds += sub->factorisation_seconds;
        }
    // The busiest process's share.
    record.assembly_seconds = distribution.max(record.assembly_seconds);
    record.factorisation_seconds =
      distribution.max(record.factorisation_seconds);
  }


  void
  Study::set_up_interface(CycleRecord                      &record,
                          const MultiplierSpace::Functions *previous)
  {
    // The multiplier set reads the friction bound at the crack nodes and
    // refuses a bound that is negative or not finite there; every process
    // builds the same set, so every process knows, and the first reports
    // in one line (collective, no MPI_Abort).
    std::string problem;
    try
      {
        coupling.setup(topology, subproblem_views(), domain.interface_curves());
      }
    catch (const ExceptionBase &e)
      {
        problem = one_line_message(e);
      }
    problem = distribution.first_error(problem);
    if (!problem.empty())
      throw CollectiveError(problem);
    coupling.space().initialize(mu);
    if (previous != nullptr)
      coupling.space().interpolate(*previous, mu);
    record.multipliers = coupling.space().n_free();
  }


  void
  Study::solve(CycleRecord &record)
  {
    pcout << "Cycle " << record.cycle << ": " << record.minus.cells << " + "
          << record.plus.cells << " "
          << (domain.triangulation(Subdomain::minus)
                  .all_reference_cells_are_hyper_cube() ?
                "quadrilaterals" :
                "triangles")
          << ", P = " << record.P << ", M = " << record.M << ", " << record.dofs
          << " dofs, " << record.multipliers << " multipliers" << std::endl;
    if (!scene.geometry.gmsh_file.empty() && record.cycle == 0)
      pcout << "  Sigma from " << scene.geometry.gmsh_file << ": "
            << domain.interface_curve().description() << ", "
            << domain.interface_curve().crack().pieces().size()
            << " crack piece(s)" << std::endl;

    Timer               solve_timer;
    const unsigned long shared_before  = distribution.shared_values();
    const double        seconds_before = distribution.shared_seconds();
    if (scene.contact.friction == Friction::coulomb &&
        scene.contact.coulomb_method == CoulombMethod::fixed_point)
      {
        FixedPointRecord fixed_point;
        record.result =
          CoulombFixedPoint(scene.solver, scene.contact, scene.output, pcout)
            .solve(subproblem_views(), coupling, mu, w, fixed_point);
        record.friction_iterations   = fixed_point.iterations;
        record.friction_bound_change = fixed_point.bound_change;
      }
    else
      record.result = create_outer_solver(scene.solver, scene.output, pcout)
                        ->solve(subproblem_views(), coupling, mu, w);
    record.theta         = record.result.theta;
    record.solve_seconds = solve_timer.wall_time();
    if (scene.solver.dual_spectrum_steps > 0)
      {
        const DualSpectrum &s = record.spectrum =
          estimate_dual_spectrum(subproblem_views(),
                                 coupling,
                                 scene.solver.dual_spectrum_steps);
        pcout << "    dual operator S: lambda_min = " << s.lambda_min
              << ", lambda_max = " << s.lambda_max
              << ", condition number = " << s.condition_number()
              << ", lambda_min / h = " << (s.h > 0 ? s.lambda_min / s.h : 0.)
              << " (" << s.iterations << " Lanczos steps)" << std::endl;
      }
    record.processes      = distribution.n_processes();
    record.shared_values  = distribution.shared_values() - shared_before;
    record.shared_seconds = distribution.shared_seconds() - seconds_before;
  }


  void
  Study::assess(CycleRecord &record)
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
        record.layer_energy[static_cast<unsigned int>(topology.layer(s))] +=
          energies[s];
      }
    record.report = bilayer::assess(coupling, w, mu);
    if (!tips.empty())
      {
        record.release =
          energy_release_rates(subproblem_views(), coupling, w, mu, tips);
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
        // The error bar: G once more with the support radius halved where
        // R/2 still holds enough cells (the same mesh: a single-mesh
        // indicator), and the sequence of G over the cycles.
        std::vector<CrackTip> halved = tips;
        bool                  any    = false;
        for (unsigned int t = 0; t < halved.size(); ++t)
          {
            const bool resolved =
              tips[t].defined() && unresolved_tips[t].empty() &&
              support_holds(0.5 * tips[t].support_radius, tip_cell_sizes[t]);
            halved[t].support_radius =
              resolved ? 0.5 * tips[t].support_radius : 0.;
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
            for (auto previous = cycle_records.rbegin();
                 previous != cycle_records.rend() && expected > 0 &&
                 previous->cycle + 1 == expected &&
                 t < previous->release.size() && sequence.size() < 4;
                 ++previous, --expected)
              sequence.insert(sequence.begin(), previous->release[t].G);
            set_g_error(record.release[t], g_error_from_cycles(sequence));
          }
      }
    // The indicators mark the next adaptive cycle; their global sum is
    // reported on every mesh (and must be finite, checked below).
    if (estimates_error(record))
      indicators = estimate_error(subproblem_views(),
                                  coupling,
                                  w,
                                  mu,
                                  scene.mesh.interface_terms,
                                  scene.mesh.contact_weight,
                                  &record.eta);
    else
      record.eta = std::numeric_limits<double>::quiet_NaN();
    check(record);
  }
} // namespace bilayer
