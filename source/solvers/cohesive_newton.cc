// The semismooth Newton method of a cohesive step on the interface alone
// (docs/cohesive.md, "The Newton method").

#include <deal.II/lac/lapack_full_matrix.h>
#include <deal.II/lac/lapack_templates.h>

#include <bilayer/core/layout.h>
#include <bilayer/solvers/cohesive_newton.h>

#include <algorithm>
#include <cmath>
#include <limits>

namespace bilayer
{
  using namespace dealii;

  std::string
  CohesiveNewton::unsupported(const bool frictional, const bool prescribed)
  {
    if (prescribed)
      return "prescribed load factors (a softening zone has several "
             "equilibria at one load factor; the secant iteration follows "
             "the path's)";
    if (frictional)
      return "friction on the crack faces (the secant iteration with the "
             "outer solver takes it)";
    return "";
  }


  CohesiveNewton::CohesiveNewton(const Subproblems  &subproblems,
                                 const Interface    &interface,
                                 const CohesiveZone &zone)
  {
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
    // (In batches of 64 columns: the condensed subproblems solve each
    // batch at once.)
    const unsigned int n = unknowns.size();
    A.reinit(n, n);
    std::vector<BlockVector<double>> units;
    std::vector<Solutions>           w;
    BlockVector<double>              g;
    for (unsigned int first = 0; first < n; first += 64)
      {
        const unsigned int last = std::min(n, first + 64);
        units.assign(last - first, mu);
        for (unsigned int j = first; j < last; ++j)
          units[j - first](unknowns[j]) = 1;
        solve_homogeneous_subproblems(subproblems, interface, units, w);
        for (unsigned int j = first; j < last; ++j)
          {
            interface.jumps(w[j - first], g, true);
            for (unsigned int r = 0; r < n; ++r)
              A(r, j) = -g(unknowns[r]);
            for (const auto *s : subproblems)
              n_solves += s != nullptr;
          }
      }
  }


  /**
   * The residual and the rows of the Jacobian of the step's equations at an
   * iterate (mu, lambda): the unknowns' rows scaled by the kept scale of
   * the multipliers, the control's row by its target.
   */
  class CohesiveNewton::Evaluation
  {
  public:
    Evaluation(const CohesiveNewton &newton,
               const CohesiveZone   &zone,
               const Vector<double> &g_fixed,
               const Step           &step,
               const double          scale)
      : newton(newton)
      , zone(zone)
      , step(step)
      , path(step.control != Control::load_factor)
      , k0(zone.initial_stiffness())
      , scale(scale)
      , g_fixed(g_fixed)
    {}

    /// The number of unknowns: the multipliers, and the load factor
    /// under path following.
    unsigned int
    size() const
    {
      return newton.size() + (path ? 1 : 0);
    }

    /// The residual at x (the multipliers, then the load factor); with
    /// @p linear the rows of the Jacobian too. With @p given, A mu is that
    /// (the line search's iterates: A mu - t A dmu), else it is computed.
    const Vector<double> &
    evaluate(const Vector<double> &x,
             const bool            linear,
             const Vector<double> *given = nullptr)
    {
      const unsigned int n = newton.size();
      Vector<double>     mu(n);
      for (unsigned int r = 0; r < n; ++r)
        mu(r) = x(r);
      if (given != nullptr)
        Amu = *given;
      else
        newton.multiply(mu, Amu);
      g = g_fixed;
      if (path)
        g *= x(n);
      g -= Amu;
      R.reinit(size());
      rows.assign(n, Row());
      for (unsigned int r = 0; r < n; ++r)
        row(r, mu);
      if (path)
        control_row(linear);
      return R;
    }

    /// The jumps of the unknowns at the last evaluation, and A mu there.
    const Vector<double> &
    jumps() const
    {
      return g;
    }
    const Vector<double> &
    products() const
    {
      return Amu;
    }

    /// The rows of the Jacobian at the last evaluation.
    const std::vector<Row> &
    jacobian_rows() const
    {
      return rows;
    }

    /// The control's row of the Jacobian (dense; empty without path
    /// following).
    const Vector<double> &
    jacobian_control_row() const
    {
      return control;
    }

  private:
    const CohesiveNewton &newton;
    const CohesiveZone   &zone;
    const Step           &step;
    const bool            path;
    const double          k0, scale;
    /// The jumps without multipliers (per unit load factor under path
    /// following).
    const Vector<double> &g_fixed;
    Vector<double>        g, R, control, Amu;
    std::vector<Row>      rows;

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

