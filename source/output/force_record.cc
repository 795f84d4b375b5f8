// The forces on the boundary parts in summary.json, table.csv and
// growth.csv.

#include <bilayer/output/cycle_record.h>

namespace bilayer
{
  using namespace dealii;

  namespace
  {
    /// [x, y] of a vector.
    std::string
    json(const Tensor<1, 2> &v)
    {
      return "[" + json_number(v[0]) + ", " + json_number(v[1]) + "]";
    }

    /// [[x, y], ...] of a list of vectors.
    std::string
    json(const std::vector<Tensor<1, 2>> &list)
    {
      std::string text = "[";
      for (unsigned int i = 0; i < list.size(); ++i)
        text += (i ? ", " : "") + json(list[i]);
      return text + "]";
    }

  } // namespace


  /// The "boundary_parts" and "force_balance" of a cycle's object.
  void
  write_forces_json(std::ostream &out, const ForceBalance &forces)
  {
    out << ", \"boundary_parts\": [";
    for (unsigned int p = 0; p < forces.parts.size(); ++p)
      {
        const PartForce &part = forces.parts[p];
        out << (p ? ", " : "") << "{\"name\": " << json_text(part.name)
            << ", \"clamped\": " << (part.clamped ? "true" : "false")
            << ", \"length\": " << json_number(part.length)
            << ", \"force\": " << json(part.force())
            << ", \"layer_forces\": " << json(part.layer_force)
            << ", \"mean_displacement\": " << json(part.mean_displacement())
            << ", \"layer_mean_displacements\": "
            << json(part.layer_mean_displacement) << ", \"regions\": [";
        for (unsigned int r = 0; r < part.regions.size(); ++r)
          out << (r ? ", " : "")
              << "{\"region\": " << part.regions[r].region + 1
              << ", \"length\": " << json_number(part.regions[r].length)
              << ", \"force\": " << json(part.regions[r].force)
              << ", \"mean_displacement\": "
              << json(part.regions[r].mean_displacement) << "}";
        out << "]}";
      }
    out << "], \"force_balance\": {\"applied\": " << json(forces.applied)
        << ", \"reactions\": " << json(forces.reactions)
        << ", \"residual\": " << json_number(forces.residual)
        << ", \"force_scale\": " << json_number(forces.force_scale)
        << ", \"relative_imbalance\": " << json_number(forces.imbalance())
        << ", \"roundoff\": " << json_number(forces.roundoff)
        << ", \"anchors\": " << json(forces.anchors) << "}";
  }


  /// The "floating" object of a cycle: the floating subproblems and their
  /// balance (nothing where every subproblem is clamped).
  void
  write_floating_json(std::ostream &out, const FloatingReport &floating)
  {
    if (floating.subproblems.empty())
      return;
    out << ", \"floating\": {\"subproblems\": [";
    for (unsigned int s = 0; s < floating.subproblems.size(); ++s)
      out << (s ? ", " : "") << json_text(floating.subproblems[s]);
    out << "], \"free_specimen\": "
        << (floating.free_specimen ? "true" : "false")
        << ", \"outer_solves\": " << floating.outer_solves
        << ", \"coarse_solves\": " << floating.jacobian_solves
        << ", \"out_of_balance\": " << json_number(floating.out_of_balance);
    if (floating.free_specimen)
      out << ", \"load_resultant\": [" << json_number(floating.resultant[0])
          << ", " << json_number(floating.resultant[1]) << ", "
          << json_number(floating.resultant[2])
          << "], \"load_magnitude\": " << json_number(floating.load_magnitude)
          << ", \"rigid_motion_removed\": ["
          << json_number(floating.normalisation[0]) << ", "
          << json_number(floating.normalisation[1]) << ", "
          << json_number(floating.normalisation[2]) << "]";
    out << "}";
  }


  std::vector<std::string>
  force_columns(const std::vector<PartForce> &parts)
  {
    std::vector<std::string> columns;
    const auto               add = [&](const std::string &suffix) {
      for (const char *key : {"Fx_", "Fy_", "ux_", "uy_"})
        columns.push_back(key + suffix);
    };
    for (const PartForce &part : parts)
      {
        add(part.name);
        if (part.regions.size() > 1)
          for (const PartForce::RegionShare &share : part.regions)
            add(part.name + "_r" + std::to_string(share.region + 1));
      }
    return columns;
  }


  std::string
  force_cells(const std::vector<PartForce> &columns_of,
              const std::vector<PartForce> &parts)
  {
    std::string cells;
    // (Both null, or both given.)
    const auto add = [&](const Tensor<1, 2> *f, const Tensor<1, 2> *u) {
      for (unsigned int k = 0; k < 4; ++k)
        cells += "," + (f ? json_number(k < 2 ? (*f)[k] : (*u)[k - 2]) :
                            std::string("null"));
    };
    for (unsigned int p = 0; p < columns_of.size(); ++p)
      {
        const PartForce   *part  = p < parts.size() ? &parts[p] : nullptr;
        const Tensor<1, 2> force = part ? part->force() : Tensor<1, 2>();
        const Tensor<1, 2> mean =
          part ? part->mean_displacement() : Tensor<1, 2>();
        add(part ? &force : nullptr, part ? &mean : nullptr);
        if (columns_of[p].regions.size() > 1)
          for (const PartForce::RegionShare &column : columns_of[p].regions)
            {
              const PartForce::RegionShare *share = nullptr;
              if (part)
                for (const PartForce::RegionShare &candidate : part->regions)
                  if (candidate.region == column.region)
                    share = &candidate;
              add(share ? &share->force : nullptr,
                  share ? &share->mean_displacement : nullptr);
            }
      }
    return cells;
  }
} // namespace bilayer
