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

  std::vector<TraceCoupling::SigmaFace>
  TraceCoupling::sigma_faces(const Triangulation<2> &tria,
                             const InterfaceCurve   &curve)
  {
    std::vector<SigmaFace> result;
    for (const auto &cell : tria.active_cell_iterators())
      for (const auto f : cell->face_indices())
        if (on_sigma(cell->face(f)))
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


  const std::array<std::vector<double>, 2> &
  TraceCoupling::locate_traces(
    const PerSubproblem<const ElasticSubproblem *> &subs,
    const InterfaceCurve                           &sigma)
  {
    subproblems = subs;
    curve       = &sigma;
    for (const Subdomain sd : {Subdomain::minus, Subdomain::plus})
      {
        const unsigned int i = static_cast<unsigned int>(sd);
        faces[i]             = sigma_faces(subs[Layout::index(Layer::first, sd)]
                                 ->dof_handler()
                                 .get_triangulation(),
                               sigma);
        traces[i].clear();
        for (const auto &face : faces[i])
          traces[i].push_back(face.x0);
        traces[i].push_back(faces[i].back().x1);
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
    coupling                = decltype(coupling)(n_blocks);
    evaluation              = decltype(evaluation)(n_blocks);
    node_traces             = decltype(node_traces)(subs.size());
    gauss_traces            = decltype(gauss_traces)(subs.size());
    unsigned int max_degree = 0;
    for (const unsigned int b : Layout::indices(n_blocks))
      max_degree = std::max(max_degree, space.degree(b));
    for (const auto *sub : subs)
      if (sub != nullptr)
        max_degree = std::max(max_degree, sub->fe().degree);
    const QGauss<1> gauss(max_degree + 2);
    const auto      for_gauss_points = [&](const std::vector<double> &b,
                                      const auto                &add) {
      for (unsigned int k = 0; k + 1 < b.size(); ++k)
        for (unsigned int q = 0; q < gauss.size(); ++q)
          add(b[k] + gauss.point(q)[0] * (b[k + 1] - b[k]),
              gauss.weight(q) * (b[k + 1] - b[k]));
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
    // The traces at the nodes of mu_1 for the diagnostics and the output:
    // (tangent, normal) of the node's normal everywhere.
    std::vector<std::array<Tensor<1, 2>, 2>> orthonormal_frames;
    for (unsigned int a = 0; a < space.n_nodes(Layout::across_sigma); ++a)
      {
        const Tensor<1, 2> &n = space.node_normal(a, Layout::across_sigma);
        orthonormal_frames.push_back({{tangent_of(n), n}});
      }

    std::vector<double> values;
    for (const unsigned int b : Layout::indices(n_blocks))
      if (active(b))
        {
          const unsigned int n       = space.n_nodes(b);
          const auto [first, second] = Layout::coupled(b);
          for (unsigned int j = 0; j < 2; ++j)
            {
              const unsigned int s = j == 0 ? first : second;
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
                  merge_breakpoints(
                    space.breakpoints(b),
                    traces[static_cast<unsigned int>(Layout::subdomain(s))],
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
              build_point_matrix(s, points, node_frames(b), coupling[b][j]);
              build_point_matrix(s, nodal(b), node_frames(b), evaluation[b][j]);
            }
        }
    for (const unsigned int s : Layout::indices(subs.size()))
      if (present(s))
        build_point_matrix(s,
                           nodal(Layout::across_sigma),
                           orthonormal_frames,
                           node_traces[s]);

    gauss_x.clear();
    gauss_weight.clear();
    for_gauss_points(merge_breakpoints(traces[0], traces[1], tol),
                     [&](const double x, const double w) {
                       gauss_x.push_back(x);
                       gauss_weight.push_back(w);
                     });
    std::vector<std::tuple<unsigned int, double, double>> at_gauss;
    for (unsigned int q = 0; q < gauss_x.size(); ++q)
      at_gauss.emplace_back(q, gauss_x[q], 1.0);
    for (const unsigned int s : Layout::indices(subs.size()))
      if (present(s))
        {
          // The Gauss points' frames: the curve's normal there.
          std::vector<std::array<Tensor<1, 2>, 2>> frames;
          for (const double x : gauss_x)
            {
              const Tensor<1, 2> n = curve->normal(x);
              frames.push_back({{tangent_of(n), n}});
            }
          build_point_matrix(s, at_gauss, frames, gauss_traces[s]);
        }
  }


  void
  TraceCoupling::build_point_matrix(
    const unsigned int                                           s,
    const std::vector<std::tuple<unsigned int, double, double>> &points,
    const std::vector<std::array<Tensor<1, 2>, 2>>              &frames,
    PointMatrix                                                 &result) const
  {
    const unsigned int       n_rows = frames.size();
    const ElasticSubproblem &sub    = *subproblems[s];
    const auto              &fe     = sub.fe();
    const auto &sfaces = faces[static_cast<unsigned int>(Layout::subdomain(s))];
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
          coupling[b][0].matrix.Tvmult_add(loads[Layout::coupled(b).first],
                                           negative);
          coupling[b][1].matrix.Tvmult_add(loads[Layout::coupled(b).second],
                                           mu.block(b));
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
          op[b][0].matrix.vmult(first, w[Layout::coupled(b).first]);
          op[b][1].matrix.vmult(second, w[Layout::coupled(b).second]);
          for (unsigned int i = 0; i < n; ++i)
            result.block(b)(i) = first(i) - second(i);
        }
  }


  void
  TraceCoupling::trace_at_nodes(const unsigned int    s,
                                const Vector<double> &w,
                                Vector<double>       &trace) const
  {
    trace.reinit(node_traces[s].matrix.m());
    node_traces[s].matrix.vmult(trace, w);
  }


  void
  TraceCoupling::trace_at_gauss_points(const unsigned int    s,
                                       const Vector<double> &w,
                                       Vector<double>       &trace) const
  {
    trace.reinit(Layout::n_components * gauss_x.size());
    gauss_traces[s].matrix.vmult(trace, w);
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
            if ((j == 0 ? Layout::coupled(b).first :
                          Layout::coupled(b).second) == s &&
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
