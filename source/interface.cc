#include <deal.II/base/quadrature_lib.h>
#include <deal.II/lac/dynamic_sparsity_pattern.h>

#include <bilayer/geometry.h>
#include <bilayer/interface.h>

#include <algorithm>
#include <cmath>
#include <iomanip>
#include <map>
#include <tuple>

namespace bilayer
{
  namespace
  {
    constexpr unsigned int u_minus = 0, u_plus = 1, v_minus = 2, v_plus = 3;

    /// The subproblems that each multiplier block couples: its jump is
    /// (trace of the first) - (trace of the second).
    constexpr unsigned int block_pair[3][2] = {{u_minus, u_plus},
                                               {u_minus, v_minus},
                                               {u_plus, v_plus}};

    /// Sorted union of two sorted break point lists, merging near-equal
    /// points.
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
  } // namespace


  Interface::Interface(const GeometryParameters &geometry,
                       const ContactParameters  &contact)
    : geometry(geometry)
    , contact(contact)
  {}


  std::vector<Interface::SigmaFace>
  Interface::sigma_faces(const Triangulation<2> &tria,
                         const double            sigma_height)
  {
    std::vector<SigmaFace> result;
    for (const auto &cell : tria.active_cell_iterators())
      for (const auto f : cell->face_indices())
        if (cell->face(f)->at_boundary() &&
            (cell->face(f)->boundary_id() == BoundaryIds::glued ||
             cell->face(f)->boundary_id() == BoundaryIds::crack))
          {
            const auto   face = cell->face(f);
            const double tol  = 1e-10 * face->diameter();
            std::array<std::pair<double, Point<2>>, 2> ends;
            for (unsigned int fv = 0; fv < 2; ++fv)
              for (const unsigned int v : cell->vertex_indices())
                if (cell->vertex(v).distance(face->vertex(fv)) < tol)
                  ends[fv] = {face->vertex(fv)[0],
                              cell->reference_cell().template vertex<2>(v)};
            Assert(std::abs(face->center()[1] - sigma_height) < 1e3 * tol,
                   ExcInternalError());
            (void)sigma_height;
            if (ends[0].first > ends[1].first)
              std::swap(ends[0], ends[1]);
            result.push_back({ends[0].first,
                              ends[1].first,
                              cell,
                              ends[0].second,
                              ends[1].second});
          }
    std::sort(result.begin(),
              result.end(),
              [](const SigmaFace &a, const SigmaFace &b) {
                return a.x0 < b.x0;
              });
    return result;
  }


  bool
  Interface::active(const unsigned int b) const
  {
    return present(block_pair[b][0]) && present(block_pair[b][1]);
  }


