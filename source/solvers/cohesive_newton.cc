// The semismooth Newton method of a cohesive step on the interface alone
// (docs/cohesive.md, "The Newton method").

#include <deal.II/lac/lapack_full_matrix.h>

#include <bilayer/core/layout.h>
#include <bilayer/solvers/cohesive_newton.h>

#include <algorithm>
#include <cmath>
#include <limits>

namespace bilayer
{
  using namespace dealii;

  std::string
  CohesiveNewton::unsupported(const Interface &interface, const bool frictional)
  {
    if (frictional)
      return "friction on the crack faces (the secant iteration with the "
             "outer solver takes it)";
    const MultiplierSpace &space = interface.space();
    for (const MultiplierSet *set : {&space.set(), &space.crack_kinds()})
      for (unsigned int i = 0; i < set->size(); ++i)
        if (set->kind(i) == MultiplierSet::Kind::friction)
          return "friction on the interfaces (the secant iteration with the "
                 "outer solver takes it)";
    return "";
  }


  CohesiveNewton::CohesiveNewton(const Subproblems  &subproblems,
                                 const Interface    &interface,
                                 const CohesiveZone &zone)
  {
    AssertThrow(unsupported(interface, false).empty(),
                ExcMessage("CohesiveNewton: " + unsupported(interface, false)));
    const MultiplierSet &set = interface.space().set();
    BlockVector<double>  mu;
    set.initialize(mu);
    const auto        &blocks = mu.get_block_indices();
    const unsigned int b      = zone.block();
    node_unknowns.assign(zone.n_block_nodes(), {{-1, -1}});
    for (unsigned int i = 0; i < mu.size(); ++i)
      {
        const auto [block, local] = blocks.global_to_local(i);
        const unsigned int a      = local / Layout::n_components;
        if (block == b && zone.in_zone(a))
          {
            const unsigned int k = local % Layout::n_components;
            node_unknowns[a][k]  = unknowns.size();
            unknowns.push_back(i);
            roles.push_back(k == Layout::normal ? Role::zone_normal :
                                                  Role::zone_tangential);
            nodes.push_back(a);
            continue;
          }
        const MultiplierSet::Kind kind = set.kind(i);
        if (kind == MultiplierSet::Kind::none)
          continue;
        AssertThrow(kind == MultiplierSet::Kind::glued ||
                      kind == MultiplierSet::Kind::contact,
                    ExcMessage("CohesiveNewton: a component of a kind it "
                               "does not know outside the zone"));
        unknowns.push_back(i);
        roles.push_back(kind == MultiplierSet::Kind::glued ? Role::glued :
                                                             Role::contact);
        nodes.push_back(0);
      }

    // The columns of A: the jumps of the homogeneous solves with a unit
    // multiplier.
    const unsigned int n = unknowns.size();
    A.reinit(n, n);
    Solutions           w;
    BlockVector<double> g;
    for (unsigned int j = 0; j < n; ++j)
      {
        mu              = 0;
        mu(unknowns[j]) = 1;
        solve_homogeneous_subproblems(subproblems, interface, mu, w);
        interface.jumps(w, g, true);
        for (unsigned int r = 0; r < n; ++r)
          A(r, j) = -g(unknowns[r]);
        for (const auto *s : subproblems)
          n_solves += s != nullptr;
      }
  }


  /**
   * The residual and Jacobian of the step's equations at an iterate
   * (mu, lambda): the unknowns' rows scaled by the scale of the
   * multipliers, the control's row by its target.
   */
  class CohesiveNewton::Evaluation
  {
  public:
    Evaluation(const CohesiveNewton              &newton,
               const CohesiveZone                &zone,
               const dealii::BlockVector<double> &g0,
               const double                       lambda0,
               const Step                        &step,
               const double                       scale)
      : newton(newton)
      , zone(zone)
      , step(step)
      , path(step.control != Control::load_factor)
      , k0(zone.initial_stiffness())
      , scale(scale)
    {
      const unsigned int n = newton.size();
      g_fixed.reinit(n);
      for (unsigned int r = 0; r < n; ++r)
        g_fixed(r) = g0(newton.unknowns[r]);
      // (Proportional loads: the jumps without multipliers are lambda d.)
      if (path)
        g_fixed /= lambda0;
    }

