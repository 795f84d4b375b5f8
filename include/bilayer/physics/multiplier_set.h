#ifndef bilayer_multiplier_set_h
#define bilayer_multiplier_set_h

#include <deal.II/lac/block_vector.h>

#include <algorithm>
#include <cmath>
#include <utility>
#include <vector>

namespace bilayer
{
  /**
   * The admissible set K of the multipliers (docs/problem.md §3): for each
   * component of a multiplier vector (a BlockVector in the layout of
   * MultiplierSpace) what it constrains and the set its value lies in. The
   * one code that knows the shape of K: the projections of the first-order
   * solvers, the active and inactive components of the active-set method,
   * the primal feasibility of the jumps and the KKT checks ask it.
   *
   * Today every component lies in a box of its own:
   *  - Kind::none: no multiplier (fixed to 0: nodes on Gamma_D, the
   *    tangential component on the crack, the crack without
   *    non-penetration);
   *  - Kind::glued: a gluing constraint [w] = 0 with the multiplier in
   *    [-p, p] (p the bound of the paper's Uzawa method);
   *  - Kind::contact: a non-penetration constraint [u].nu >= 0 with the
   *    multiplier in [0, p];
   *  - Kind::friction: the tangential component on the crack with friction,
   *    in [-g, g] (g the friction bound of the node, at most p): the faces
   *    stick ([u].tau = 0) where the multiplier lies inside, and slip
   *    against it where a jump holds it at a bound. In two dimensions the
   *    Tresca disk is this interval, so K stays a box.
   *  - Kind::cohesive: a component of a node of a cohesive zone that is not
   *    fully damaged (docs/cohesive.md): the multiplier, in [-p, p], is the
   *    traction of a spring of compliance c (the inverse of the secant
   *    stiffness k (1 - d) of the traction-separation law) on the jump:
   *    g = c mu for a tangential component, g = c min(mu, 0) for a normal
   *    one (a spring in tension, non-penetration g = 0 exact under
   *    pressure). The dual function gains -D c phi(mu)^2 / 2
   *    (cohesive_term()), its gradient D (g - c phi(mu)), its Hessian
   *    -(F + D c') (cohesive_slope()).
   * A set that couples the components of a node (a Coulomb cone with its
   * normal force as a variable) would be a kind of its own here, with its
   * projection and its classification.
   */
  class MultiplierSet
  {
  public:
    enum class Kind
    {
      none,
      glued,
      contact,
      friction,
      cohesive
    };

    /// Blocks of @p sizes components, every one of kind none.
    void
    reinit(const std::vector<dealii::types::global_dof_index> &sizes)
    {
      lower.reinit(sizes);
      upper.reinit(sizes);
      kinds.assign(lower.size(), Kind::none);
      compliance.assign(lower.size(), 0.);
      tension_only.assign(lower.size(), false);
      cones.clear();
    }

    /**
     * Component @p i of block @p b: a cohesive spring of compliance @p c
     * (>= 0) acting on the jump, in tension only with @p normal
     * (Kind::cohesive), bound @p p.
     */
    void
    set_cohesive(const unsigned int b,
                 const unsigned int i,
                 const double       c,
                 const bool         normal,
                 const double       p)
    {
      lower.block(b)(i)    = -p;
      upper.block(b)(i)    = p;
      const unsigned int k = global(b, i);
      kinds[k]             = Kind::cohesive;
      compliance[k]        = c;
      tension_only[k]      = normal;
    }

    /// Component @p i of block @p b as it is in @p other (a set of the
    /// same layout): kind, box and spring.
    void
    copy_component(const MultiplierSet &other,
                   const unsigned int   b,
                   const unsigned int   i)
    {
      const unsigned int k = global(b, i);
      lower.block(b)(i)    = other.lower.block(b)(i);
      upper.block(b)(i)    = other.upper.block(b)(i);
      kinds[k]             = other.kinds[k];
      compliance[k]        = other.compliance[k];
      tension_only[k]      = other.tension_only[k];
    }

    /// Whether component @p i is a cohesive spring.
    bool
    cohesive(const unsigned int i) const
    {
      return kind(i) == Kind::cohesive;
    }

    /// Whether component @p i of block @p b is a cohesive spring.
    bool
    cohesive(const unsigned int b, const unsigned int i) const
    {
      return cohesive(global(b, i));
    }

    /// Whether some component is a cohesive spring.
    bool
    has_cohesive() const
    {
      return std::find(kinds.begin(), kinds.end(), Kind::cohesive) !=
             kinds.end();
    }