  void
  Interface::setup(const std::array<const ElasticSubproblem *, 4> &subs)
  {
    subproblems = subs;
    for (const Subdomain sd : {Subdomain::minus, Subdomain::plus})
      faces[static_cast<unsigned int>(sd)] = sigma_faces(
        subs[index(Layer::first, sd)]->dof_handler().get_triangulation(),
        geometry.sigma_height);

    const double length = geometry.x_max - geometry.x_min;
    const double tol    = 1e-10 * length;

    const auto face_breakpoints = [&](const unsigned int sd) {
      std::vector<double> b;
      for (const auto &face : faces[sd])
        b.push_back(face.x0);
      b.push_back(faces[sd].back().x1);
      return b;
    };
    const std::array<std::vector<double>, 2> traces = {
      {face_breakpoints(0), face_breakpoints(1)}};

    // The multiplier meshes: the union of the traces for mu_1, each side's
    // trace for mu- and mu+.
    degree        = subs[u_minus]->fe().degree;
    fe_multiplier = std::make_unique<FE_Q<1>>(QGaussLobatto<1>(degree + 1));
    meshes[0].breakpoints = merge_breakpoints(traces[0], traces[1], tol);
    meshes[1].breakpoints = traces[0];
    meshes[2].breakpoints = traces[1];
    // Without layer 2 the blocks that glue the layers have no nodes.
    for (unsigned int b = 1; b < 3; ++b)
      if (!active(b))
        meshes[b].breakpoints.clear();
    const QGaussLobatto<1> lobatto(degree + 1);
    for (auto &mesh : meshes)
      {
        const unsigned int n_segments =
          mesh.breakpoints.empty() ? 0 : mesh.breakpoints.size() - 1;
        const unsigned int n = n_segments > 0 ? n_segments * degree + 1 : 0;
        mesh.node_x.assign(n, 0.);
        mesh.node_weight.assign(n, 0.);
        for (unsigned int e = 0; e < n_segments; ++e)
          {
            const double h = mesh.breakpoints[e + 1] - mesh.breakpoints[e];
            for (unsigned int i = 0; i <= degree; ++i)
              {
                const unsigned int a = multiplier_node(e, i);
                mesh.node_x[a] =
                  mesh.breakpoints[e] +
                  fe_multiplier->get_unit_support_points()[i][0] * h;
                for (unsigned int q = 0; q < lobatto.size(); ++q)
                  mesh.node_weight[a] +=
                    fe_multiplier->shape_value(i, lobatto.point(q)) *
                    lobatto.weight(q) * h;
              }
          }
      }

    // Multiplier sets (paper.md §3) as bounds per component.
    const double                         p = contact.multiplier_bound;
    std::vector<types::global_dof_index> sizes;
    for (const auto &mesh : meshes)
      sizes.push_back(2 * mesh.node_x.size());
    lower.reinit(sizes);
    upper.reinit(sizes);
    on_crack.assign(n_nodes(), false);
    for (unsigned int b = 0; b < 3; ++b)
      for (unsigned int a = 0; a < meshes[b].node_x.size(); ++a)
        {
          const double x     = meshes[b].node_x[a];
          const bool   crack = geometry.has_crack() &&
                             x > geometry.crack_start + tol &&
                             x < geometry.crack_end - tol;
          if (b == 0)
            on_crack[a] = crack;
          const bool on_gamma_d =
            (std::abs(x - geometry.x_min) < tol &&
             geometry.clamped[static_cast<unsigned int>(Side::left)]) ||
            (std::abs(x - geometry.x_max) < tol &&
             geometry.clamped[static_cast<unsigned int>(Side::right)]);
          if (on_gamma_d)
            continue;
          for (unsigned int c = 0; c < 2; ++c)
            {
              lower.block(b)(2 * a + c) = -p;
              upper.block(b)(2 * a + c) = p;
            }
          if (b == 0 && crack)
            {
              lower.block(0)(2 * a)     = 0;
              upper.block(0)(2 * a)     = 0;
              lower.block(0)(2 * a + 1) = 0;
              upper.block(0)(2 * a + 1) = contact.non_penetration ? p : 0;
            }
        }

    // Coupling (lumped or consistent) and evaluation at the nodes of each
    // block, traces at the nodes of block 0, and the Gauss points of the
    // common refinement of all traces (= the union mesh of block 0).
    unsigned int max_degree = degree;
    for (const auto *sub : subs)
      if (sub != nullptr)
        max_degree = std::max(max_degree, sub->fe().degree);
    const QGauss<1> gauss(max_degree + 2);
    const auto      gauss_points = [&](const std::vector<double> &b,
                                  const auto                &add) {
      for (unsigned int k = 0; k + 1 < b.size(); ++k)
        for (unsigned int q = 0; q < gauss.size(); ++q)
          add(b[k] + gauss.point(q)[0] * (b[k + 1] - b[k]),
              gauss.weight(q) * (b[k + 1] - b[k]));
    };
    const auto nodal = [&](const unsigned int b) {
      std::vector<std::tuple<unsigned int, double, double>> points;
      for (unsigned int a = 0; a < meshes[b].node_x.size(); ++a)
        points.emplace_back(a, meshes[b].node_x[a], 1.0);
      return points;
    };

    std::vector<double> values;
    for (unsigned int b = 0; b < 3; ++b)
      if (active(b))
        {
          const unsigned int n = meshes[b].node_x.size();
          for (unsigned int j = 0; j < 2; ++j)
            {
              const unsigned int s = block_pair[b][j];
              std::vector<std::tuple<unsigned int, double, double>> points;
              if (contact.coupling == MultiplierCoupling::lumped)
                for (unsigned int a = 0; a < n; ++a)
                  points.emplace_back(a,
                                      meshes[b].node_x[a],
                                      meshes[b].node_weight[a]);
              else
                gauss_points(merge_breakpoints(meshes[b].breakpoints,
                                               traces[s % 2],
                                               tol),
                             [&](const double x, const double w) {
                               const unsigned int e =
                                 multiplier_shape_values(b, x, values);
                               for (unsigned int i = 0; i <= degree; ++i)
                                 points.emplace_back(multiplier_node(e, i),
                                                     x,
                                                     w * values[i]);
                             });
              build_point_matrix(s, points, n, coupling[b][j]);
              build_point_matrix(s, nodal(b), n, evaluation[b][j]);
            }
        }
    for (unsigned int s = 0; s < 4; ++s)
      if (present(s))
        build_point_matrix(s, nodal(0), n_nodes(), node_traces[s]);

    gauss_x.clear();
    gauss_weight.clear();
    gauss_points(meshes[0].breakpoints, [&](const double x, const double w) {
      gauss_x.push_back(x);
      gauss_weight.push_back(w);
    });
    std::vector<std::tuple<unsigned int, double, double>> at_gauss;
    for (unsigned int q = 0; q < gauss_x.size(); ++q)
      at_gauss.emplace_back(q, gauss_x[q], 1.0);
    for (unsigned int s = 0; s < 4; ++s)
      if (present(s))
        build_point_matrix(s, at_gauss, gauss_x.size(), gauss_traces[s]);
  }


