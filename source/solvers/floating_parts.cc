#include <deal.II/base/bounding_box.h>
#include <deal.II/base/quadrature_lib.h>
#include <deal.II/base/timer.h>
#include <deal.II/dofs/dof_tools.h>
#include <deal.II/fe/fe_values.h>
#include <deal.II/grid/grid_tools.h>
#include <deal.II/lac/lapack_full_matrix.h>

#include <bilayer/core/layout.h>
#include <bilayer/solvers/floating_parts.h>

#include <algorithm>
#include <cmath>
#include <sstream>

namespace bilayer
{
  using namespace dealii;

  namespace
  {
    /// The relative tolerance of the coarse matrices' held-set solves: a
    /// Newton step with the matrix gains about this factor while the held
    /// set holds.
    constexpr double coarse_tolerance = 1e-7;

    Subproblems
    const_views(const PerSubproblem<ElasticSubproblem *> &subproblems)
    {
      Subproblems views(subproblems.size(), nullptr);
      for (unsigned int s = 0; s < subproblems.size(); ++s)
        views[s] = subproblems[s];
      return views;
    }

    std::string
    number(const double x)
    {
      std::ostringstream s;
      s.precision(3);
      s << x;
      return s.str();
    }

    /**
     * The search along a Newton step of the anchors that gained too little
     * (the held set changed along it; r is piecewise affine, the gradient
     * of a convex function of the anchors' displacements): phi(t) =
     * r(t) . r_0 / |r_0| is bracketed by t_a (phi > 0; 0 at first) and t_b
     * (phi < 0, once found), and the next t is the secant in the bracket
     * (Illinois), kept a tenth inside it.
     */
    class LineSearch
    {
    public:
      LineSearch(const std::vector<double> &r0, const double norm)
        : r0(r0)
        , norm(norm)
        , phi_a(norm)
      {}

      /// The next t after the reactions @p r at @p t; negative where
      /// there is no bracket yet (phi > 0 all along).
      double
      next(const double t, const std::vector<double> &r)
      {
        double phi = 0;
        for (unsigned int u = 0; u < r.size(); ++u)
          phi += r[u] * r0[u];
        phi /= norm;
        if (phi < 0)
          {
            if (t_b >= 0 && phi_b < 0)
              phi_a /= 2;
            t_b   = t;
            phi_b = phi;
          }
        else
          {
            if (t_b >= 0)
              phi_b /= 2;
            t_a   = t;
            phi_a = phi;
          }
        if (t_b < 0)
          return -1;
        const double width = t_b - t_a;
        return std::clamp(t_a + phi_a * width / (phi_a - phi_b),
                          t_a + 0.1 * width,
                          t_b - 0.1 * width);
      }

    private:
      std::vector<double> r0;
      double              norm;
      double              phi_a = 0, t_a = 0, t_b = -1, phi_b = 0;
    };
  } // namespace


  FloatingParts::FloatingParts(
    const PerSubproblem<ElasticSubproblem *> &subproblems,
    const Interface                          &interface)
    : targets(subproblems)
    , subproblems(const_views(subproblems))
    , interface(interface)
  {
    unsigned int present = 0;
    for (unsigned int s = 0; s < subproblems.size(); ++s)
      if (subproblems[s] != nullptr)
        {
          ++present;
          if (subproblems[s]->floating())
            floating.push_back(s);
        }
    free = !floating.empty() && floating.size() == present;
    // A free specimen keeps the first subproblem's anchors where they are:
    // the rigid motion of the whole, fixed later by normalise().
    for (unsigned int f = free ? 1 : 0; f < floating.size(); ++f)
      for (unsigned int k = 0; k < 3; ++k)
        unknowns.emplace_back(floating[f], k);
  }


  std::vector<std::string>
  FloatingParts::names() const
  {
    std::vector<std::string> result;
    for (const unsigned int s : floating)
      result.push_back(subproblems[s]->name());
    return result;
  }


  Solutions
  FloatingParts::state_loads(const BlockVector<double> &mu) const
  {
    Solutions loads;
    interface.apply(mu, loads);
    loads.resize(subproblems.size());
    for (const unsigned int s : Layout::indices(subproblems.size()))
      if (subproblems[s] != nullptr)
        {
          if (loads[s].size() == subproblems[s]->n_dofs())
            loads[s] += subproblems[s]->load();
          else
            loads[s] = subproblems[s]->load();
        }
    return loads;
  }


