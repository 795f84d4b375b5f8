#include <deal.II/base/exceptions.h>
#include <deal.II/base/multithread_info.h>

#include <bilayer/core/build_info.h>
#include <bilayer/output/cycle_record.h>

#include <algorithm>
#include <cmath>
#include <iomanip>
#include <limits>
#include <set>
#include <sstream>

namespace bilayer
{
  using namespace dealii;

  std::string
  json_number(const double value)
  {
    if (!std::isfinite(value))
      return "null";
    std::ostringstream s;
    s << std::setprecision(17) << value;
    return s.str();
  }


  std::string
  json_text(const std::string &text)
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


  namespace
  {
    std::string
    json(const double value)
    {
      return json_number(value);
    }

    std::string
    json(const std::string &text)
    {
      return json_text(text);
    }

    /// A value as JSON.
    std::string
    json(const RecordValue &value)
    {
      if (const bool *flag = std::get_if<bool>(&value))
        return *flag ? "true" : "false";
      if (const unsigned long *count = std::get_if<unsigned long>(&value))
        return std::to_string(*count);
      if (const double *number = std::get_if<double>(&value))
        return json(*number);
      if (const std::string *text = std::get_if<std::string>(&value))
        return json(*text);
      std::string list = "[";
      for (const double x : std::get<std::vector<double>>(value))
        list += (list.size() > 1 ? ", " : "") + json(x);
      return list + "]";
    }

    /// A value as a CSV cell: flags 1/0, numbers as in JSON.
    std::string
    csv(const RecordValue &value)
    {
      if (const bool *flag = std::get_if<bool>(&value))
        return *flag ? "1" : "0";
      Assert(!std::holds_alternative<std::vector<double>>(value),
             ExcMessage("a list is no CSV cell"));
      return json(value);
    }

    using R = CycleRecord;

    /// A quantity that is positive where it was computed: NaN (null in
    /// summary.json and table.csv) where it was not.
    double
    computed(const double value)
    {
      return value > 0 ? value : std::numeric_limits<double>::quiet_NaN();
    }

    /// The cycle, the sizes of the meshes and the numbers of unknowns.
    std::vector<RecordField>
    mesh_fields()
    {
      // clang-format off
      return {
        record_field("cycle", [](const R &r) { return r.cycle; })
          .csv(0, "cycle").column("cycle"),
        record_field("vertices_minus", [](const R &r) { return r.minus.vertices; })
          .csv(7, "vertices_minus").column("Nod-"),
        record_field("cells_minus", [](const R &r) { return r.minus.cells; })
          .csv(8, "cells_minus").column("Cells-"),
        record_field("vertices_plus", [](const R &r) { return r.plus.vertices; })
          .csv(9, "vertices_plus").column("Nod+"),
        record_field("cells_plus", [](const R &r) { return r.plus.cells; })
          .csv(10, "cells_plus").column("Cells+"),
        record_field("P", [](const R &r) { return r.P; })
          .csv(1, "P").column("P"),
        record_field("M", [](const R &r) { return r.M; })
          .csv(2, "M").column("M"),
        record_field("h_min_minus", [](const R &r) { return r.minus.h_min; })
          .csv(3, "h_min_minus").column("h-min", 3, true),
        record_field("h_max_minus", [](const R &r) { return r.minus.h_max; })
          .csv(4, "h_max_minus").column("h-max", 3, true),
        record_field("h_min_plus", [](const R &r) { return r.plus.h_min; })
          .csv(5, "h_min_plus").column("h+min", 3, true),
        record_field("h_max_plus", [](const R &r) { return r.plus.h_max; })
          .csv(6, "h_max_plus").column("h+max", 3, true),
        record_field("dofs", [](const R &r) { return r.dofs; })
          .csv(11, "dofs").column("dofs"),
        record_field("multipliers", [](const R &r) { return r.multipliers; })
          .csv(12, "multipliers"),
      };
      // clang-format on
    }

