#ifndef bilayer_model_h
#define bilayer_model_h

#include <deal.II/base/conditional_ostream.h>
#include <deal.II/lac/block_vector.h>

#include <bilayer/core/layout.h>
#include <bilayer/geometry/geometry.h>
#include <bilayer/interface/interface.h>
#include <bilayer/output/cycle_record.h>
#include <bilayer/output/output.h>
#include <bilayer/parameters/parameters.h>
#include <bilayer/postprocess/fracture.h>
#include <bilayer/solvers/outer_solver.h>
#include <bilayer/subproblem/distribution.h>
#include <bilayer/subproblem/subproblem.h>

#include <memory>
#include <string>
#include <vector>

namespace bilayer
{
  /**
   * The model of one scene: the meshes of its regions, the subproblems of
   * its layers (assembled and factorised), the couplings on its interfaces
   * and their multipliers, the solution, and the crack with its tips. It is
   * the one source of truth for the crack (set_crack()) and the tips (found
   * again on the present meshes whenever the crack or the meshes change).
   * The drivers (Study: mesh cycles, states, growth) ask it for meshes, a
   * set-up, a solve and an assessment, and keep the records and the
   * outputs; each step fills its part of a CycleRecord.
   *
   * The tips are found on the meshes present when the crack last changed
   * (cycle 0, or the state's crack) and kept under refinement: where a tip
   * lies and how far its velocity field may reach depend on the geometry,
   * not on the mesh.
   */
  class Model
  {
  public:
    /**
     * The model of @p scene, run by the processes of @p distribution;
     * progress goes to @p progress (the first process, Output/Terminal
     * output = full). The three are referred to, not copied.
     */
    Model(const Scene                &scene,
          const Distribution         &distribution,
          dealii::ConditionalOStream &progress);

    // The meshes.

    /**
     * The meshes of mesh cycle @p cycle: created (the structured meshes or
     * the Gmsh scene of that cycle), or, with @p refine, refined from the
     * present ones by the error indicators (and at every tip whose support
     * holds too few cells). The subproblems of the old meshes are gone.
     * Their sizes go into @p record, and the tips are found on them.
     */
    void
    build_meshes(CycleRecord &record, const unsigned int cycle, bool refine);

    /// The sizes of the present meshes (cells, h, P, M) in @p record.
    void
    describe_meshes(CycleRecord &record) const;

    /**
     * From now on the meshes stay those of the present state for every
     * state to come (the growth driver): the tips' supports are checked
     * against them alone, not against later cycles.
     */
    void
    keep_meshes()
    {
      fixed_meshes = true;
    }

    // The crack and its tips.

    /// The crack of interface @p i on the present meshes; the tips are
    /// found again at the next update_tips() (the one place where the
    /// crack changes).
    void
    set_crack(const CrackSet    &crack,
              const unsigned int i             = 0,
              const bool         whole_allowed = false);

    /**
     * The tips of the present crack (found if the crack changed since they
     * were last found) and whether their supports hold enough
     * cells of them (min_cells_per_support_radius): refuses a scene whose
     * last cycle cannot (a given radius under uniform refinement), else
     * keeps why G is not reported at a tip on the cycle of @p record.
     */
    void
    update_tips(const CycleRecord &record);

    /// The tips (update_tips()).
    const std::vector<CrackTip> &
    tips() const
    {
      return crack_tips_found;
    }

    /// Why the tips of @p crack on interface @p i would not fit a given
    /// Fracture/Support radius (empty: they fit, or the radius is
    /// automatic).
    std::string
    support_refusal(const CrackSet &crack, const unsigned int i) const;

    // The loads.

    /**
     * Scale the proportional loads by @p lambda (Study::set_load_factor())
     * on every present subproblem and every later set-up.
     */
    void
    set_load_factor(const double lambda);

    double
    load_factor() const
    {
      return lambda;
    }