    /// Whether min(a, b) of row r takes its first argument: a <= b, or
    /// at a tie (within 1e-9 of the scale: a far node's traction at
    /// round-off, whose sign is noise) the branch of the kept Jacobian's
    /// row (both are derivatives of the min there), so that the row stays
    /// the kept one.
    bool
    first_branch(const unsigned int r, const double a, const double b) const
    {
      if (std::abs(a - b) <= 1e-9 * scale && r < newton.kept.rows.size())
        return newton.kept.rows[r].unit != 0;
      return a <= b;
    }

    /// Adds factor times the derivative of g_q to row r.
    void
    add_term(const unsigned int r, const unsigned int q, const double factor)
    {
      Row &row                  = rows[r];
      row.q[row.n_terms]        = q;
      row.factor[row.n_terms++] = factor;
    }

    void
    row(const unsigned int r, const Vector<double> &mu)
    {
      switch (newton.roles[r])
        {
          case Role::glued:
            R(r) = k0 * g(r) / scale;
            add_term(r, r, k0 / scale);
            return;
          case Role::contact:
            if (first_branch(r, mu(r), -k0 * g(r)))
              {
                R(r)         = mu(r) / scale;
                rows[r].unit = 1 / scale;
              }
            else
              {
                R(r) = -k0 * g(r) / scale;
                add_term(r, r, -k0 / scale);
              }
            return;
          default:
            zone_row(r, mu);
        }
    }

    /// A row of a zone's node: mu_t - k g_t, or min(mu_n - k g_n, -k0 g_n).
    void
    zone_row(const unsigned int r, const Vector<double> &mu)
    {
      const unsigned int a  = newton.nodes[r];
      const unsigned int rt = newton.node_unknowns[a][Layout::tangential];
      const unsigned int rn = newton.node_unknowns[a][Layout::normal];
      const double       gn = g(rn), gt = g(rt);
      const double       k = stiffness(a, gn, gt);
      const double       y = mu(r) - k * g(r);
      if (newton.roles[r] == Role::zone_normal && !first_branch(r, y, -k0 * gn))
        {
          R(r) = -k0 * gn / scale;
          add_term(r, rn, -k0 / scale);
          return;
        }
      R(r)          = y / scale;
      const auto dk = gradient(
        [&](const double n, const double t, const bool loading) {
          return stiffness(a, n, t, loading);
        },
        a,
        gn,
        gt);
      rows[r].unit = 1 / scale;
      add_term(r, r, -k / scale);
      // (Zero terms left out: an intact or unloading node's row stays the
      // one kept.)
      if (dk[0] != 0 || dk[1] != 0)
        {
          add_term(r, rn, -g(r) * dk[0] / scale);
          add_term(r, rt, -g(r) * dk[1] / scale);
        }
    }

