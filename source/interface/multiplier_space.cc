#include <deal.II/base/quadrature_lib.h>
#include <deal.II/lac/vector.h>

#include <bilayer/interface/multiplier_space.h>

#include <algorithm>
#include <cmath>

namespace bilayer
{
  using namespace dealii;

  std::vector<double>
  merge_breakpoints(const std::vector<double> &a,
                    const std::vector<double> &b,
                    const double               tol)
  {
    std::vector<double> all(a);
    all.insert(all.end(), b.begin(), b.end());
    std::sort(all.begin(), all.end());
    std::vector<double> merged;
    for (const double x : all)
      if (merged.empty() || x - merged.back() > tol)
        merged.push_back(x);
    return merged;
  }


  namespace
  {
    /// The mesh of a block across an interface with the traces @p t0
    /// (below) and @p t1 (above): per macro segment between shared points,
    /// the trace with more (coarser trace: fewer) segments, the one below
    /// on a tie.
    std::vector<double>
    across_mesh(const std::vector<double> &t0,
                const std::vector<double> &t1,
                const MultiplierMesh       rule,
                const double               tol)
    {
      std::vector<double> mesh;
      if (!t0.empty() && !t1.empty())
        {
          mesh.push_back(t0.front());
          std::size_t i = 0, j = 0;
          while (i + 1 < t0.size() && j + 1 < t1.size())
            {
              // The next shared point: t0[i1] = t1[j1].
              std::size_t i1 = i + 1, j1 = j + 1;
              while (std::abs(t0[i1] - t1[j1]) > tol &&
                     !(i1 + 1 == t0.size() && j1 + 1 == t1.size()))
                if ((t0[i1] < t1[j1] && i1 + 1 < t0.size()) ||
                    j1 + 1 == t1.size())
                  ++i1;
                else
                  ++j1;
              const std::size_t n0 = i1 - i, n1 = j1 - j;
              const bool        plus =
                rule == MultiplierMesh::finer_trace ? n1 > n0 : n1 < n0;
              if (plus)
                mesh.insert(mesh.end(),
                            t1.begin() + j + 1,
                            t1.begin() + j1 + 1);
              else
                mesh.insert(mesh.end(),
                            t0.begin() + i + 1,
                            t0.begin() + i1 + 1);
              i = i1;
              j = j1;
            }
        }
      return mesh;
    }
  } // namespace


  PerBlock<MultiplierSpace::BlockChoice>
  MultiplierSpace::choose(const Topology                     &topology,
                          const std::vector<InterfaceTraces> &traces,
                          const std::vector<unsigned int>    &degrees,
                          const MultiplierMesh                rule,
                          const double                        tol)
  {
    PerBlock<BlockChoice> choice(topology.n_blocks());
    for (const unsigned int b : Layout::indices(choice.size()))
      {
        const Coupling c = topology.coupling(b);
        if (c.kind == Coupling::Kind::across)
          // Layer 1 across interface i, degree p1.
          choice[b] = {across_mesh(traces[c.interface][0],
                                   traces[c.interface][1],
                                   rule,
                                   tol),
                       degrees[0]};
        else
          // The gluing of layer k to layer k - 1 on a region: the layers
          // share the region's mesh, so its trace on Sigma, with the smaller
          // of the two degrees.
          choice[b] = {
            traces[c.interface][topology.side(c.interface, c.region)],
            std::min(
              degrees[static_cast<unsigned int>(topology.layer(c.first))],
              degrees[static_cast<unsigned int>(topology.layer(c.second))])};
      }
    return choice;
  }


  namespace
  {
    /// The dual basis on the unit segment of the element @p fe of degree
    /// @p degree: diag(int phi_i) M^{-1}.
    void
    compute_dual_basis(const FE_Q<1>      &fe,
                       const unsigned int  degree,
                       FullMatrix<double> &dual)
    {
      const unsigned int q1 = degree + 1;
      const QGauss<1>    gauss(q1);
      FullMatrix<double> mass(q1, q1), inverse(q1, q1);
      Vector<double>     integral(q1);
      for (unsigned int q = 0; q < gauss.size(); ++q)
        for (unsigned int i = 0; i < q1; ++i)
          {
            const double phi_i = fe.shape_value(i, gauss.point(q));
            integral(i) += phi_i * gauss.weight(q);
            for (unsigned int k = 0; k < q1; ++k)
              mass(i, k) +=
                phi_i * fe.shape_value(k, gauss.point(q)) * gauss.weight(q);
          }
      inverse.invert(mass);
      dual.reinit(q1, q1);
      for (unsigned int i = 0; i < q1; ++i)
        for (unsigned int k = 0; k < q1; ++k)
          dual(i, k) = integral(i) * inverse(i, k);
    }


