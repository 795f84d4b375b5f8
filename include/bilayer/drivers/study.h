#ifndef bilayer_study_h
#define bilayer_study_h

#include <deal.II/base/conditional_ostream.h>
#include <deal.II/base/convergence_table.h>
#include <deal.II/base/timer.h>
#include <deal.II/lac/block_vector.h>

#include <bilayer/core/layout.h>
#include <bilayer/geometry/geometry.h>
#include <bilayer/interface/interface.h>
#include <bilayer/model/model.h>
#include <bilayer/output/cycle_record.h>
#include <bilayer/output/growth_record.h>
#include <bilayer/output/output.h>
#include <bilayer/parameters/parameters.h>
#include <bilayer/postprocess/fracture.h>
#include <bilayer/postprocess/growth_law.h>
#include <bilayer/solvers/outer_solver.h>
#include <bilayer/subproblem/distribution.h>
#include <bilayer/subproblem/subproblem.h>

#include <array>
#include <functional>
#include <limits>
#include <memory>
#include <ostream>
#include <utility>
#include <vector>

namespace bilayer
{
  class CohesiveZone;
  class CohesiveLaw;
  class CohesiveNewton;

  /**
   * A study of one scene: a sequence of states, each solved and checked and
   * written as one record (VTU/PVD, interface-NN.csv, summary.json, the
   * mesh-size table). Two drivers make the sequence:
   *  - run(): the mesh cycles of the paper; each cycle builds the two
   *    meshes (created or refined), the four subproblems (assembled and
   *    factorised once) and the interface, and runs the contact solver;
   *  - run_states(): states on the meshes of cycle 0 that differ in the
   *    crack; the subproblems are assembled and factorised once, and each
   *    state rebuilds only the interface (the crack changes which part of
   *    Sigma is glued, not the subproblems' matrices) and recomputes the
   *    crack tips.
   * Each state is solved by solve_state(): interface, outer solve,
   * assessment, outputs.
   */
  class Study
  {
  public:
    /**
     * A study of @p scene that reports to @p out, run by the processes of
     * @p distribution (the MPI job if MPI is initialised; results are
     * reported and written by its first process, the VTU/HDF5 pieces by
     * the owners of the subproblems).
     */
    Study(const Scene        &scene,
          std::ostream       &out,
          const Distribution &distribution = Distribution::world());

    ~Study();

    /// All cycles; true if every cycle converged and passed its checks.
    /// Stops at the first cycle that does not.
    bool
    run();

    /// One cycle (mesh cycle @p cycle); appends to records().
    const CycleRecord &
    run_cycle(const unsigned int cycle);

    /**
     * The states driver: on the meshes of cycle 0, state k has the crack
     * @p cracks[k] (its pieces on Sigma, ending at mesh vertices) and is
     * solved from a cold start (zero multipliers); record k is numbered k.
     * The subproblems are set up once, before state 0. True if every state
     * converged and passed its checks; stops at the first that does not.
     */
    bool
    run_states(const std::vector<CrackSet> &cracks,
               const std::vector<double>   &load_factors = {});

    /**
     * Scale the proportional loads by @p lambda (any finite number; 1 at
     * the start): the tractions, the body forces and the prescribed
     * displacements become lambda times those of the scene, while the
     * preload (the eigenstrains and the thermal strains of Loads/
     * Temperature change) stays as given. Applied to every present
     * subproblem (ElasticSubproblem::set_load_factor(): no new assembly or
     * factorisation) and to the body forces that the energy release rate
     * and the error estimator read (ScaledVolumeLoad), at once, and to the
     * subproblems of every later set-up (new cycles). Call it on every
     * process, between states (before solve_state()); the next state is
     * solved at lambda. Refused (lambda != 1) where a subproblem is shared
     * by a group of processes (more than four processes).
     */
    void
    set_load_factor(const double lambda)
    {
      model.set_load_factor(lambda);
    }

    /// The load factor of set_load_factor() (1 at the start).
    double
    load_factor() const
    {
      return model.load_factor();
    }

