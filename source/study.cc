#include <deal.II/base/thread_management.h>
#include <deal.II/base/timer.h>
#include <deal.II/base/utilities.h>

#include <bilayer/estimator.h>
#include <bilayer/outer_solver.h>
#include <bilayer/output.h>
#include <bilayer/resources.h>
#include <bilayer/study.h>
#include <bilayer/tasks.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <iomanip>
#include <sstream>

namespace bilayer
{
  namespace
  {
    /// A JSON number (null for NaN and infinities), with the 17
    /// significant digits that identify the double.
    std::string
    json(const double value)
    {
      if (!std::isfinite(value))
        return "null";
      std::ostringstream s;
      s << std::setprecision(17) << value;
      return s.str();
    }

    std::string
    json(const std::string &text)
    {
      std::string quoted = "\"";
      for (const char c : text)
        {
          if (c == '"' || c == '\\')
            quoted += '\\';
          quoted += c;
        }
      return quoted + "\"";
    }

    std::string
    two_digits(const unsigned int n)
    {
      std::ostringstream s;
      s << std::setw(2) << std::setfill('0') << n;
      return s.str();
    }
  } // namespace


  bool
  CycleRecord::accepted() const
  {
    for (const auto &c : checks)
      if (!c.second)
        return false;
    return !checks.empty();
  }


  std::string
  CycleRecord::failure() const
  {
    std::string failed;
    for (const auto &c : checks)
      if (!c.second)
        failed += (failed.empty() ? "" : ", ") + c.first;
    return failed + " (" + result.message + ")" +
           (note.empty() ? "" : "; " + note);
  }


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
    , coupling(scene.geometry, scene.contact)
  {}


  bool
  Study::run()
  {
    for (unsigned int cycle = 0; cycle < scene.mesh.n_cycles; ++cycle)
      {
        const CycleRecord &record = run_cycle(cycle);
        if (!record.accepted())
          return false;
      }
    if (scene.output.terminal == TerminalOutput::full && distribution.is_root())
      {
        out << "\n";
        table.write_text(out, TableHandler::org_mode_table);
      }
    return true;
  }


  void
  Study::set_indicators(const std::array<Vector<float>, 2> &new_indicators)
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

    // The multipliers of the previous cycle, for a warm start.
    const bool warm =
      scene.solver.warm_start && !cycle_records.empty() && mu.size() > 0;
    const Interface::MultiplierFunctions previous =
      warm ? coupling.functions(mu) : Interface::MultiplierFunctions();
    for (auto &sub : subproblems)
      sub.reset();
    if (cycle > 0 && scene.mesh.refinement == Refinement::adaptive)
      {
        AssertThrow(!cycle_records.empty() &&
                      cycle_records.back().cycle + 1 == cycle,
                    ExcMessage("adaptive cycle " + std::to_string(cycle) +
                               " needs cycle " + std::to_string(cycle - 1) +
                               " of the same study first"));
        domain.refine(indicators);
      }
    else
      domain.create_meshes(cycle);
    record.minus = domain.statistics(Subdomain::minus);
    record.plus  = domain.statistics(Subdomain::plus);
    record.P     = domain.n_sigma_vertices();
    record.M     = domain.n_outer_vertices();
    {
      // Adaptive cycles and mesh files: the sizes are known only now.
      const ResourceEstimate need =
        estimate_resources(scene, record.minus.cells, record.plus.cells);
      record.memory_estimate_mib = need.memory / (1 << 20);
      const double available     = distribution.max(-available_memory());
      if (need.memory > -available)
        throw RunFailure(cycle,
                         "the meshes of this cycle (" +
                           std::to_string(record.minus.cells +
                                          record.plus.cells) +
                           " cells) would need about " +
                           format_bytes(need.memory) + " of memory, but " +
                           format_bytes(-available) +
                           " are available: use fewer cycles "
                           "(Mesh/Number of cycles) or a smaller "
                           "Mesh/Refinement fraction");
    }