    /// Whether the coordinate @p s is an end of its interface @p curve on
    /// Gamma_D for the coupling @p c, whose region lies on side @p side.
    bool
    end_on_gamma_d(const InterfaceCurve &curve,
                   const double          s,
                   const Coupling       &c,
                   const unsigned int    side)
    {
      // For the gluing across Sigma where both sides' end nodes are clamped,
      // for the gluing of the layers on one subdomain where that subdomain's
      // end node is clamped. Where only one side of Sigma is clamped the end
      // keeps its multiplier: its row couples the free dof of the other side
      // to the prescribed value.
      return c.kind == Coupling::Kind::across ? curve.on_gamma_d(s) :
                                                curve.on_gamma_d(s, side);
    }


    /// The sets of a union-find over the elements 0 ... n - 1.
    class Connections
    {
    public:
      explicit Connections(const unsigned int n)
        : parent(n)
      {
        for (unsigned int i = 0; i < n; ++i)
          parent[i] = i;
      }
      unsigned int
      find(unsigned int i)
      {
        while (parent[i] != i)
          i = parent[i] = parent[parent[i]];
        return i;
      }
      /// Join the sets of @p i and @p j; false if they were one.
      bool
      join(const unsigned int i, const unsigned int j)
      {
        const unsigned int a = find(i), b = find(j);
        parent[a] = b;
        return a != b;
      }

    private:
      std::vector<unsigned int> parent;
    };
  } // namespace


  void
  MultiplierSpace::reinit(const Topology                     &topology,
                          const std::vector<InterfaceCurve>  &curves,
                          const ContactParameters            &contact,
                          const std::vector<InterfaceTraces> &traces,
                          const std::vector<unsigned int>    &degrees,
                          const PerBlock<bool>               &active)
  {
    topology_        = topology;
    const double tol = curves[0].tolerance();

    // The meshes: the slave's trace of each block, Gauss-Lobatto nodes of
    // the block's degree on each segment.
    const PerBlock<BlockChoice> choice =
      choose(topology, traces, degrees, contact.mesh, tol);
    meshes.resize(choice.size());
    for (const unsigned int b : Layout::indices(choice.size()))
      {
        Mesh &mesh  = meshes[b];
        mesh.degree = choice[b].degree;
        if (!mesh.fe || mesh.fe->degree != mesh.degree)
          mesh.fe =
            std::make_shared<FE_Q<1>>(QGaussLobatto<1>(mesh.degree + 1));
        // Without layer 2 the blocks that glue the layers have no nodes.
        if (active[b])
          mesh.breakpoints = choice[b].breakpoints;
        else
          mesh.breakpoints.clear();
        place_nodes(b, curves[topology.coupling(b).interface]);
        find_nodal_sides(b, traces, degrees, tol);
        compute_dual_basis(*mesh.fe, mesh.degree, mesh.dual);
      }

    drop_cross_point_ends(curves);
    build_set(curves, contact);
    crack_set = set_;
    join_end_rows(curves);
  }


  bool
  MultiplierSpace::end_removed(const unsigned int    a,
                               const unsigned int    b,
                               const InterfaceCurve &curve) const
  {
    const Coupling c = topology_.coupling(b);
    return (a == 0 && dropped_ends[b][0]) ||
           (a + 1 == n_nodes(b) && dropped_ends[b][1]) ||
           end_on_gamma_d(curve,
                          meshes[b].node_x[a],
                          c,
                          topology_.side(c.interface, c.region));
  }