    /**
     * Whether the response scales with the load factor, every state at
     * lambda >= 0 being lambda times the state at 1 (the displacements
     * and multipliers; energy and G lambda^2 times): no preload (no
     * eigenstrain entry other than 0, and no temperature change on a
     * material that expands) and no friction (Contact/Friction on the
     * crack faces = none); the contact conditions without an initial gap
     * are positively homogeneous. (For lambda < 0 only without contact.)
     * With Loads/Load factor scales = thermal: no mechanical load instead
     * of no preload; with all, any load.
     */
    bool
    proportional_loading() const
    {
      return model.proportional_loading();
    }


    /**
     * The growth driver (Fracture/Crack growth = quasi-static or sweep,
     * docs/fracture.md section 9): on the meshes of the last cycle, with
     * the subproblems factorised once, the load factors of Loads/Load
     * factor (and, under proportional loading with Fracture/Exact onsets,
     * the critical load of each crack between them); at each load the tips
     * whose criterion reaches 1 (all free tips of a sweep) advance by
     * Fracture/Growth increment vertices of Sigma and the state is solved
     * again. Each step is a record (numbered 0, 1, ...) and a GrowthStep;
     * growth.csv and summary.json are written after every step. True if
     * every step converged and passed its checks; stops at the first that
     * does not.
     */
    bool
    run_growth();

    /**
     * The cohesive driver (Cohesive/Law, docs/cohesive.md): on the meshes
     * of the last cycle, with the subproblems factorised once, the zone
     * joins the crack of its interface with its nodes intact, and each
     * step solves the equilibrium at the step's control (a load factor of
     * Loads/Load factor, or, with Control = separation, the load factor
     * at which the largest separation in the zone grows by Separation
     * increment) by the secant iteration: solve with the springs of the
     * damage so far, damage from the new separations, until no damage
     * changes by more than Damage tolerance. Each step is a record and a
     * GrowthStep (growth.csv: the load-displacement curve) and a row of
     * cohesive.csv (the zone: process zone, cracked length, dissipated
     * energy); cohesive-NNNN.csv holds the zone's nodes of each written
     * step. True if every step converged and passed its checks.
     */
    bool
    run_cohesive();

    /// The steps of run_growth() so far.
    const std::vector<GrowthStep> &
    growth() const
    {
      return growth_steps;
    }

    const std::vector<CycleRecord> &
    records() const
    {
      return cycle_records;
    }
    /// The model the drivers ask (meshes, subproblems, couplings, the
    /// crack and its tips, the solution).
    const Model &
    state() const
    {
      return model;
    }
    const Interface &
    interface() const
    {
      return model.interface();
    }
    const Solutions &
    solutions() const
    {
      return model.solutions();
    }
    const dealii::BlockVector<double> &
    multipliers() const
    {
      return model.multipliers();
    }
    const ElasticSubproblem &
    subproblem(const Layer layer, const Subdomain subdomain) const
    {
      return model.subproblem(Layout::index(layer, subdomain));
    }
    /// Subproblem @p s (Topology::index()).
    const ElasticSubproblem &
    subproblem(const unsigned int s) const
    {
      return model.subproblem(s);
    }
    const Topology &
    layout() const
    {
      return model.topology();
    }

    /**
     * Replace the error indicators by which the next adaptive cycle marks
     * cells (one value per active cell of each subdomain, in the order of
     * active_cell_iterators(); Mesh/Marking applies as usual), so that a
     * driver can refine by a criterion of its own.
     */
    void
    set_indicators(const std::vector<dealii::Vector<double>> &new_indicators)
    {
      model.set_indicators(new_indicators);
    }

    /// As above, from single precision indicators.
    void
    set_indicators(const std::vector<dealii::Vector<float>> &new_indicators);

    /// The error indicators of the last cycle (estimate_error()).
    const std::vector<dealii::Vector<double>> &
    error_indicators() const
    {
      return model.error_indicators();
    }

    /**
     * Called on the first process before and after each cycle's files are
     * written (StagedDirectory::verify(): the output directory is still
     * the one the run made, with the files written so far); set on every
     * process or on none. Without it, the output directory is created if
     * missing.
     */
    void
    set_directory_check(std::function<void()> check)
    {
      directory_check = std::move(check);
    }

  private:
    std::function<void()> directory_check;

    // The cohesive driver (cohesive.cc).

