#include <deal.II/base/quadrature_lib.h>

#include <bilayer/interface/interface.h>
#include <bilayer/interface/interface_diagnostics.h>

#include <algorithm>
#include <cmath>
#include <iomanip>
#include <numeric>
#include <utility>

namespace bilayer
{
  using namespace dealii;

  namespace
  {
    /// The traces of the subproblems on interface @p i at the nodes of the
    /// block across it; without layer 2 its traces are those of layer 1
    /// (no layer gap); empty for the subproblems of other regions.
    PerSubproblem<Vector<double>>
    traces_at_nodes(const Interface   &interface,
                    const Solutions   &w,
                    const unsigned int i)
    {
      PerSubproblem<Vector<double>> t(interface.n_subproblems());
      for (const unsigned int s : Layout::indices(t.size()))
        {
          const unsigned int source =
            interface.present(s) ? s : interface.topology().region(s);
          if (interface.coupling().touches(source, i))
            interface.coupling().trace_at_nodes(source, w[source], t[s], i);
        }
      return t;
    }

    /**
     * The openings [u].nu = (u+ - u-).nu of layer 1 at node @p a of mu_1
     * against the faces that meet there, from the traces @p tm, @p tp in
     * the node's orthonormal frame (TraceCoupling::trace_at_nodes): at a
     * corner of Sigma inside the crack against the normals of the piece
     * before and of the piece after the corner (MultiplierSpace::
     * node_frame), elsewhere the normal opening twice.
     */
    std::array<double, 2>
    face_openings(const MultiplierSpace &space,
                  const Vector<double>  &tm,
                  const Vector<double>  &tp,
                  const unsigned int     a,
                  const unsigned int     b)
    {
      const unsigned int x = Layout::entry(a, Layout::tangential),
                         y = Layout::entry(a, Layout::normal);
      if (!space.corner(a, b))
        return {{tp(y) - tm(y), tp(y) - tm(y)}};
      const Tensor<1, 2> &n = space.node_normal(a, b);
      const Tensor<1, 2>  jump =
        (tp(x) - tm(x)) * tangent_of(n) + (tp(y) - tm(y)) * n;
      const auto &frame = space.node_frame(a, b);
      return {{jump * frame[0], jump * frame[1]}};
    }
  } // namespace


  double
  displacement_scale(const Interface &interface, const Solutions &w)
  {
    double         scale = 0;
    Vector<double> trace;
    for (const unsigned int i : Layout::indices(interface.n_interfaces()))
      for (const unsigned int s : Layout::indices(interface.n_subproblems()))
        if (interface.coupling().touches(s, i))
          {
            interface.coupling().trace_at_nodes(s, w[s], trace, i);
            scale = std::max(scale, trace.linfty_norm());
          }
    return scale;
  }


  namespace
  {
    /// The friction parts of @p report (InterfaceReport) at the multipliers
    /// @p mu with jumps @p g.
    void
    add_friction_report(const Interface           &interface,
                        const BlockVector<double> &g,
                        const BlockVector<double> &mu,
                        InterfaceReport           &report)
    {
      const MultiplierSpace &space = interface.space();
      double                 sum_g = 0, gap = 0;
      for (const unsigned int mu_1 : Layout::indices(interface.n_interfaces()))
        for (unsigned int a = 0; a < space.n_nodes(mu_1); ++a)
          {
            // (A Coulomb cone at an open node has the bound 0: free.)
            const double bound = space.friction_bound(a, mu_1);
            if (bound == 0)
              continue;
            const unsigned int t = Layout::entry(a, Layout::tangential);
            const double       d = space.node_weight(a, mu_1);
            const double       m = mu.block(mu_1)(t), jump = g.block(mu_1)(t);
            sum_g += d * bound;
            gap += d * (bound * std::abs(jump) - m * jump);
            report.friction_dissipation += d * m * jump;
            report.max_slip = std::max(report.max_slip, std::abs(jump));
            if (friction_state(bound, m) == FrictionState::slip)
              ++report.slip_nodes;
            else
              ++report.stick_nodes;
          }
      const double scale = report.displacement_scale;
      report.friction_complementarity =
        sum_g > 0 && scale > 0 ? gap / (sum_g * scale) : 0.;
    }
  } // namespace


