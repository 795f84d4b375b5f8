#ifndef bilayer_cycle_record_h
#define bilayer_cycle_record_h

#include <deal.II/base/convergence_table.h>

#include <bilayer/geometry/geometry.h>
#include <bilayer/interface/interface.h>
#include <bilayer/interface/interface_diagnostics.h>
#include <bilayer/parameters/output_parameters.h>
#include <bilayer/postprocess/boundary_forces.h>
#include <bilayer/postprocess/fracture.h>
#include <bilayer/solvers/floating_parts.h>
#include <bilayer/solvers/outer_solver.h>

#include <array>
#include <functional>
#include <optional>
#include <ostream>
#include <string>
#include <type_traits>
#include <utility>
#include <variant>
#include <vector>

/**
 * @file
 * What is reported about one cycle of a study, and the one description of
 * how it is written: CycleRecord::fields() lists every field with its key in
 * summary.json, its column of table.csv and of the mesh-size table
 * (table.txt, table.tex and the terminal), and how its value is read from
 * the record. Every format is written from that list.
 */
namespace bilayer
{
  struct RecordField;

  /// Everything reported about one cycle (one mesh) of a study.
  struct CycleRecord
  {
    unsigned int   cycle = 0;
    MeshStatistics minus, plus;
    /// Vertices on Sigma and on the outer boundary (P and M of Table 1).
    unsigned int P = 0, M = 0;
    unsigned int dofs = 0, multipliers = 0;
    double       theta = 0;
    SolverResult result;
    /// Extreme eigenvalues of the dual operator (Solver/Dual spectrum
    /// steps; zero when not estimated).
    DualSpectrum spectrum;
    double       energy = 0;
    /// The energy of each layer slot (both subdomains; its strain energy
    /// minus the work of its own loads): energy = their sum (energy_of:
    /// layer_1, layer_2, and layers, all of them).
    std::vector<double> layer_energy = {0, 0};
    /// The global a-posteriori error estimate in the energy norm
    /// (estimate_error(), estimator.h), [energy^1/2]: compare with
    /// (2 |Pi_h - Pi|)^1/2.
    double eta = 0;
    /// The dual-weighted residual estimate of Pi - Pi_h (signed; NaN where
    /// not computed), its dual solves' conjugate-gradient iterations and
    /// the wall time of all goal-oriented estimates of the cycle [s].
    double          energy_dwr     = std::numeric_limits<double>::quiet_NaN();
    unsigned int    dwr_iterations = 0;
    double          dwr_seconds    = 0;
    std::string     dwr_note;
    InterfaceReport report;
    /// Coulomb friction: the fixed-point iterations (Tresca solves) and the
    /// last change of the friction bounds relative to the largest bound
    /// (0 without Coulomb friction).
    unsigned int friction_iterations   = 0;
    double       friction_bound_change = 0;
    /// The energy release rate at each crack tip, ordered by s (empty
    /// without a crack or with Fracture/Energy release rate = false).
    std::vector<EnergyReleaseRate> release;
    /// The floating subproblems and their balance (FloatingParts; empty
    /// where every subproblem is clamped).
    FloatingReport floating;
    /// The forces and mean displacements of the boundary parts, and their
    /// balance (boundary_forces()).
    ForceBalance forces;
    /// Acceptance checks: (description, passed).
    std::vector<std::pair<std::string, bool>> checks;
    double setup_seconds = 0, solve_seconds = 0, total_seconds = 0;
    /// MPI processes, values sent from the subproblems' owners to all
    /// processes in the iterations (traces on Sigma), and the peak resident
    /// memory of each process [MiB].
    unsigned int  processes     = 1;
    unsigned long shared_values = 0;
    /// Wall time of that exchange on the first process [s].
    double              shared_seconds = 0;
    std::vector<double> memory_mib;
    /// The memory this cycle was estimated to need before it was built
    /// (bilayer/resources.h) [MiB].
    double memory_estimate_mib = 0;
    /// Parts of setup_seconds: assembly and factorisation of the four
    /// subproblems, summed.
    double assembly_seconds = 0, factorisation_seconds = 0;
    /// Per subproblem: the fill-reducing ordering of its factorisation
    /// (Solver/Ordering), the factorisation's flops and the factor's
    /// entries (CHOLMOD's fl and lnz; 0 where a group of processes shares
    /// the subproblem: MUMPS or KLU).
    std::vector<std::string> factor_orderings;
    std::vector<double>      factor_flops, factor_entries;

    /// What the solver or the checks add to a failure (e.g. the bound p).
    std::string note;

    bool
    accepted() const;

    /// One line for a cycle that is not accepted: the failed checks, the
    /// solver's message and the note.
    std::string
    failure() const;

    /// The fields of a record as written, in the order of summary.json.
    static const std::vector<RecordField> &
    fields();

    /// Every key of a cycle's object in summary.json, in the order written
    /// (the keys of the nested objects, e.g. "wall_seconds", before their
    /// own keys).
    static std::vector<std::string>
    json_keys();

    /// The header of table.csv, column by column.
    static std::vector<std::string>
    csv_keys();
  };

  /// A field's value: a flag, a count, a number, a text or a list of
  /// numbers.
  using RecordValue =
    std::variant<bool, unsigned long, double, std::string, std::vector<double>>;