  void
  MultiplierSpace::drop_cross_point_ends(
    const std::vector<InterfaceCurve> &curves)
  {
    dropped_ends.assign(meshes.size(), {{false, false}});
    // The ends of the blocks with nodes, and their points.
    struct End
    {
      unsigned int b, k;
      Point<2>     point;
    };
    std::vector<End> ends;
    for (const unsigned int b : Layout::indices(meshes.size()))
      if (n_nodes(b) > 0)
        for (const unsigned int k : {0u, 1u})
          ends.push_back(
            {b,
             k,
             curves[topology_.coupling(b).interface].point(
               k == 0 ? meshes[b].node_x.front() : meshes[b].node_x.back())});
    const double      tol = curves[0].tolerance();
    std::vector<bool> seen(ends.size(), false);
    for (unsigned int e = 0; e < ends.size(); ++e)
      {
        if (seen[e])
          continue;
        // The ends at the point of end e, in block order.
        std::vector<unsigned int> here;
        std::vector<unsigned int> interfaces;
        for (unsigned int f = e; f < ends.size(); ++f)
          if (!seen[f] && ends[f].point.distance(ends[e].point) <= tol)
            {
              seen[f] = true;
              here.push_back(f);
              const unsigned int i = topology_.coupling(ends[f].b).interface;
              if (std::count(interfaces.begin(), interfaces.end(), i) == 0)
                interfaces.push_back(i);
            }
        if (interfaces.size() < 2)
          continue;
        // The copies of the point: one per subproblem, and Gamma_D (the
        // last element).
        const unsigned int ground = topology_.n_subproblems();
        Connections        connected(ground + 1);
        for (const unsigned int f : here)
          {
            const unsigned int i = topology_.coupling(ends[f].b).interface;
            const double s = ends[f].k == 0 ? meshes[ends[f].b].node_x.front() :
                                              meshes[ends[f].b].node_x.back();
            for (const unsigned int side : {0u, 1u})
              if (curves[i].on_gamma_d(s, side))
                for (const unsigned int l :
                     Layout::indices(topology_.n_slots()))
                  connected.join(ground,
                                 topology_.index(static_cast<Layer>(l),
                                                 topology_.regions_of(
                                                   i)[side]));
          }
        // A block whose traces both lie in its multiplier space ties the
        // point's copies (its rows there are nodal jumps, or a mass matrix
        // times them): where the nodal blocks before it or Gamma_D connect
        // its two subproblems, its end is implied exactly. A mortar block (a
        // side not nodal) ties weighted means near the point; around a
        // cycle these are dependent too, through the traces' higher modes
        // (seen with layers of degrees 2 and 1 at a T-joint), and its end's
        // basis function joins its neighbour's, as at Gamma_D (the mortar
        // modification at cross-points: join_end_rows()). So the nodal
        // blocks come first, and a cycle is broken at a mortar block where
        // it has one.
        for (const bool nodal_pass : {true, false})
          for (const unsigned int f : here)
            {
              const unsigned int b = ends[f].b;
              const unsigned int a = ends[f].k == 0 ? 0 : n_nodes(b) - 1;
              if ((meshes[b].nodal[0] && meshes[b].nodal[1]) != nodal_pass ||
                  end_removed(a, b, curves[topology_.coupling(b).interface]))
                continue;
              const Coupling c = topology_.coupling(b);
              if (!connected.join(c.first, c.second))
                dropped_ends[b][ends[f].k] = true;
            }
      }
  }