  std::vector<double>
  FloatingParts::reactions(
    const std::function<std::array<double, 3>(unsigned int)> &alpha,
    const Solutions                                          &b,
    const bool                                                sigma_only,
    double                                                   &scale) const
  {
    std::vector<double> r;
    scale = 0;
    PerSubproblem<std::array<double, 3>> by_subproblem(subproblems.size());
    for (const unsigned int s : floating)
      {
        if (b[s].size() > 0)
          scale += b[s].l1_norm();
        by_subproblem[s] =
          subproblems[s]->anchor_reactions(alpha(s), b[s], sigma_only);
      }
    for (const auto &[s, k] : unknowns)
      r.push_back(by_subproblem[s][k]);
    return r;
  }


  FloatingParts::Jacobian
  FloatingParts::jacobian(const Solutions           &w,
                          const BlockVector<double> &mu,
                          const bool                 keep_z) const
  {
    Jacobian J;
    // One Dirichlet preconditioner for all columns (the columns share the
    // held set), built once per FloatingParts.
    if (!preconditioner)
      preconditioner =
        std::make_unique<FetiPreconditioner>(DualPreconditioner::dirichlet,
                                             subproblems,
                                             interface);
    Solutions zero(subproblems.size());
    for (const unsigned int s : Layout::indices(subproblems.size()))
      if (subproblems[s] != nullptr)
        zero[s].reinit(subproblems[s]->n_dofs());
    for (const auto &[s, k] : unknowns)
      {
        // The jumps of the anchor's unit motion, held by the multipliers
        // of the held set.
        Solutions shift = zero;
        shift[s]        = subproblems[s]->anchor_mode(k);
        BlockVector<double> offset;
        interface.jumps(shift, offset);
        HeldSetSolution held =
          bilayer::solve_with_held_set(subproblems,
                                       interface,
                                       w,
                                       mu,
                                       zero,
                                       coarse_tolerance,
                                       2000,
                                       &offset,
                                       preconditioner.get(),
                                       keep_z);
        J.subdomain_solves += held.subdomain_solves;
        AssertThrow(held.converged,
                    ExcMessage("the response of the floating subproblem " +
                               subproblems[s]->name() +
                               " to a motion of its anchors did not converge "
                               "in 2000 conjugate-gradient iterations"));
        if (keep_z)
          held.z[s] += shift[s];
        Solutions loads;
        interface.apply(held.nu, loads);
        loads.resize(subproblems.size());
        double scale = 0;
        J.columns.push_back(reactions(
          [&, s = s, k = k](const unsigned int t) {
            std::array<double, 3> alpha = {{0, 0, 0}};
            if (t == s)
              alpha[k] = 1;
            return alpha;
          },
          loads,
          true,
          scale));
        J.nu.push_back(std::move(held.nu));
        if (keep_z)
          J.z.push_back(std::move(held.z));
      }
    return J;
  }


  std::vector<double>
  FloatingParts::newton_step(const Jacobian            &J,
                             const std::vector<double> &r) const
  {
    const unsigned int       n = unknowns.size();
    LAPACKFullMatrix<double> A(n, n);
    for (unsigned int c = 0; c < n; ++c)
      for (unsigned int i = 0; i < n; ++i)
        A(i, c) = J.columns[c][i];
    A.compute_svd();
    const double largest  = A.singular_value(0);
    const double smallest = A.singular_value(n - 1);
    if (!(smallest > 1e-10 * largest))
      {
        // The anchor the null direction moves most names the subproblem.
        const LAPACKFullMatrix<double> &vt    = A.get_svd_vt();
        unsigned int                    worst = 0;
        for (unsigned int c = 1; c < n; ++c)
          if (std::abs(vt(n - 1, c)) > std::abs(vt(n - 1, worst)))
            worst = c;
        AssertThrow(false,
                    ExcMessage(
                      "the rigid motion of subproblem " +
                      subproblems[unknowns[worst].first]->name() +
                      " is held by nothing: it touches no clamped part "
                      "(Geometry/Clamped sides) and neither the glued "
                      "interface nor a closed crack fixes it (the coarse "
                      "matrix of its rigid motions has the singular value " +
                      number(smallest) + ", " + number(smallest / largest) +
                      " of the largest)"));
      }
    const LAPACKFullMatrix<double> &u  = A.get_svd_u();
    const LAPACKFullMatrix<double> &vt = A.get_svd_vt();
    std::vector<double>             step(n, 0.), y(n, 0.);
    for (unsigned int i = 0; i < n; ++i)
      {
        for (unsigned int j = 0; j < n; ++j)
          y[i] -= u(j, i) * r[j];
        y[i] /= A.singular_value(i);
      }
    for (unsigned int c = 0; c < n; ++c)
      for (unsigned int i = 0; i < n; ++i)
        step[c] += vt(i, c) * y[i];
    return step;
  }


