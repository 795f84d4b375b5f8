#include <deal.II/base/thread_management.h>
#include <deal.II/base/timer.h>
#include <deal.II/base/utilities.h>

#include <bilayer/estimator.h>
#include <bilayer/outer_solver.h>
#include <bilayer/output.h>
#include <bilayer/progress.h>
#include <bilayer/resources.h>
#include <bilayer/study.h>
#include <bilayer/tasks.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <iomanip>
#include <limits>
#include <sstream>

namespace bilayer
{
  using namespace dealii;

  namespace
  {
    std::string
    two_digits(const unsigned int n)
    {
      std::ostringstream s;
      s << std::setw(2) << std::setfill('0') << n;
      return s.str();
    }

    /**
     * Runs writers until one fails and keeps that failure as one line (a
     * file that cannot be written, e.g. on a full disk, stops every process
     * together, with the file and the reason).
     */
    class FirstFailure
    {
    public:
      void
      operator()(const std::function<void()> &write)
      {
        if (message.empty())
          try
            {
              write();
            }
          catch (const ExceptionBase &e)
            {
              message = one_line_message(e);
            }
          catch (const std::exception &e)
            {
              message = e.what();
            }
      }

      std::string message;
    };
  } // namespace


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
    , domain(scene.geometry, scene.mesh)
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
  Study::set_indicators(
    const std::array<Vector<float>, Layout::n_subdomains> &new_indicators)
  {
    std::array<Vector<double>, Layout::n_subdomains> converted;
    for (unsigned int k = 0; k < Layout::n_subdomains; ++k)
      converted[k] = new_indicators[k];
    set_indicators(converted);
  }


