// The model of a scene: its meshes, the subproblems of its layers, the
// couplings on its interfaces, the outer solve and the assessment of a
// state.

#include <deal.II/base/timer.h>
#include <deal.II/fe/fe_values.h>
#include <deal.II/grid/grid_tools.h>

#include <bilayer/core/tasks.h>
#include <bilayer/model/model.h>
#include <bilayer/parameters/expressions.h>
#include <bilayer/parameters/parameter_entries.h>
#include <bilayer/parameters/thermal_volume_load.h>
#include <bilayer/solvers/coulomb_fixed_point.h>
#include <bilayer/solvers/outer_solver.h>

#include <cmath>
#include <limits>

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


  Model::Model(const Scene        &scene,
               const Distribution &distribution,
               ConditionalOStream &progress)
    : scene(scene)
    , distribution(distribution)
    , pcout(progress)
    , regions_and_layers(scene.geometry.n_regions(), scene.materials.n_layers)
    , volume_loads(regions_and_layers.n_subproblems())
    , domain(scene.geometry,
             scene.mesh,
             scene.materials.all_ply_heights(),
             scene.materials.all_ply_groups())
    , subproblems(regions_and_layers.n_subproblems())
    , coupling(scene.contact)
  {}


  void
  Model::build_meshes(CycleRecord       &record,
                      const unsigned int cycle,
                      const bool         refine)
  {
    for (auto &sub : subproblems)
      sub.reset();
    if (refine)
      {
        // The cells at a tip whose support of theta holds too few of them
        // (support_holds()) are refined as well (G is asked for at every
        // tip).
        std::vector<PointResolution> resolve;
        for (const CrackTip &tip : crack_tips_found)
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
    regions_and_layers = Topology(domain.n_regions(),
                                  scene.materials.n_layers,
                                  domain.interface_regions());
    describe_meshes(record);
    update_tips(record);
  }


  void
  Model::describe_meshes(CycleRecord &record) const
  {
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
  }


  void
  Model::set_crack(const CrackSet    &crack,
                   const unsigned int i,
                   const bool         whole_allowed)
  {
    domain.set_crack(crack, i, whole_allowed);
    tips_current = false;
  }


  PerSubproblem<const ElasticSubproblem *>
  Model::subproblem_views() const
  {
    PerSubproblem<const ElasticSubproblem *> views(subproblems.size());
    for (const unsigned int s : Layout::indices(subproblems.size()))
      views[s] = subproblems[s].get();
    return views;
  }


  Model::TractionFunctions
  Model::traction_functions() const
  {
    const unsigned int n_slots = Layout::n_slots(scene.materials.n_layers);
    TractionFunctions  functions;
    functions.owners.resize(n_slots);
    functions.by_layer.resize(n_slots);
    for (const Layer layer : scene.materials.layers())
      if (scene.materials.has_layer(layer))
        for (unsigned int part = 0; part < scene.geometry.parts.size(); ++part)
          {
            const unsigned int l = static_cast<unsigned int>(layer);
            functions.owners[l].push_back(
              scene.loads.traction_function(layer, part));
            functions.by_layer[l].push_back(functions.owners[l].back().get());
          }
    return functions;
  }


  void
  Model::set_up_subproblems()
  {
    // The loads of each layer, then the set-ups (assembly and
    // factorisation) as parallel tasks.
    const unsigned int n_slots = Layout::n_slots(scene.materials.n_layers);
    std::vector<decltype(scene.loads.prescribed_function(Layer::first))>
                            prescribed(n_slots);
    const TractionFunctions tractions = traction_functions();
    const auto             &traction  = tractions.by_layer;
    Tasks                   setups;
    for (const Layer layer : scene.materials.layers())
      if (scene.materials.has_layer(layer))
        {
          const unsigned int l = static_cast<unsigned int>(layer);
          prescribed[l]        = scene.loads.prescribed_function(layer);
          for (const unsigned int r :
               Layout::indices(regions_and_layers.n_regions()))
            {
              const unsigned int i = regions_and_layers.index(layer, r);
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
              sub       = std::make_unique<ElasticSubproblem>(
                layer,
                static_cast<Subdomain>(r),
                domain.triangulation(r),
                scene.mesh.degree(layer),
                plies,
                scene.materials.division(layer),
                distribution,
                regions_and_layers.n_regions());
              ElasticSubproblem *const target = sub.get();
              target->set_ordering(static_cast<SparseCholesky::OrderingChoice>(
                scene.solver.ordering));
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
            for (const unsigned int r :
                 Layout::indices(regions_and_layers.n_regions()))
              if (scene.materials.has_layer(layer) &&
                  subproblems[regions_and_layers.index(layer, r)])
                check_temperature_change(
                  *subproblems[regions_and_layers.index(layer, r)],
                  scene.loads,
                  scene.materials.material(layer, Topology::material_side(r)),
                  domain_diameter(domain));
        }
      catch (const ExceptionBase &e)
        {
          problem = one_line_message(e);
        }
    // Floating subproblems (no clamped side) are balanced through
    // held-set solves of all subproblems in one process.
    if (problem.empty() && distribution.n_processes() > 1)
      for (const auto &sub : subproblems)
        if (sub != nullptr && sub->floating())
          {
            problem = "subproblem " + sub->name() +
                      " touches no clamped part (Geometry/Clamped sides): "
                      "floating subproblems are solved in runs of one "
                      "process; run without mpirun or clamp a part of it";
            break;
          }
    problem = distribution.first_error(problem);
    if (!problem.empty())
      throw CollectiveError(problem);
    // The load factor of the study (setup() assembles at 1).
    if (lambda != 1)
      set_load_factor(lambda);
  }


  void
  Model::count_dofs(CycleRecord &record) const
  {
    for (const auto &sub : subproblems)
      if (sub)
        record.dofs += sub->n_dofs();
  }


  void
  Model::count_set_up_times(CycleRecord &record) const
  {
    for (const auto &sub : subproblems)
      if (sub != nullptr && sub->owned())
        {
          record.assembly_seconds += sub->assembly_seconds;
          record.factorisation_seconds += sub->factorisation_seconds;
        }
    // The ordering, flops and entries of each factor, from its owner.
    PerSubproblem<double> ordering(subproblems.size(), 0),
      flops(subproblems.size(), 0), entries(subproblems.size(), 0);
    for (unsigned int s = 0; s < subproblems.size(); ++s)
      if (subproblems[s] != nullptr && subproblems[s]->owned())
        {
          const auto &report = subproblems[s]->ordering_report();
          ordering[s]        = static_cast<double>(report.chosen);
          flops[s]           = report.flops;
          entries[s]         = report.entries;
        }
    distribution.share(ordering);
    distribution.share(flops);
    distribution.share(entries);
    record.factor_orderings.clear();
    for (unsigned int s = 0; s < subproblems.size(); ++s)
      record.factor_orderings.push_back(
        flops[s] > 0 ?
          SparseCholesky::name(
            static_cast<SparseCholesky::Ordering>(std::lround(ordering[s]))) :
          "shared solver");
    record.factor_flops   = flops;
    record.factor_entries = entries;
    // The busiest process's share.
    record.assembly_seconds = distribution.max(record.assembly_seconds);
    record.factorisation_seconds =
      distribution.max(record.factorisation_seconds);
  }


  void
  Model::set_up_interface(CycleRecord                      &record,
                          const MultiplierSpace::Functions *previous)
  {
    // The multiplier set reads the friction bound at the crack nodes and
    // refuses a bound that is negative or not finite there; every process
    // builds the same set, so every process knows, and the first reports
    // in one line (collective, no MPI_Abort).
    std::string problem;
    try
      {
        coupling.setup(regions_and_layers,
                       subproblem_views(),
                       domain.interface_curves());
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


  FloatingParts
  Model::floating_parts() const
  {
    PerSubproblem<ElasticSubproblem *> targets(subproblems.size(), nullptr);
    for (unsigned int s = 0; s < subproblems.size(); ++s)
      targets[s] = subproblems[s].get();
    return FloatingParts(targets, coupling);
  }


  MultiplierSpace::Functions
  Model::multiplier_functions() const
  {
    return mu.size() > 0 ? coupling.space().functions(mu) :
                           MultiplierSpace::Functions();
  }


  void
  Model::solve(CycleRecord &record)
  {
    if (steps_named)
      pcout << "Step " << record.cycle << ", load factor " << lambda << ": ";
    else
      pcout << "Cycle " << record.cycle << ": ";
    pcout << record.minus.cells << " + " << record.plus.cells << " "
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
    const auto          outer = [&](BlockVector<double> &m, Solutions &u) {
      if (scene.contact.friction == Friction::coulomb &&
          scene.contact.coulomb_method == CoulombMethod::fixed_point)
        {
          FixedPointRecord   fixed_point;
          const SolverResult result =
            CoulombFixedPoint(scene.solver, scene.contact, scene.output, pcout)
              .solve(subproblem_views(), coupling, m, u, fixed_point);
          record.friction_iterations += fixed_point.iterations;
          record.friction_bound_change = fixed_point.bound_change;
          return result;
        }
      return create_outer_solver(scene.solver, scene.output, pcout)
        ->solve(subproblem_views(), coupling, m, u);
    };
    record.friction_iterations   = 0;
    const FloatingParts floating = floating_parts();
    if (floating.any())
      record.result = floating.balance(outer,
                                       scene.solver.tolerance,
                                       scene.solver.acceptance_tolerance,
                                       mu,
                                       w,
                                       record.floating,
                                       pcout);
    else
      record.result = outer(mu, w);
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
} // namespace bilayer