  Tensor<1, 2>
  Interface::multiplier_traction(const BlockVector<double> &mu,
                                 const unsigned int         s,
                                 const double               x) const
  {
    Tensor<1, 2>        t;
    std::vector<double> values;
    for (unsigned int b = 0; b < 3; ++b)
      for (unsigned int j = 0; j < 2; ++j)
        if (block_pair[b][j] == s && active(b))
          {
            const unsigned int e = multiplier_shape_values(b, x, values);
            for (unsigned int i = 0; i <= degree; ++i)
              for (unsigned int c = 0; c < 2; ++c)
                t[c] += (j == 0 ? -1. : 1.) * values[i] *
                        mu.block(b)(2 * multiplier_node(e, i) + c);
          }
    return t;
  }


  Interface::MultiplierFunctions
  Interface::functions(const BlockVector<double> &mu) const
  {
    MultiplierFunctions f;
    f.degree = degree;
    for (unsigned int b = 0; b < 3; ++b)
      f.breakpoints[b] = meshes[b].breakpoints;
    f.values = mu;
    return f;
  }


  void
  Interface::interpolate(const MultiplierFunctions &old,
                         BlockVector<double>       &mu) const
  {
    initialize(mu);
    if (old.degree != degree || old.values.n_blocks() != 3)
      return;
    const FE_Q<1> fe_old(QGaussLobatto<1>(old.degree + 1));
    for (unsigned int b = 0; b < 3; ++b)
      if (active(b) && old.breakpoints[b].size() >= 2)
        {
          const auto &bp = old.breakpoints[b];
          for (unsigned int a = 0; a < meshes[b].node_x.size(); ++a)
            {
              const double x = meshes[b].node_x[a];
              const auto it = std::upper_bound(bp.begin() + 1, bp.end() - 1, x);
              const unsigned int e = (it - bp.begin()) - 1;
              const double       t = (x - bp[e]) / (bp[e + 1] - bp[e]);
              for (unsigned int i = 0; i <= degree; ++i)
                {
                  const double v = fe_old.shape_value(i, Point<1>(t));
                  for (unsigned int c = 0; c < 2; ++c)
                    mu.block(b)(2 * a + c) +=
                      v * old.values.block(b)(2 * multiplier_node(e, i) + c);
                }
            }
        }
    project(mu);
  }


