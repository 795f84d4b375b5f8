#include <deal.II/base/quadrature_lib.h>

#include <bilayer/multiplier_space.h>

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


  void
  MultiplierSpace::reinit(const GeometryParameters                 &geometry,
                          const ContactParameters                  &contact,
                          const std::array<std::vector<double>, 2> &traces,
                          const unsigned int                        degree,
                          const PerBlock<bool>                     &active)
  {
    const double tol = 1e-10 * (geometry.x_max - geometry.x_min);

    // The meshes: the union of the traces for mu_1, each side's trace for
    // lambda- and lambda+.
    degree_ = degree;
    fe      = std::make_unique<FE_Q<1>>(QGaussLobatto<1>(degree_ + 1));
    meshes[Layout::across_sigma].breakpoints =
      merge_breakpoints(traces[0], traces[1], tol);
    for (const Subdomain sd : {Subdomain::minus, Subdomain::plus})
      meshes[Layout::gluing_block(sd)].breakpoints =
        traces[static_cast<unsigned int>(sd)];
    // Without layer 2 the blocks that glue the layers have no nodes.
    for (const unsigned int b : Layout::blocks)
      if (!active[b])
        meshes[b].breakpoints.clear();
    const QGaussLobatto<1> lobatto(degree_ + 1);
    for (auto &mesh : meshes)
      {
        const unsigned int n_segments =
          mesh.breakpoints.empty() ? 0 : mesh.breakpoints.size() - 1;
        const unsigned int n = n_segments > 0 ? n_segments * degree_ + 1 : 0;
        mesh.node_x.assign(n, 0.);
        mesh.node_weight.assign(n, 0.);
        for (unsigned int e = 0; e < n_segments; ++e)
          {
            const double h = mesh.breakpoints[e + 1] - mesh.breakpoints[e];
            for (unsigned int i = 0; i <= degree_; ++i)
              {
                const unsigned int a = node(e, i);
                mesh.node_x[a] =
                  mesh.breakpoints[e] + fe->get_unit_support_points()[i][0] * h;
                for (unsigned int q = 0; q < lobatto.size(); ++q)
                  mesh.node_weight[a] += fe->shape_value(i, lobatto.point(q)) *
                                         lobatto.weight(q) * h;
              }
          }
      }

    // Multiplier sets (paper.md §3) as bounds per component.
    const double                         p     = contact.multiplier_bound;
    const CrackSet                       crack = geometry.crack();
    std::vector<types::global_dof_index> sizes;
    for (const auto &mesh : meshes)
      sizes.push_back(Layout::n_components * mesh.node_x.size());
    lower.reinit(sizes);
    upper.reinit(sizes);
    crack_nodes.assign(n_nodes(Layout::across_sigma), false);
    for (const unsigned int b : Layout::blocks)
      for (unsigned int a = 0; a < meshes[b].node_x.size(); ++a)
        {
          const double x        = meshes[b].node_x[a];
          const bool   on_crack = crack.contains(x);
          if (b == Layout::across_sigma)
            crack_nodes[a] = on_crack;
          // The ends of Sigma on a clamped side belong to Gamma_D.
          const bool on_gamma_d =
            (std::abs(x - geometry.x_min) < tol &&
             geometry.clamped[static_cast<unsigned int>(Side::left)]) ||
            (std::abs(x - geometry.x_max) < tol &&
             geometry.clamped[static_cast<unsigned int>(Side::right)]);
          if (on_gamma_d)
            continue;
          for (unsigned int c = 0; c < Layout::n_components; ++c)
            {
              lower.block(b)(Layout::entry(a, c)) = -p;
              upper.block(b)(Layout::entry(a, c)) = p;
            }
          if (b == Layout::across_sigma && on_crack)
            {
              const unsigned int t = Layout::entry(a, Layout::tangential),
                                 n = Layout::entry(a, Layout::normal);
              lower.block(b)(t)    = 0;
              upper.block(b)(t)    = 0;
              lower.block(b)(n)    = 0;
              upper.block(b)(n)    = contact.non_penetration ? p : 0;
            }
        }
  }


  void
  MultiplierSpace::project(BlockVector<double> &mu) const
  {
    for (unsigned int i = 0; i < mu.size(); ++i)
      mu(i) = std::min(std::max(mu(i), lower(i)), upper(i));
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
    for (unsigned int i = 0; i < lower.size(); ++i)
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
  MultiplierSpace::discrete_violation(const BlockVector<double> &g) const
  {
    double violation = 0;
    for (unsigned int i = 0; i < g.size(); ++i)
      if (free(i))
        violation =
          std::max(violation,
                   lower(i) == 0. ? std::max(g(i), 0.) : std::abs(g(i)));
    return violation;
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
    values.resize(degree_ + 1);
    for (unsigned int i = 0; i <= degree_; ++i)
      values[i] = fe->shape_value(i, Point<1>(t));
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
    for (unsigned int i = 0; i <= degree_; ++i)
      result += values[i] * mu.block(b)(Layout::entry(node(e, i), c));
    return result;
  }


  MultiplierSpace::Functions
  MultiplierSpace::functions(const BlockVector<double> &mu) const
  {
    Functions f;
    f.degree = degree_;
    for (const unsigned int b : Layout::blocks)
      f.breakpoints[b] = meshes[b].breakpoints;
    f.values = mu;
    return f;
  }


  void
  MultiplierSpace::interpolate(const Functions     &old,
                               BlockVector<double> &mu) const
  {
    initialize(mu);
    if (old.degree != degree_ || old.values.n_blocks() != Layout::n_blocks)
      return;
    const FE_Q<1> fe_old(QGaussLobatto<1>(old.degree + 1));
    for (const unsigned int b : Layout::blocks)
      if (!meshes[b].node_x.empty() && old.breakpoints[b].size() >= 2)
        {
          const auto &bp = old.breakpoints[b];
          for (unsigned int a = 0; a < meshes[b].node_x.size(); ++a)
            {
              const double x = meshes[b].node_x[a];
              const auto it = std::upper_bound(bp.begin() + 1, bp.end() - 1, x);
              const unsigned int e = (it - bp.begin()) - 1;
              const double       t = (x - bp[e]) / (bp[e + 1] - bp[e]);
              for (unsigned int i = 0; i <= degree_; ++i)
                {
                  const double v = fe_old.shape_value(i, Point<1>(t));
                  for (unsigned int c = 0; c < Layout::n_components; ++c)
                    mu.block(b)(Layout::entry(a, c)) +=
                      v * old.values.block(b)(Layout::entry(node(e, i), c));
                }
            }
        }
    project(mu);
  }
} // namespace bilayer