  KKTResidual
  kkt_residual(const Interface           &interface,
               const Solutions           &w,
               const BlockVector<double> &g,
               const BlockVector<double> &mu)
  {
    const MultiplierSpace &space = interface.space();
    const MultiplierSet   &set   = space.set();
    KKTResidual            kkt;
    const double           scale = displacement_scale(interface, w);
    // A multiplier held at a bound of its box by a jump that pushes it
    // outward is optimal there (mu = P(mu + theta g)): its jump is no
    // residual. Only the bound p can hold a constraint violated this way.
    BlockVector<double> free_g(g);
    for (unsigned int i = 0; i < mu.size(); ++i)
      if (set.held_at_bound(i, mu(i), g(i)))
        free_g(i) = 0;
    kkt.primal = scale > 0 ? space.discrete_violation(free_g, mu) / scale :
                             space.discrete_violation(free_g, mu);
    const double mu_scale = mu.linfty_norm();
    if (mu_scale > 0)
      for (unsigned int i = 0; i < mu.size(); ++i)
        if (set.contact(i) && set.below_bound(i, mu(i)))
          {
            kkt.dual = std::max(kkt.dual, -mu(i) / mu_scale);
            if (scale > 0)
              kkt.complementarity =
                std::max(kkt.complementarity,
                         std::abs(mu(i) * g(i)) / (mu_scale * scale));
          }
    return kkt;
  }


  std::vector<double>
  normal_opening(const Interface   &interface,
                 const Solutions   &w,
                 const unsigned int i)
  {
    Vector<double> tm, tp;
    interface.coupling().crack_face_traces(w, tm, tp, i);
    std::vector<double> result(interface.space().n_nodes(i));
    for (unsigned int a = 0; a < interface.space().n_nodes(i); ++a)
      {
        const auto open = face_openings(interface.space(), tm, tp, a, i);
        result[a]       = std::min(open[0], open[1]);
      }
    return result;
  }


  namespace
  {
    /// The integral (12) and the pointwise penetration at the Gauss points
    /// of each interface into @p report, the integral of the traces' size
    /// into @p size. Without layer 2 its traces are those of layer 1 (no
    /// layer gap).
    void
    add_constraint_violation(const Interface &interface,
                             const Solutions &w,
                             InterfaceReport &report,
                             double          &size)
    {
      const MultiplierSpace   &space    = interface.space();
      const TraceCoupling     &coupling = interface.coupling();
      const ContactParameters &contact  = interface.contact_parameters();
      const Topology          &topology = interface.topology();
      for (const unsigned int i : Layout::indices(interface.n_interfaces()))
        {
          PerSubproblem<Vector<double>> t(interface.n_subproblems());
          for (const unsigned int s : Layout::indices(t.size()))
            {
              const unsigned int source =
                interface.present(s) ? s : topology.region(s);
              if (coupling.touches(source, i))
                coupling.trace_at_gauss_points(source, w[source], t[s], i);
            }
          const Coupling  across = topology.coupling(i);
          const CrackSet &crack  = interface.curve(i).crack();
          const auto     &x      = coupling.gauss_points(i);
          const auto     &wq     = coupling.gauss_weights(i);
          for (unsigned int q = 0; q < x.size(); ++q)
            {
              const bool on_crack = crack.contains(x[q]);
              double     density  = 0;
              for (unsigned int c = 0; c < Layout::n_components; ++c)
                {
                  const unsigned int k = Layout::entry(q, c);
                  const double       jump_1 =
                    t[across.first](k) - t[across.second](k);
                  if (!on_crack)
                    density += std::abs(jump_1);
                  else if (c == Layout::normal)
                    {
                      report.max_penetration =
                        std::max(report.max_penetration, jump_1);
                      if (contact.non_penetration)
                        density += std::max(jump_1, 0.);
                    }
                  // The gluing of the layers on each side (lambda-, lambda+,
                  // and the gluing of layer k to layer k - 1), along Sigma.
                  for (unsigned int b = interface.n_interfaces();
                       b < interface.n_blocks();
                       ++b)
                    if (topology.coupling(b).interface == i)
                      density += std::abs(t[topology.coupling(b).first](k) -
                                          t[topology.coupling(b).second](k));
                  for (const unsigned int s : Layout::indices(t.size()))
                    if (coupling.touches(s, i))
                      size += wq[q] * std::abs(t[s](k));
                }
              report.constraint_violation += wq[q] * density;
            }
          // Penetration at the crack nodes as well (the Gauss points miss
          // them).
          const std::vector<double> open = normal_opening(interface, w, i);
          for (unsigned int a = 0; a < space.n_nodes(i); ++a)
            if (space.on_crack(a, i))
              report.max_penetration =
                std::max(report.max_penetration, -open[a]);
        }
    }
  } // namespace