  void
  FloatingParts::predict_multipliers(const Jacobian            &J,
                                     const std::vector<double> &step,
                                     BlockVector<double>       &mu) const
  {
    // The multipliers the held set predicts: exact where it holds. Not on
    // a contact multiplier that is zero now (an open crack node, or one at
    // its bound): a coarse matrix carried over from another state would
    // leave a stray value there, which the outer solver may accept as it
    // stands (its residual small) though the node is open.
    const MultiplierSet &set = interface.space().set();
    BlockVector<double>  change;
    set.initialize(change);
    for (unsigned int u = 0; u < unknowns.size(); ++u)
      change.add(step[u], J.nu[u]);
    for (unsigned int i = 0; i < change.size(); ++i)
      if (set.contact(i) && mu(i) == 0)
        change(i) = 0;
    mu += change;
    set.project(mu);
  }


  void
  FloatingParts::move_anchors(const std::vector<double> &step) const
  {
    for (unsigned int u = 0; u < unknowns.size(); ++u)
      {
        ElasticSubproblem    &sub   = *targets[unknowns[u].first];
        std::array<double, 3> alpha = sub.anchor_displacements();
        alpha[unknowns[u].second] += step[u];
        sub.set_anchor_displacements(alpha);
      }
  }


  void
  FloatingParts::check_free_loads(FloatingReport &report) const
  {
    if (!free)
      return;
    // The resultant force and moment about the centre of the bounding box:
    // the work of the load on the rigid motions, each made of the anchor
    // modes (rigid motions with unit anchor values: t^T F = sum_k
    // t(a_k) E_k^T F).
    BoundingBox<2> box;
    bool           first = true;
    for (const unsigned int s : floating)
      {
        const auto b = GridTools::compute_bounding_box(
          subproblems[s]->dof_handler().get_triangulation());
        if (first)
          box = b;
        else
          box.merge_with(b);
        first = false;
      }
    const Point<2> centre = box.center();
    const Point<2> low    = box.get_boundary_points().first,
                   high   = box.get_boundary_points().second;
    double fx = 0, fy = 0, m = 0, magnitude = 0;
    for (const unsigned int s : floating)
      {
        const ElasticSubproblem &sub = *subproblems[s];
        const Vector<double>    &F   = sub.load();
        magnitude += F.l1_norm();
        for (unsigned int k = 0; k < 3; ++k)
          {
            const double work = sub.anchor_mode(k) * F;
            const auto [p, c] = sub.anchor_place(k);
            const double turning =
              c == 0 ? -(p[1] - centre[1]) : p[0] - centre[0];
            (c == 0 ? fx : fy) += work;
            m += turning * work;
          }
      }
    const double diameter  = low.distance(high);
    report.resultant       = {{fx, fy, m}};
    report.load_magnitude  = magnitude;
    const double tolerance = free_specimen_tolerance * magnitude;
    AssertThrow(
      std::abs(fx) <= tolerance && std::abs(fy) <= tolerance &&
        std::abs(m) <= tolerance * std::max(diameter, 1e-300),
      ExcMessage(
        "nothing is clamped (Geometry/Clamped sides is empty): a free "
        "specimen's loads must be in equilibrium, but their resultant force "
        "is (" +
        number(fx) + ", " + number(fy) + ") and their moment about (" +
        number(centre[0]) + ", " + number(centre[1]) + ") is " + number(m) +
        " (" +
        number(std::max({std::abs(fx),
                         std::abs(fy),
                         std::abs(m) / std::max(diameter, 1e-300)}) /
               std::max(magnitude, 1e-300)) +
        " of the loads' magnitude; at most " + number(free_specimen_tolerance) +
        " is accepted): balance the tractions (Loads) or clamp a part"));
  }