  unsigned int
  Interface::multiplier_shape_values(const unsigned int   b,
                                     const double         x,
                                     std::vector<double> &values) const
  {
    const auto        &bp = meshes[b].breakpoints;
    const auto         it = std::upper_bound(bp.begin() + 1, bp.end() - 1, x);
    const unsigned int e  = (it - bp.begin()) - 1;
    const double       t  = (x - bp[e]) / (bp[e + 1] - bp[e]);
    values.resize(degree + 1);
    for (unsigned int i = 0; i <= degree; ++i)
      values[i] = fe_multiplier->shape_value(i, Point<1>(t));
    return e;
  }


  void
  Interface::build_point_matrix(
    const unsigned int                                           s,
    const std::vector<std::tuple<unsigned int, double, double>> &points,
    const unsigned int                                           n_rows,
    PointMatrix                                                 &result) const
  {
    const ElasticSubproblem &sub    = *subproblems[s];
    const auto              &fe     = sub.fe();
    const auto              &sfaces = faces[s % 2];
    std::vector<double>      starts;
    for (const auto &face : sfaces)
      starts.push_back(face.x0);

    std::vector<std::map<types::global_dof_index, double>> rows(2 * n_rows);
    std::vector<types::global_dof_index> local(fe.n_dofs_per_cell());
    for (const auto &[r, x, weight] : points)
      {
        if (weight == 0.)
          continue;
        const auto it = std::upper_bound(starts.begin() + 1, starts.end(), x);
        const SigmaFace &face = sfaces[(it - starts.begin()) - 1];
        const double     t    = (x - face.x0) / (face.x1 - face.x0);
        const Point<2>   unit = face.unit0 + t * (face.unit1 - face.unit0);
        const DoFHandler<2>::active_cell_iterator cell(
          &sub.dof_handler().get_triangulation(),
          face.cell->level(),
          face.cell->index(),
          &sub.dof_handler());
        cell->get_dof_indices(local);
        for (unsigned int i = 0; i < fe.n_dofs_per_cell(); ++i)
          {
            const double v = fe.shape_value(i, unit);
            if (std::abs(v) > 1e-14)
              rows[2 * r + fe.system_to_component_index(i).first][local[i]] +=
                weight * v;
          }
      }

    DynamicSparsityPattern dsp(2 * n_rows, sub.n_dofs());
    for (unsigned int r = 0; r < rows.size(); ++r)
      for (const auto &entry : rows[r])
        dsp.add(r, entry.first);
    result.matrix.clear();
    result.pattern.copy_from(dsp);
    result.matrix.reinit(result.pattern);
    for (unsigned int r = 0; r < rows.size(); ++r)
      for (const auto &entry : rows[r])
        result.matrix.set(r, entry.first, entry.second);
  }


  void
  Interface::initialize(BlockVector<double> &multipliers) const
  {
    multipliers.reinit(lower);
  }


  unsigned int
  Interface::n_multipliers() const
  {
    unsigned int count = 0;
    for (unsigned int i = 0; i < lower.size(); ++i)
      count += (lower(i) < upper(i));
    return count;
  }


  void
  Interface::apply(const BlockVector<double> &mu, Solutions &loads) const
  {
    for (unsigned int s = 0; s < 4; ++s)
      loads[s].reinit(present(s) ? subproblems[s]->n_dofs() : 0);
    Vector<double> term;
    for (unsigned int b = 0; b < 3; ++b)
      for (unsigned int j = 0; j < 2 && active(b); ++j)
        {
          const unsigned int s = block_pair[b][j];
          term.reinit(subproblems[s]->n_dofs());
          coupling[b][j].matrix.Tvmult(term, mu.block(b));
          loads[s].add(j == 0 ? -1. : 1., term);
        }
  }