  InterfaceReport
  assess(const Interface           &interface,
         const Solutions           &w,
         const BlockVector<double> &mu)
  {
    const MultiplierSpace   &space    = interface.space();
    const TraceCoupling     &coupling = interface.coupling();
    const ContactParameters &contact  = interface.contact_parameters();
    const Topology          &topology = interface.topology();
    InterfaceReport          report;
    BlockVector<double>      g;
    interface.jumps(w, g);
    // (The jumps less the cohesive springs': the residual of their law.)
    interface.space().add_cohesive_jumps(mu, g);
    const double scale        = displacement_scale(interface, w);
    report.displacement_scale = scale;
    const double violation    = space.discrete_violation(g, mu);
    report.relative_discrete_violation =
      scale > 0 ? violation / scale : violation;

    // The nodes without multipliers off the crack: their nodal jumps are
    // fixed by the Dirichlet data alone, or by the blocks that tie a
    // cross-point, and must vanish (an end dropped from the constraints
    // while one side's node is free would leave a jump here).
    {
      BlockVector<double> nodal;
      space.initialize(nodal);
      coupling.differences(w, false, nodal);
      double largest = 0;
      for (const unsigned int b : Layout::indices(interface.n_blocks()))
        if (interface.active(b))
          for (unsigned int i = 0; i < nodal.block(b).size(); ++i)
            {
              const unsigned int a       = i / Layout::n_components;
              const bool         carries = space.set().free(b, i);
              // (A mortar block's end removed at a cross-point: its jump
              // is a discretisation error, as between its nodes.)
              const bool mortar_end = space.cross_point_end(a, b) &&
                                      !(space.nodal(b, 0) && space.nodal(b, 1));
              if (!carries && !mortar_end &&
                  !(topology.across(b) && space.on_crack(a, b)))
                largest = std::max(largest, std::abs(nodal.block(b)(i)));
            }
      report.relative_jump_without_multiplier =
        scale > 0 ? largest / scale : largest;
    }

    // Contact multipliers: the normal component of mu_1 at crack nodes,
    // both components at a crack corner.
    double sum_mu = 0, sum_mu_jump = 0;
    bool   any = false;
    for (const unsigned int mu_1 : Layout::indices(interface.n_interfaces()))
      for (unsigned int a = 0; a < space.n_nodes(mu_1); ++a)
        for (const unsigned int c : space.contact_components(a, mu_1))
          {
            const unsigned int n = Layout::entry(a, c);
            if (space.set().contact(mu_1, n))
              {
                const double m = mu.block(mu_1)(n);
                report.min_contact_multiplier =
                  any ? std::min(report.min_contact_multiplier, m) : m;
                any            = true;
                const double d = space.node_weight(a, mu_1);
                sum_mu += d * m;
                sum_mu_jump += d * m * std::abs(g.block(mu_1)(n));
              }
          }
    report.complementarity =
      sum_mu > 0 && scale > 0 ? sum_mu_jump / (sum_mu * scale) : 0.;
    add_friction_report(interface, g, mu, report);
    report.max_multiplier_over_bound =
      mu.linfty_norm() / contact.multiplier_bound;
    report.kkt = kkt_residual(interface, w, g, mu);

    double size = 0;
    add_constraint_violation(interface, w, report, size);
    report.relative_constraint_violation =
      size > 0 ? report.constraint_violation / size :
                 report.constraint_violation;
    return report;
  }