  SolverResult
  FloatingParts::balance(const std::function<SolverResult(BlockVector<double> &,
                                                          Solutions &)> &outer,
                         const double              solver_tolerance,
                         const double              acceptance_tolerance,
                         BlockVector<double>      &mu,
                         Solutions                &w,
                         FloatingReport           &report,
                         const ConditionalOStream &pcout) const
  {
    report.free_specimen = free;
    report.subproblems   = names();
    check_free_loads(report);
    const double target =
      std::max(1e-12, floating_balance_target * solver_tolerance);
    // The last outer solve's result, and the work before it.
    SolverResult       earlier;
    SolverResult       last;
    const unsigned int max_outer = 20;
    // The last accepted state's reactions (2-norm and relative size), the
    // Newton step taken from it and the fraction t of it taken, and the
    // search along it.
    double              accepted_relative = 0;
    std::vector<double> step;
    double              t = 0;
    LineSearch          search({}, 1);
    Jacobian            J;
    bool                fresh = false;
    for (unsigned int solve = 0;; ++solve)
      {
        if (solve > 0)
          earlier.add_work(last);
        last = outer(mu, w);
        ++report.outer_solves;
        if (!last.converged || unknowns.empty())
          break;
        double                    scale = 0;
        const std::vector<double> r     = reactions(
          [&](const unsigned int s) {
            return subproblems[s]->anchor_displacements();
          },
          state_loads(mu),
          false,
          scale);
        double largest = 0, norm = 0;
        for (const double x : r)
          {
            largest = std::max(largest, std::abs(x));
            norm += x * x;
          }
        norm                  = std::sqrt(norm);
        const double relative = largest / std::max(scale, 1e-300);
        report.out_of_balance = relative;
        pcout << "    floating parts (" << floating.size()
              << " subproblems): largest anchor reaction " << relative
              << " of the load scale" << std::endl;
        if (relative <= target || scale == 0)
          break;
        if (solve + 1 >= max_outer)
          {
            // No more solves: the outer solver's own accuracy, or an
            // active set that changes from solve to solve.
            if (relative > acceptance_tolerance)
              {
                last.converged = false;
                last.message += "; the anchors of the floating subproblems "
                                "still carry " +
                                number(relative) + " of the load scale after " +
                                std::to_string(max_outer) +
                                " outer solves (Solver/Acceptance "
                                "tolerance = " +
                                number(acceptance_tolerance) + ")";
              }
            break;
          }
        // Too little gain along a step computed with the coarse matrix of
        // its own start: the held set changed along it (r is piecewise
        // affine, the gradient of a convex function of the anchors'
        // displacements). Search the step's line for phi = 0: the secant
        // in the bracket [t_a, t_b] (Illinois), kept a tenth inside it.
        const bool poor = !step.empty() && relative > 0.5 * accepted_relative;
        if (poor && fresh)
          {
            const double t_new = search.next(t, r);
            if (t_new >= 0)
              {
                std::vector<double> move(step.size());
                for (unsigned int u = 0; u < step.size(); ++u)
                  move[u] = (t_new - t) * step[u];
                move_anchors(move);
                t = t_new;
                continue;
              }
            // (No sign change along the step: start again from here.)
          }
        // A new coarse matrix only where the last Newton step gained less
        // than a factor 100 (the held set changed along it): an older one
        // that contracts faster costs fewer outer solves than a new one
        // costs coarse solves. (A step with a matrix carried over that
        // gained too little thus starts again from where it ended, with
        // the matrix computed there.)
        fresh = J.columns.empty() || relative > 0.01 * accepted_relative;
        if (fresh)
          {
            Timer timer;
            J = jacobian(w, mu, false);
            report.coarse_seconds += timer.wall_time();
            report.jacobian_solves += unknowns.size();
            earlier.subdomain_solves += J.subdomain_solves;
          }
        accepted_relative = relative;
        search            = LineSearch(r, norm);
        step              = newton_step(J, r);
        t                 = 1;
        move_anchors(step);
        predict_multipliers(J, step, mu);
      }
    // (The work of every outer solve and coarse matrix in the result; the
    // message is the last outer solve's.)
    last.add_work(earlier);
    if (report.outer_solves > 1)
      last.message += " (the last of " + std::to_string(report.outer_solves) +
                      " outer solves balancing the floating subproblems)";
    report.subdomain_solves = last.subdomain_solves;
    if (free)
      normalise(w, report);
    return last;
  }


