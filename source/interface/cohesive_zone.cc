#include <deal.II/base/exceptions.h>

#include <bilayer/interface/cohesive_zone.h>

#include <algorithm>
#include <cmath>
#include <limits>

namespace bilayer
{
  using namespace dealii;


  CohesiveZone::CohesiveZone(const CohesiveLaw                        &law,
                             const MultiplierSpace                    &space,
                             const unsigned int                        b,
                             const std::vector<std::array<double, 2>> &pieces,
                             const double tolerance)
    : law(law)
    , space(space)
    , b(b)
  {
    const unsigned int n = space.n_nodes(b);
    zone.assign(n, false);
    unsigned int count = 0;
    for (unsigned int a = 0; a < n; ++a)
      {
        const double s = space.node_position(a, b);
        for (const auto &piece : pieces)
          if (s >= piece[0] - tolerance && s <= piece[1] + tolerance &&
              space.cohesive_node(a, b))
            zone[a] = true;
        count += zone[a];
      }
    AssertThrow(count > 0,
                ExcMessage("Cohesive/Zone holds no node of the interface's "
                           "multipliers that may carry a spring (a node of "
                           "the zone's pieces off the clamped sides and the "
                           "corners)"));
    committed_history.assign(n, 0.);
    committed_damage.assign(n, 0.);
    trial_history = committed_history;
    trial_damage  = committed_damage;
    trial_mixity.assign(n, 0.);
    committed_mixity = trial_mixity;
  }


  std::vector<CohesiveZone::Separation>
  CohesiveZone::separations(const Interface &interface,
                            const Solutions &w) const
  {
    BlockVector<double> g;
    // (Every component: a broken node's frictionless sliding has no
    // multiplier, and its mixity and history read it.)
    interface.jumps(w, g, true);
    std::vector<Separation> delta(space.n_nodes(b), {{0., 0.}});
    for (unsigned int a = 0; a < delta.size(); ++a)
      {
        // g = -[u] in the node's frame (tangential, normal).
        delta[a][0] = -g.block(b)(Layout::entry(a, Layout::normal));
        delta[a][1] = -g.block(b)(Layout::entry(a, Layout::tangential));
      }
    return delta;
  }


  namespace
  {
    /// The equivalent separation sqrt(<delta_n>^2 + delta_t^2) and the
    /// mixity delta_t^2 / delta^2 (1 in shear under pressure).
    std::pair<double, double>
    equivalent(const CohesiveZone::Separation &d, const double scale)
    {
      const double n = std::max(d[0], 0.) * scale, t = d[1] * scale;
      const double e = std::sqrt(n * n + t * t);
      return {e, e > 0 ? t * t / (e * e) : (d[0] < 0 ? 1. : 0.)};
    }
  } // namespace


  bool
  CohesiveZone::loads(const unsigned int a, const Separation &delta) const
  {
    return committed_damage[a] < 1 &&
           equivalent(delta, 1.).first >= committed_history[a];
  }


  CohesiveZone::NodeState
  CohesiveZone::node_state(const unsigned int a,
                           const Separation  &delta,
                           const bool         loading) const
  {
    const auto [e, B] = equivalent(delta, 1.);
    NodeState state;
    if (loading)
      {
        state.mixity  = B;
        state.history = e;
        state.damage  = law.damage(e, B);
        return state;
      }
    // A fully damaged node keeps its mixity (its shear is no longer a
    // separation of the law).
    state.mixity  = committed_damage[a] < 1 ? B : committed_mixity[a];
    state.history = std::max(committed_history[a], e);
    state.damage =
      std::max(committed_damage[a], law.damage(state.history, state.mixity));
    return state;
  }


  double
  CohesiveZone::node_dissipation(const unsigned int a,
                                 const NodeState   &state) const
  {
    return space.node_mass(a, b) *
           law.dissipated_energy(state.history, state.mixity);
  }


  double
  CohesiveZone::try_separations(const std::vector<Separation> &delta,
                                const double                   scale)
  {
    double change = 0;
    for (unsigned int a = 0; a < zone.size(); ++a)
      if (zone[a])
        {
          const NodeState state =
            node_state(a, {{delta[a][0] * scale, delta[a][1] * scale}});
          trial_mixity[a]  = state.mixity;
          trial_history[a] = state.history;
          change = std::max(change, std::abs(state.damage - trial_damage[a]));
          trial_damage[a] = state.damage;
        }
    return change;
  }


  std::vector<double>
  CohesiveZone::trial_histories() const
  {
    std::vector<double> h;
    for (unsigned int a = 0; a < zone.size(); ++a)
      if (zone[a])
        h.push_back(trial_history[a]);
    return h;
  }


  void
  CohesiveZone::set_trial_histories(const std::vector<double> &histories)
  {
    unsigned int k = 0;
    for (unsigned int a = 0; a < zone.size(); ++a)
      if (zone[a])
        {
          AssertIndexRange(k, histories.size());
          trial_history[a] = std::max(committed_history[a], histories[k++]);
          trial_damage[a] =
            std::max(committed_damage[a],
                     law.damage(trial_history[a], trial_mixity[a]));
        }
  }


  std::vector<double>
  CohesiveZone::predicted_histories(const double fraction) const
  {
    std::vector<double> h;
    for (unsigned int a = 0; a < zone.size(); ++a)
      if (zone[a])
        h.push_back(previous_history.empty() ?
                      committed_history[a] :
                      committed_history[a] + fraction * (committed_history[a] -
                                                         previous_history[a]));
    return h;
  }


