#include <bilayer/output/cycle_record.h>
#include <bilayer/output/growth_record.h>

#include <cmath>
#include <sstream>

namespace bilayer
{
  void
  write_growth_csv_head(std::ostream                 &out,
                        const unsigned int            n_tips,
                        const unsigned int            n_points,
                        const std::vector<PartForce> &parts)
  {
    out << "# kind: load (a load factor), onset (the critical load of the "
           "crack), growth (the crack advanced at the load before); "
           "unstable: the growth at this load goes on\n"
        << "# conjugate_displacement: (F_1, w), the work of the unit "
           "proportional loads on the solution; ux_k, uy_k: layer 1 at "
           "Output/Displacement points k\n"
        << "# tip columns: position s, x, y; G, G_I, G_II; criterion (1: "
           "critical); critical_load (lambda at which it reaches 1); "
           "piece_length (of the tip's crack piece); status\n"
        << "# Fx_NAME, Fy_NAME: the force on boundary part NAME (the reaction "
           "of a clamped part, the traction's resultant on a loaded one; "
           "_rK: its share in region K); ux_NAME, uy_NAME: the part's mean "
           "displacement\n";
    out << "step,load_factor,kind,unstable,energy,conjugate_displacement,"
           "crack_length";
    for (unsigned int p = 1; p <= n_points; ++p)
      out << ",ux_" << p << ",uy_" << p;
    for (unsigned int t = 1; t <= n_tips; ++t)
      for (const char *key : {"s",
                              "x",
                              "y",
                              "G",
                              "G_I",
                              "G_II",
                              "criterion",
                              "critical_load",
                              "piece_length",
                              "status"})
        out << ",tip" << t << "_" << key;
    for (const std::string &column : force_columns(parts))
      out << ',' << column;
    out << '\n';
  }


  void
  write_growth_csv_row(std::ostream                 &out,
                       const GrowthStep             &step,
                       const unsigned int            n_tips,
                       const unsigned int            n_points,
                       const std::vector<PartForce> &parts)
  {
    out << step.step << ',' << json_number(step.load_factor) << ',' << step.kind
        << ',' << (step.unstable ? 1 : 0) << ',' << json_number(step.energy)
        << ',' << json_number(step.conjugate_displacement) << ','
        << json_number(step.crack_length);
    for (unsigned int p = 0; p < n_points; ++p)
      for (unsigned int d = 0; d < 2; ++d)
        out << ','
            << (p < step.point_displacements.size() ?
                  json_number(step.point_displacements[p][d]) :
                  std::string("null"));
    for (unsigned int t = 0; t < n_tips; ++t)
      {
        const GrowthTip *tip = nullptr;
        for (const GrowthTip &candidate : step.tips)
          if (candidate.number == t + 1 && candidate.present)
            tip = &candidate;
        if (!tip)
          {
            out << std::string(10, ',');
            continue;
          }
        for (const double value : {tip->s,
                                   tip->point[0],
                                   tip->point[1],
                                   tip->G,
                                   tip->G_I,
                                   tip->G_II,
                                   tip->criterion,
                                   tip->critical_load,
                                   tip->piece_length})
          out << ',' << json_number(value);
        // A status has no commas (a CSV cell).
        std::string status = tip->status;
        for (char &c : status)
          if (c == ',')
            c = ';';
        out << ',' << status;
      }
    out << force_cells(parts, step.parts) << '\n';
  }


  void
  write_growth_csv(std::ostream                  &out,
                   const std::vector<GrowthStep> &steps,
                   const unsigned int             n_tips,
                   const unsigned int             n_points)
  {
    const std::vector<PartForce>  none;
    const std::vector<PartForce> &parts = steps.empty() ? none : steps[0].parts;
    write_growth_csv_head(out, n_tips, n_points, parts);
    for (const GrowthStep &step : steps)
      write_growth_csv_row(out, step, n_tips, n_points, parts);
  }


  std::vector<UnstableRun>
  unstable_runs(const std::vector<GrowthStep> &steps)
  {
    std::vector<UnstableRun> runs;
    for (unsigned int k = 0; k < steps.size(); ++k)
      if (steps[k].unstable)
        {
          UnstableRun run;
          run.load_factor = steps[k].load_factor;
          run.first_step  = steps[k].step;
          run.from_length =
            k > 0 ? steps[k - 1].crack_length : steps[k].crack_length;
          unsigned int last = k;
          while (last + 1 < steps.size() && steps[last].unstable &&
                 steps[last + 1].kind == "growth")
            ++last;
          run.last_step = steps[last].step;
          run.to_length = steps[last].crack_length;
          runs.push_back(run);
          k = last;
        }
    return runs;
  }


  std::string
  growth_json(const std::string              &mode,
              const std::vector<GrowthStep>  &steps,
              const std::vector<UnstableRun> &unstable,
              const std::string              &stop)
  {
    std::ostringstream out;
    out << "{\"mode\": " << json_text(mode) << ", \"stop\": " << json_text(stop)
        << ", \"unstable\": [";
    for (unsigned int k = 0; k < unstable.size(); ++k)
      out << (k ? ", " : "")
          << "{\"load_factor\": " << json_number(unstable[k].load_factor)
          << ", \"first_step\": " << unstable[k].first_step
          << ", \"last_step\": " << unstable[k].last_step
          << ", \"from_length\": " << json_number(unstable[k].from_length)
          << ", \"to_length\": " << json_number(unstable[k].to_length) << "}";
    out << "],\n    \"steps\": [";
    for (unsigned int k = 0; k < steps.size(); ++k)
      {
        const GrowthStep &step = steps[k];
        out << (k ? "," : "") << "\n      {\"step\": " << step.step
            << ", \"load_factor\": " << json_number(step.load_factor)
            << ", \"kind\": " << json_text(step.kind)
            << ", \"unstable\": " << (step.unstable ? "true" : "false")
            << ", \"energy\": " << json_number(step.energy)
            << ", \"conjugate_displacement\": "
            << json_number(step.conjugate_displacement)
            << ", \"crack_length\": " << json_number(step.crack_length)
            << ", \"point_displacements\": [";
        for (unsigned int p = 0; p < step.point_displacements.size(); ++p)
          out << (p ? ", " : "") << "["
              << json_number(step.point_displacements[p][0]) << ", "
              << json_number(step.point_displacements[p][1]) << "]";
        out << "], \"tips\": [";
        bool first = true;
        for (const GrowthTip &tip : step.tips)
          {
            if (!tip.present)
              continue;
            out << (first ? "" : ", ") << "{\"tip\": " << tip.number
                << ", \"s\": " << json_number(tip.s)
                << ", \"x\": " << json_number(tip.point[0])
                << ", \"y\": " << json_number(tip.point[1])
                << ", \"G\": " << json_number(tip.G)
                << ", \"G_I\": " << json_number(tip.G_I)
                << ", \"G_II\": " << json_number(tip.G_II)
                << ", \"criterion\": " << json_number(tip.criterion)
                << ", \"critical_load\": " << json_number(tip.critical_load)
                << ", \"piece_length\": " << json_number(tip.piece_length)
                << ", \"status\": " << json_text(tip.status) << "}";
            first = false;
          }
        out << "]}";
      }
    out << "\n  ]}";
    return out.str();
  }
} // namespace bilayer