    // The loads of each layer, then the four set-ups (assembly and
    // factorisation) as parallel tasks.
    std::array<decltype(scene.loads.prescribed_function(Layer::first)), 2>
      prescribed;
    std::array<std::array<std::unique_ptr<FunctionParser<2>>, 4>, 2>
                                                      traction_owners;
    std::array<std::array<const Function<2> *, 4>, 2> traction;
    Tasks                                             setups;
    for (const Layer layer : {Layer::first, Layer::second})
      if (scene.materials.has_layer(layer))
        {
          const unsigned int l = static_cast<unsigned int>(layer);
          prescribed[l]        = scene.loads.prescribed_function(layer);
          for (unsigned int side = 0; side < 4; ++side)
            {
              traction_owners[l][side] =
                scene.loads.traction_function(layer, static_cast<Side>(side));
              traction[l][side] = traction_owners[l][side].get();
            }
          for (const Subdomain sd : {Subdomain::minus, Subdomain::plus})
            {
              auto &sub = subproblems[Interface::index(layer, sd)];
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
                              scene.solver.shared_solver);
              });
            }
        }
    setups.join_all();
    for (const auto &sub : subproblems)
      if (sub)
        record.dofs += sub->n_dofs();
    std::array<const ElasticSubproblem *, 4> views;
    Subproblems                              solvers;
    for (unsigned int s = 0; s < 4; ++s)
      {
        views[s]   = subproblems[s].get();
        solvers[s] = subproblems[s].get();
      }
    for (unsigned int s = 0; s < 4; ++s)
      if (subproblems[s] != nullptr && subproblems[s]->owned())
        {
          record.assembly_seconds += subproblems[s]->assembly_seconds;
          record.factorisation_seconds += subproblems[s]->factorisation_seconds;
        }
    // The busiest process's share.
    record.assembly_seconds = distribution.max(record.assembly_seconds);
    record.factorisation_seconds =
      distribution.max(record.factorisation_seconds);
    coupling.setup(views);
    coupling.initialize(mu);
    if (warm)
      coupling.interpolate(previous, mu);
    record.multipliers   = coupling.n_multipliers();
    record.setup_seconds = total.wall_time();

    pcout << "Cycle " << cycle << ": " << record.minus.cells << " + "
          << record.plus.cells << " "
          << (scene.mesh.shape == ElementShape::quadrilateral ?
                "quadrilaterals" :
                "triangles")
          << ", P = " << record.P << ", M = " << record.M << ", " << record.dofs
          << " dofs, " << record.multipliers << " multipliers" << std::endl;

    Timer               solve_timer;
    const unsigned long shared_before  = distribution.shared_values();
    const double        seconds_before = distribution.shared_seconds();
    record.result = create_outer_solver(scene.solver, scene.output, pcout)
                      ->solve(solvers, coupling, mu, w);
    record.theta          = record.result.theta;
    record.solve_seconds  = solve_timer.wall_time();
    record.processes      = distribution.n_processes();
    record.shared_values  = distribution.shared_values() - shared_before;
    record.shared_seconds = distribution.shared_seconds() - seconds_before;

    // Energies (whole solutions: evaluated by the owners), summed in the
    // order of the subproblems as in a serial run.
    for (const double e : share_values(solvers, [&](const unsigned int s) {
           return subproblems[s]->energy(w[s]);
         }))
      record.energy += e;
    record.report = coupling.assess(w, mu);
    check(record);
    if (scene.mesh.refinement == Refinement::adaptive)
      indicators = estimate_error(views,
                                  coupling,
                                  w,
                                  mu,
                                  scene.mesh.interface_terms,
                                  scene.mesh.contact_weight);

    // A file that cannot be written (a full disk) stops every process
    // together, with the file and the reason.
    const std::string &dir = scene.output.directory;
    std::string        write_error;
    const auto         writing = [&](const std::function<void()> &write) {
      if (write_error.empty())
        try
          {
            write();
          }
        catch (const ExceptionBase &e)
          {
            write_error = one_line_message(e);
          }
        catch (const std::exception &e)
          {
            write_error = e.what();
          }
    };
    // (Each cycle: drivers may call run_cycle() without run().)
    if (distribution.is_root())
      writing([&]() { std::filesystem::create_directories(dir); });
    distribution.barrier();
    if (scene.output.write_vtu || scene.output.write_hdf5)
      writing(
        [&]() { write_solution(dir, cycle, views, w, scene.output, outputs); });
    record.total_seconds = distribution.max(total.wall_time());
    Utilities::System::MemoryStats memory;
    Utilities::System::get_memory_stats(memory);
    record.memory_mib = distribution.gather(memory.VmHWM / 1024.);

    cycle_records.push_back(record);
    add_to_table(record);
    if (distribution.is_root())
      writing([&]() {
        if (scene.output.write_interface)
          write_atomically(dir + "/interface-" + two_digits(cycle) + ".csv",
                           [&](std::ostream &o) {
                             coupling.write_csv(o, w, mu);
                           });
        write_summary();
        write_atomically(dir + "/table.txt", [&](std::ostream &o) {
          table.write_text(o, TableHandler::org_mode_table);
        });
        write_atomically(dir + "/table.tex",
                         [&](std::ostream &o) { table.write_tex(o); });
        write_atomically(dir + "/table.csv",
                         [&](std::ostream &o) { write_csv_table(o); });
      });
    write_error = distribution.first_error(write_error);
    if (!write_error.empty())
      throw CollectiveError("writing the results of cycle " +
                            std::to_string(cycle) + " failed: " + write_error);
    print_report(record);
    // Every process's files are complete before the run may commit them.
    distribution.barrier();
    return cycle_records.back();
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
    if (scene.contact.non_penetration && scene.geometry.has_crack())
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
      std::isfinite(r.min_contact_multiplier) &&
      std::isfinite(r.complementarity) && std::isfinite(r.kkt.value());
    record.checks.emplace_back("energy and residuals finite", finite);
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
        record.note = note.str();
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
          << "  constraint violation (12)    " << r.constraint_violation
          << "  (relative " << r.relative_constraint_violation << ")\n"
          << "  largest interpenetration     " << r.max_penetration
          << "  (displacement scale " << r.displacement_scale << ")\n"
          << "  discrete violation           " << r.relative_discrete_violation
          << " (relative)\n"
          << "  smallest mu_c                " << r.min_contact_multiplier
          << "\n"
          << "  complementarity              " << r.complementarity << "\n"
          << "  KKT residual (relative)      " << r.kkt.value() << "\n"
          << std::defaultfloat << std::setprecision(3)
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
        const std::vector<double> opening = coupling.normal_opening(w);
        int                       a_max   = -1;
        for (unsigned int a = 0; a < coupling.n_nodes(); ++a)
          if (coupling.node_on_crack(a) &&
              (a_max < 0 || opening[a] > opening[a_max]))
            a_max = a;
        if (a_max >= 0)
          {
            std::ostringstream x;
            x << std::setprecision(6) << coupling.node_position(a_max);
            rout << "cycle " << record.cycle << ": largest crack opening "
                 << scaled(opening[a_max]) << " at x = " << x.str()
                 << std::endl;
          }
      }
    if (!record.accepted())
      rout << "bilayer: cycle " << record.cycle
           << " FAILED: " << record.failure() << std::endl;
  }


  void
  Study::add_to_table(const CycleRecord &r)
  {
    table.add_value("cycle", r.cycle);
    table.add_value("P", r.P);
    table.add_value("M", r.M);
    table.add_value("h-min", r.minus.h_min);
    table.add_value("h-max", r.minus.h_max);
    table.add_value("h+min", r.plus.h_min);
    table.add_value("h+max", r.plus.h_max);
    table.add_value("Nod-", r.minus.vertices);
    table.add_value("Cells-", r.minus.cells);
    table.add_value("Nod+", r.plus.vertices);
    table.add_value("Cells+", r.plus.cells);
    table.add_value("dofs", r.dofs);
    table.add_value("iter", r.result.iterations);
    table.add_value("solves",
                    static_cast<unsigned int>(r.result.subdomain_solves));
    table.add_value("energy", r.energy);
    table.add_value("violation", r.report.constraint_violation);
    table.add_value("time [s]", r.total_seconds);
    for (const auto &key : {"h-min", "h-max", "h+min", "h+max"})
      table.set_precision(key, 4);
    table.set_precision("energy", 8);
    table.set_scientific("energy", true);
    table.set_precision("violation", 2);
    table.set_scientific("violation", true);
    table.set_precision("time [s]", 3);
  }


  void
  Study::write_csv_table(std::ostream &o) const
  {
    o << "cycle,P,M,h_min_minus,h_max_minus,h_min_plus,h_max_plus,"
         "vertices_minus,cells_minus,vertices_plus,cells_plus,dofs,"
         "multipliers,theta,iterations,subdomain_solves,converged,energy,"
         "constraint_violation,max_penetration,setup_seconds,solve_seconds,"
         "total_seconds\n";
    for (const auto &r : cycle_records)
      o << r.cycle << ',' << r.P << ',' << r.M << ',' << json(r.minus.h_min)
        << ',' << json(r.minus.h_max) << ',' << json(r.plus.h_min) << ','
        << json(r.plus.h_max) << ',' << r.minus.vertices << ',' << r.minus.cells
        << ',' << r.plus.vertices << ',' << r.plus.cells << ',' << r.dofs << ','
        << r.multipliers << ',' << json(r.theta) << ',' << r.result.iterations
        << ',' << r.result.subdomain_solves << ','
        << (r.result.converged ? 1 : 0) << ',' << json(r.energy) << ','
        << json(r.report.constraint_violation) << ','
        << json(r.report.max_penetration) << ',' << json(r.setup_seconds) << ','
        << json(r.solve_seconds) << ',' << json(r.total_seconds) << '\n';
  }


  void
  Study::write_summary() const
  {
    write_atomically(
      scene.output.directory + "/summary.json", [&](std::ostream &o) {
        o << "{\n  \"scene\": " << json(scene.name) << ",\n  \"cycles\": [";
        for (unsigned int i = 0; i < cycle_records.size(); ++i)
          {
            const auto &r = cycle_records[i];
            const auto &k = r.report;
            o << (i ? "," : "") << "\n    {"
              << "\"cycle\": " << r.cycle
              << ", \"vertices_minus\": " << r.minus.vertices
              << ", \"cells_minus\": " << r.minus.cells
              << ", \"vertices_plus\": " << r.plus.vertices
              << ", \"cells_plus\": " << r.plus.cells << ", \"P\": " << r.P
              << ", \"M\": " << r.M
              << ", \"h_min_minus\": " << json(r.minus.h_min)
              << ", \"h_max_minus\": " << json(r.minus.h_max)
              << ", \"h_min_plus\": " << json(r.plus.h_min)
              << ", \"h_max_plus\": " << json(r.plus.h_max)
              << ", \"dofs\": " << r.dofs
              << ", \"multipliers\": " << r.multipliers
              << ", \"solver\": " << json(r.result.solver)
              << ", \"theta\": " << json(r.theta)
              << ", \"lambda_max\": " << json(r.result.lambda_max)
              << ", \"predicted_threshold\": "
              << json(r.result.predicted_threshold)
              << ", \"threshold_at_solution\": "
              << json(r.result.threshold_at_solution)
              << ", \"iterations\": " << r.result.iterations
              << ", \"subdomain_solves\": " << r.result.subdomain_solves
              << ", \"preconditioner_solves\": "
              << r.result.preconditioner_solves
              << ", \"linear_iterations\": " << r.result.linear_iterations
              << ", \"converged\": " << (r.result.converged ? "true" : "false")
              << ", \"diverged\": " << (r.result.diverged ? "true" : "false")
              << ", \"stopping_value\": " << json(r.result.stopping_value)
              << ", \"message\": " << json(r.result.message)
              << ", \"energy\": " << json(r.energy)
              << ", \"constraint_violation\": " << json(k.constraint_violation)
              << ", \"relative_constraint_violation\": "
              << json(k.relative_constraint_violation)
              << ", \"max_penetration\": " << json(k.max_penetration)
              << ", \"displacement_scale\": " << json(k.displacement_scale)
              << ", \"relative_discrete_violation\": "
              << json(k.relative_discrete_violation)
              << ", \"min_contact_multiplier\": "
              << json(k.min_contact_multiplier)
              << ", \"complementarity\": " << json(k.complementarity)
              << ", \"max_multiplier_over_bound\": "
              << json(k.max_multiplier_over_bound)
              << ", \"kkt_residual\": " << json(k.kkt.value())
              << ", \"kkt\": {\"primal\": " << json(k.kkt.primal)
              << ", \"dual\": " << json(k.kkt.dual)
              << ", \"complementarity\": " << json(k.kkt.complementarity) << "}"
              << ", \"accepted\": " << (r.accepted() ? "true" : "false")
              << ", \"processes\": " << r.processes
              << ", \"shared_values\": " << r.shared_values
              << ", \"shared_seconds\": " << json(r.shared_seconds)
              << ", \"memory_mib\": [";
            for (unsigned int p = 0; p < r.memory_mib.size(); ++p)
              o << (p ? ", " : "") << json(r.memory_mib[p]);
            o << "]"
              << ", \"memory_estimate_mib\": " << json(r.memory_estimate_mib)
              << ", \"wall_seconds\": {\"setup\": " << json(r.setup_seconds)
              << ", \"assembly\": " << json(r.assembly_seconds)
              << ", \"factorisation\": " << json(r.factorisation_seconds)
              << ", \"solve\": " << json(r.solve_seconds)
              << ", \"solver_setup\": " << json(r.result.setup_seconds)
              << ", \"iteration\": " << json(r.result.iteration_seconds)
              << ", \"total\": " << json(r.total_seconds) << "}}";
          }
        o << "\n  ]\n}\n";
      });
  }
} // namespace bilayer