    /// One step of the cohesive driver: what cohesive.csv holds.
    struct CohesiveStep
    {
      unsigned int step = 0, iterations = 0;
      /// The Newton method's iterations (-1 where it was not used or did
      /// not converge).
      int    newton_iterations = -1;
      double load_factor = 0, conjugate_displacement = 0;
      /// The external work along the path (trapezoidal rule over the
      /// steps) and the energy dissipated by the energy balance: work
      /// less the stored energy lambda q / 2 (Clapeyron).
      double external_work = 0, dissipated_balance = 0;
      /// The zone (CohesiveZone::summary()).
      double dissipated = 0, cracked_length = 0, process_length = 0,
             process_start = 0, process_end = 0, largest_damage = 0,
             largest_separation = 0;
      /// The nodes of the process zone (0 < d < 1) and the broken ones.
      unsigned int process_nodes = 0, cracked_nodes = 0;
    };
    std::vector<CohesiveStep> cohesive_steps;
    /// The zone of a cohesive run while it runs (its damage goes into the
    /// interface files).
    const CohesiveZone *written_zone = nullptr;

    /// The cohesive run's set-up: the meshes of the last cycle and their
    /// subproblems in @p first, the zone joined to its interface's crack,
    /// the interface; the zone of @p law on it, intact.
    std::unique_ptr<CohesiveZone>
    start_cohesive(CycleRecord &first, const CohesiveLaw &law, const bool path);

    /// How the secant iteration of a step ended: its iterations, and
    /// whether the zone cannot dissipate another increment (Control =
    /// dissipation; the step is then not taken).
    struct CohesiveSettle
    {
      unsigned int iterations = 0;
      /// The iterations of the Newton method that gave the first iterate
      /// (-1 where it did not).
      int  newton_iterations = -1;
      bool exhausted         = false;
      /// Whether the iteration settled (false only under path following:
      /// the caller halves the increment), and the last damage change.
      bool   converged = true;
      double change    = 0;
    };

    /**
     * The secant iteration of the step of @p record at the load factor
     * @p lambda (with path following: from it, and the step's on return),
     * Anderson-accelerated on the zone's trial histories; with @p to_onset
     * the step ends at the elastic limit. The state is solved with the
     * springs of the trial damage within Damage tolerance of the one
     * returned (and again with the nodes broken in the last update as
     * crack faces); the zone holds the trial state. Path following takes
     * @p fraction of the increment.
     */
    CohesiveSettle
    settle_cohesive_step(CycleRecord  &record,
                         CohesiveZone &zone,
                         double       &lambda,
                         const bool    to_onset,
                         const double  fraction);

    /**
     * The first iterate of a step's secant iteration by the Newton method
     * on the interface (CohesiveNewton; Cohesive/Method = newton), built on
     * its first use: from the state of the last step at the load factor
     * @p lambda, the step's control (its @p target dissipation, or
     * @p fraction of the separation increment at the node @p control, which
     * it picks where negative). Where it converges, the zone's trial state,
     * the springs, the multipliers and the load factor are its solution's
     * and it returns its iterations; else -1, and nothing changes. The
     * solves it spends go into @p work.
     */
    int
    newton_first_iterate(CohesiveZone &zone,
                         double       &lambda,
                         const double  fraction,
                         const double  target,
                         int          &control,
                         SolverResult &work);

    /// The Newton method of the cohesive run (built on its first use), or
    /// why it is not used.
    std::unique_ptr<CohesiveNewton> cohesive_newton;
    std::string                     cohesive_newton_skipped;

    /// settle_cohesive_step() of the whole increment; under path
    /// following, where it does not settle, again from the step's start
    /// with half the increment, down to 1/64 (then a RunFailure).
    CohesiveSettle
    settle_or_halve(CycleRecord  &record,
                    CohesiveZone &zone,
                    double       &lambda,
                    const bool    to_onset);

    /// The end of a cohesive run: why it ended in @p stop (set where it
    /// is empty), the last step's fields where Output/Written steps wants
    /// them, growth.csv and summary.json, the terminal's line.
    void
    finish_cohesive(std::string        &stop,
                    const bool          path,
                    const CohesiveZone &zone);

    /// The GrowthStep and the row of cohesive.csv of the step just
    /// recorded, the files, and its line in the terminal.
    void
    record_cohesive_step(const CohesiveZone   &zone,
                         const unsigned int    step,
                         const CohesiveSettle &settled,
                         const double          lambda);