    /// The number of unknowns: the multipliers, and the load factor
    /// under path following.
    unsigned int
    size() const
    {
      return newton.size() + (path ? 1 : 0);
    }

    /// The residual at x (the multipliers, then the load factor).
    Vector<double>
    residual(const Vector<double> &x, const double lambda_fixed)
    {
      evaluate(x, lambda_fixed, false);
      return R;
    }

    /// The residual and the Jacobian at x.
    void
    linearise(const Vector<double> &x,
              const double          lambda_fixed,
              Vector<double>       &r,
              FullMatrix<double>   &J)
    {
      evaluate(x, lambda_fixed, true);
      r = R;
      J = jacobian;
    }

    /// The jumps of the unknowns at the last evaluation.
    const Vector<double> &
    jumps() const
    {
      return g;
    }

  private:
    const CohesiveNewton &newton;
    const CohesiveZone   &zone;
    const Step           &step;
    const bool            path;
    const double          k0, scale;
    /// The jumps without multipliers (per unit load factor under path
    /// following).
    Vector<double>     g_fixed, g, R;
    FullMatrix<double> jacobian;

    /// The separation (normal, tangential) of the jumps (gn, gt).
    static CohesiveZone::Separation
    separation(const double gn, const double gt)
    {
      return {{-gn, -gt}};
    }

    /// The secant stiffness k0 (1 - d) of node a at the jumps (gn, gt)
    /// (with @p loading, of the law's loading branch).
    double
    stiffness(const unsigned int a,
              const double       gn,
              const double       gt,
              const bool         loading = false) const
    {
      return k0 * (1. - zone.node_state(a, separation(gn, gt), loading).damage);
    }

    /// What the control's row measures at node a (its dissipation, or its
    /// equivalent separation for the control node).
    double
    control_measure(const unsigned int a,
                    const double       gn,
                    const double       gt,
                    const bool         loading = false) const
    {
      if (step.control == Control::dissipation)
        return zone.node_dissipation(
          a, zone.node_state(a, separation(gn, gt), loading));
      const double dn = std::max(-gn, 0.);
      return std::sqrt(dn * dn + gt * gt);
    }

    /// Central differences of f(gn, gt, loading) in gn and gt, on the
    /// loading branch where node a loads (a node at its committed history,
    /// as every node of the process zone at a step's start, takes the
    /// loading branch's slope, not the mean of it and the unloading one).
    template <typename F>
    std::array<double, 2>
    gradient(const F           &f,
             const unsigned int a,
             const double       gn,
             const double       gt) const
    {
      const bool   loading = zone.loads(a, separation(gn, gt));
      const double h = 1e-6 * std::max({std::abs(gn), std::abs(gt), 1e-300});
      return {{(f(gn + h, gt, loading) - f(gn - h, gt, loading)) / (2 * h),
               (f(gn, gt + h, loading) - f(gn, gt - h, loading)) / (2 * h)}};
    }

    /// Row r of the Jacobian += factor times the derivative of g_q.
    void
    add_jump_derivative(const unsigned int r,
                        const unsigned int q,
                        const double       factor)
    {
      const unsigned int n = newton.size();
      for (unsigned int j = 0; j < n; ++j)
        jacobian(r, j) -= factor * newton.A(q, j);
      if (path)
        jacobian(r, n) += factor * g_fixed(q);
    }