  void
  MultiplierSpace::place_nodes(const unsigned int    b,
                               const InterfaceCurve &curve)
  {
    Mesh                  &mesh = meshes[b];
    const QGaussLobatto<1> lobatto(mesh.degree + 1);
    const unsigned int     n_segments =
      mesh.breakpoints.empty() ? 0 : mesh.breakpoints.size() - 1;
    const unsigned int n = n_segments > 0 ? n_segments * mesh.degree + 1 : 0;
    mesh.node_x.assign(n, 0.);
    mesh.node_weight.assign(n, 0.);
    mesh.normal.assign(n, Tensor<1, 2>());
    for (unsigned int e = 0; e < n_segments; ++e)
      {
        const double h = mesh.breakpoints[e + 1] - mesh.breakpoints[e];
        // The segment's chord turned by +90 degrees: its normal times
        // its length.
        const Tensor<1, 2> chord = curve.point(mesh.breakpoints[e + 1]) -
                                   curve.point(mesh.breakpoints[e]);
        const Tensor<1, 2> chord_normal({-chord[1], chord[0]});
        for (unsigned int i = 0; i <= mesh.degree; ++i)
          {
            const unsigned int a = node(e, i, b);
            mesh.node_x[a]       = mesh.breakpoints[e] +
                             mesh.fe->get_unit_support_points()[i][0] * h;
            double integral = 0;
            for (unsigned int q = 0; q < lobatto.size(); ++q)
              {
                const double phi_w =
                  mesh.fe->shape_value(i, lobatto.point(q)) * lobatto.weight(q);
                mesh.node_weight[a] += phi_w * h;
                integral += phi_w;
              }
            mesh.normal[a] += integral * chord_normal;
          }
      }
    // Weighted nodal normals: int phi_a nu_h ds over the chords of the
    // multiplier mesh, normalised.
    for (auto &normal : mesh.normal)
      normal = unit_vector(normal);
    mesh.frame.resize(n);
    for (unsigned int a = 0; a < n; ++a)
      mesh.frame[a] = {{tangent_of(mesh.normal[a]), mesh.normal[a]}};
    mesh.node_mass = mesh.node_weight;
    mesh.row.resize(n);
    for (unsigned int a = 0; a < n; ++a)
      mesh.row[a] = a;
  }


  void
  MultiplierSpace::find_nodal_sides(const unsigned int                  b,
                                    const std::vector<InterfaceTraces> &traces,
                                    const std::vector<unsigned int>    &degrees,
                                    const double                        tol)
  {
    Mesh              &mesh = meshes[b];
    const unsigned int n    = mesh.node_x.size();
    // Which coupled traces lie in the multiplier space.
    const Coupling c = topology_.coupling(b);
    for (unsigned int j = 0; j < 2; ++j)
      {
        const unsigned int s = j == 0 ? c.first : c.second;
        const auto        &trace =
          traces[c.interface][topology_.side(c.interface, topology_.region(s))];
        const unsigned int degree_s =
          degrees[static_cast<unsigned int>(topology_.layer(s))];
        bool        inside = degree_s <= mesh.degree;
        std::size_t k      = 0;
        for (const double x : trace)
          {
            while (k < mesh.breakpoints.size() && mesh.breakpoints[k] < x - tol)
              ++k;
            inside = inside && k < mesh.breakpoints.size() &&
                     std::abs(mesh.breakpoints[k] - x) <= tol;
          }
        mesh.nodal[j] = inside || n == 0;
      }
  }


  void
  MultiplierSpace::build_set(const std::vector<InterfaceCurve> &curves,
                             const ContactParameters           &contact)
  {
    // The multiplier set (docs/problem.md §3), per component.
    const double p   = contact.multiplier_bound;
    multiplier_bound = p;
    std::vector<types::global_dof_index> sizes;
    for (const auto &mesh : meshes)
      sizes.push_back(Layout::n_components * mesh.node_x.size());
    set_.reinit(sizes);
    crack_nodes.resize(meshes.size());
    corner_nodes.resize(meshes.size());
    for (const unsigned int b : Layout::indices(meshes.size()))
      {
        crack_nodes[b].assign(n_nodes(b), false);
        corner_nodes[b].assign(n_nodes(b), false);
      }
    for (const unsigned int b : Layout::indices(meshes.size()))
      for (unsigned int a = 0; a < meshes[b].node_x.size(); ++a)
        {
          const Coupling        coupling = topology_.coupling(b);
          const InterfaceCurve &curve    = curves[coupling.interface];
          const double          x        = meshes[b].node_x[a];
          const bool across   = coupling.kind == Coupling::Kind::across;
          const bool on_crack = across && curve.crack().contains(x);
          crack_nodes[b][a]   = on_crack;
          if (end_removed(a, b, curve))
            continue;
          for (unsigned int c = 0; c < Layout::n_components; ++c)
            set_.set_glued(b, Layout::entry(a, c), p);
          if (on_crack)
            {
              const unsigned int t = Layout::entry(a, Layout::tangential),
                                 n = Layout::entry(a, Layout::normal);
              set_.set_none(b, t);
              if (contact.non_penetration)
                set_.set_contact(b, n, p);
              else
                set_.set_none(b, n);
              if (contact.friction == Friction::tresca)
                {
                  const Point<2>    point   = curve.point(x);
                  const double      g       = contact.tresca_bound(point, x);
                  const std::string refusal = friction_bound_refusal(g, point);
                  AssertThrow(refusal.empty(), ExcMessage(refusal));
                  if (g > 0)
                    set_.set_friction(b, t, std::min(g, p));
                }
              // A corner of Sigma: one contact constraint per piece, along
              // its normal (the mean normal would let the node slide
              // through the other face).
              Tensor<1, 2> before, after;
              if (curve.corner(x, before, after))
                {
                  corner_nodes[b][a] = true;
                  meshes[b].frame[a] = {{before, after}};
                  if (contact.non_penetration)
                    set_.set_contact(b, t, p);
                }
              else if (contact.friction == Friction::coulomb &&
                       contact.coulomb_method == CoulombMethod::direct &&
                       contact.friction_coefficient > 0)
                set_.set_cone(b, t, n, contact.friction_coefficient, p);
            }
        }
  }