  void
  Interface::difference(const Vector<double> &a,
                        const Vector<double> &b,
                        const unsigned int    block,
                        BlockVector<double>  &g) const
  {
    const bool  weighted = contact.sampling == JumpSampling::weighted;
    const auto &weight   = meshes[block].node_weight;
    for (unsigned int i = 0; i < a.size(); ++i)
      g.block(block)(i) = lower.block(block)(i) < upper.block(block)(i) ?
                            (a(i) - b(i)) / (weighted ? weight[i / 2] : 1.) :
                            0.;
  }


  void
  Interface::jumps(const Solutions &w, BlockVector<double> &g) const
  {
    const auto &op =
      contact.sampling == JumpSampling::weighted ? coupling : evaluation;
    g.reinit(lower, true);
    Vector<double> first, second;
    for (unsigned int b = 0; b < 3; ++b)
      if (active(b))
        {
          first.reinit(lower.block(b).size());
          second.reinit(lower.block(b).size());
          op[b][0].matrix.vmult(first, w[block_pair[b][0]]);
          op[b][1].matrix.vmult(second, w[block_pair[b][1]]);
          difference(first, second, b, g);
        }
  }


  void
  Interface::project(BlockVector<double> &mu) const
  {
    for (unsigned int i = 0; i < mu.size(); ++i)
      mu(i) = std::min(std::max(mu(i), lower(i)), upper(i));
  }


  void
  Interface::restrict_to_free(BlockVector<double> &x) const
  {
    for (unsigned int i = 0; i < x.size(); ++i)
      if (!(lower(i) < upper(i)))
        x(i) = 0;
  }


  double
  Interface::weighted_dot(const BlockVector<double> &x,
                          const BlockVector<double> &y) const
  {
    double sum = 0;
    for (unsigned int b = 0; b < x.n_blocks(); ++b)
      for (unsigned int i = 0; i < x.block(b).size(); ++i)
        sum += meshes[b].node_weight[i / 2] * x.block(b)(i) * y.block(b)(i);
    return sum;
  }


  double
  Interface::weighted_norm(const BlockVector<double> &x) const
  {
    return std::sqrt(weighted_dot(x, x));
  }


  double
  Interface::discrete_violation(const BlockVector<double> &g) const
  {
    double violation = 0;
    for (unsigned int i = 0; i < g.size(); ++i)
      if (lower(i) < upper(i))
        violation =
          std::max(violation,
                   lower(i) == 0. ? std::max(g(i), 0.) : std::abs(g(i)));
    return violation;
  }


  double
  Interface::displacement_scale(const Solutions &w) const
  {
    double         scale = 0;
    Vector<double> trace(2 * n_nodes());
    for (unsigned int s = 0; s < 4; ++s)
      if (present(s))
        {
          node_traces[s].matrix.vmult(trace, w[s]);
          scale = std::max(scale, trace.linfty_norm());
        }
    return scale;
  }


  KKTResidual
  Interface::kkt_residual(const Solutions           &w,
                          const BlockVector<double> &g,
                          const BlockVector<double> &mu) const
  {
    KKTResidual  kkt;
    const double scale = displacement_scale(w);
    // A multiplier held at a bound of its box by a jump that pushes it
    // outward is optimal there (mu = P(mu + theta g)): its jump is no
    // residual. Only the bound p can hold a constraint violated this way.
    BlockVector<double> free_g(g);
    for (unsigned int i = 0; i < mu.size(); ++i)
      if (lower(i) < upper(i) && ((mu(i) >= upper(i) && g(i) >= 0) ||
                                  (mu(i) <= lower(i) && g(i) <= 0)))
        free_g(i) = 0;
    kkt.primal            = scale > 0 ? discrete_violation(free_g) / scale :
                                        discrete_violation(free_g);
    const double mu_scale = mu.linfty_norm();
    if (mu_scale > 0)
      for (unsigned int i = 0; i < mu.size(); ++i)
        if (lower(i) == 0. && upper(i) > 0. && mu(i) < upper(i))
          {
            kkt.dual = std::max(kkt.dual, -mu(i) / mu_scale);
            if (scale > 0)
              kkt.complementarity =
                std::max(kkt.complementarity,
                         std::abs(mu(i) * g(i)) / (mu_scale * scale));
          }
    return kkt;
  }


