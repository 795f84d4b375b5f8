#ifndef bilayer_cohesive_zone_h
#define bilayer_cohesive_zone_h

#include <deal.II/lac/block_vector.h>

#include <bilayer/interface/interface.h>
#include <bilayer/physics/cohesive_law.h>
#include <bilayer/subproblem/subproblem.h>

#include <algorithm>
#include <array>
#include <vector>

namespace bilayer
{
  /**
   * The state of a cohesive zone (docs/cohesive.md): the nodes of the
   * multipliers across one interface that lie in Cohesive/Zone, and per
   * node the largest equivalent separation reached (the history), the
   * damage and the mode mixity, committed at the end of each step and
   * tried during its secant iteration. It turns the separations of a
   * solution into damage (irreversibly: never below the committed
   * damage) and the damage into the compliances of the springs
   * (MultiplierSpace::set_cohesive_compliance()).
   */
  class CohesiveZone
  {
  public:
    /// The separation at a node: normal (opening > 0) and tangential.
    using Separation = std::array<double, 2>;

    /**
     * The nodes of block @p b of @p space that may carry springs
     * (MultiplierSpace::cohesive_node()) and lie in one of the closed
     * intervals @p pieces (within @p tolerance), intact. Refuses a zone
     * without nodes.
     */
    CohesiveZone(const CohesiveLaw                        &law,
                 const MultiplierSpace                    &space,
                 const unsigned int                        b,
                 const std::vector<std::array<double, 2>> &pieces,
                 const double                              tolerance);

    /// The block whose nodes the zone holds.
    unsigned int
    block() const
    {
      return b;
    }

    /// The separations of @p w at every node of the block (the jumps in
    /// each node's frame, opening positive).
    std::vector<Separation>
    separations(const Interface &interface, const Solutions &w) const;

    /**
     * The trial state of the separations @p delta times @p scale: history
     * max(committed, equivalent separation), damage max(committed, law's).
     * Returns the largest change of a trial damage since the last call.
     */
    double
    try_separations(const std::vector<Separation> &delta, const double scale);

    /// A node's state for the separation @p delta from the committed one
    /// (what try_separations() gives it with scale 1).
    struct NodeState
    {
      double history = 0, damage = 0, mixity = 0;
    };

    /// With @p loading, the state of the law's loading branch at
    /// @p delta (history the equivalent separation, without the committed
    /// state's bounds): its derivatives where the node loads.
    NodeState
    node_state(const unsigned int a,
               const Separation  &delta,
               const bool         loading = false) const;

    /// Whether @p delta loads node @p a: its equivalent separation at
    /// least its committed history, the node not fully damaged.
    bool
    loads(const unsigned int a, const Separation &delta) const;

    /// The energy that node @p a dissipates in the state @p state (the
    /// law's at its history and mixity, with the node's weight of Sigma).
    double
    node_dissipation(const unsigned int a, const NodeState &state) const;

    /// The law's initial stiffness k0 [stress / length].
    double
    initial_stiffness() const
    {
      return law.initial_stiffness();
    }

    /// The committed history (largest equivalent separation) of node @p a.
    double
    committed_history_of(const unsigned int a) const
    {
      return committed_history[a];
    }

    /// Whether node @p a is fully damaged in the committed state.
    bool
    committed_broken(const unsigned int a) const
    {
      return committed_damage[a] >= 1;
    }

    /// The number of nodes of the zone's block (in the zone or not).
    unsigned int
    n_block_nodes() const
    {
      return zone.size();
    }

    /// The trial histories (largest equivalent separations) of the zone's
    /// nodes, in the order of the nodes.
    std::vector<double>
    trial_histories() const;

    /// Set the trial histories of the zone's nodes (in the order of
    /// trial_histories()), each at least the committed one, and their
    /// damage from them.
    void
    set_trial_histories(const std::vector<double> &histories);

    /// The histories of the next step extrapolated linearly from the last
    /// two committed ones, the last increment times @p fraction (the
    /// committed ones before a second commit), in the order of
    /// trial_histories(): the first iterate of a step.
    std::vector<double>
    predicted_histories(const double fraction) const;

    /// The trial state back to the committed one (a step taken again).
    void
    reset_trial()
    {
      trial_history = committed_history;
      trial_damage  = committed_damage;
      trial_mixity  = committed_mixity;
    }