  std::vector<ContactSegment>
  contact_residual(const Interface           &interface,
                   const Solutions           &w,
                   const BlockVector<double> &mu,
                   const unsigned int         i)
  {
    std::vector<ContactSegment> result;
    if (!interface.contact_parameters().non_penetration)
      return result;
    const MultiplierSpace &space  = interface.space();
    const unsigned int     degree = space.degree(i);
    Vector<double>         tm, tp;
    interface.coupling().crack_face_traces(w, tm, tp, i);
    // Normal jump and contact multiplier at node a (the traces' components
    // are in the node's frame (tangent, normal)); at a crack corner the
    // pair of the constraint of the segment's own piece: component
    // @p side (0 for the segment before the corner, 1 after).
    const auto gap = [&](const unsigned int a, const unsigned int side) {
      return face_openings(space, tm, tp, a, i)[side];
    };
    const auto mu_c = [&](const unsigned int a, const unsigned int side) {
      return space.corner(a, i) ? mu.block(i)(Layout::entry(a, side)) :
                                  space.contact_multiplier(mu, a, i);
    };
    const auto &bp = space.breakpoints(i);
    // Degree >= 3: Gauss quadrature exact for the product of the two
    // interpolants (degree 2 * degree), shape values of the multiplier
    // element at its points.
    const QGauss<1>                  gauss(degree + 1);
    std::vector<std::vector<double>> shape(gauss.size());
    if (degree >= 3 && bp.size() >= 2)
      for (unsigned int q = 0; q < gauss.size(); ++q)
        space.shape_values(i,
                           bp[0] + gauss.point(q)[0] * (bp[1] - bp[0]),
                           shape[q]);
    for (unsigned int e = 0; e + 1 < bp.size(); ++e)
      {
        const unsigned int a0 = space.node(e, 0, i), a1 = space.node(e, 1, i);
        if (!space.on_crack(a0, i) && !space.on_crack(a1, i))
          continue;
        const double h   = bp[e + 1] - bp[e];
        double       sum = 0;
        if (degree <= 2)
          {
            // Simpson's rule; midpoint values: the middle node for degree
            // 2, the mean for degree 1 (then it is exact for the product).
            // a0 is the segment's start (side 1 of a corner there), a1 its
            // end (side 0).
            const double g0 = gap(a0, 1), g1 = gap(a1, 0), m0 = mu_c(a0, 1),
                         m1 = mu_c(a1, 0);
            const double g_m =
              degree == 2 ? gap(space.node(e, 2, i), 0) : 0.5 * (g0 + g1);
            const double mu_m =
              degree == 2 ? mu_c(space.node(e, 2, i), 0) : 0.5 * (m0 + m1);
            sum = h / 6 * (m0 * g0 + 4 * mu_m * g_m + m1 * g1);
          }
        else
          for (unsigned int q = 0; q < gauss.size(); ++q)
            {
              double g_q = 0, mu_q = 0;
              for (unsigned int k = 0; k <= degree; ++k)
                {
                  const unsigned int side = k == 0 ? 1 : 0;
                  g_q += shape[q][k] * gap(space.node(e, k, i), side);
                  mu_q += shape[q][k] * mu_c(space.node(e, k, i), side);
                }
              sum += gauss.weight(q) * h * mu_q * g_q;
            }
        result.push_back({bp[e], bp[e + 1], sum});
      }
    return result;
  }


