#include <deal.II/base/quadrature_lib.h>
#include <deal.II/lac/dynamic_sparsity_pattern.h>

#include <bilayer/core/boundary_ids.h>
#include <bilayer/interface/trace_coupling.h>

#include <algorithm>
#include <cmath>
#include <map>

namespace bilayer
{
  using namespace dealii;

  namespace
  {
    /// @p add(x, w) for the points x and weights w of @p rule on each
    /// segment between the break points @p b.
    template <typename Add>
    void
    for_points_of(const Quadrature<1>       &rule,
                  const std::vector<double> &b,
                  const Add                 &add)
    {
      for (unsigned int k = 0; k + 1 < b.size(); ++k)
        for (unsigned int q = 0; q < rule.size(); ++q)
          add(b[k] + rule.point(q)[0] * (b[k + 1] - b[k]),
              rule.weight(q) * (b[k + 1] - b[k]));
    }
  } // namespace


  std::vector<TraceCoupling::SigmaFace>
  TraceCoupling::sigma_faces(const Triangulation<2> &tria,
                             const InterfaceCurve   &curve,
                             const unsigned int      i)
  {
    std::vector<SigmaFace> result;
    for (const auto &cell : tria.active_cell_iterators())
      for (const auto f : cell->face_indices())
        if (on_interface(cell->face(f), i))
          {
            const auto   face = cell->face(f);
            const double tol  = 1e-10 * face->diameter();
            std::array<std::pair<double, Point<2>>, 2> ends;
            for (unsigned int fv = 0; fv < 2; ++fv)
              for (const unsigned int v : cell->vertex_indices())
                if (cell->vertex(v).distance(face->vertex(fv)) < tol)
                  ends[fv] = {curve.parameter(face->vertex(fv)),
                              cell->reference_cell().template vertex<2>(v)};
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


  const std::vector<InterfaceTraces> &
  TraceCoupling::locate_traces(
    const Topology                                 &topology_,
    const PerSubproblem<const ElasticSubproblem *> &subs,
    const std::vector<InterfaceCurve>              &curves_)
  {
    topology    = topology_;
    subproblems = subs;
    curves      = &curves_;
    faces.assign(topology.n_interfaces(), {});
    traces.assign(topology.n_interfaces(), {});
    for (const unsigned int i : Layout::indices(topology.n_interfaces()))
      for (const unsigned int side : {0u, 1u})
        {
          auto &f = faces[i][side];
          f       = sigma_faces(
            subs[topology.index(Layer::first, topology.regions_of(i)[side])]
              ->dof_handler()
              .get_triangulation(),
            curves_[i],
            i);
          auto &t = traces[i][side];
          t.clear();
          for (const auto &face : f)
            t.push_back(face.x0);
          t.push_back(f.back().x1);
        }
    return traces;
  }


  void
  TraceCoupling::reinit(const MultiplierSpace   &space,
                        const MultiplierCoupling coupling_kind,
                        const double             tol)
  {
    const auto &subs = subproblems;

    // Coupling (lumped or consistent) and evaluation at the nodes of each
    // block, traces at the nodes of mu_1, and the Gauss points of the
    // common refinement of the two traces.
    const unsigned int n_blocks = space.n_blocks();
    // (Fresh matrices: a sparse matrix cannot be copied over one in use.)
    const unsigned int n_interfaces = topology.n_interfaces();
    coupling                        = decltype(coupling)(n_blocks);
    evaluation                      = decltype(evaluation)(n_blocks);
    node_traces                     = decltype(node_traces)(n_interfaces);
    gauss_traces                    = decltype(gauss_traces)(n_interfaces);
    gauss                           = decltype(gauss)(n_interfaces);
    unsigned int max_degree         = 0;
    for (const unsigned int b : Layout::indices(n_blocks))
      max_degree = std::max(max_degree, space.degree(b));
    for (const auto *sub : subs)
      if (sub != nullptr)
        max_degree = std::max(max_degree, sub->fe().degree);
    const QGauss<1> rule_1d(max_degree + 2);
    const auto      for_gauss_points = [&](const std::vector<double> &b,
                                      const auto                &add) {
      for_points_of(rule_1d, b, add);
    };
    const auto nodal = [&](const unsigned int b) {
      std::vector<std::tuple<unsigned int, double, double>> points;
      for (unsigned int a = 0; a < space.n_nodes(b); ++a)
        points.emplace_back(a, space.node_position(a, b), 1.0);
      return points;
    };
    // The rows of the constraints: each multiplier node's frame
    // (MultiplierSpace::node_frame; two normals at a crack corner).
    const auto node_frames = [&](const unsigned int b) {
      std::vector<std::array<Tensor<1, 2>, 2>> frames;
      for (unsigned int a = 0; a < space.n_nodes(b); ++a)
        frames.push_back(space.node_frame(a, b));
      return frames;
    };

    std::vector<double> values;
    for (const unsigned int b : Layout::indices(n_blocks))
      if (active(b))
        {
          const unsigned int n = space.n_nodes(b);
          const Coupling     c = topology.coupling(b);
          for (unsigned int j = 0; j < 2; ++j)
            {
              const unsigned int s = j == 0 ? c.first : c.second;
              // Lumped: the dual basis psi_a, exact at the nodes where the
              // trace lies in the multiplier space (C_s = D E_s), else
              // integrated on the common refinement; consistent: the
              // Lagrange basis phi_a on the common refinement. Rows follow
              // MultiplierSpace::row (ends on Gamma_D).
              const bool lumped = coupling_kind == MultiplierCoupling::lumped;
              std::vector<std::tuple<unsigned int, double, double>> points;
              if (lumped && space.nodal(b, j))
                for (unsigned int a = 0; a < n; ++a)
                  points.emplace_back(space.row(a, b),
                                      space.node_position(a, b),
                                      space.node_mass(a, b));
              else
                for_gauss_points(
                  merge_breakpoints(space.breakpoints(b),
                                    traces[c.interface][topology.side(
                                      c.interface, topology.region(s))],
                                    tol),
                  [&](const double x, const double w) {
                    const unsigned int e =
                      lumped ? space.dual_shape_values(b, x, values) :
                               space.shape_values(b, x, values);
                    for (unsigned int i = 0; i <= space.degree(b); ++i)
                      points.emplace_back(space.row(space.node(e, i, b), b),
                                          x,
                                          w * values[i]);
                  });
              build_point_matrix(
                s, c.interface, points, node_frames(b), coupling[b][j]);
              build_point_matrix(
                s, c.interface, nodal(b), node_frames(b), evaluation[b][j]);
            }
        }

    for (const unsigned int i : Layout::indices(n_interfaces))
      {
        // The traces at the nodes of the block across interface i for the
        // diagnostics and the output: (tangent, normal) of the node's
        // normal everywhere.
        std::vector<std::array<Tensor<1, 2>, 2>> orthonormal_frames;
        for (unsigned int a = 0; a < space.n_nodes(i); ++a)
          {
            const Tensor<1, 2> &n = space.node_normal(a, i);
            orthonormal_frames.push_back({{tangent_of(n), n}});
          }
        node_traces[i]  = PerSubproblem<PointMatrix>(subs.size());
        gauss_traces[i] = PerSubproblem<PointMatrix>(subs.size());
        for (const unsigned int s : Layout::indices(subs.size()))
          if (touches(s, i))
            build_point_matrix(
              s, i, nodal(i), orthonormal_frames, node_traces[i][s]);

        build_gauss_traces(i, rule_1d, tol);
      }
  }


  void
  TraceCoupling::build_gauss_traces(const unsigned int   i,
                                    const Quadrature<1> &rule_1d,
                                    const double         tol)
  {
    GaussRule &rule = gauss[i];
    for_points_of(rule_1d,
                  merge_breakpoints(traces[i][0], traces[i][1], tol),
                  [&](const double x, const double w) {
                    rule.x.push_back(x);
                    rule.weight.push_back(w);
                  });
    std::vector<std::tuple<unsigned int, double, double>> at_gauss;
    for (unsigned int q = 0; q < rule.x.size(); ++q)
      at_gauss.emplace_back(q, rule.x[q], 1.0);
    // The Gauss points' frames: the curve's normal there.
    std::vector<std::array<Tensor<1, 2>, 2>> frames;
    for (const double x : rule.x)
      {
        const Tensor<1, 2> n = (*curves)[i].normal(x);
        frames.push_back({{tangent_of(n), n}});
      }
    for (const unsigned int s : Layout::indices(subproblems.size()))
      if (touches(s, i))
        build_point_matrix(s, i, at_gauss, frames, gauss_traces[i][s]);
  }


  void
  TraceCoupling::build_point_matrix(
    const unsigned int                                           s,
    const unsigned int                                           i,
    const std::vector<std::tuple<unsigned int, double, double>> &points,
    const std::vector<std::array<Tensor<1, 2>, 2>>              &frames,
    PointMatrix                                                 &result) const
  {
    const unsigned int       n_rows = frames.size();
    const ElasticSubproblem &sub    = *subproblems[s];
    const auto              &fe     = sub.fe();
    const auto         &sfaces = faces[i][topology.side(i, topology.region(s))];
    std::vector<double> starts;
    for (const auto &face : sfaces)
      starts.push_back(face.x0);

    std::vector<std::map<types::global_dof_index, double>> rows(
      Layout::n_components * n_rows);
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
              {
                // Component k of the frame of row r: the displacement
                // component c of the shape function times frame[k][c].
                const unsigned int c = fe.system_to_component_index(i).first;
                for (unsigned int k = 0; k < Layout::n_components; ++k)
                  if (frames[r][k][c] != 0.)
                    rows[Layout::entry(r, k)][local[i]] +=
                      weight * v * frames[r][k][c];
              }
          }
      }

    DynamicSparsityPattern dsp(rows.size(), sub.n_dofs());
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
  TraceCoupling::apply_transpose(const BlockVector<double> &mu,
                                 Solutions                 &loads) const
  {
    loads.resize(subproblems.size());
    for (const unsigned int s : Layout::indices(subproblems.size()))
      loads[s].reinit(present(s) ? subproblems[s]->n_dofs() : 0);
    // Added into the loads directly (the first subproblem of a block with
    // -mu): no vector of the subproblem's size per block.
    Vector<double> negative;
    for (const unsigned int b : Layout::indices(coupling.size()))
      if (active(b))
        {
          negative = mu.block(b);
          negative *= -1.;
          const Coupling c = topology.coupling(b);
          coupling[b][0].matrix.Tvmult_add(loads[c.first], negative);
          coupling[b][1].matrix.Tvmult_add(loads[c.second], mu.block(b));
        }
  }


  void
  TraceCoupling::differences(const Solutions     &w,
                             const bool           weighted,
                             BlockVector<double> &result) const
  {
    const auto    &op = weighted ? coupling : evaluation;
    Vector<double> first, second;
    for (const unsigned int b : Layout::indices(coupling.size()))
      if (active(b))
        {
          const unsigned int n = result.block(b).size();
          first.reinit(n);
          second.reinit(n);
          const Coupling c = topology.coupling(b);
          op[b][0].matrix.vmult(first, w[c.first]);
          op[b][1].matrix.vmult(second, w[c.second]);
          for (unsigned int i = 0; i < n; ++i)
            result.block(b)(i) = first(i) - second(i);
        }
  }


  void
  TraceCoupling::trace_at_nodes(const unsigned int    s,
                                const Vector<double> &w,
                                Vector<double>       &trace,
                                const unsigned int    i) const
  {
    trace.reinit(node_traces[i][s].matrix.m());
    node_traces[i][s].matrix.vmult(trace, w);
  }


  void
  TraceCoupling::trace_at_gauss_points(const unsigned int    s,
                                       const Vector<double> &w,
                                       Vector<double>       &trace,
                                       const unsigned int    i) const
  {
    trace.reinit(Layout::n_components * gauss[i].x.size());
    gauss_traces[i][s].matrix.vmult(trace, w);
  }


  void
  TraceCoupling::gram(const BlockVector<double> &mask,
                      SparsityPattern           &pattern,
                      SparseMatrix<double>      &gram) const
  {
    PerBlock<unsigned int> offset(coupling.size(), 0);
    for (unsigned int b = 1; b < coupling.size(); ++b)
      offset[b] = offset[b - 1] + mask.block(b - 1).size();
    const unsigned int                                      n = mask.size();
    std::map<std::pair<unsigned int, unsigned int>, double> entries;
    for (const unsigned int s : Layout::indices(subproblems.size()))
      {
        // The columns of the signed coupling of s: (global row, value) per
        // dof of s.
        std::map<types::global_dof_index,
                 std::vector<std::pair<unsigned int, double>>>
          columns;
        for (const unsigned int b : Layout::indices(coupling.size()))
          for (unsigned int j = 0; j < 2; ++j)
            if ((j == 0 ? topology.coupling(b).first :
                          topology.coupling(b).second) == s &&
                active(b))
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
} // namespace bilayer