  void
  Interface::scale_by_weights(BlockVector<double> &x, const bool inverse) const
  {
    for (unsigned int b = 0; b < x.n_blocks(); ++b)
      for (unsigned int i = 0; i < x.block(b).size(); ++i)
        x.block(b)(i) = inverse ? x.block(b)(i) / meshes[b].node_weight[i / 2] :
                                  x.block(b)(i) * meshes[b].node_weight[i / 2];
  }


  void
  Interface::coupling_gram(const BlockVector<double> &mask,
                           SparsityPattern           &pattern,
                           SparseMatrix<double>      &gram) const
  {
    // B: +C on the first and -C on the second subproblem of each block.
    std::array<unsigned int, 3> offset = {{0, 0, 0}};
    for (unsigned int b = 1; b < 3; ++b)
      offset[b] = offset[b - 1] + lower.block(b - 1).size();
    const unsigned int                                      n = lower.size();
    std::map<std::pair<unsigned int, unsigned int>, double> entries;
    for (unsigned int s = 0; s < 4; ++s)
      {
        // The columns of the signed coupling of s: (global row, value) per
        // dof of s.
        std::map<types::global_dof_index,
                 std::vector<std::pair<unsigned int, double>>>
          columns;
        for (unsigned int b = 0; b < 3; ++b)
          for (unsigned int j = 0; j < 2; ++j)
            if (block_pair[b][j] == s && active(b))
              {
                const auto &matrix = coupling[b][j].matrix;
                for (unsigned int r = 0; r < matrix.m(); ++r)
                  for (auto e = matrix.begin(r); e != matrix.end(r); ++e)
                    if (mask(offset[b] + r) != 0. && e->value() != 0.)
                      columns[e->column()].emplace_back(offset[b] + r,
                                                        (j == 0 ? 1. : -1.) *
                                                          e->value());
              }
        for (const auto &column : columns)
          for (const auto &[i, vi] : column.second)
            for (const auto &[j, vj] : column.second)
              entries[{i, j}] += vi * vj;
      }
    DynamicSparsityPattern dsp(n);
    for (unsigned int i = 0; i < n; ++i)
      dsp.add(i, i);
    for (const auto &e : entries)
      dsp.add(e.first.first, e.first.second);
    pattern.copy_from(dsp);
    gram.reinit(pattern);
    for (unsigned int i = 0; i < n; ++i)
      if (mask(i) == 0.)
        gram.set(i, i, 1.);
    for (const auto &e : entries)
      gram.add(e.first.first, e.first.second, e.second);
  }


  std::vector<double>
  Interface::normal_opening(const Solutions &w) const
  {
    Vector<double> tm(2 * n_nodes()), tp(2 * n_nodes());
    node_traces[u_minus].matrix.vmult(tm, w[u_minus]);
    node_traces[u_plus].matrix.vmult(tp, w[u_plus]);
    std::vector<double> result(n_nodes());
    for (unsigned int a = 0; a < n_nodes(); ++a)
      result[a] = tp(2 * a + 1) - tm(2 * a + 1);
    return result;
  }