    /// cohesive.csv (the rows so far), and with @p zone the zone's nodes
    /// of step @p step (cohesive-NNNN.csv).
    void
    write_cohesive(const unsigned int step, const CohesiveZone *zone);

    // The growth driver (growth.cc, growth_output.cc).

    /// A tip followed through the growth: its number (the initial tips
    /// ordered by s, from 1), where it is, the direction of growth, whether
    /// it still exists and why it can advance no further (empty: it can).
    struct FollowedTip
    {
      unsigned int number = 0;
      /// The tip's interface (Sigma: 0), its parameter on it, its sense.
      unsigned int interface = 0;
      double       s = 0, sign = 1;
      bool         present = true;
      std::string  stopped;
      /// The critical load predicted for the tip by the step before (or
      /// the probe): an onset step at it makes the tip critical.
      double onset = std::numeric_limits<double>::infinity();
    };
    bool                     growth_run = false, onsets_exact = false;
    std::vector<GrowthStep>  growth_steps;
    std::vector<FollowedTip> followed;
    /// The vertices of each interface (Sigma first) where a tip may stand.
    std::vector<std::vector<double>> interface_vertices;
    /// The subproblem of each Output/Displacement point.
    std::vector<unsigned int> point_subproblems;
    std::string               growth_stop;
    /// What growth.csv holds: its head, and the rows of this many steps.
    bool        growth_head_written = false;
    std::size_t growth_rows_written = 0;

    /// The followed tips, Sigma's vertices and the points' subproblems.
    void
    start_growth();
    bool
    tip_may_grow(const unsigned int number) const;
    bool
    growth_stopped() const;
    /// Whether the state of @p record has an error estimate: every cycle of
    /// a static run and the first step of a growth run. The later steps
    /// keep the mesh of the first (their indicators would refine nothing):
    /// eta is NaN there, and the estimator's pass over every cell, the
    /// largest part of a step, is saved.
    bool
    estimates_error(const CycleRecord &record) const;
    /// One step at the load factor @p lambda on the present crack.
    bool
    solve_growth_step(CycleRecord         &record,
                      const double         lambda,
                      const std::string   &kind,
                      const dealii::Timer &total);
    GrowthStep
    growth_step(const CycleRecord &record,
                const double       lambda,
                const std::string &kind);
    /// The smallest critical load of the growing tips of the last step.
    double
    next_onset();
    /// The smallest critical load of the growing tips of the crack at the
    /// start, from a state solved at @p lambda on the meshes of @p first
    /// and neither written nor printed (infinite if none or lambda = 0).
    double
    probe_onset(const CycleRecord &first, const double lambda);
    /// The criterion of Fracture/Mixed-mode law at the tip of @p g.
    GrowthCriterion
    criterion_at(const EnergyReleaseRate &g) const;

    /// @p g with the mode split the growth law reads (Fracture/Mode mix):
    /// the closure split, or G cos^2 psi, G sin^2 psi of the phase angle of
    /// K (NaN, with a note, where there is none).
    EnergyReleaseRate
    law_split(const EnergyReleaseRate &g) const;
    /// Growth at the load @p lambda until every criterion is below 1.
    bool
    grow_at_load(const double lambda, const dealii::Timer &total);
    /// Advance the followed tips @p growing; false if none moved.
    bool
    advance_tips(const std::vector<unsigned int> &growing);
    void
    measure_loading(GrowthStep &step) const;
    std::string
    growth_mode() const;
    /// growth.csv's rows of the steps that are final; with @p final (the
    /// end of the run, or a failure) all of them, summary.json, the tables
    /// and the collections.
    void
    write_growth(const bool final);
    /// table.txt, table.tex and table.csv of the records so far.
    void
    write_tables();
    void
    print_growth_step(const GrowthStep &step) const;
    bool
    finish_growth(const bool passed);
    /// The solution fields and interface files of step @p step (the
    /// present solution).
    void
    write_step_fields(const unsigned int step);
    void
    write_interface_files(const unsigned int cycle,
                          const bool         interface_vtu,
                          const bool         interface_csv);
    // The steps of run_cycle(), in this order.