    /// The jump c phi(mu_i) that the spring of component @p i holds at the
    /// multiplier @p mu_i (0 for other kinds).
    double
    cohesive_term(const unsigned int i, const double mu_i) const
    {
      if (!cohesive(i))
        return 0.;
      return compliance[i] * (tension_only[i] ? std::min(mu_i, 0.) : mu_i);
    }

    /// The derivative of cohesive_term() at @p mu_i (the tension side's at
    /// a normal component's kink mu = 0 only below it).
    double
    cohesive_slope(const unsigned int i, const double mu_i) const
    {
      if (!cohesive(i))
        return 0.;
      return tension_only[i] && mu_i >= 0 ? 0. : compliance[i];
    }

    /// Component @p i of block @p b: a gluing constraint, bound @p p.
    void
    set_glued(const unsigned int b, const unsigned int i, const double p)
    {
      lower.block(b)(i)   = -p;
      upper.block(b)(i)   = p;
      kinds[global(b, i)] = Kind::glued;
    }

    /// Component @p i of block @p b: a contact constraint, bound @p p.
    void
    set_contact(const unsigned int b, const unsigned int i, const double p)
    {
      lower.block(b)(i)   = 0;
      upper.block(b)(i)   = p;
      kinds[global(b, i)] = Kind::contact;
    }

    /**
     * Component @p i of block @p b: a tangential crack component with the
     * friction bound @p g (> 0; a zero bound is no multiplier, set_none()).
     */
    void
    set_friction(const unsigned int b, const unsigned int i, const double g)
    {
      lower.block(b)(i)   = -g;
      upper.block(b)(i)   = g;
      kinds[global(b, i)] = Kind::friction;
    }

    /**
     * Component @p i of block @p b: a tangential crack component in the
     * Coulomb cone of its node, |mu_t| <= min(F max(mu_n, 0), p) with
     * @p F the friction coefficient and mu_n the component @p n of the
     * same block (the node's contact component). Its box follows mu_n:
     * project() sets it from the projected mu_n, and held(), violation()
     * and friction_bound() read the box of the last projection.
     */
    void
    set_cone(const unsigned int b,
             const unsigned int i,
             const unsigned int n,
             const double       F,
             const double       p)
    {
      set_friction(b, i, 0.);
      cones.push_back({global(b, i), global(b, n), F, p});
    }

    /// Component @p i of block @p b: no multiplier.
    void
    set_none(const unsigned int b, const unsigned int i)
    {
      lower.block(b)(i)   = 0;
      upper.block(b)(i)   = 0;
      kinds[global(b, i)] = Kind::none;
    }

    /// The number of components.
    unsigned int
    size() const
    {
      return lower.size();
    }

    /// Zero multipliers of the layout of the set.
    void
    initialize(dealii::BlockVector<double> &mu) const
    {
      mu.reinit(lower);
    }

    /// What component @p i (global index) constrains.
    Kind
    kind(const unsigned int i) const
    {
      return kinds[i];
    }

    /// Whether component @p i carries a multiplier.
    bool
    free(const unsigned int i) const
    {
      return kinds[i] != Kind::none;
    }

    /// Whether component @p i of block @p b carries a multiplier.
    bool
    free(const unsigned int b, const unsigned int i) const
    {
      return free(global(b, i));
    }

    /// Whether component @p i is a contact constraint.
    bool
    contact(const unsigned int i) const
    {
      return kind(i) == Kind::contact;
    }

    /// Whether component @p i is a tangential crack component with
    /// friction.
    bool
    friction(const unsigned int i) const
    {
      return kind(i) == Kind::friction;
    }

    /// Whether component @p i of block @p b is a contact constraint.
    bool
    contact(const unsigned int b, const unsigned int i) const
    {
      return contact(global(b, i));
    }

    /// The projection onto K.
    void
    project(dealii::BlockVector<double> &mu) const
    {
      for (unsigned int i = 0; i < mu.size(); ++i)
        mu(i) = std::min(std::max(mu(i), lower(i)), upper(i));
      // Coulomb cones: the tangential component onto the bound of the
      // projected normal one (in two dimensions the cone's sequential
      // projection, normal first).
      for (const Cone &c : cones)
        {
          if (kinds[c.tangential] == Kind::cohesive)
            continue; // a cohesive node's spring, its cone once cracked
          const double g      = std::min(c.F * std::max(mu(c.normal), 0.), c.p);
          lower(c.tangential) = -g;
          upper(c.tangential) = g;
          mu(c.tangential)    = std::min(std::max(mu(c.tangential), -g), g);
        }
    }

    /// Whether some components lie in Coulomb cones (set_cone()).
    bool
    has_cones() const
    {
      return !cones.empty();
    }