    /// The outer solver: its parameters, iterations and outcome.
    std::vector<RecordField>
    solver_fields()
    {
      // clang-format off
      return {
        record_field("solver", [](const R &r) { return r.result.solver; }),
        record_field("theta", [](const R &r) { return computed(r.theta); })
          .csv(13, "theta"),
        record_field("lambda_max", [](const R &r) { return computed(r.result.lambda_max); }),
        record_field("predicted_threshold",
                     [](const R &r) { return computed(r.result.predicted_threshold); }),
        record_field("threshold_at_solution",
                     [](const R &r) { return computed(r.result.threshold_at_solution); }),
        record_field("iterations", [](const R &r) { return r.result.iterations; })
          .csv(14, "iterations").column("iter"),
        record_field("subdomain_solves",
                     [](const R &r) { return r.result.subdomain_solves; })
          .csv(15, "subdomain_solves").column("solves"),
        record_field("preconditioner_solves",
                     [](const R &r) { return r.result.preconditioner_solves; }),
        record_field("linear_iterations",
                     [](const R &r) { return r.result.linear_iterations; }),
        record_field("converged", [](const R &r) { return r.result.converged; })
          .csv(16, "converged"),
        record_field("diverged", [](const R &r) { return r.result.diverged; }),
        record_field("stopping_value",
                     [](const R &r) { return r.result.stopping_value; }),
        record_field("message", [](const R &r) { return r.result.message; }),
      };
      // clang-format on
    }

    /// The energies, the estimate and the report on the interface.
    std::vector<RecordField>
    solution_fields()
    {
      // clang-format off
      return {
        record_field("energy", [](const R &r) { return r.energy; })
          .csv(17, "energy").column("energy", 8, true),
        record_field("layer_1", [](const R &r) { return r.layer_energy[0]; })
          .in("energy_of"),
        record_field("layer_2", [](const R &r) { return r.layer_energy[1]; })
          .in("energy_of"),
        record_field("layers", [](const R &r) { return r.layer_energy; })
          .in("energy_of"),
        record_field("constraint_violation",
                     [](const R &r) { return r.report.constraint_violation; })
          .csv(18, "constraint_violation").column("violation", 2, true),
        record_field("eta", [](const R &r) { return r.eta; })
          .csv(19, "eta").column("eta", 2, true),
        record_field("energy_dwr", [](const R &r) { return r.energy_dwr; }),
        record_field("relative_constraint_violation",
                     [](const R &r) { return r.report.relative_constraint_violation; }),
        record_field("max_penetration",
                     [](const R &r) { return r.report.max_penetration; })
          .csv(20, "max_penetration"),
        record_field("displacement_scale",
                     [](const R &r) { return r.report.displacement_scale; }),
        record_field("relative_discrete_violation",
                     [](const R &r) { return r.report.relative_discrete_violation; }),
        record_field("relative_jump_without_multiplier",
                     [](const R &r) { return r.report.relative_jump_without_multiplier; }),
        record_field("min_contact_multiplier",
                     [](const R &r) { return r.report.min_contact_multiplier; }),
        record_field("complementarity",
                     [](const R &r) { return r.report.complementarity; }),
        record_field("max_multiplier_over_bound",
                     [](const R &r) { return r.report.max_multiplier_over_bound; }),
        record_field("kkt_residual", [](const R &r) { return r.report.kkt.value(); }),
        record_field("primal", [](const R &r) { return r.report.kkt.primal; })
          .in("kkt"),
        record_field("dual", [](const R &r) { return r.report.kkt.dual; })
          .in("kkt"),
        record_field("complementarity",
                     [](const R &r) { return r.report.kkt.complementarity; })
          .in("kkt"),
        record_field("iterations",
                     [](const R &r) { return r.friction_iterations; })
          .in("friction"),
        record_field("bound_change",
                     [](const R &r) { return r.friction_bound_change; })
          .in("friction"),
        record_field("complementarity",
                     [](const R &r) { return r.report.friction_complementarity; })
          .in("friction"),
        record_field("dissipation",
                     [](const R &r) { return r.report.friction_dissipation; })
          .in("friction"),
        record_field("max_slip",
                     [](const R &r) { return r.report.max_slip; })
          .in("friction"),
        record_field("stick_nodes",
                     [](const R &r) { return r.report.stick_nodes; })
          .in("friction"),
        record_field("slip_nodes",
                     [](const R &r) { return r.report.slip_nodes; })
          .in("friction"),
      };
      // clang-format on
    }