    /// The control's row: the dissipation less its target, or the control
    /// node's equivalent separation less its committed history and the
    /// increment, relative to the target.
    void
    control_row(const bool linear)
    {
      const unsigned int n      = newton.size();
      double             value  = 0;
      const double       target = step.target;
      if (linear)
        control.reinit(n + 1);
      Vector<double> values;
      const auto     node = [&](const unsigned int a) {
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
        if (d[0] == 0 && d[1] == 0)
          return;
        Row row;
        row.n_terms = 2;
        row.q       = {
                {static_cast<unsigned int>(rn), static_cast<unsigned int>(rt), 0}};
        row.factor = {{d[0] / target, d[1] / target, 0.}};
        newton.materialise(n, row, g_fixed, values);
        control += values;
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


  void
  CohesiveNewton::predict(const CohesiveZone &zone,
                          const Step         &step,
                          Evaluation         &equations,
                          Vector<double>     &x) const
  {
    const double increment = step.control == Control::dissipation ?
                               step.target - zone.committed_dissipation() :
                               step.target;
    // (A step taken again with a smaller increment starts where it did.)
    if (kept.start.size() != x.size() || kept.start != x)
      {
        kept.start_before     = kept.start;
        kept.increment_before = kept.increment;
        kept.start            = x;
      }
    kept.increment = increment;
    if (kept.start_before.size() != x.size() || !(kept.increment_before > 0))
      return;
    // The last step's solution extrapolated by this step's increment.
    const double   ratio = increment / kept.increment_before;
    Vector<double> guess = x;
    guess.add(ratio, x, -ratio, kept.start_before);
    const double at_guess = equations.evaluate(guess, false).norm_sqr();
    if (at_guess < equations.evaluate(x, false).norm_sqr())
      x = guess;
  }


  double
  CohesiveNewton::line_search(Evaluation           &equations,
                              const Vector<double> &x,
                              const Vector<double> &dx,
                              const Vector<double> &Ax,
                              const Vector<double> &r,
                              const bool            damped,
                              Vector<double>       &Adx) const
  {
    const unsigned int n = size();
    Vector<double>     dmu(n);
    // Backtracking on |R|^2: the best of the halved steps where none
    // decreases it enough.
    // (A is linear: A (mu - t dmu) = A mu - t A dmu, one product.)
    for (unsigned int k = 0; k < n; ++k)
      dmu(k) = dx(k);
    multiply(dmu, Adx);
    const double   merit       = r.norm_sqr();
    double         best        = std::numeric_limits<double>::infinity();
    double         best_length = 1;
    Vector<double> trial, Atrial;
    for (double length = 1; length > 1e-3; length /= 2)
      {
        trial = x;
        trial.add(-length, dx);
        Atrial = Ax;
        Atrial.add(-length, Adx);
        const double m = equations.evaluate(trial, false, &Atrial).norm_sqr();
        if (m < best)
          {
            best        = m;
            best_length = length;
          }
        // (Undamped, the full step unless its residual is not finite or
        // grows a hundred million times.)
        if (m <= (1 - 1e-4 * length) * merit ||
            (!damped && length == 1 && m <= 1e8 * merit))
          return length;
      }
    return best < merit ? best_length : 0.;
  }


  void
  CohesiveNewton::solution_state(const CohesiveZone        &zone,
                                 const Vector<double>      &g,
                                 const Vector<double>      &x,
                                 const BlockVector<double> &mu0,
                                 Result                    &result) const
  {
    const unsigned int n = size();
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
  }


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
    double             largest = 0;
    for (unsigned int r = 0; r < n; ++r)
      largest = std::max(largest, std::abs(mu0(unknowns[r])));
    if (!(largest > 0) || !(lambda0 != 0) || (path && !(step.target > 0)) ||
        (step.control == Control::separation && step.control_node < 0))
      return result;
    // (The rows' scale is kept with the factorisation: a row that does not
    // change keeps its bits.)
    if (!(kept.row_scale > 0))
      kept.row_scale = largest;
    Vector<double> &g_fixed = g_unit;
    g_fixed.reinit(n);
    for (unsigned int r = 0; r < n; ++r)
      g_fixed(r) = g0(unknowns[r]) / (path ? lambda0 : 1.);
    Evaluation     equations(*this, zone, g_fixed, step, kept.row_scale);
    Vector<double> x(equations.size());
    for (unsigned int k = 0; k < n; ++k)
      x(k) = mu0(unknowns[k]);
    if (path)
      {
        x(n) = lambda0;
        predict(zone, step, equations, x);
      }
    unsigned int   non_monotone = 0;
    Vector<double> Ax, Adx(n);
    for (result.iterations = 0;; ++result.iterations)
      {
        // (A mu carried along the steps, computed afresh every tenth.)
        const Vector<double> r =
          equations.evaluate(x,
                             true,
                             result.iterations % 10 == 0 ? nullptr : &Ax);
        Ax = equations.products();
        // (Relative to the present multipliers' scale.)
        double now = 0;
        for (unsigned int k = 0; k < n; ++k)
          now = std::max(now, std::abs(x(k)));
        result.residual = 0;
        for (unsigned int k = 0; k < r.size(); ++k)
          result.residual =
            std::max(result.residual,
                     std::abs(r(k)) * (k < n ? kept.row_scale / now : 1.));
        if (!std::isfinite(result.residual))
          return result;
        if (result.residual <= tolerance)
          {
            result.converged = true;
            break;
          }
        if (result.iterations >= max_iterations)
          return result;
        Vector<double> dx;
        try
          {
            dx = direction(equations.jacobian_rows(),
                           equations.jacobian_control_row(),
                           r);
          }
        catch (const ExceptionBase &)
          {
            // (A singular Jacobian: the secant iteration goes on alone.)
            kept.lu.reset();
            return result;
          }
        if (!std::isfinite(dx.linfty_norm()))
          {
            kept.lu.reset();
            return result;
          }
        // (Pure semismooth Newton steps first: across the law's kinks the
        // residual's norm is a poor guide, and damped steps crawl; after
        // 30 iterations, damped ones.)
        double best_length =
          line_search(equations, x, dx, Ax, r, result.iterations >= 30, Adx);
        // (No decrease along the direction: a kink of the law between the
        // iterate and the solution; the full step, a few times per solve.)
        if (!(best_length > 0))
          {
            if (++non_monotone > 5)
              return result;
            best_length = 1;
          }
        x.add(-best_length, dx);
        Ax.add(-best_length, Adx);
      }
    // The state of the solution: every component's multiplier, the zone's
    // separations.
    result.lambda = path ? x(n) : lambda0;
    equations.evaluate(x, false);
    solution_state(zone, equations.jumps(), x, mu0, result);
    return result;
  }
} // namespace bilayer