  InterfaceReport
  Interface::assess(const Solutions &w, const BlockVector<double> &mu) const
  {
    InterfaceReport     report;
    BlockVector<double> g;
    jumps(w, g);
    const double scale        = displacement_scale(w);
    report.displacement_scale = scale;
    const double violation    = discrete_violation(g);
    report.relative_discrete_violation =
      scale > 0 ? violation / scale : violation;

    // Contact multiplier: the normal component of block 0 at crack nodes.
    double sum_mu = 0, sum_mu_jump = 0;
    bool   any = false;
    for (unsigned int a = 0; a < n_nodes(); ++a)
      if (on_crack[a] && upper.block(0)(2 * a + 1) > 0)
        {
          const double m = mu.block(0)(2 * a + 1);
          report.min_contact_multiplier =
            any ? std::min(report.min_contact_multiplier, m) : m;
          any            = true;
          const double d = meshes[0].node_weight[a];
          sum_mu += d * m;
          sum_mu_jump += d * m * std::abs(g.block(0)(2 * a + 1));
        }
    report.complementarity =
      sum_mu > 0 && scale > 0 ? sum_mu_jump / (sum_mu * scale) : 0.;
    report.max_multiplier_over_bound =
      mu.linfty_norm() / contact.multiplier_bound;
    report.kkt = kkt_residual(w, g, mu);

    // The integral (12) and the pointwise penetration at the Gauss points.
    // Without layer 2 its traces are those of layer 1 (no layer gap).
    std::array<Vector<double>, 4> t;
    for (unsigned int s = 0; s < 4; ++s)
      {
        t[s].reinit(2 * gauss_x.size());
        if (present(s))
          gauss_traces[s].matrix.vmult(t[s], w[s]);
        else
          gauss_traces[s % 2].matrix.vmult(t[s], w[s % 2]);
      }
    const double tol  = 1e-10 * (geometry.x_max - geometry.x_min);
    double       size = 0;
    for (unsigned int q = 0; q < gauss_x.size(); ++q)
      {
        const double x     = gauss_x[q];
        const bool   crack = geometry.has_crack() &&
                           x > geometry.crack_start + tol &&
                           x < geometry.crack_end - tol;
        double density = 0;
        for (unsigned int c = 0; c < 2; ++c)
          {
            const double jump_1 = t[u_minus](2 * q + c) - t[u_plus](2 * q + c);
            if (!crack)
              density += std::abs(jump_1);
            else if (c == 1)
              {
                report.max_penetration =
                  std::max(report.max_penetration, jump_1);
                if (contact.non_penetration)
                  density += std::max(jump_1, 0.);
              }
            density += std::abs(t[u_minus](2 * q + c) - t[v_minus](2 * q + c));
            density += std::abs(t[u_plus](2 * q + c) - t[v_plus](2 * q + c));
            for (unsigned int s = 0; s < 4; ++s)
              if (present(s))
                size += gauss_weight[q] * std::abs(t[s](2 * q + c));
          }
        report.constraint_violation += gauss_weight[q] * density;
      }
    // Penetration at the crack nodes as well (the Gauss points miss them).
    const std::vector<double> open = normal_opening(w);
    for (unsigned int a = 0; a < n_nodes(); ++a)
      if (on_crack[a])
        report.max_penetration = std::max(report.max_penetration, -open[a]);
    report.relative_constraint_violation =
      size > 0 ? report.constraint_violation / size :
                 report.constraint_violation;
    return report;
  }