    /// The extreme eigenvalues of the dual operator (dual_spectrum).
    std::vector<RecordField>
    spectrum_fields()
    {
      // clang-format off
      return {
        record_field("lambda_min", [](const R &r) { return computed(r.spectrum.lambda_min); })
          .in("dual_spectrum"),
        record_field("lambda_max", [](const R &r) { return computed(r.spectrum.lambda_max); })
          .in("dual_spectrum"),
        record_field("condition_number", [](const R &r) {
            return r.spectrum.lambda_min > 0 ? r.spectrum.condition_number() :
                                               computed(0.); })
          .in("dual_spectrum"),
        record_field("h", [](const R &r) { return computed(r.spectrum.h); })
          .in("dual_spectrum"),
        record_field("lanczos_steps", [](const R &r) { return r.spectrum.iterations; })
          .in("dual_spectrum"),
      };
      // clang-format on
    }

    /// Acceptance, processes, communication, memory and wall times.
    std::vector<RecordField>
    run_fields()
    {
      // clang-format off
      return {
        record_field("accepted", [](const R &r) { return r.accepted(); }),
        record_field("processes", [](const R &r) { return r.processes; }),
        record_field("shared_values", [](const R &r) { return r.shared_values; }),
        record_field("shared_seconds", [](const R &r) { return r.shared_seconds; }),
        record_field("memory_mib", [](const R &r) { return r.memory_mib; }),
        record_field("memory_estimate_mib",
                     [](const R &r) { return r.memory_estimate_mib; }),
        record_field("ordering", [](const R &r) {
          std::string names;
          for (const auto &o : r.factor_orderings)
            names += (names.empty() ? "" : ", ") + o;
          return names; }).in("factors"),
        record_field("flops", [](const R &r) { return r.factor_flops; })
          .in("factors"),
        record_field("entries", [](const R &r) { return r.factor_entries; })
          .in("factors"),
        record_field("setup", [](const R &r) { return r.setup_seconds; })
          .in("wall_seconds").csv(21, "setup_seconds"),
        record_field("assembly", [](const R &r) { return r.assembly_seconds; })
          .in("wall_seconds"),
        record_field("factorisation",
                     [](const R &r) { return r.factorisation_seconds; })
          .in("wall_seconds"),
        record_field("solve", [](const R &r) { return r.solve_seconds; })
          .in("wall_seconds").csv(22, "solve_seconds"),
        record_field("solver_setup",
                     [](const R &r) { return r.result.setup_seconds; })
          .in("wall_seconds"),
        record_field("iteration",
                     [](const R &r) { return r.result.iteration_seconds; })
          .in("wall_seconds"),
        record_field("total", [](const R &r) { return r.total_seconds; })
          .in("wall_seconds").csv(23, "total_seconds").column("time [s]", 3),
      };
      // clang-format on
    }

    /**
     * The description of the record. Order: that of summary.json; the
     * columns of table.csv are numbered, the mesh-size table has a subset
     * of them in the same order.
     */
    std::vector<RecordField>
    describe_fields()
    {
      std::vector<RecordField> fields = mesh_fields();
      for (const std::vector<RecordField> &part : {solver_fields(),
                                                   solution_fields(),
                                                   spectrum_fields(),
                                                   run_fields()})
        fields.insert(fields.end(), part.begin(), part.end());
      return fields;
    }

    /// The fields in table.csv, in the order of its columns.
    std::vector<const RecordField *>
    csv_fields()
    {
      std::vector<const RecordField *> in_csv;
      for (const RecordField &field : CycleRecord::fields())
        if (!field.csv_key.empty())
          in_csv.push_back(&field);
      std::sort(in_csv.begin(),
                in_csv.end(),
                [](const RecordField *a, const RecordField *b) {
                  return a->csv_column < b->csv_column;
                });
      return in_csv;
    }