    /**
     * Whether the multiplier @p mu_i of component @p i with the jump
     * @p g_i is held on the boundary of K by a jump that pushes it outward
     * (mu = P(mu + theta g) for every theta > 0: optimal there, the
     * constraint "active" for the active-set method). A component without
     * multiplier is held.
     */
    bool
    held(const unsigned int i, const double mu_i, const double g_i) const
    {
      return !free(i) || (mu_i <= lower(i) && g_i <= 0) ||
             (mu_i >= upper(i) && g_i >= 0);
    }

    /**
     * Whether a multiplier component is held at a bound of K by its jump
     * (held() of a component that carries one): its jump is no residual
     * of the KKT conditions.
     */
    bool
    held_at_bound(const unsigned int i,
                  const double       mu_i,
                  const double       g_i) const
    {
      return free(i) &&
             ((mu_i >= upper(i) && g_i >= 0) || (mu_i <= lower(i) && g_i <= 0));
    }

    /**
     * The violation of the constraint of component @p i by the jump
     * @p g_i at the multiplier @p mu_i: |g| of a gluing constraint,
     * max(g, 0) of a contact constraint ([u].nu >= 0 with g = -[u].nu),
     * for a friction component |g| where it sticks (inside its box, or at a
     * bound with a jump that pushes inward) and 0 where it slips (held at a
     * bound), 0 without multiplier; for a cohesive component |g| of the
     * jumps less the springs' (MultiplierSpace::add_cohesive_jumps()).
     */
    double
    violation(const unsigned int i, const double g_i, const double mu_i) const
    {
      switch (kinds[i])
        {
          case Kind::glued:
            return std::abs(g_i);
          case Kind::contact:
            return std::max(g_i, 0.);
          case Kind::friction:
            return held_at_bound(i, mu_i, g_i) ? 0. : std::abs(g_i);
          case Kind::cohesive:
            return held_at_bound(i, mu_i, g_i) ? 0. : std::abs(g_i);
          default:
            return 0.;
        }
    }

    /**
     * The friction bound g of component @p i (the upper end of its box; 0
     * for a component that is not a friction component).
     */
    double
    friction_bound(const unsigned int i) const
    {
      return friction(i) ? upper(i) : 0.;
    }

    /// The friction bound of component @p i of block @p b.
    double
    friction_bound(const unsigned int b, const unsigned int i) const
    {
      return friction_bound(global(b, i));
    }

    /**
     * Whether a contact multiplier @p mu_i lies below its bound p, where
     * the sign and complementarity conditions of contact are checked
     * (mu = p is the paper's cap, not a contact state).
     */
    bool
    below_bound(const unsigned int i, const double mu_i) const
    {
      return mu_i < upper(i);
    }

    /// The bound of component @p i that a step of sign @p direction meets.
    double
    bound_towards(const unsigned int i, const double direction) const
    {
      return direction < 0 ? lower(i) : upper(i);
    }

    /// The largest a <= @p a_max with mu + a d in K, for the step @p d.
    double
    step_to_boundary(const dealii::BlockVector<double> &mu,
                     const dealii::BlockVector<double> &d,
                     double                             a_max) const
    {
      for (unsigned int i = 0; i < mu.size(); ++i)
        if (d(i) < 0)
          a_max = std::min(a_max, (lower(i) - mu(i)) / d(i));
        else if (d(i) > 0)
          a_max = std::min(a_max, (upper(i) - mu(i)) / d(i));
      return a_max;
    }

    /// The box [lower, upper] of component @p i of block @p b.
    std::pair<double, double>
    box(const unsigned int b, const unsigned int i) const
    {
      return {lower.block(b)(i), upper.block(b)(i)};
    }

  private:
    /// The global index of component @p i of block @p b.
    dealii::types::global_dof_index
    global(const unsigned int b, const unsigned int i) const
    {
      return lower.get_block_indices().local_to_global(b, i);
    }

    /// The box of each component: [0, 0] none, [-p, p] glued, [0, p]
    /// contact (p > 0), [-g, g] friction (0 < g <= p).
    /// (Mutable: the boxes of the Coulomb cones follow their normal
    /// components in project().)
    mutable dealii::BlockVector<double> lower, upper;
    /// A Coulomb cone: the global indices of the tangential and normal
    /// components of a node, the friction coefficient and the bound p.
    struct Cone
    {
      unsigned int tangential, normal;
      double       F, p;
    };
    std::vector<Cone> cones;
    /// What each component constrains: set with its box, never inferred
    /// from it.
    std::vector<Kind> kinds;
    /// Per component: the compliance of a cohesive spring, and whether it
    /// acts in tension only (set_cohesive()).
    std::vector<double> compliance;
    std::vector<bool>   tension_only;
  };
} // namespace bilayer

#endif