  std::vector<Interface::ContactSegment>
  Interface::contact_residual(const Solutions           &w,
                              const BlockVector<double> &mu) const
  {
    std::vector<ContactSegment> result;
    if (!contact.non_penetration)
      return result;
    std::array<Vector<double>, 2> t;
    for (const unsigned int s : {u_minus, u_plus})
      {
        t[s].reinit(2 * n_nodes());
        node_traces[s].matrix.vmult(t[s], w[s]);
      }
    // Normal jump and contact multiplier at node a (nu = e_y).
    const auto gap = [&](const unsigned int a) {
      return t[u_plus](2 * a + 1) - t[u_minus](2 * a + 1);
    };
    const auto mu_c = [&](const unsigned int a) {
      return on_crack[a] ? mu.block(0)(2 * a + 1) : 0.;
    };
    const auto &mesh = meshes[0];
    for (unsigned int e = 0; e + 1 < mesh.breakpoints.size(); ++e)
      {
        const unsigned int a0 = multiplier_node(e, 0),
                           a1 = multiplier_node(e, 1);
        if (!on_crack[a0] && !on_crack[a1])
          continue;
        // Midpoint values: the middle node for degree 2, the mean for
        // degree 1 (then Simpson's rule is exact for the product).
        const double g_m =
          degree == 2 ? gap(multiplier_node(e, 2)) : 0.5 * (gap(a0) + gap(a1));
        const double mu_m = degree == 2 ? mu_c(multiplier_node(e, 2)) :
                                          0.5 * (mu_c(a0) + mu_c(a1));
        const double h    = mesh.breakpoints[e + 1] - mesh.breakpoints[e];
        result.push_back(
          {mesh.breakpoints[e],
           mesh.breakpoints[e + 1],
           h / 6 * (mu_c(a0) * gap(a0) + 4 * mu_m * g_m + mu_c(a1) * gap(a1))});
      }
    return result;
  }


  void
  Interface::write_csv(std::ostream              &out,
                       const Solutions           &w,
                       const BlockVector<double> &mu) const
  {
    // Without layer 2 its columns repeat layer 1 (gaps and mu+- zero).
    std::array<Vector<double>, 4> t;
    for (unsigned int s = 0; s < 4; ++s)
      {
        t[s].reinit(2 * n_nodes());
        node_traces[present(s) ? s : s % 2].matrix.vmult(
          t[s], w[present(s) ? s : s % 2]);
      }
    // mu- and mu+ at the nodes of block 0.
    std::vector<double> values;
    const auto          value =
      [&](const unsigned int b, const double x, const unsigned int c) {
        if (!active(b))
          return 0.;
        const unsigned int e      = multiplier_shape_values(b, x, values);
        double             result = 0;
        for (unsigned int i = 0; i <= degree; ++i)
          result += values[i] * mu.block(b)(2 * multiplier_node(e, i) + c);
        return result;
      };
    out << "x,on_crack,jump_normal,jump_tangential,mu_c,mu_g_x,mu_g_y,"
           "mu_minus_x,mu_minus_y,mu_plus_x,mu_plus_y,gap_minus_x,"
           "gap_minus_y,gap_plus_x,gap_plus_y,u_minus_x,u_minus_y,u_plus_x,"
           "u_plus_y,v_minus_x,v_minus_y,v_plus_x,v_plus_y\n";
    out << std::setprecision(12);
    for (unsigned int a = 0; a < n_nodes(); ++a)
      {
        const unsigned int x = 2 * a, y = 2 * a + 1;
        const double       position = meshes[0].node_x[a];
        out << position << ',' << (on_crack[a] ? 1 : 0) << ','
            << t[u_plus](y) - t[u_minus](y) << ','
            << t[u_plus](x) - t[u_minus](x) << ','
            << (on_crack[a] ? mu.block(0)(y) : 0.) << ','
            << (on_crack[a] ? 0. : mu.block(0)(x)) << ','
            << (on_crack[a] ? 0. : mu.block(0)(y)) << ','
            << value(1, position, 0) << ',' << value(1, position, 1) << ','
            << value(2, position, 0) << ',' << value(2, position, 1) << ','
            << t[u_minus](x) - t[v_minus](x) << ','
            << t[u_minus](y) - t[v_minus](y) << ','
            << t[u_plus](x) - t[v_plus](x) << ','
            << t[u_plus](y) - t[v_plus](y);
        for (unsigned int s = 0; s < 4; ++s)
          out << ',' << t[s](x) << ',' << t[s](y);
        out << '\n';
      }
  }
} // namespace bilayer