    /// Whether the description is consistent: the CSV columns are numbered
    /// 0, 1, ... without gaps, every table column is a CSV column, and the
    /// fields of each nested object of summary.json are consecutive.
    bool
    consistent(const std::vector<RecordField> &fields)
    {
      std::vector<unsigned int> columns;
      for (const RecordField &field : fields)
        {
          if (!field.csv_key.empty())
            columns.push_back(field.csv_column);
          else if (!field.table.header.empty())
            return false;
        }
      std::sort(columns.begin(), columns.end());
      for (unsigned int i = 0; i < columns.size(); ++i)
        if (columns[i] != i)
          return false;
      std::vector<std::string> closed;
      for (unsigned int i = 1; i < fields.size(); ++i)
        if (fields[i].json_object != fields[i - 1].json_object)
          {
            if (std::find(closed.begin(),
                          closed.end(),
                          fields[i].json_object) != closed.end())
              return false;
            if (!fields[i - 1].json_object.empty())
              closed.push_back(fields[i - 1].json_object);
          }
      return true;
    }

    std::vector<RecordField>
    checked(std::vector<RecordField> fields)
    {
      AssertThrow(consistent(fields),
                  ExcMessage("the description of CycleRecord in "
                             "source/cycle_record.cc is inconsistent"));
      return fields;
    }
  } // namespace


  RecordField
  RecordField::in(const std::string &object) const
  {
    RecordField field = *this;
    field.json_object = object;
    return field;
  }


  RecordField
  RecordField::csv(const unsigned int column, const std::string &key) const
  {
    RecordField field = *this;
    field.csv_column  = column;
    field.csv_key     = key;
    return field;
  }