    /// The trial state becomes the committed one.
    void
    commit();

    /**
     * Path following: the factor f by which the separations @p delta must
     * be scaled for the largest growth of an equivalent separation beyond
     * its committed history, over the nodes not yet fully damaged, to be
     * @p increment: f = min over them of (history + increment) /
     * separation. Infinity where no such node separates. The node that
     * gives the minimum is returned in @p control when it is negative on
     * entry; otherwise the node @p control is the one that must grow by
     * the increment (the control node kept through a step's iterations).
     */
    double
    scale_for_increment(const std::vector<Separation> &delta,
                        const double                   increment,
                        int                           &control) const;

    /**
     * Dissipation control: the factor f by which the separations @p delta
     * must be scaled for the zone's dissipated energy (with the histories
     * max(committed, f delta), the mixities of @p delta) to be @p target:
     * the smallest such f, by bisection (the dissipation is a
     * nondecreasing function of f). A target beyond what the whole zone
     * can dissipate (every node broken) is replaced by all but 1e-6 of
     * that; infinity where the committed state dissipates that already;
     * NaN where no scaling of @p delta reaches the target (nodes that do
     * not open under it hold the rest of the zone's toughness).
     */
    double
    scale_for_dissipation(const std::vector<Separation> &delta,
                          const double                   target) const;

    /// The committed dissipated energy (per unit width).
    double
    committed_dissipation() const;

    /// Whether the committed state has dissipated all but 1e-6 of what the
    /// zone can (every node's toughness at its committed mixity times its
    /// length): dissipation control has nothing left to trace.
    bool
    exhausted() const;

    /// Path following to the onset: the factor by which the separations
    /// @p delta must be scaled for the first node to reach the onset
    /// separation of its mixity (the elastic limit, the peak of a bilinear
    /// law). Infinity where no node separates.
    double
    scale_for_onset(const std::vector<Separation> &delta) const;

    /// Whether no node has damage yet (committed state).
    bool
    undamaged() const
    {
      for (const double d : committed_damage)
        if (d > 0)
          return false;
      return true;
    }

    /// Per node of the block: the compliance of the springs (trial state),
    /// NaN off the zone, infinity where fully damaged.
    std::vector<double>
    compliance() const;

    /// The largest growth of a node's damage in the trial state over the
    /// committed one.
    double
    largest_damage_growth() const
    {
      double growth = 0;
      for (unsigned int a = 0; a < zone.size(); ++a)
        if (zone[a])
          growth = std::max(growth, trial_damage[a] - committed_damage[a]);
      return growth;
    }

    /// Whether every node of the zone is fully damaged (trial state).
    bool
    fully_damaged() const;

    /// What the zone holds (trial state).
    struct Summary
    {
      /// The energy dissipated per unit width (the law's at each node's
      /// history and mixity, with the node's weight of Sigma).
      double dissipated = 0;
      /// The length of the fully damaged part, and of the process zone
      /// (0 < d < 1), and where the process zone starts and ends (s).
      double cracked_length = 0, process_length = 0;
      double process_start = 0, process_end = 0;
      /// The largest damage, the largest equivalent separation.
      double       largest_damage = 0, largest_separation = 0;
      unsigned int n_nodes = 0, n_cracked = 0, n_process = 0;
    };

    Summary
    summary() const;

    /// Per node of the block: whether it is in the zone, its coordinate,
    /// damage, history and mixity (trial state).
    bool
    in_zone(const unsigned int a) const
    {
      return zone[a];
    }
    double
    damage(const unsigned int a) const
    {
      return trial_damage[a];
    }
    double
    history(const unsigned int a) const
    {
      return trial_history[a];
    }
    double
    mixity(const unsigned int a) const
    {
      return trial_mixity[a];
    }

  private:
    const CohesiveLaw     &law;
    const MultiplierSpace &space;
    const unsigned int     b;
    std::vector<bool>      zone;
    std::vector<double> committed_history, committed_damage, committed_mixity;
    /// The committed histories before the last commit.
    std::vector<double> previous_history;
    std::vector<double> trial_history, trial_damage, trial_mixity;
  };
} // namespace bilayer

#endif