  /**
   * One field of a CycleRecord and where it is written. Built with
   * record_field() and the setters below, e.g.
   * @code
   * record_field("setup", [](const CycleRecord &r) { return r.setup_seconds; })
   *   .in("wall_seconds")
   *   .csv(20, "setup_seconds")
   * @endcode
   */
  struct RecordField
  {
    /// A column of the mesh-size table (deal.II's ConvergenceTable).
    struct TableColumn
    {
      /// Header text; empty: not in the table.
      std::string header;
      /// Digits (ConvergenceTable::set_precision); none: the table's
      /// default.
      std::optional<unsigned int> precision;
      bool                        scientific = false;
    };

    /// Key in summary.json.
    std::string json_key;
    /// Key of the object of summary.json that holds it ("kkt",
    /// "wall_seconds"); empty: the cycle's object itself. The fields of one
    /// object are consecutive.
    std::string json_object;
    /// Header of its column of table.csv; empty: not in table.csv.
    std::string csv_key;
    /// Position of that column in table.csv (0, 1, ...). The mesh-size
    /// table has its columns in the same order.
    unsigned int csv_column = 0;
    TableColumn  table;
    /// The value of the field in a record.
    std::function<RecordValue(const CycleRecord &)> value;

    /// This field inside the object @p object of summary.json.
    RecordField
    in(const std::string &object) const;

    /// This field also as column @p column of table.csv, headed @p key.
    RecordField
    csv(const unsigned int column, const std::string &key) const;

    /// This field also in the mesh-size table, headed @p header, with
    /// @p precision digits (none: the table's default), in scientific
    /// notation if @p scientific.
    RecordField
    column(const std::string                &header,
           const std::optional<unsigned int> precision  = std::nullopt,
           const bool                        scientific = false) const;
  };

  /// A field of summary.json named @p json_key whose value is @p get(record)
  /// (bool, an unsigned count, a floating-point number, a string or a
  /// vector of doubles).
  template <typename Get>
  RecordField
  record_field(const std::string &json_key, const Get &get)
  {
    RecordField field;
    field.json_key = json_key;
    field.value    = [get](const CycleRecord &record) -> RecordValue {
      using T = std::decay_t<decltype(get(record))>;
      if constexpr (std::is_same_v<T, bool>)
        return RecordValue(std::in_place_type<bool>, get(record));
      else if constexpr (std::is_integral_v<T>)
        {
          static_assert(std::is_unsigned_v<T>, "counts are unsigned");
          return RecordValue(std::in_place_type<unsigned long>, get(record));
        }
      else if constexpr (std::is_floating_point_v<T>)
        return RecordValue(std::in_place_type<double>, get(record));
      else
        return RecordValue(std::in_place_type<T>, get(record));
    };
    return field;
  }

  /// summary.json: {"scene": ..., "build": {"bilayer": version,
  /// "git_commit", "deal_ii", "blas"} (build_info.h), "cycles": [one object
  /// per record], "growth": @p growth (a JSON value) where not empty, and
  /// last "units": {"system", "length", "stress", "force",
  /// "energy_release_rate", "energy"} (@p units: names only)}.
  void
  write_summary_json(std::ostream                   &out,
                     const std::string              &scene,
                     const std::vector<CycleRecord> &records,
                     const std::string              &growth = "",
                     const UnitNames                &units  = UnitNames());

  /// A JSON number: 17 significant digits, null for NaN and infinities.
  std::string
  json_number(const double value);

  /// A JSON string of @p text (quotes and backslashes escaped).
  std::string
  json_text(const std::string &text);

  /// table.csv: where the crack tips are ('#' lines, tip_notes(); none
  /// without tips), the header and one row per record.
  void
  write_csv_table(std::ostream                   &out,
                  const std::vector<CycleRecord> &records,
                  const bool                      along_x);

  /// ", \"boundary_parts\": [...], \"force_balance\": {...}" of a cycle's
  /// object in summary.json.
  void
  write_forces_json(std::ostream &out, const ForceBalance &forces);

  /// The "floating" object of a cycle's object in summary.json (nothing
  /// where no subproblem floats).
  void
  write_floating_json(std::ostream &out, const FloatingReport &floating);

  /// The columns of the forces and mean displacements of the boundary
  /// parts @p parts in table.csv and growth.csv: Fx_NAME, Fy_NAME, ux_NAME,
  /// uy_NAME per part (the force summed over layers and regions, the
  /// displacement averaged over the layers), and for a part in several
  /// regions the same per region, suffixed _rK (region K = 1, 2, ...;
  /// Omega- and Omega+ are regions 1 and 2).
  std::vector<std::string>
  force_columns(const std::vector<PartForce> &parts);

  /// The cells of force_columns(@p columns_of) for the state @p parts
  /// (null where a part or region is missing), each preceded by a comma.
  std::string
  force_cells(const std::vector<PartForce> &columns_of,
              const std::vector<PartForce> &parts);

  /// Append the last of @p records (all records so far) as a row of the
  /// mesh-size table; where the records differ in their number of crack
  /// tips (states of one mesh), the cells of tips a row lacks are empty.
  void
  add_to_table(dealii::ConvergenceTable       &table,
               const std::vector<CycleRecord> &records);

  /// Row @p n - 1 of @p records (the records before it: the earlier rows)
  /// into @p table; with @p compact only the columns cycle, dofs, energy,
  /// eta and G, dG at each tip.
  void
  add_to_table(dealii::ConvergenceTable       &table,
               const std::vector<CycleRecord> &records,
               const std::size_t               n,
               const bool                      compact);

  /// table.tex: the compact table of @p records (add_to_table(), compact),
  /// the columns a paper quotes; table.txt and table.csv have the rest.
  void
  write_compact_tex(std::ostream &out, const std::vector<CycleRecord> &records);
} // namespace bilayer

#endif