  RecordField
  RecordField::column(const std::string                &header,
                      const std::optional<unsigned int> precision,
                      const bool                        scientific) const
  {
    RecordField field = *this;
    field.table       = {header, precision, scientific};
    return field;
  }


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
    // The failed checks as the check lines print them ("...: NO").
    std::string failed;
    for (const auto &c : checks)
      if (!c.second)
        failed += (failed.empty() ? "" : ", ") + c.first + ": NO";
    return failed + " (" + result.message + ")" +
           (note.empty() ? "" : "; " + note);
  }


  const std::vector<RecordField> &
  CycleRecord::fields()
  {
    static const std::vector<RecordField> list = checked(describe_fields());
    return list;
  }


  std::vector<std::string>
  CycleRecord::json_keys()
  {
    std::vector<std::string> keys;
    std::string              object;
    for (const RecordField &field : fields())
      {
        if (field.json_object != object && !field.json_object.empty())
          keys.push_back(field.json_object);
        object = field.json_object;
        keys.push_back(field.json_key);
      }
    return keys;
  }


  std::vector<std::string>
  CycleRecord::csv_keys()
  {
    std::vector<std::string> keys;
    for (const RecordField *field : csv_fields())
      keys.push_back(field->csv_key);
    return keys;
  }


  void
  write_summary_json(std::ostream                   &out,
                     const std::string              &scene,
                     const std::vector<CycleRecord> &records,
                     const std::string              &growth,
                     const UnitNames                &units)
  {
    out << "{\n  \"scene\": " << json(scene) << ",\n  \"build\": {"
        << "\"bilayer\": " << json(version())
        << ", \"git_commit\": " << json(git_commit())
        << ", \"deal_ii\": " << json(deal_ii_version())
        << ", \"blas\": " << json(blas_library())
        << ", \"threads\": {\"tasks\": " << MultithreadInfo::n_threads()
        << ", \"blas\": " << blas_threads() << ", \"blas_set_by\": "
        << json(blas_threads_variable().empty() ? "bilayer" :
                                                  blas_threads_variable())
        << ", \"factorisation_loops\": "
        << (factorisation_loops_serial() ? 1 : 0) << "}},\n  \"cycles\": [";
    for (unsigned int i = 0; i < records.size(); ++i)
      {
        out << (i ? "," : "") << "\n    {";
        // The object being written: "" (the cycle's) or a nested one.
        std::string object;
        bool        first = true;
        for (const RecordField &field : CycleRecord::fields())
          {
            if (field.json_object != object)
              {
                if (!object.empty())
                  out << "}";
                if (!field.json_object.empty())
                  out << ", " << json(field.json_object) << ": {";
                object = field.json_object;
                first  = !object.empty();
              }
            out << (first ? "" : ", ") << json(field.json_key) << ": "
                << json(field.value(records[i]));
            first = false;
          }
        out << (object.empty() ? "" : "}");
        // The crack tips, ordered by s.
        out << ", \"crack_tips\": [";
        for (unsigned int t = 0; t < records[i].release.size(); ++t)
          {
            const EnergyReleaseRate &g = records[i].release[t];
            out << (t ? ", " : "") << "{\"interface\": " << g.tip.interface + 1
                << ", \"s\": " << json(g.tip.s)
                << ", \"x\": " << json(g.tip.point[0])
                << ", \"y\": " << json(g.tip.point[1]) << ", \"direction\": ["
                << json(g.tip.direction[0] + 0.) << ", "
                << json(g.tip.direction[1] + 0.)
                << "], \"support_radius\": " << json(g.tip.support_radius)
                << ", \"G\": " << json(g.G)
                << ", \"G_contact\": " << json(g.contact)
                << ", \"G_friction\": " << json(g.friction)
                << ", \"G_error\": " << json(g.error)
                << ", \"G_error_estimate\": " << json(g.error_estimate)
                << ", \"G_half_support\": " << json(g.G_half_support)
                << ", \"G_I\": " << json(g.G_I)
                << ", \"G_II\": " << json(g.G_II)
                << ", \"phase_angle\": " << json(g.phase_angle)
                << ", \"mode_split_length\": " << json(g.mode_split_length)
                << ", \"mode_split_note\": " << json(g.mode_split_note)
                << ", \"K_I\": " << json(g.K_I)
                << ", \"K_II\": " << json(g.K_II)
                << ", \"K_magnitude\": " << json(g.K_magnitude)
                << ", \"K_phase_angle\": " << json(g.K_phase_angle)
                << ", \"reference_length\": " << json(g.reference_length)
                << ", \"oscillation_index\": " << json(g.oscillation_index)
                << ", \"G_from_K\": " << json(g.G_from_K)
                << ", \"K_note\": " << json(g.K_note)
                << ", \"G_dwr\": " << json(g.G_dwr)
                << ", \"G_dwr_absolute\": " << json(g.G_dwr_absolute)
                << ", \"dual_work\": " << json(g.dual_work) << "}";
          }
        out << "]";
        write_forces_json(out, records[i].forces);
        write_floating_json(out, records[i].floating);
        out << "}";
      }
    out << "\n  ]";
    if (!growth.empty())
      out << ",\n  \"growth\": " << growth;
    // (Last: a reader that greps the first "energy" finds the cycles'.)
    out << ",\n  \"units\": {\"system\": " << json(units.system)
        << ", \"length\": " << json(units.length)
        << ", \"stress\": " << json(units.stress)
        << ", \"force\": " << json(units.force)
        << ", \"energy_release_rate\": " << json(units.energy_release_rate)
        << ", \"energy\": " << json(units.energy) << "}\n}\n";
  }


  void
  write_csv_table(std::ostream                   &out,
                  const std::vector<CycleRecord> &records,
                  const bool                      along_x)
  {
    const std::vector<const RecordField *> columns = csv_fields();
    // The fields, the forces of the boundary parts, then G at each tip,
    // last (the tips are the same in every cycle; states of one mesh may
    // differ in the crack and their number of tips: null where a record has
    // fewer).
    unsigned int n_tips = 0;
    for (const CycleRecord &record : records)
      n_tips = std::max<unsigned int>(n_tips, record.release.size());
    // Where the tips are: '#' lines before the header.
    if (n_tips > 0)
      for (const std::string &note : tip_notes(records[0].release, along_x))
        out << "# " << note << '\n';
    for (unsigned int c = 0; c < columns.size(); ++c)
      out << (c ? "," : "") << columns[c]->csv_key;
    // The forces and mean displacements of the boundary parts (those of
    // the first record: every state of a run has the same parts).
    const std::vector<PartForce>  none;
    const std::vector<PartForce> &parts =
      records.empty() ? none : records[0].forces.parts;
    for (const std::string &column : force_columns(parts))
      out << ',' << column;
    for (unsigned int t = 0; t < n_tips; ++t)
      out << ",G_tip" << t + 1 << ",dG_tip" << t + 1;
    out << '\n';
    for (const CycleRecord &record : records)
      {
        for (unsigned int c = 0; c < columns.size(); ++c)
          out << (c ? "," : "") << csv(columns[c]->value(record));
        out << force_cells(parts, record.forces.parts);
        for (unsigned int t = 0; t < n_tips; ++t)
          out << ","
              << (t < record.release.size() ? json(record.release[t].G) :
                                              std::string("null"))
              << ","
              << (t < record.release.size() ? json(record.release[t].error) :
                                              std::string("null"));
        out << '\n';
      }
  }


  void
  add_to_table(ConvergenceTable               &table,
               const std::vector<CycleRecord> &records,
               const std::size_t               n,
               const bool                      compact)
  {
    // The columns of the compact table (table.tex) besides the tips'.
    static const std::set<std::string> paper  = {"cycle",
                                                 "dofs",
                                                 "energy",
                                                 "eta"};
    const CycleRecord                 &record = records[n - 1];
    for (const RecordField *field : csv_fields())
      {
        const RecordField::TableColumn &column = field->table;
        if (column.header.empty() ||
            (compact && paper.count(column.header) == 0))
          continue;
        const RecordValue value = field->value(record);
        if (const unsigned long *count = std::get_if<unsigned long>(&value))
          table.add_value(column.header, static_cast<unsigned int>(*count));
        else if (const double *number = std::get_if<double>(&value))
          table.add_value(column.header, *number);
        else
          AssertThrow(false,
                      ExcMessage("the table column " + column.header +
                                 " holds no count or number"));
        if (column.precision)
          table.set_precision(column.header, *column.precision);
        if (column.scientific)
          table.set_scientific(column.header, true);
      }
    // States of one mesh (Study::run_states) may differ in their number of
    // tips (an edge crack has one): the cells of tips a row lacks are empty,
    // in the earlier rows of a column that appears later as well.
    std::size_t earlier_tips = 0;
    for (std::size_t r = 0; r + 1 < n; ++r)
      earlier_tips = std::max(earlier_tips, records[r].release.size());
    for (unsigned int t = 0; t < record.release.size(); ++t)
      {
        const std::string header = "G tip " + std::to_string(t + 1);
        const std::string error  = "dG tip " + std::to_string(t + 1);
        if (t >= earlier_tips)
          for (std::size_t r = 0; r + 1 < n; ++r)
            {
              table.add_value(header, std::string());
              table.add_value(error, std::string());
            }
        table.add_value(header, record.release[t].G);
        table.set_precision(header, 4);
        table.set_scientific(header, true);
        table.add_value(error, record.release[t].error);
        table.set_precision(error, 1);
        table.set_scientific(error, true);
      }
    table.start_new_row();
  }


  void
  add_to_table(ConvergenceTable &table, const std::vector<CycleRecord> &records)
  {
    add_to_table(table, records, records.size(), false);
  }


  void
  write_compact_tex(std::ostream &out, const std::vector<CycleRecord> &records)
  {
    ConvergenceTable table;
    for (std::size_t n = 1; n <= records.size(); ++n)
      add_to_table(table, records, n, true);
    table.write_tex(out);
  }
} // namespace bilayer
