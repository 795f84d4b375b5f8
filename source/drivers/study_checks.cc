// The study's checks: the memory a cycle needs and the acceptance checks of
// each record.

#include <bilayer/drivers/resources.h>
#include <bilayer/drivers/study.h>

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
    /// The reactions of the clamps balance the applied loads to round-off
    /// (boundary_forces(); the check appears only where it fails).
    void
    check_forces(CycleRecord &record)
    {
      if (record.forces.balanced())
        return;
      std::ostringstream what;
      what << std::setprecision(3) << "reactions balance the applied loads ("
           << record.forces.residual << " against the round-off bound "
           << record.forces.roundoff << " + " << force_balance_tolerance
           << " x " << record.forces.force_scale << ")";
      record.checks.emplace_back(what.str(), false);
    }


    /// With floating subproblems: their anchors balanced to the
    /// acceptance tolerance.
    void
    check_floating(CycleRecord &record, const double tolerance)
    {
      if (record.floating.subproblems.empty())
        return;
      std::ostringstream what;
      what << std::setprecision(3)
           << "anchors of the floating subproblems carry at most " << tolerance
           << " of the load scale";
      record.checks.emplace_back(what.str(),
                                 record.floating.out_of_balance <= tolerance);
    }
  } // namespace


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
                "use fewer cycles (Mesh/Number of cycles) or cells",
              need.memory);
    throw RunFailure(record.cycle, what.str());
  }


  std::string
  Study::TargetEstimate::text(const TargetQuantity quantity) const
  {
    std::ostringstream t;
    t << std::setprecision(3) << "the estimated relative error of "
      << (quantity == TargetQuantity::G ? "G" : "the energy");
    if (std::isnan(relative))
      t << " is not known yet" << (where.empty() ? "" : " (" + where + ")");
    else
      t << " is " << relative << (where.empty() ? "" : " (" + where + ")");
    if (round_off)
      t << ", the energy-norm estimate at round-off (a scene without "
           "stresses)";
    return t.str();
  }


  Study::TargetEstimate
  Study::target_estimate(const CycleRecord &record) const
  {
    TargetEstimate e;
    const double   scale =
      std::sqrt(model.stiffness_scale()) * record.report.displacement_scale;
    e.round_off = record.eta <= 1e-10 * scale;
    if (scene.mesh.target_quantity == TargetQuantity::energy)
      {
        e.relative = record.eta * record.eta / (2 * std::abs(record.energy));
        return e;
      }
    if (record.release.empty())
      e.where = "no crack tip";
    double largest = 0;
    for (const EnergyReleaseRate &g : record.release)
      if (std::isfinite(g.G))
        largest = std::max(largest, std::abs(g.G));
    for (unsigned int t = 0; t < record.release.size(); ++t)
      {
        const EnergyReleaseRate &g = record.release[t];
        // (0 / 0: an exact zero of G and of its bar.) A tip whose G and bar
        // together are below the target times the largest G of the state
        // (a closed tip: G = 0 to the target's accuracy) is measured
        // against that largest G: its own G is noise.
        const bool closed =
          largest > 0 && std::abs(g.G) + std::abs(g.error) <=
                           scene.mesh.target_accuracy * largest;
        const double relative =
          g.error == 0 ? 0. :
                         std::abs(g.error) / (closed ? largest : std::abs(g.G));
        if (std::isnan(relative))
          {
            e.relative = relative;
            e.where    = "tip " + std::to_string(t + 1) + " has no error bar";
            break;
          }
        if (t == 0 || relative > e.relative)
          {
            e.relative = relative;
            e.where    = "tip " + std::to_string(t + 1);
          }
      }
    return e;
  }


  bool
  Study::target_met(const CycleRecord &record) const
  {
    const double         target = scene.mesh.target_accuracy;
    const TargetQuantity what   = scene.mesh.target_quantity;
    const TargetEstimate e      = target_estimate(record);
    const bool           met    = e.round_off || e.relative <= target;
    std::ostringstream   line;
    line << std::setprecision(3) << "Mesh/Target accuracy = " << target << ": "
         << e.text(what);
    rout << state_name(record.cycle) << ": " << line.str()
         << (met ? ": met, the cycles stop" : ": not met") << std::endl;
    if (!met && record.cycle + 1 == scene.mesh.n_cycles)
      throw RunFailure(record.cycle,
                       line.str() +
                         " after the last of Mesh/Number of "
                         "cycles = " +
                         std::to_string(scene.mesh.n_cycles) +
                         ": the target is not reached (more cycles, or a "
                         "larger target)");
    return met;
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
        !model.geometry().interface_curve().crack().empty())
      {
        record.checks.emplace_back("contact multiplier mu_c >= 0",
                                   r.min_contact_multiplier >= 0);
        record.checks.emplace_back("complementarity <= " + t.str(),
                                   r.complementarity <= tol);
        if (scene.contact.frictional())
          record.checks.emplace_back("friction complementarity <= " + t.str(),
                                     r.friction_complementarity <= tol);
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
      std::isfinite(r.friction_complementarity) &&
      std::isfinite(r.friction_dissipation) &&
      (std::isfinite(record.eta) || !estimates_error(record));
    record.checks.emplace_back("energy and residuals finite", finite);
    check_forces(record);
    check_floating(record, scene.solver.acceptance_tolerance);
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
               << ", and the energy, the residuals and the error estimate "
                  "(squares of the stresses) exceed double precision "
                  "(1.8e308): choose units in which the moduli (Materials) "
                  "and the loads (the Loads section) are nearer 1, e.g. GPa "
                  "and mm (the problem is linear: the stresses scale with "
                  "the loads, the displacements with the loads over the "
                  "moduli, the energy with the loads' square over the "
                  "moduli)";
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

} // namespace bilayer