  HeldSetSolution
  FloatingParts::solve_with_held_set(const Solutions           &w,
                                     const BlockVector<double> &mu,
                                     const Solutions           &j,
                                     const double               tolerance,
                                     const unsigned int max_iterations) const
  {
    HeldSetSolution result = bilayer::solve_with_held_set(
      subproblems, interface, w, mu, j, tolerance, max_iterations);
    if (unknowns.empty())
      return result;
    // The anchors' reactions under the load j and the multiplier terms,
    // removed by the responses to the anchors' motions.
    Solutions loads;
    interface.apply(result.nu, loads);
    loads.resize(subproblems.size());
    for (const unsigned int s : Layout::indices(subproblems.size()))
      if (subproblems[s] != nullptr)
        {
          if (loads[s].size() == j[s].size())
            loads[s] += j[s];
          else
            loads[s] = j[s];
        }
    double                    scale = 0;
    const std::vector<double> r     = reactions(
      [](const unsigned int) {
        return std::array<double, 3>{{0, 0, 0}};
      },
      loads,
      false,
      scale);
    const Jacobian J = jacobian(w, mu, true);
    result.subdomain_solves += J.subdomain_solves;
    const std::vector<double> delta = newton_step(J, r);
    for (unsigned int u = 0; u < unknowns.size(); ++u)
      {
        result.nu.add(delta[u], J.nu[u]);
        for (const unsigned int s : Layout::indices(subproblems.size()))
          if (subproblems[s] != nullptr)
            result.z[s].add(delta[u], J.z[u][s]);
      }
    return result;
  }


  void
  FloatingParts::normalise(Solutions &w, FloatingReport &report) const
  {
    // The moments of the area and of the displacement, over all
    // subproblems.
    double m0 = 0, mx = 0, my = 0, mxx = 0, myy = 0, ux = 0, uy = 0, rw = 0;
    for (const unsigned int s : floating)
      {
        const ElasticSubproblem    &sub = *subproblems[s];
        const QGauss<2>             quadrature(sub.fe().degree + 1);
        FEValues<2>                 values(sub.mapping(),
                           sub.fe(),
                           quadrature,
                           update_values | update_quadrature_points |
                             update_JxW_values);
        std::vector<Vector<double>> local(quadrature.size(), Vector<double>(2));
        for (const auto &cell : sub.dof_handler().active_cell_iterators())
          {
            values.reinit(cell);
            values.get_function_values(w[s], local);
            for (unsigned int q = 0; q < quadrature.size(); ++q)
              {
                const Point<2> &p  = values.quadrature_point(q);
                const double    dx = values.JxW(q);
                m0 += dx;
                mx += p[0] * dx;
                my += p[1] * dx;
                mxx += p[0] * p[0] * dx;
                myy += p[1] * p[1] * dx;
                ux += local[q](0) * dx;
                uy += local[q](1) * dx;
                rw += (p[0] * local[q](1) - p[1] * local[q](0)) * dx;
              }
          }
      }
    const double xc = mx / m0, yc = my / m0;
    const double a = ux / m0, b = uy / m0;
    const double polar   = mxx + myy - m0 * (xc * xc + yc * yc);
    const double omega   = (rw - xc * uy + yc * ux) / polar;
    report.normalisation = {{a, b, omega}};
    for (const unsigned int s : floating)
      {
        ElasticSubproblem    &sub   = *targets[s];
        std::array<double, 3> alpha = sub.anchor_displacements();
        for (unsigned int k = 0; k < 3; ++k)
          {
            const auto [p, c] = sub.anchor_place(k);
            const double rigid =
              c == 0 ? a - omega * (p[1] - yc) : b + omega * (p[0] - xc);
            alpha[k] -= rigid;
            w[s].add(-rigid, sub.anchor_mode(k));
          }
        sub.set_anchor_displacements(alpha);
      }
  }
} // namespace bilayer