  void
  Study::set_indicators(
    const std::array<Vector<double>, Layout::n_subdomains> &new_indicators)
  {
    for (const Subdomain s : {Subdomain::minus, Subdomain::plus})
      AssertThrow(new_indicators[static_cast<unsigned int>(s)].size() ==
                    domain.triangulation(s).n_active_cells(),
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

    build_meshes(record);
    check_memory(record);
    set_up_subproblems();
    count_subproblems(record);
    set_up_interface(record, warm ? &previous : nullptr);
    record.setup_seconds = total.wall_time();
    solve(record);
    assess(record);
    write(record, total);
    print_report(record);
    // Every process's files are complete before the run may commit them.
    distribution.barrier();
    return cycle_records.back();
  }


  PerSubproblem<const ElasticSubproblem *>
  Study::subproblem_views() const
  {
    PerSubproblem<const ElasticSubproblem *> views;
    for (const unsigned int s : Layout::subproblems)
      views[s] = subproblems[s].get();
    return views;
  }


  void
  Study::build_meshes(CycleRecord &record)
  {
    const unsigned int cycle = record.cycle;
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
      domain.create_meshes(cycle);
    record.minus = domain.statistics(Subdomain::minus);
    record.plus  = domain.statistics(Subdomain::plus);
    record.P     = domain.n_sigma_vertices();
    record.M     = domain.n_outer_vertices();
    // The tips (and a refusal of Fracture/Support radius) before anything
    // is computed or written.
    if (!tips_found && scene.fracture.energy_release_rate)
      {
        tips       = crack_tips(domain.interface_curve(),
                          {{&domain.triangulation(Subdomain::minus),
                                  &domain.triangulation(Subdomain::plus)}},
                          scene.fracture.support_radius);
        tips_found = true;
      }
    if (!tips.empty())
      check_supports(record);
  }


  void
  Study::write_tip_notes(std::ostream &out) const
  {
    if (!cycle_records.empty())
      for (const std::string &note :
           tip_notes(cycle_records.back().release,
                     scene.geometry.gmsh_file.empty()))
        out << "# " << note << "\n";
  }


  void
  Study::check_supports(const CycleRecord &record)
  {
    const bool rectangle =
      scene.geometry.gmsh_file.empty() && scene.mesh.mesh_files.empty();
    const bool uniform = scene.mesh.refinement != Refinement::adaptive;
    // Cycles after this one, each halving the cells under uniform
    // refinement.
    const unsigned int n_later = scene.mesh.n_cycles > record.cycle + 1 ?
                                   scene.mesh.n_cycles - record.cycle - 1 :
                                   0;
    unresolved_tips.assign(tips.size(), "");
    tip_cell_sizes.assign(tips.size(), 0.);
    for (unsigned int t = 0; t < tips.size(); ++t)
      {
        const CrackTip &tip = tips[t];
        if (!tip.defined())
          continue;
        const TipCells cells =
          support_cells(tip,
                        {{&domain.triangulation(Subdomain::minus),
                          &domain.triangulation(Subdomain::plus)}});
        tip_cell_sizes[t] = cells.size;
        const double R    = tip.support_radius;
        if (support_holds(R, cells.size))
          continue;
        const double last_size =
          uniform ? std::ldexp(cells.size, -int(n_later)) : cells.size;
        const bool         last_resolved = support_holds(R, last_size);
        std::ostringstream m;
        m << std::setprecision(3);
        if (scene.fracture.support_radius > 0)
          m << "Fracture/Support radius = " << R;
        else
          m << "the automatic support radius R = " << R
            << " (Fracture/Support radius = 0: half the distance "
            << tip.free_distance << " to the nearest obstacle of theta)";
        m << " at the crack tip at "
          << tip_position(tip, scene.geometry.gmsh_file.empty()) << " holds "
          << R / cells.size << " cells of the mesh of Omega"
          << (cells.mesh == 0 ? "-" : "+")
          << " along its radius (cells of size " << cells.size
          << " at the tip on cycle " << record.cycle;
        if (uniform && n_later > 0)
          m << ", " << last_size << " on the last cycle";
        m << "): G needs at least " << min_cells_per_support_radius
          << " (R >= the cell size, else G tends to 0 with R)";
        // The remedies: a larger radius where the obstacles allow it, or
        // cells no larger than R at the tip.
        std::vector<std::string> remedies;
        const double             needed =
          min_cells_per_support_radius * (uniform ? last_size : cells.size);
        if (needed < tip.free_distance)
          {
            std::ostringstream r;
            r << std::setprecision(3) << "Fracture/Support radius in ["
              << needed << ", " << tip.free_distance << ")";
            remedies.push_back(r.str());
          }
        if (rectangle)
          {
            std::ostringstream r;
            r << "at least "
              << std::ceil(scene.mesh.cells_along_sigma *
                           (uniform ? last_size : cells.size) / R)
              << " Mesh/Cells along Sigma"
              << (scene.mesh.cells_along_sigma_plus > 0 ?
                    " (and on the plus side in proportion)" :
                    "")
              << (uniform ? "" : " or more adaptive cycles");
            remedies.push_back(r.str());
          }
        else
          remedies.push_back(uniform ? "more Mesh/Number of cycles" :
                                       "more adaptive cycles");
        m << ": use ";
        for (unsigned int i = 0; i < remedies.size(); ++i)
          m << (i == 0 ? "" : ", or ") << remedies[i];
        // A given radius under uniform refinement: the last cycle is known
        // now; refuse the scene before anything is computed if it cannot
        // hold the support. (The automatic radius: G is not reported at
        // this tip on this cycle, the run goes on; G is a by-product of
        // every scene with a crack, coarse meshes included.)
        AssertThrow(!(scene.fracture.support_radius > 0 && record.cycle == 0 &&
                      uniform && !last_resolved),
                    ExcMessage(m.str()));
        unresolved_tips[t] = m.str();
      }
  }


  void
  Study::check_memory(CycleRecord &record) const
  {
    // Adaptive cycles and mesh files: the sizes are known only now.
    const ResourceEstimate need =
      estimate_resources(scene, record.minus.cells, record.plus.cells);
    record.memory_estimate_mib = need.memory / (1 << 20);
    // The process with the least memory decides (its limits describe it).
    const MemoryAvailability mine      = memory_availability();
    const double             available = -distribution.max(-mine.bytes);
    if (need.memory <= available ||
        (!scene.mesh.refuse_above_memory && available > 0))
      return;
    MemoryAvailability least = mine;
    least.bytes              = available;
    std::ostringstream what;
    what << "the meshes of this cycle ("
         << record.minus.cells + record.plus.cells
         << " cells) would need about " << format_bytes(need.memory)
         << " of memory, but "
         << least.shortage(
              scene.mesh.refinement == Refinement::adaptive ?
                "use fewer cycles (Mesh/Number of cycles) or a smaller "
                "Mesh/Refinement fraction" :
                "use fewer cycles (Mesh/Number of cycles) or cells");
    throw RunFailure(record.cycle, what.str());
  }


  void
  Study::set_up_subproblems()
  {
    // The loads of each layer, then the set-ups (assembly and
    // factorisation) as parallel tasks.
    std::array<decltype(scene.loads.prescribed_function(Layer::first)),
               Layout::n_layers>
      prescribed;
    std::array<std::vector<std::unique_ptr<FunctionParser<2>>>,
               Layout::n_layers>
      traction_owners;
    std::array<std::vector<const Function<2> *>, Layout::n_layers> traction;
    Tasks                                                          setups;
    for (const Layer layer : {Layer::first, Layer::second})
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
          for (const Subdomain sd : {Subdomain::minus, Subdomain::plus})
            {
              auto &sub = subproblems[Layout::index(layer, sd)];
              sub =
                std::make_unique<ElasticSubproblem>(layer,
                                                    sd,
                                                    domain.triangulation(sd),
                                                    scene.mesh.degree(layer),
                                                    scene.materials.layer[l],
                                                    distribution);
              ElasticSubproblem *const target = sub.get();
              setups.add([&, target, l]() {
                target->setup(scene.geometry.clamped,
                              *prescribed[l],
                              traction[l],
                              scene.solver.shared_solver,
                              scene.solver.iterates_on_sigma());
              });
            }
        }
    setups.join_all();
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
    coupling.setup(subproblem_views(), domain.interface_curve());
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
    for (const unsigned int s : Layout::subproblems)
      {
        record.energy += energies[s];
        record.layer_energy[static_cast<unsigned int>(Layout::layer(s))] +=
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
    indicators = estimate_error(subproblem_views(),
                                coupling,
                                w,
                                mu,
                                scene.mesh.interface_terms,
                                scene.mesh.contact_weight,
                                &record.eta);
    check(record);
  }


  void
  Study::write(CycleRecord &record, const Timer &total)
  {
    const std::string &dir = scene.output.directory;
    FirstFailure       writing;
    // The directory the run made (a run of the program), or created if
    // missing (drivers may call run_cycle() without run()).
    if (distribution.is_root())
      writing([&]() {
        if (directory_check)
          directory_check();
        else
          std::filesystem::create_directories(dir);
      });
    distribution.barrier();
    const bool fields = scene.output.writes_fields(record.cycle,
                                                   scene.mesh.n_cycles,
                                                   record.accepted());
    if (fields)
      writing([&]() {
        write_solution(
          dir, record.cycle, subproblem_views(), w, scene.output, outputs);
      });
    record.total_seconds = distribution.max(total.wall_time());
    Utilities::System::MemoryStats memory;
    Utilities::System::get_memory_stats(memory);
    record.memory_mib = distribution.gather(memory.VmHWM / 1024.);

    cycle_records.push_back(record);
    add_to_table(table, record);
    if (distribution.is_root())
      writing([&]() { write_records(record.cycle, fields); });
    std::string error = distribution.first_error(writing.message);
    // The files just written are there (checked again at the next cycle
    // and before the results are published).
    if (error.empty() && directory_check)
      {
        FirstFailure written;
        if (distribution.is_root())
          written(directory_check);
        error = distribution.first_error(written.message);
      }
    if (!error.empty())
      throw CollectiveError("writing the results of cycle " +
                            std::to_string(record.cycle) + " failed: " + error);
  }


  void
  Study::write_records(const unsigned int cycle, const bool fields)
  {
    const std::string &dir           = scene.output.directory;
    const bool         interface_vtu = fields && scene.output.write_vtu;
    if (scene.output.write_interface || interface_vtu)
      {
        const std::vector<InterfaceNode> nodes =
          interface_nodes(coupling, w, mu, scene.solver.acceptance_tolerance);
        if (scene.output.write_interface)
          write_atomically(dir + "/interface-" + two_digits(cycle) + ".csv",
                           [&](std::ostream &o) {
                             write_interface_csv(
                               o,
                               nodes,
                               release_notes(cycle_records.back().release,
                                             scene.geometry.gmsh_file.empty()));
                           });
        if (interface_vtu)
          write_interface_vtu(dir, cycle, nodes, outputs);
      }
    write_atomically(dir + "/summary.json", [&](std::ostream &o) {
      write_summary_json(o, scene.name, cycle_records);
    });
    write_atomically(dir + "/table.txt", [&](std::ostream &o) {
      write_tip_notes(o);
      table.write_text(o, TableHandler::org_mode_table);
    });
    write_atomically(dir + "/table.tex",
                     [&](std::ostream &o) { table.write_tex(o); });
    write_atomically(dir + "/table.csv", [&](std::ostream &o) {
      write_csv_table(o, cycle_records, scene.geometry.gmsh_file.empty());
    });
  }


  void
  Study::check(CycleRecord &record) const
  {
    const double       tol = scene.solver.acceptance_tolerance;
    std::ostringstream t;
    t << tol;
    const auto &r = record.report;
    record.checks.emplace_back("stopping rule met", record.result.converged);
    record.checks.emplace_back("relative violation of the discrete "
                               "constraints <= " +
                                 t.str(),
                               r.relative_discrete_violation <= tol);
    record.checks.emplace_back("relative jump at the glued nodes without "
                               "multipliers <= " +
                                 t.str(),
                               r.relative_jump_without_multiplier <= tol);
    if (!(r.relative_jump_without_multiplier <= tol))
      record.note += std::string(record.note.empty() ? "" : "; ") +
                     "a jump is left at an end of Sigma on Gamma_D: the "
                     "prescribed displacements of the sides or layers glued "
                     "there must agree at that point";
    if (scene.contact.non_penetration &&
        !domain.interface_curve().crack().empty())
      {
        record.checks.emplace_back("contact multiplier mu_c >= 0",
                                   r.min_contact_multiplier >= 0);
        record.checks.emplace_back("complementarity <= " + t.str(),
                                   r.complementarity <= tol);
      }
    record.checks.emplace_back("relative KKT residual <= " + t.str(),
                               r.kkt.value() <= tol);
    record.checks.emplace_back("multipliers below the bound p",
                               r.max_multiplier_over_bound < 1.);
    // Comparisons with NaN are false: a non-finite result must fail here,
    // not pass the checks below by being compared.
    const bool finite =
      std::isfinite(record.energy) && std::isfinite(r.constraint_violation) &&
      std::isfinite(r.max_penetration) && std::isfinite(r.displacement_scale) &&
      std::isfinite(r.relative_discrete_violation) &&
      std::isfinite(r.relative_jump_without_multiplier) &&
      std::isfinite(r.min_contact_multiplier) &&
      std::isfinite(r.complementarity) && std::isfinite(r.kkt.value()) &&
      std::isfinite(record.eta);
    record.checks.emplace_back("energy and residuals finite", finite);
    // With a given support radius the last cycle must report G at every
    // tip where it is defined (the check appears only where it fails:
    // earlier cycles report NaN).
    if (scene.fracture.support_radius > 0 &&
        record.cycle + 1 >= scene.mesh.n_cycles)
      {
        std::string unresolved;
        for (const EnergyReleaseRate &g : record.release)
          if (!g.unresolved.empty())
            unresolved += (unresolved.empty() ? "" : "; ") + g.unresolved;
        if (!unresolved.empty())
          {
            record.checks.emplace_back(
              "energy release rate resolved at every crack tip", false);
            record.note += (record.note.empty() ? "" : "; ") + unresolved;
          }
      }
    if (!finite)
      {
        // The cause, in place of the solver's message (a stagnation or a
        // limit reached with non-finite numbers says nothing of the
        // tolerance or the conditioning).
        std::ostringstream what;
        what << std::setprecision(3);
        const std::vector<std::pair<std::string, double>> values = {
          {"energy Pi", record.energy},
          {"error estimate eta", record.eta},
          {"displacement scale", r.displacement_scale},
          {"relative KKT residual", r.kkt.value()},
          {"complementarity", r.complementarity}};
        std::string listed;
        for (const auto &v : values)
          if (!std::isfinite(v.second))
            {
              std::ostringstream one;
              one << v.first << " = " << v.second;
              listed += (listed.empty() ? "" : ", ") + one.str();
            }
        what << "not finite: " << listed << "; ";
        if (std::isfinite(r.displacement_scale) && r.displacement_scale > 0)
          what << "the displacements reach " << r.displacement_scale
               << ", and the energy and the residuals grow with the square "
                  "of the loads' scale beyond double precision (1.8e308): "
                  "scale the loads down (the Loads section: the problem is "
                  "linear, the displacements scale with the loads, the "
                  "energy with their square)";
        else
          what << "the solution itself is not finite: the loads' scale "
                  "(the Loads section) overflows double precision, or the "
                  "problem is singular (Geometry/Clamped sides)";
        record.result.message = what.str();
      }
    if (r.max_multiplier_over_bound >= 1.)
      {
        std::ostringstream note;
        note << std::setprecision(3) << "the multipliers reach the bound p = "
             << scene.contact.multiplier_bound
             << " (Contact/Multiplier bound p), so the constraints are "
                "violated: integral (12) = "
             << r.constraint_violation << " (relative "
             << r.relative_constraint_violation
             << "), largest interpenetration " << r.max_penetration
             << "; estimate (12) bounds this by K/p: increase "
                "Contact/Multiplier bound p";
        record.note += (record.note.empty() ? "" : "; ") + note.str();
      }
  }


  void
  Study::print_report(const CycleRecord &record) const
  {
    const auto &r = record.report;
    pcout << "  " << record.result.solver << ": " << record.result.message
          << " (" << record.result.subdomain_solves << " subdomain solves";
    if (record.result.preconditioner_solves > 0)
      pcout << " + " << record.result.preconditioner_solves
            << " Dirichlet solves";
    if (record.theta > 0)
      pcout << ", theta = " << record.theta;
    pcout << ")\n"
          << std::scientific << std::setprecision(4)
          << "  energy Pi                    " << record.energy << "\n"
          << "  error estimate eta           " << record.eta
          << "  (energy norm, sqrt(2 (Pi_h - Pi)) by the estimator)\n"
          << "  constraint violation (12)    " << r.constraint_violation
          << "  (relative " << r.relative_constraint_violation << ")\n"
          << "  largest interpenetration     " << r.max_penetration
          << "  (displacement scale " << r.displacement_scale << ")\n"
          << "  discrete violation           " << r.relative_discrete_violation
          << " (relative)\n"
          << "  smallest mu_c                " << r.min_contact_multiplier
          << "\n"
          << "  complementarity              " << r.complementarity << "\n"
          << "  KKT residual (relative)      " << r.kkt.value() << "\n";
    for (unsigned int t = 0; t < record.release.size(); ++t)
      {
        const EnergyReleaseRate &g = record.release[t];
        pcout << "  energy release rate G, tip " << t + 1 << " ("
              << tip_position(g.tip, scene.geometry.gmsh_file.empty()) << "): ";
        if (!g.tip.defined())
          pcout << "not defined (the tip is at a corner of Sigma)\n";
        else if (!g.unresolved.empty())
          pcout << "not resolved: " << g.unresolved << "\n";
        else
          {
            pcout << "G = " << g.G;
            if (std::isfinite(g.error))
              pcout << " ± " << std::setprecision(1) << g.error
                    << std::setprecision(4) << " (error estimate from the "
                    << g.error_estimate << "; ";
            else
              pcout << " ± ? (error estimate " << g.error_estimate << "; ";
            if (g.tip.curved())
              pcout << "contact term " << g.contact << "; ";
            pcout << std::defaultfloat << std::setprecision(3)
                  << "support radius " << g.tip.support_radius << ")"
                  << std::scientific << std::setprecision(4) << "\n";
          }
      }
    pcout << std::defaultfloat << std::setprecision(3)
          << "  processes                    " << record.processes
          << ", traces sent " << record.shared_values << " values in "
          << record.shared_seconds << " s, peak memory per process [MiB]";
    for (const double m : record.memory_mib)
      pcout << " " << std::fixed << std::setprecision(0) << m;
    pcout << " (estimated " << record.memory_estimate_mib << ")";
    pcout << "\n"
          << std::defaultfloat << std::setprecision(3)
          << "  wall time                    setup " << record.setup_seconds
          << " s, solve " << record.solve_seconds << " s, total "
          << record.total_seconds << " s" << std::endl;
    for (const auto &c : record.checks)
      rout << "cycle " << record.cycle << ": " << c.first << ": "
           << (c.second ? "yes" : "NO") << std::endl;
    // Two numbers that the tests meet with an independent computation
    // (tests/prm_references.cc): the energy and the largest normal opening
    // (u+ - u-).nu at the layer-1 nodes of the crack, with its position,
    // each as v = m 10^k, 1 <= |m| < 10, m with 8 digits (O(1) for numdiff).
    const auto scaled = [](const double v) {
      int    k = v == 0 ? 0 : int(std::floor(std::log10(std::abs(v))));
      double m = v / std::pow(10., k);
      if (std::abs(m) >= 9.99999995)
        m /= 10, ++k;
      std::ostringstream s;
      s << "[10^" << k << "]: " << std::fixed << std::setprecision(7) << m;
      return s.str();
    };
    rout << "cycle " << record.cycle << ": energy Pi " << scaled(record.energy)
         << std::endl;
    if (distribution.is_root())
      {
        const std::vector<double> opening = normal_opening(coupling, w);
        int                       a_max   = -1;
        for (unsigned int a = 0; a < coupling.space().n_nodes(); ++a)
          if (coupling.space().on_crack(a) &&
              (a_max < 0 || opening[a] > opening[a_max]))
            a_max = a;
        if (a_max >= 0)
          {
            // The position: s = x on the rectangle, else s and the point.
            const double       s_max = coupling.space().node_position(a_max);
            std::ostringstream x;
            x << std::setprecision(6);
            if (scene.geometry.gmsh_file.empty())
              x << "x = " << s_max;
            else
              {
                const Point<2> p = coupling.curve().point(s_max);
                x << "s = " << s_max << ", (x, y) = (" << p[0] << ", " << p[1]
                  << ")";
              }
            rout << "cycle " << record.cycle << ": largest crack opening "
                 << scaled(opening[a_max]) << " at " << x.str() << std::endl;
          }
      }
  }
} // namespace bilayer