    void
    evaluate(const Vector<double> &x, const double lambda_fixed, bool linear)
    {
      const unsigned int n      = newton.size();
      const double       lambda = path ? x(n) : lambda_fixed;
      Vector<double>     mu(n), Amu(n);
      for (unsigned int r = 0; r < n; ++r)
        mu(r) = x(r);
      newton.A.vmult(Amu, mu);
      g = g_fixed;
      g *= path ? lambda : 1.;
      g -= Amu;
      R.reinit(size());
      if (linear)
        jacobian.reinit(size(), size());
      for (unsigned int r = 0; r < n; ++r)
        row(r, mu, linear);
      if (path)
        control_row(linear);
    }

    void
    row(const unsigned int r, const Vector<double> &mu, const bool linear)
    {
      switch (newton.roles[r])
        {
          case Role::glued:
            R(r) = k0 * g(r) / scale;
            if (linear)
              add_jump_derivative(r, r, k0 / scale);
            return;
          case Role::contact:
            if (mu(r) <= -k0 * g(r))
              {
                R(r) = mu(r) / scale;
                if (linear)
                  jacobian(r, r) += 1 / scale;
              }
            else
              {
                R(r) = -k0 * g(r) / scale;
                if (linear)
                  add_jump_derivative(r, r, -k0 / scale);
              }
            return;
          default:
            zone_row(r, mu, linear);
        }
    }

    /// A row of a zone's node: mu_t - k g_t, or min(mu_n - k g_n, -k0 g_n).
    void
    zone_row(const unsigned int r, const Vector<double> &mu, const bool linear)
    {
      const unsigned int a  = newton.nodes[r];
      const unsigned int rt = newton.node_unknowns[a][Layout::tangential];
      const unsigned int rn = newton.node_unknowns[a][Layout::normal];
      const double       gn = g(rn), gt = g(rt);
      const double       k = stiffness(a, gn, gt);
      const double       y = mu(r) - k * g(r);
      if (newton.roles[r] == Role::zone_normal && !(y <= -k0 * gn))
        {
          R(r) = -k0 * gn / scale;
          if (linear)
            add_jump_derivative(r, rn, -k0 / scale);
          return;
        }
      R(r) = y / scale;
      if (!linear)
        return;
      const auto dk = gradient(
        [&](const double n, const double t, const bool loading) {
          return stiffness(a, n, t, loading);
        },
        a,
        gn,
        gt);
      jacobian(r, r) += 1 / scale;
      add_jump_derivative(r, r, -k / scale);
      add_jump_derivative(r, rn, -g(r) * dk[0] / scale);
      add_jump_derivative(r, rt, -g(r) * dk[1] / scale);
    }

    /// The control's row: the dissipation less its target, or the control
    /// node's equivalent separation less its committed history and the
    /// increment, relative to the target.
    void
    control_row(const bool linear)
    {
      const unsigned int n      = newton.size();
      double             value  = 0;
      double             target = step.target;
      const auto         node   = [&](const unsigned int a) {
        const int rt = newton.node_unknowns[a][Layout::tangential];
        const int rn = newton.node_unknowns[a][Layout::normal];
        if (rt < 0 || rn < 0)
          return;
        const double gn = g(rn), gt = g(rt);
        value += control_measure(a, gn, gt);
        if (!linear)
          return;
        const auto d = gradient(
          [&](const double p, const double q, const bool loading) {
            return control_measure(a, p, q, loading);
          },
          a,
          gn,
          gt);
        add_jump_derivative(n, rn, d[0] / target);
        add_jump_derivative(n, rt, d[1] / target);
      };
      if (step.control == Control::dissipation)
        for (unsigned int a = 0; a < newton.node_unknowns.size(); ++a)
          node(a);
      else
        {
          node(step.control_node);
          value -= zone.committed_history_of(step.control_node);
        }
      R(n) = (value - target) / target;
    }
  };