    /// Whether every state at lambda >= 0 is lambda times the state at 1
    /// (Study::proportional_loading()).
    bool
    proportional_loading() const;

    // The set-up and the solve.

    /// Name the states "Step N, load factor L" in the terminal (a growth
    /// run) instead of "Cycle N".
    void
    name_states_as_steps()
    {
      steps_named = true;
    }

    /// The subproblems of the present layers on the present meshes,
    /// assembled and factorised as parallel tasks.
    void
    set_up_subproblems();

    /// Their dofs in @p record.
    void
    count_dofs(CycleRecord &record) const;

    /// Their set-up times (of the busiest process) in @p record.
    void
    count_set_up_times(CycleRecord &record) const;

    /// The couplings and the multipliers, started from @p previous if
    /// given; their number in @p record.
    void
    set_up_interface(CycleRecord                      &record,
                     const MultiplierSpace::Functions *previous);

    /// The multipliers as functions on the interfaces (a warm start of the
    /// next state); empty before the first set-up.
    MultiplierSpace::Functions
    multiplier_functions() const;

    /// The springs of the cohesive zone of block @p b (docs/cohesive.md;
    /// Interface::set_cohesive_compliance()), kept for the next solve.
    void
    set_cohesive_compliance(const std::vector<double> &compliance,
                            const unsigned int         b)
    {
      coupling.set_cohesive_compliance(compliance, b);
    }

    /// Scale the multipliers by @p factor (a warm start at a new load
    /// factor under proportional loading).
    void
    scale_multipliers(const double factor)
    {
      mu *= factor;
    }

    /// Start the next solve from @p start (multipliers of this mesh).
    void
    set_multipliers(const dealii::BlockVector<double> &start)
    {
      AssertDimension(start.size(), mu.size());
      mu = start;
    }

    /// The floating subproblems of the present mesh (FloatingParts: none
    /// where every subproblem touches a clamped part).
    FloatingParts
    floating_parts() const;

    /// The outer solve (the solver of Solver/Method; Coulomb friction by
    /// the fixed point where asked), its times and the MPI exchange in
    /// @p record.
    void
    solve(CycleRecord &record);

    /**
     * The energy, the residuals, G with its mode split and error bar at
     * every tip (the G of the same tip in @p history, the records before,
     * gives the sequence of dG), and, with @p estimate, the error
     * indicators of the next adaptive cycle (eta NaN without).
     */
    void
    assess(CycleRecord                    &record,
           const std::vector<CycleRecord> &history,
           const bool                      estimate);

    /// Replace the error indicators (Study::set_indicators()).
    void
    set_indicators(const std::vector<dealii::Vector<double>> &new_indicators);

    const std::vector<dealii::Vector<double>> &
    error_indicators() const
    {
      return indicators;
    }

    /// The cell terms of the goal-oriented estimates of the last assess()
    /// (dwr_energy, dwr_G; none without Fracture/Goal-oriented estimate),
    /// for the solution files.
    const CellFields &
    goal_cell_fields() const
    {
      return goal_fields;
    }

    // What the drivers read.

    /// The forces and mean displacements of the boundary parts in the
    /// present state, and their balance (boundary_forces()).
    ForceBalance
    forces() const;


    /// The work of the unit proportional loads on the present solution.
    double
    load_work() const;

    /// The largest norm |C| of the tangents of the laws of all plies of
    /// all subproblems [stress]: with the displacement scale d, sqrt(|C|) d
    /// is the scale of the energy norm (round-off of the estimates).
    double
    stiffness_scale() const;

    /// Layer 1's displacement at @p p, read in subproblem @p s.
    dealii::Tensor<1, 2>
    point_displacement(const dealii::Point<2> &p, const unsigned int s) const;

    /// The subproblem of layer 1 whose region holds @p p (a point on an
    /// interface: the region below it).
    unsigned int
    point_subproblem(const dealii::Point<2> &p) const;