  std::vector<unsigned int>
  trace_subproblems(const Topology &topology, const unsigned int i)
  {
    if (topology.n_regions() == Layout::n_subdomains)
      {
        std::vector<unsigned int> all;
        for (const unsigned int s : Layout::indices(topology.n_subproblems()))
          all.push_back(s);
        return all;
      }
    // Each layer's regions below and above interface i.
    std::vector<unsigned int> reported;
    for (const unsigned int l : Layout::indices(topology.n_slots()))
      for (const unsigned int r : topology.regions_of(i))
        reported.push_back(topology.index(static_cast<Layer>(l), r));
    return reported;
  }


  std::vector<InterfaceNode>
  interface_nodes(const Interface           &interface,
                  const Solutions           &w,
                  const BlockVector<double> &mu,
                  const double               closed_tolerance,
                  const unsigned int         i)
  {
    const MultiplierSpace &space    = interface.space();
    const Topology        &topology = interface.topology();
    // Without layer 2 its traces repeat layer 1 (gaps and mu+- zero).
    const PerSubproblem<Vector<double>> t  = traces_at_nodes(interface, w, i);
    const double                    scale  = displacement_scale(interface, w);
    const Coupling                  across = topology.coupling(i);
    const unsigned int              below = across.first, above = across.second;
    const std::vector<unsigned int> reported = trace_subproblems(topology, i);
    // Layer 2 glued to layer 1 along interface i on each side (its slot
    // absent on a one-layer scene of two regions: zero multipliers, its
    // traces those of layer 1).
    const bool                 layered = topology.n_slots() > 1;
    std::vector<InterfaceNode> nodes(space.n_nodes(i));
    for (unsigned int a = 0; a < nodes.size(); ++a)
      {
        InterfaceNode     &n = nodes[a];
        const unsigned int x = Layout::entry(a, Layout::tangential),
                           y = Layout::entry(a, Layout::normal);
        n.s                  = space.node_position(a, i);
        n.point              = interface.curve(i).point(n.s);
        n.normal             = space.node_normal(a, i);
        n.on_crack           = space.on_crack(a, i);
        n.jump_normal        = t[above](y) - t[below](y);
        n.jump_tangential    = t[above](x) - t[below](x);
        n.mu_c               = space.contact_multiplier(mu, a, i);
        for (const unsigned int c : {Layout::tangential, Layout::normal})
          {
            n.mu_g[c] = space.gluing_multiplier(mu, a, c, i);
            if (layered)
              {
                const auto &regions = topology.regions_of(i);
                n.mu_minus[c] =
                  space.value(mu,
                              topology.glue_block(Layer::second, regions[0], i),
                              n.s,
                              c);
                n.mu_plus[c] =
                  space.value(mu,
                              topology.glue_block(Layer::second, regions[1], i),
                              n.s,
                              c);
              }
          }
        // Layer 1 against layer 2 on each side.
        if (layered)
          for (const unsigned int side : {0u, 1u})
            {
              const unsigned int r = topology.regions_of(i)[side],
                                 u = topology.index(Layer::first, r),
                                 v = topology.index(Layer::second, r);
              n.layer_gap[side] =
                Tensor<1, 2>({t[u](x) - t[v](x), t[u](y) - t[v](y)});
            }
        for (const unsigned int s : reported)
          n.trace.push_back(Tensor<1, 2>({t[s](x), t[s](y)}));
        n.normal_traction = n.on_crack ? n.mu_c : n.mu_g[Layout::normal];
        n.frictional      = interface.contact_parameters().frictional();
        if (n.on_crack)
          {
            const double m     = mu.block(i)(x);
            n.friction_bound   = space.friction_bound(a, i);
            n.tangential_force = n.friction_bound > 0 ? -m : 0.;
            n.friction_state   = friction_state(n.friction_bound, m);
          }
        // The smallest opening against the faces that meet at the node.
        const auto   open    = face_openings(space, t[below], t[above], a, i);
        const double opening = std::min(open[0], open[1]);
        n.state              = !n.on_crack ? ContactState::glued :
                               (n.mu_c > 0 || opening <= closed_tolerance * scale) ?
                                             ContactState::closed :
                                             ContactState::open;
      }
    // Crack tips: glued nodes next to a crack node along Sigma.
    std::vector<unsigned int> order(nodes.size());
    std::iota(order.begin(), order.end(), 0u);
    std::sort(order.begin(), order.end(), [&](const auto a, const auto b) {
      return nodes[a].s < nodes[b].s;
    });
    for (unsigned int i = 0; i < order.size(); ++i)
      {
        InterfaceNode &n = nodes[order[i]];
        n.crack_tip      = !n.on_crack &&
                      ((i > 0 && nodes[order[i - 1]].on_crack) ||
                       (i + 1 < order.size() && nodes[order[i + 1]].on_crack));
        n.contact_pressure = n.on_crack  ? n.mu_c :
                             n.crack_tip ? std::max(n.normal_traction, 0.) :
                                           0.;
      }
    return nodes;
  }