  void
  CohesiveZone::commit()
  {
    previous_history  = committed_history;
    committed_history = trial_history;
    committed_damage  = trial_damage;
    committed_mixity  = trial_mixity;
  }


  double
  CohesiveZone::scale_for_increment(const std::vector<Separation> &delta,
                                    const double                   increment,
                                    int &control) const
  {
    const auto scale = [&](const unsigned int a) {
      const double e = equivalent(delta[a], 1.).first;
      return e > 0 ? (committed_history[a] + increment) / e :
                     std::numeric_limits<double>::infinity();
    };
    if (control >= 0)
      return scale(control);
    double f = std::numeric_limits<double>::infinity();
    for (unsigned int a = 0; a < zone.size(); ++a)
      if (zone[a] && committed_damage[a] < 1 && scale(a) < f)
        {
          f       = scale(a);
          control = a;
        }
    return f;
  }


  double
  CohesiveZone::scale_for_dissipation(const std::vector<Separation> &delta,
                                      const double target) const
  {
    const auto dissipation = [&](const double f) {
      double sum = 0;
      for (unsigned int a = 0; a < zone.size(); ++a)
        if (zone[a])
          {
            const auto [e, B]   = equivalent(delta[a], f);
            const double mixity = committed_damage[a] < 1 ? B : trial_mixity[a];
            sum +=
              space.node_mass(a, b) *
              law.dissipated_energy(std::max(committed_history[a], e), mixity);
          }
      return sum;
    };
    // The most the zone can dissipate (every node broken at the mixities
    // of delta): a target beyond it is the zone's rest, all but 1e-6 of it.
    double most = 0;
    for (unsigned int a = 0; a < zone.size(); ++a)
      if (zone[a])
        {
          const auto [e, B] = equivalent(delta[a], 1.);
          (void)e;
          most += space.node_mass(a, b) *
                  law.toughness(committed_damage[a] < 1 ? B : trial_mixity[a]);
        }
    const double reachable = std::min(target, (1 - 1e-6) * most);
    if (!(reachable > committed_dissipation()))
      return std::numeric_limits<double>::infinity();
    double high = 1;
    for (unsigned int k = 0; dissipation(high) < reachable; ++k, high *= 2)
      if (k == 200)
        return std::numeric_limits<double>::quiet_NaN();
    double low = 0;
    for (unsigned int k = 0; k < 200 && high - low > 1e-15 * high; ++k)
      {
        const double mid                            = 0.5 * (low + high);
        (dissipation(mid) < reachable ? low : high) = mid;
      }
    return high;
  }


  double
  CohesiveZone::committed_dissipation() const
  {
    double sum = 0;
    for (unsigned int a = 0; a < zone.size(); ++a)
      if (zone[a])
        sum += space.node_mass(a, b) *
               law.dissipated_energy(committed_history[a], committed_mixity[a]);
    return sum;
  }


  bool
  CohesiveZone::exhausted() const
  {
    double most = 0;
    for (unsigned int a = 0; a < zone.size(); ++a)
      if (zone[a])
        most += space.node_mass(a, b) * law.toughness(committed_mixity[a]);
    return !(committed_dissipation() < (1 - 1e-6) * most);
  }


  double
  CohesiveZone::scale_for_onset(const std::vector<Separation> &delta) const
  {
    double f = std::numeric_limits<double>::infinity();
    for (unsigned int a = 0; a < zone.size(); ++a)
      if (zone[a])
        {
          const auto [e, B] = equivalent(delta[a], 1.);
          if (e > 0)
            f = std::min(f, law.onset_separation(B) / e);
        }
    return f;
  }


  std::vector<double>
  CohesiveZone::compliance() const
  {
    const double        k0 = law.initial_stiffness();
    std::vector<double> c(zone.size(),
                          std::numeric_limits<double>::quiet_NaN());
    for (unsigned int a = 0; a < zone.size(); ++a)
      if (zone[a])
        c[a] = trial_damage[a] >= 1 ? std::numeric_limits<double>::infinity() :
                                      1. / (k0 * (1. - trial_damage[a]));
    return c;
  }


  bool
  CohesiveZone::fully_damaged() const
  {
    for (unsigned int a = 0; a < zone.size(); ++a)
      if (zone[a] && trial_damage[a] < 1)
        return false;
    return true;
  }


  CohesiveZone::Summary
  CohesiveZone::summary() const
  {
    Summary s;
    bool    first = true;
    for (unsigned int a = 0; a < zone.size(); ++a)
      if (zone[a])
        {
          const double weight = space.node_mass(a, b);
          const double d      = trial_damage[a];
          ++s.n_nodes;
          s.dissipated +=
            weight * law.dissipated_energy(trial_history[a], trial_mixity[a]);
          s.largest_damage = std::max(s.largest_damage, d);
          s.largest_separation =
            std::max(s.largest_separation, trial_history[a]);
          if (d >= 1)
            {
              s.cracked_length += weight;
              ++s.n_cracked;
            }
          else if (d > 0)
            {
              s.process_length += weight;
              ++s.n_process;
              const double x  = space.node_position(a, b);
              s.process_start = first ? x : std::min(s.process_start, x);
              s.process_end   = first ? x : std::max(s.process_end, x);
              first           = false;
            }
        }
    return s;
  }
} // namespace bilayer