    /// The subproblems as the interface reads them and as the solvers use
    /// them (null where a layer is absent).
    PerSubproblem<const ElasticSubproblem *>
    subproblem_views() const;

    const Topology &
    topology() const
    {
      return regions_and_layers;
    }
    const Geometry &
    geometry() const
    {
      return domain;
    }
    const Interface &
    interface() const
    {
      return coupling;
    }
    const Solutions &
    solutions() const
    {
      return w;
    }
    const dealii::BlockVector<double> &
    multipliers() const
    {
      return mu;
    }
    const ElasticSubproblem &
    subproblem(const unsigned int s) const
    {
      return *subproblems[s];
    }

  private:
    /// The traction functions of every present layer on every boundary
    /// part (Loads/Layer k/Traction on ...): their owners and, by layer
    /// slot, the functions in the order of the parts.
    struct TractionFunctions
    {
      std::vector<std::vector<std::unique_ptr<dealii::FunctionParser<2>>>>
                                                            owners;
      std::vector<std::vector<const dealii::Function<2> *>> by_layer;
    };
    TractionFunctions
    traction_functions() const;

    /// The tips of interface @p i with the crack of @p curve (the other
    /// interfaces and the faces between plies, @p material_faces, are
    /// obstacles of theta).
    std::vector<CrackTip>
    tips_on(const InterfaceCurve       &curve,
            const unsigned int          i,
            const std::vector<Segment> &material_faces) const;

    /// The faces between plies of different laws or thermal expansions, of
    /// every layer in every region (material_boundaries()): obstacles of
    /// the tips' theta where it would move them.
    std::vector<Segment>
    ply_boundaries() const;

    /// The check of update_tips() on the tips found.
    void
    check_supports(const CycleRecord &record);

    /// G, its mode split and its error bar at every tip (assess()).
    void
    assess_tips(CycleRecord &record, const std::vector<CycleRecord> &history);

    /// The goal-oriented estimates of G and the energy into @p record
    /// (docs/fracture.md §11), dG widened to them, and with a
    /// Mesh/Refinement goal their indicators for the next adaptive cycle.
    void
    estimate_goals(CycleRecord &record);

    const Scene                &scene;
    const Distribution         &distribution;
    dealii::ConditionalOStream &pcout;
    /// The regions, interfaces and layers of the scene.
    /// The regions, interfaces and layers (the interfaces' regions known
    /// once the meshes are built: build_meshes()).
    Topology regions_and_layers;

    /// Per subproblem: its body force and eigenstrain (Loads/Layer k, and
    /// the thermal strain of its material under Loads/Temperature change),
    /// null where it has none; the subproblem refers to it (so declared
    /// before them).
    PerSubproblem<std::unique_ptr<ScaledVolumeLoad>> volume_loads;
    /// The load factor (set_load_factor()).
    double lambda = 1;
    /// keep_meshes().
    bool fixed_meshes = false;
    /// name_states_as_steps().
    bool steps_named = false;

    Geometry                                          domain;
    PerSubproblem<std::unique_ptr<ElasticSubproblem>> subproblems;
    Interface                                         coupling;
    Solutions                                         w;
    dealii::BlockVector<double>                       mu;
    /// The crack tips and the supports of their velocity fields, and
    /// whether they belong to the present crack.
    std::vector<CrackTip> crack_tips_found;
    bool                  tips_current = false;
    /// Per tip: why its support holds too few cells of this cycle's meshes
    /// (empty where it holds enough).
    std::vector<std::string> unresolved_tips;
    /// Per tip: the size of the largest cell at it on this cycle's meshes
    /// (support_cells()), 0 where G is not defined.
    std::vector<double> tip_cell_sizes;
    /// Error indicators of the last cycle, per region (adaptive
    /// refinement).
    std::vector<dealii::Vector<double>> indicators;
    /// goal_cell_fields().
    CellFields goal_fields;
  };
} // namespace bilayer

#endif