  CohesiveNewton::Result
  CohesiveNewton::solve(const CohesiveZone        &zone,
                        const BlockVector<double> &g0,
                        const BlockVector<double> &mu0,
                        const double               lambda0,
                        const Step                &step,
                        const unsigned int         max_iterations,
                        const double               tolerance) const
  {
    const unsigned int n    = size();
    const bool         path = step.control != Control::load_factor;
    Result             result;
    double             scale = 0;
    for (unsigned int r = 0; r < n; ++r)
      scale = std::max(scale, std::abs(mu0(unknowns[r])));
    if (!(scale > 0) || !(lambda0 != 0) || (path && !(step.target > 0)) ||
        (step.control == Control::separation && step.control_node < 0))
      return result;
    Evaluation     equations(*this, zone, g0, lambda0, step, scale);
    Vector<double> x(equations.size()), r, dx;
    for (unsigned int k = 0; k < n; ++k)
      x(k) = mu0(unknowns[k]);
    if (path)
      x(n) = lambda0;
    FullMatrix<double>       J;
    LAPACKFullMatrix<double> lu;
    unsigned int             non_monotone = 0;
    for (result.iterations = 0;; ++result.iterations)
      {
        equations.linearise(x, lambda0, r, J);
        result.residual = r.linfty_norm();
        if (!std::isfinite(result.residual))
          return result;
        if (result.residual <= tolerance)
          {
            result.converged = true;
            break;
          }
        if (result.iterations >= max_iterations)
          return result;
        lu.reinit(J.m());
        lu = J;
        dx = r;
        try
          {
            lu.compute_lu_factorization();
            lu.solve(dx);
          }
        catch (const ExceptionBase &)
          {
            // (A singular Jacobian: the secant iteration goes on alone.)
            return result;
          }
        if (!std::isfinite(dx.linfty_norm()))
          return result;
        // Backtracking on |R|^2: the best of the halved steps where none
        // decreases it enough.
        const double   merit = r.norm_sqr();
        double         best  = std::numeric_limits<double>::infinity();
        Vector<double> best_x;
        for (double length = 1; length > 1e-3; length /= 2)
          {
            Vector<double> trial = x;
            trial.add(-length, dx);
            const double m = equations.residual(trial, lambda0).norm_sqr();
            if (m < best)
              {
                best   = m;
                best_x = trial;
              }
            if (m <= (1 - 1e-4 * length) * merit)
              break;
          }
        // (No decrease along the direction: a kink of the law between the
        // iterate and the solution; the full step, a few times per solve.)
        if (!(best < merit))
          {
            if (++non_monotone > 5)
              return result;
            x.add(-1., dx);
            continue;
          }
        x = best_x;
      }
    // The state of the solution: every component's multiplier, the zone's
    // separations.
    result.lambda = path ? x(n) : lambda0;
    equations.residual(x, lambda0);
    const Vector<double> &g = equations.jumps();
    // (An open contact component, and a broken node's open or sliding
    // one, carry no multiplier: exactly zero, as the outer solver's
    // bounds hold them, not the round-off of the solve.)
    const double k0 = zone.initial_stiffness();
    result.mu.reinit(mu0);
    for (unsigned int k = 0; k < n; ++k)
      {
        bool zero = false;
        if (roles[k] == Role::contact)
          zero = x(k) <= -k0 * g(k);
        else if (roles[k] != Role::glued)
          {
            const unsigned int a  = nodes[k];
            const double       gn = g(node_unknowns[a][Layout::normal]);
            const double       gt = g(node_unknowns[a][Layout::tangential]);
            const bool broken = zone.node_state(a, {{-gn, -gt}}).damage >= 1;
            zero =
              broken && (roles[k] == Role::zone_tangential || x(k) <= -k0 * gn);
          }
        result.mu(unknowns[k]) = zero ? 0. : x(k);
      }
    result.delta.assign(zone.n_block_nodes(), {{0., 0.}});
    for (unsigned int a = 0; a < node_unknowns.size(); ++a)
      if (node_unknowns[a][0] >= 0)
        result.delta[a] = {{-g(node_unknowns[a][Layout::normal]),
                            -g(node_unknowns[a][Layout::tangential])}};
    return result;
  }
} // namespace bilayer