    /// The meshes of mesh cycle @p cycle (build_meshes()), with @p crack
    /// if given, checked against the memory, and the subproblems set up on
    /// them; their sizes, dofs and set-up times in @p record.
    void
    set_up_cycle(CycleRecord       &record,
                 const unsigned int cycle,
                 const CrackSet    *crack = nullptr);
    /// The meshes of mesh cycle @p cycle (created, or refined from the
    /// last cycle's), their sizes in @p record, and the tips.
    void
    build_meshes(CycleRecord &record, const unsigned int cycle);
    /// A state on the meshes and subproblems of the first record: their
    /// sizes, memory estimate and dofs in @p record, and the tips (of the
    /// present crack) checked on those meshes.
    void
    reuse_meshes(CycleRecord &record);
    /// Refuses a cycle that would not fit into the memory (the estimate
    /// goes into @p record).
    void
    check_memory(CycleRecord &record) const;

    /// What Mesh/Target accuracy reads of a cycle.
    struct TargetEstimate
    {
      /// The estimated relative error of Mesh/Target quantity (NaN where
      /// the cycle has none: G's error bar on the first cycle).
      double relative = std::numeric_limits<double>::quiet_NaN();
      /// Where: the tip of the largest relative error of G.
      std::string where;
      /// The energy-norm estimate eta is at round-off: at most 1e-10
      /// sqrt(|C|) d (Model::stiffness_scale(), the displacement scale d),
      /// a scene whose discrete solution is exact (no stresses).
      bool round_off = false;

      /// "the estimated relative error of G is 3.2e-4 (tip 2)".
      std::string
      text(const TargetQuantity quantity) const;
    };

    TargetEstimate
    target_estimate(const CycleRecord &record) const;

    /// Whether the cycles stop after @p record (its target met, or its
    /// estimate at round-off), with a line on the terminal; throws
    /// RunFailure where the last cycle passes without it.
    bool
    target_met(const CycleRecord &record) const;

    /// "# tip k: <where>, grows towards ..." for each crack tip (none
    /// without tips): the head of table.txt and of the terminal's table.
    void
    write_tip_notes(std::ostream &out) const;
    /// The energy, the residuals, the acceptance checks and (adaptive
    /// refinement) the error indicators of the next cycle.
    void
    assess(CycleRecord &record);
    void
    check(CycleRecord &record) const;

    /// The forces and mean displacements of the boundary parts and their
    /// balance, a line each.
    void
    print_forces(const ForceBalance &forces) const;
    /// The floating subproblems' balance (nothing where none floats).
    void
    print_floating(const FloatingReport &floating) const;

    /// The .pvd time of growth step @p step, the present state
    /// (Output/Time of growth steps: its load factor, number or crack
    /// length).
    double
    growth_step_time(const unsigned int step) const;

    /// The total length of the cracks of all interfaces now.
    double
    crack_length() const;

    /// "step N" in a growth run, "cycle N" else: how the terminal names
    /// state @p cycle.
    std::string
    state_name(const unsigned int cycle) const;

    /**
     * One state on the present subproblems: the interface (and the
     * multipliers, from @p previous if given), the outer solve, the
     * assessment and the outputs; appends the record. @p total has run
     * since the state began.
     */
    const CycleRecord &
    solve_state(CycleRecord                      &record,
                const MultiplierSpace::Functions *previous,
                const dealii::Timer              &total);
    /// The outputs of the cycle (solution, interface CSV, summary.json, the
    /// tables); appends @p record to records(), with the total time and the
    /// memory.
    void
    write(CycleRecord &record, const dealii::Timer &total);
    /// The interface-NN.csv of this cycle (and, with @p fields, its
    /// interface-NN.vtu), and summary.json, table.txt, table.tex and
    /// table.csv of all cycles so far (first process).
    void
    write_records(const unsigned int cycle,
                  const bool         fields,
                  const bool         interface_csv);
    void
    print_report(const CycleRecord &record) const;
    /// The report's lines of G and its mode split at each tip.
    void
    print_release(const CycleRecord &record) const;

    const Scene         scene;
    std::ostream       &out;
    const Distribution &distribution;
    /// Progress (Output/Terminal output = full) and the checks, both on the
    /// first process only.
    dealii::ConditionalOStream pcout, rout;
    /// The meshes, subproblems, couplings, crack and solution.
    Model                    model;
    std::vector<CycleRecord> cycle_records;
    SolutionRecords          outputs;
    /// The mesh-size table of the cycles so far.
    dealii::ConvergenceTable table;
  };
} // namespace bilayer

#endif