  void
  write_interface_csv(std::ostream                     &out,
                      const std::vector<InterfaceNode> &nodes,
                      const std::vector<std::string>   &trace_names,
                      const std::vector<std::string>   &notes)
  {
    for (const std::string &note : notes)
      out << "# " << note << '\n';
    // The traces of every subproblem reported: u_minus, u_plus, v_minus,
    // v_plus and, with more layers, w3_minus, ...
    out << "x,on_crack,jump_normal,jump_tangential,mu_c,mu_g_x,mu_g_y,"
           "mu_minus_x,mu_minus_y,mu_plus_x,mu_plus_y,gap_minus_x,"
           "gap_minus_y,gap_plus_x,gap_plus_y";
    for (const std::string &name : trace_names)
      out << ',' << name << "_x," << name << "_y";
    out << ",s,y,normal_x,normal_y,contact_pressure,normal_traction,state";
    const bool frictional = !nodes.empty() && nodes.front().frictional;
    const bool cohesive   = !nodes.empty() && nodes.front().cohesive;
    out << (frictional ? ",tangential_force,friction_bound,friction_state" : "")
        << (cohesive ? ",damage\n" : "\n");
    out << std::setprecision(12);
    for (const InterfaceNode &n : nodes)
      {
        out << n.point[0] << ',' << (n.on_crack ? 1 : 0) << ',' << n.jump_normal
            << ',' << n.jump_tangential << ',' << n.mu_c << ',' << n.mu_g[0]
            << ',' << n.mu_g[1];
        for (const Tensor<1, 2> &m : {n.mu_minus, n.mu_plus})
          out << ',' << m[0] << ',' << m[1];
        // Layer 1 against layer 2 on each side.
        for (const Tensor<1, 2> &gap : n.layer_gap)
          out << ',' << gap[0] << ',' << gap[1];
        for (const unsigned int s : Layout::indices(n.trace.size()))
          out << ',' << n.trace[s][0] << ',' << n.trace[s][1];
        // (+ 0. turns a negative zero into a positive one.)
        out << ',' << n.s << ',' << n.point[1] << ',' << n.normal[0] + 0. << ','
            << n.normal[1] + 0. << ',' << n.contact_pressure << ','
            << n.normal_traction << ',' << static_cast<int>(n.state);
        if (frictional)
          out << ',' << n.tangential_force + 0. << ',' << n.friction_bound
              << ',' << static_cast<int>(n.friction_state);
        if (cohesive)
          out << ',' << n.damage;
        out << '\n';
      }
  }
} // namespace bilayer