  void
  MultiplierSpace::join_end_rows(const std::vector<InterfaceCurve> &curves)
  {
    // The mortar modification at the ends on Gamma_D of blocks with a side
    // that is not nodal: the end's basis function joins the other vertex of
    // its segment.
    for (const unsigned int b : Layout::indices(meshes.size()))
      {
        Mesh              &mesh = meshes[b];
        const unsigned int n    = mesh.node_x.size();
        if (n == 0 || (mesh.nodal[0] && mesh.nodal[1]))
          continue;
        for (const auto &[end, neighbour] :
             {std::make_pair(0u, mesh.degree),
              std::make_pair(n - 1, n - 1 - mesh.degree)})
          if (end_removed(end, b, curves[topology_.coupling(b).interface]))
            {
              mesh.row[end] = neighbour;
              mesh.node_weight[neighbour] += mesh.node_mass[end];
            }
      }
  }


  void
  MultiplierSpace::restrict_to_free(BlockVector<double> &x) const
  {
    for (unsigned int i = 0; i < x.size(); ++i)
      if (!free(i))
        x(i) = 0;
  }


  unsigned int
  MultiplierSpace::n_free() const
  {
    unsigned int count = 0;
    for (unsigned int i = 0; i < set_.size(); ++i)
      count += free(i);
    return count;
  }


  double
  MultiplierSpace::weighted_dot(const BlockVector<double> &x,
                                const BlockVector<double> &y) const
  {
    double sum = 0;
    for (unsigned int b = 0; b < x.n_blocks(); ++b)
      for (unsigned int i = 0; i < x.block(b).size(); ++i)
        sum += meshes[b].node_weight[i / Layout::n_components] * x.block(b)(i) *
               y.block(b)(i);
    return sum;
  }


  void
  MultiplierSpace::scale_by_weights(BlockVector<double> &x,
                                    const bool           inverse) const
  {
    for (unsigned int b = 0; b < x.n_blocks(); ++b)
      for (unsigned int i = 0; i < x.block(b).size(); ++i)
        {
          const double d = meshes[b].node_weight[i / Layout::n_components];
          x.block(b)(i)  = inverse ? x.block(b)(i) / d : x.block(b)(i) * d;
        }
  }


  double
  MultiplierSpace::discrete_violation(const BlockVector<double> &g,
                                      const BlockVector<double> &mu) const
  {
    double violation = 0;
    for (unsigned int i = 0; i < g.size(); ++i)
      violation = std::max(violation, set_.violation(i, g(i), mu(i)));
    return violation;
  }


  void
  MultiplierSpace::set_friction_bounds(const std::vector<double> &bounds,
                                       const unsigned int         b)
  {
    AssertThrow(bounds.size() == n_nodes(b),
                ExcMessage("MultiplierSpace::set_friction_bounds: one bound "
                           "per node of the block is needed"));
    for (unsigned int a = 0; a < n_nodes(b); ++a)
      if (friction_node(a, b) &&
          set_.free(b, Layout::entry(a, Layout::normal)) &&
          !set_.cohesive(b, Layout::entry(a, Layout::tangential)))
        {
          const unsigned int t = Layout::entry(a, Layout::tangential);
          const double       g = std::min(bounds[a], multiplier_bound);
          if (g > 0)
            set_.set_friction(b, t, g);
          else
            set_.set_none(b, t);
        }
  }


