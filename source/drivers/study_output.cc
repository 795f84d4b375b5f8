// The study's outputs: the files of each record (solution, interface CSV,
// summary.json, the tables) and the terminal report.

#include <deal.II/base/utilities.h>

#include <bilayer/drivers/study.h>
#include <bilayer/interface/cohesive_zone.h>
#include <bilayer/output/output.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <iomanip>
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


    /// The line of K at a tip (docs/fracture.md §10) on @p out.
    void
    write_stress_intensity(const ConditionalOStream &out,
                           const EnergyReleaseRate  &g)
    {
      if (g.K_note.empty() && !std::isfinite(g.K_magnitude))
        return; // Fracture/Stress intensity factors = false
      out << "    stress intensity           ";
      if (std::isfinite(g.K_I))
        out << "K_I = " << g.K_I << ", K_II = " << g.K_II << std::defaultfloat
            << std::setprecision(4) << " (phase angle " << g.K_phase_angle
            << " degrees" << std::scientific << std::setprecision(4);
      else if (std::isfinite(g.K_magnitude))
        out << "|K| = " << g.K_magnitude << " (";
      else
        out << "not computed";
      if (std::isfinite(g.K_magnitude))
        {
          if (std::isfinite(g.K_I))
            out << ", ";
          out << std::defaultfloat << std::setprecision(4)
              << "eps = " << g.oscillation_index;
          if (std::isfinite(g.reference_length))
            out << " at L = " << g.reference_length;
          out << "; G from K " << std::scientific << std::setprecision(4)
              << g.G_from_K << ", relative to G " << std::setprecision(1)
              << (g.G_from_K - g.G) / std::abs(g.G) << std::setprecision(4)
              << ")";
        }
      if (!g.K_note.empty())
        out << " (" << g.K_note << ")";
      out << "\n";
    }
  } // namespace


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
    outputs.time = growth_run ? growth_step_time(record.cycle) :
                                std::numeric_limits<double>::quiet_NaN();
    // A growth step is written where Output/Written steps asks (and where
    // it fails its checks: the run ends there).
    const bool step_written = !growth_run ||
                              scene.output.writes_step(record.cycle) ||
                              !record.accepted();
    const bool fields =
      step_written &&
      (growth_run ? scene.output.write_vtu || scene.output.write_hdf5 :
                    scene.output.writes_fields(record.cycle,
                                               scene.mesh.n_cycles,
                                               record.accepted()));
    if (fields)
      writing([&]() {
        write_solution(dir,
                       record.cycle,
                       model.subproblem_views(),
                       model.solutions(),
                       scene.output,
                       outputs,
                       model.goal_cell_fields());
      });
    record.total_seconds = distribution.max(total.wall_time());
    Utilities::System::MemoryStats memory;
    Utilities::System::get_memory_stats(memory);
    record.memory_mib = distribution.gather(memory.VmHWM / 1024.);

    cycle_records.push_back(record);
    add_to_table(table, cycle_records);
    if (distribution.is_root())
      writing([&]() { write_records(record.cycle, fields, step_written); });
    std::string error = distribution.first_error(writing.message);
    // The files just written are there (checked again at the next cycle
    // and before the results are published); a write that failed because
    // the directory was removed or replaced is reported as such.
    if (directory_check)
      {
        FirstFailure written;
        if (distribution.is_root())
          written(directory_check);
        const std::string changed = distribution.first_error(written.message);
        if (!changed.empty())
          error = changed;
      }
    if (!error.empty())
      throw CollectiveError(std::string("writing the results of ") +
                            (growth_run ? "step " : "cycle ") +
                            std::to_string(record.cycle) + " failed: " + error);
  }


  void
  Study::write_step_fields(const unsigned int step)
  {
    const std::string &dir = scene.output.directory;
    std::string        failure;
    outputs.time = growth_step_time(step);
    try
      {
        if (scene.output.write_vtu || scene.output.write_hdf5)
          write_solution(dir,
                         step,
                         model.subproblem_views(),
                         model.solutions(),
                         scene.output,
                         outputs,
                         model.goal_cell_fields());
        if (distribution.is_root())
          write_interface_files(step, scene.output.write_vtu, true);
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
      throw CollectiveError("writing the results of step " +
                            std::to_string(step) + " failed: " + error);
  }


  void
  Study::write_interface_files(const unsigned int cycle,
                               const bool         interface_vtu,
                               const bool         interface_csv)
  {
    const std::string &dir = scene.output.directory;
    const bool         csv = interface_csv && scene.output.write_interface;
    if (!csv && !interface_vtu)
      return;
    // One file of each kind per interface.
    for (const unsigned int i :
         Layout::indices(model.topology().n_interfaces()))
      {
        std::vector<InterfaceNode> nodes =
          interface_nodes(model.interface(),
                          model.solutions(),
                          model.multipliers(),
                          scene.solver.acceptance_tolerance,
                          i);
        // The cohesive zone's damage (committed: the step's state).
        if (written_zone != nullptr && written_zone->block() == i)
          for (unsigned int a = 0; a < nodes.size(); ++a)
            {
              nodes[a].cohesive = true;
              if (written_zone->in_zone(a))
                nodes[a].damage = written_zone->damage(a);
            }
        std::vector<std::string> trace_names;
        for (const unsigned int s : trace_subproblems(model.topology(), i))
          trace_names.push_back(model.topology().field_name(s));
        if (csv)
          write_atomically(dir + "/" + interface_stem(i) + "-" +
                             two_digits(cycle) + ".csv",
                           [&](std::ostream &o) {
                             write_interface_csv(
                               o,
                               nodes,
                               trace_names,
                               release_notes(cycle_records.back().release,
                                             scene.geometry.gmsh_file.empty(),
                                             i));
                           });
        if (interface_vtu)
          write_interface_vtu(dir, cycle, nodes, trace_names, outputs, i);
      }
  }


  void
  Study::write_records(const unsigned int cycle,
                       const bool         fields,
                       const bool         interface_csv)
  {
    write_interface_files(cycle,
                          fields && scene.output.write_vtu,
                          interface_csv);
    const std::string &dir = scene.output.directory;
    // (A growth step's summary.json, with the growth object, comes from
    // write_growth() once the step is measured.)
    if (!growth_run)
      write_atomically(dir + "/summary.json", [&](std::ostream &o) {
        write_summary_json(
          o, scene.name, cycle_records, "", scene.output.units);
      });
    // (A growth run writes its tables once, at the end: write_growth().)
    if (!growth_run)
      write_tables();
  }


  void
  Study::write_tables()
  {
    const std::string &dir = scene.output.directory;
    write_atomically(dir + "/table.txt", [&](std::ostream &o) {
      write_tip_notes(o);
      table.write_text(o, TableHandler::org_mode_table);
    });
    write_atomically(dir + "/table.tex", [&](std::ostream &o) {
      write_compact_tex(o, cycle_records);
    });
    write_atomically(dir + "/table.csv", [&](std::ostream &o) {
      write_csv_table(o, cycle_records, scene.geometry.gmsh_file.empty());
    });
  }


  void
  Study::print_forces(const ForceBalance &forces) const
  {
    if (!forces.computed())
      {
        pcout << "  forces on the boundary parts not computed (a subproblem "
                 "shared by a group of processes)\n";
        return;
      }
    const auto vector = [](const Tensor<1, 2> &v) {
      std::ostringstream s;
      s << std::scientific << std::setprecision(4) << "(" << v[0] << ", "
        << v[1] << ")";
      return s.str();
    };
    for (const PartForce &part : forces.parts)
      {
        pcout << "  boundary part " << part.name
              << (part.clamped ? " (clamped): reaction " : ": traction force ")
              << vector(part.force());
        if (part.layer_force.size() > 1)
          {
            pcout << " = layers";
            for (const Tensor<1, 2> &f : part.layer_force)
              pcout << " " << vector(f);
          }
        if (part.regions.size() > 1)
          {
            pcout << ", regions";
            for (const PartForce::RegionShare &share : part.regions)
              pcout << " " << share.region + 1 << ": " << vector(share.force);
          }
        pcout << "; mean displacement " << vector(part.mean_displacement())
              << "\n";
      }
    pcout << "  force balance                applied loads "
          << vector(forces.applied) << ", reactions "
          << vector(forces.reactions) << ", imbalance " << std::scientific
          << std::setprecision(2) << forces.residual << " (round-off bound "
          << forces.roundoff << ")\n";
  }


  void
  Study::print_floating(const FloatingReport &floating) const
  {
    if (floating.subproblems.empty())
      return;
    pcout << "  floating subproblems         ";
    for (unsigned int s = 0; s < floating.subproblems.size(); ++s)
      pcout << (s ? ", " : "") << floating.subproblems[s];
    pcout << (floating.free_specimen ? " (free specimen)" : "")
          << ": largest anchor reaction " << std::scientific
          << std::setprecision(2) << floating.out_of_balance
          << " of the load scale after " << floating.outer_solves
          << " outer solves and " << floating.jacobian_solves
          << " coarse solves (" << std::setprecision(3)
          << floating.coarse_seconds << " s)\n";
    if (floating.free_specimen)
      pcout << "  free specimen                load resultant ("
            << floating.resultant[0] << ", " << floating.resultant[1]
            << "), moment " << floating.resultant[2]
            << "; rigid motion removed (" << floating.normalisation[0] << ", "
            << floating.normalisation[1] << "), rotation "
            << floating.normalisation[2] << "\n";
  }


  void
  Study::print_release(const CycleRecord &record) const
  {
    pcout << std::scientific << std::setprecision(4);
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
            if (scene.contact.frictional())
              pcout << "friction term " << g.friction << "; ";
            pcout << std::defaultfloat << std::setprecision(3)
                  << "support radius " << g.tip.support_radius << ")"
                  << std::scientific << std::setprecision(4) << "\n";
            pcout << "    mode split                 ";
            if (std::isfinite(g.G_I))
              pcout << "G_I = " << g.G_I << ", G_II = " << g.G_II
                    << std::defaultfloat << std::setprecision(3)
                    << " (phase angle " << g.phase_angle
                    << " degrees, closure length " << g.mode_split_length << ")"
                    << std::scientific << std::setprecision(4);
            else
              pcout << "not defined";
            if (!g.mode_split_note.empty())
              pcout << " (" << g.mode_split_note << ")";
            pcout << "\n";
            write_stress_intensity(pcout, g);
            if (std::isfinite(g.G_dwr))
              pcout << "    goal-oriented estimate     G - G_h = " << g.G_dwr
                    << " (DWR; sum of |cell terms| " << g.G_dwr_absolute
                    << ")\n";
          }
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
          << (estimates_error(record) ?
                "  (energy norm, sqrt(2 (Pi_h - Pi)) by the estimator)\n" :
                "  (not estimated: a growth step on the mesh of step 0)\n");
    if (std::isfinite(record.energy_dwr))
      pcout << "  goal-oriented estimate       Pi - Pi_h = "
            << record.energy_dwr << " (DWR; " << record.dwr_iterations
            << " dual conjugate-gradient iterations, " << std::defaultfloat
            << std::setprecision(3) << record.dwr_seconds << " s"
            << (record.dwr_note.empty() ? "" : "; " + record.dwr_note) << ")"
            << std::scientific << std::setprecision(4) << "\n";
    pcout << "  constraint violation (12)    " << r.constraint_violation
          << "  (relative " << r.relative_constraint_violation << ")\n"
          << "  largest interpenetration     " << r.max_penetration
          << "  (displacement scale " << r.displacement_scale << ")\n"
          << "  discrete violation           " << r.relative_discrete_violation
          << " (relative)\n"
          << "  smallest mu_c                " << r.min_contact_multiplier
          << "\n"
          << "  complementarity              " << r.complementarity << "\n"
          << "  KKT residual (relative)      " << r.kkt.value() << "\n";
    print_release(record);
    print_forces(record.forces);
    print_floating(record.floating);
    pcout << std::defaultfloat << std::setprecision(3)
          << "  processes                    " << record.processes
          << ", traces sent " << record.shared_values << " values in "
          << record.shared_seconds << " s, peak memory per process [MiB]";
    for (const double m : record.memory_mib)
      pcout << " " << std::fixed << std::setprecision(0) << m;
    pcout << " (estimated " << record.memory_estimate_mib << ")";
    pcout << "\n" << std::defaultfloat << std::setprecision(3);
    if (!record.factor_flops.empty())
      {
        pcout << "  factorisations               ";
        for (unsigned int s = 0; s < record.factor_flops.size(); ++s)
          pcout << (s > 0 ? "; " : "") << record.factor_orderings[s] << " "
                << record.factor_flops[s] << " flops "
                << record.factor_entries[s] << " entries";
        pcout << "\n";
      }
    pcout << "  wall time                    setup " << record.setup_seconds
          << " s, solve " << record.solve_seconds << " s, total "
          << record.total_seconds << " s" << std::endl;
    for (const auto &c : record.checks)
      rout << state_name(record.cycle) << ": " << c.first << ": "
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
    rout << state_name(record.cycle) << ": energy Pi " << scaled(record.energy)
         << std::endl;
    if (distribution.is_root())
      {
        // Over the cracks of all interfaces.
        int          a_max   = -1;
        unsigned int i_max   = 0;
        double       largest = 0;
        for (const unsigned int i :
             Layout::indices(model.interface().n_interfaces()))
          {
            const std::vector<double> opening =
              normal_opening(model.interface(), model.solutions(), i);
            for (unsigned int a = 0; a < model.interface().space().n_nodes(i);
                 ++a)
              if (model.interface().space().on_crack(a, i) &&
                  (a_max < 0 || opening[a] > largest))
                a_max = a, i_max = i, largest = opening[a];
          }
        if (a_max >= 0)
          {
            // The position: s = x on the rectangle, else s and the point.
            const double s_max =
              model.interface().space().node_position(a_max, i_max);
            std::ostringstream x;
            x << std::setprecision(6);
            if (scene.geometry.gmsh_file.empty())
              {
                x << "x = " << s_max;
                if (i_max > 0)
                  x << " on interface " << i_max + 1;
              }
            else
              {
                const Point<2> p = model.interface().curve(i_max).point(s_max);
                x << "s = " << s_max << ", (x, y) = (" << p[0] << ", " << p[1]
                  << ")";
                if (i_max > 0)
                  x << " on interface " << i_max + 1;
              }
            rout << state_name(record.cycle) << ": largest crack opening "
                 << scaled(largest) << " at " << x.str() << std::endl;
          }
      }
  }
} // namespace bilayer