  unsigned int
  MultiplierSpace::shape_values(const unsigned int   b,
                                const double         x,
                                std::vector<double> &values) const
  {
    const auto        &bp = meshes[b].breakpoints;
    const auto         it = std::upper_bound(bp.begin() + 1, bp.end() - 1, x);
    const unsigned int e  = (it - bp.begin()) - 1;
    const double       t  = (x - bp[e]) / (bp[e + 1] - bp[e]);
    values.resize(meshes[b].degree + 1);
    for (unsigned int i = 0; i <= meshes[b].degree; ++i)
      values[i] = meshes[b].fe->shape_value(i, Point<1>(t));
    return e;
  }


  unsigned int
  MultiplierSpace::shape_values(const unsigned int   b,
                                const double         x,
                                std::vector<double> &values,
                                std::vector<double> &derivatives) const
  {
    const unsigned int e  = shape_values(b, x, values);
    const auto        &bp = meshes[b].breakpoints;
    const double       h  = bp[e + 1] - bp[e];
    const double       t  = (x - bp[e]) / h;
    derivatives.resize(values.size());
    for (unsigned int i = 0; i < values.size(); ++i)
      derivatives[i] = meshes[b].fe->shape_grad(i, Point<1>(t))[0] / h;
    return e;
  }


  unsigned int
  MultiplierSpace::dual_shape_values(const unsigned int   b,
                                     const double         x,
                                     std::vector<double> &values) const
  {
    std::vector<double> phi;
    const unsigned int  e = shape_values(b, x, phi);
    values.assign(phi.size(), 0.);
    for (unsigned int i = 0; i < phi.size(); ++i)
      for (unsigned int k = 0; k < phi.size(); ++k)
        values[i] += meshes[b].dual(i, k) * phi[k];
    return e;
  }


  double
  MultiplierSpace::value(const BlockVector<double> &mu,
                         const unsigned int         b,
                         const double               x,
                         const unsigned int         c) const
  {
    if (meshes[b].node_x.empty())
      return 0.;
    std::vector<double> values;
    const unsigned int  e      = shape_values(b, x, values);
    double              result = 0;
    for (unsigned int i = 0; i <= degree(b); ++i)
      result +=
        values[i] * mu.block(b)(Layout::entry(row(node(e, i, b), b), c));
    return result;
  }


  MultiplierSpace::Functions
  MultiplierSpace::functions(const BlockVector<double> &mu) const
  {
    Functions f;
    f.degree.resize(meshes.size());
    f.breakpoints.resize(meshes.size());
    for (const unsigned int b : Layout::indices(meshes.size()))
      {
        f.degree[b]      = meshes[b].degree;
        f.breakpoints[b] = meshes[b].breakpoints;
      }
    f.values = mu;
    return f;
  }


  void
  MultiplierSpace::interpolate(const Functions     &old,
                               BlockVector<double> &mu) const
  {
    initialize(mu);
    if (old.values.n_blocks() != meshes.size())
      return;
    for (const unsigned int b : Layout::indices(meshes.size()))
      if (!meshes[b].node_x.empty() && old.breakpoints[b].size() >= 2)
        {
          const FE_Q<1> fe_old(QGaussLobatto<1>(old.degree[b] + 1));
          const auto   &bp = old.breakpoints[b];
          for (unsigned int a = 0; a < meshes[b].node_x.size(); ++a)
            {
              const double x = meshes[b].node_x[a];
              const auto it = std::upper_bound(bp.begin() + 1, bp.end() - 1, x);
              const unsigned int e = (it - bp.begin()) - 1;
              const double       t = (x - bp[e]) / (bp[e + 1] - bp[e]);
              for (unsigned int i = 0; i <= old.degree[b]; ++i)
                {
                  const double v = fe_old.shape_value(i, Point<1>(t));
                  for (unsigned int c = 0; c < Layout::n_components; ++c)
                    mu.block(b)(Layout::entry(a, c)) +=
                      v * old.values.block(b)(
                            Layout::entry(node_of(old.degree[b], e, i), c));
                }
            }
        }
    project(mu);
  }
} // namespace bilayer
