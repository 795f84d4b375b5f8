// The weighted residual of the goal-oriented estimates: the patchwise
// reconstruction of degree p + 1 of a field, and the residual of the state
// of a subproblem against its interpolation error (docs/fracture.md §11).

#include <deal.II/base/quadrature_lib.h>
#include <deal.II/fe/fe_values.h>
#include <deal.II/lac/lapack_full_matrix.h>

#include <bilayer/core/boundary_ids.h>
#include <bilayer/core/similarity_breaker.h>
#include <bilayer/postprocess/goal_estimate.h>

#include <algorithm>
#include <cmath>

namespace bilayer
{
  using namespace dealii;

  namespace
  {
    /// The monomials x^a y^b of the reconstruction: a, b <= k on
    /// quadrilaterals (Q_k), a + b <= k on triangles (P_k).
    std::vector<std::array<unsigned int, 2>>
    exponents(const unsigned int k, const bool tensor)
    {
      std::vector<std::array<unsigned int, 2>> e;
      for (unsigned int a = 0; a <= k; ++a)
        for (unsigned int b = 0; b <= k; ++b)
          if (tensor || a + b <= k)
            e.push_back({{a, b}});
      return e;
    }


    /// A polynomial field of the reconstruction on one cell: coefficients
    /// by component, in the variable (x - c) / h.
    struct LocalPolynomial
    {
      Point<2>                                 c;
      double                                   h = 1;
      std::vector<std::array<unsigned int, 2>> e;
      std::array<Vector<double>, 2>            coefficients;

      Tensor<1, 2>
      operator()(const Point<2> &x) const
      {
        const double xi = (x[0] - c[0]) / h, eta = (x[1] - c[1]) / h;
        Tensor<1, 2> v;
        for (unsigned int k = 0; k < e.size(); ++k)
          {
            const double m = std::pow(xi, e[k][0]) * std::pow(eta, e[k][1]);
            v[0] += coefficients[0](k) * m;
            v[1] += coefficients[1](k) * m;
          }
        return v;
      }
    };


    /// The sample points and the values of each field at them, by active
    /// cell: the patches read them.
    struct Samples
    {
      std::vector<std::vector<Point<2>>>                  x;
      std::vector<std::vector<std::vector<Tensor<1, 2>>>> values;
    };


    Samples
    sample(const ElasticSubproblem                   &sub,
           const std::vector<const Vector<double> *> &fields)
    {
      const auto &tria = sub.dof_handler().get_triangulation();
      Samples     samples;
      const auto  n = tria.n_active_cells();
      samples.x.resize(n);
      samples.values.resize(n);
      FEValues<2> fe_values(
        sub.mapping(),
        sub.fe(),
        sub.fe().reference_cell().get_gauss_type_quadrature<2>(sub.fe().degree +
                                                               2),
        update_values | update_quadrature_points);
      const FEValuesExtractors::Vector displacement(0);
      const SimilarityBreaker          fresh(sub.fe().reference_cell());
      std::vector<Tensor<1, 2>>        v(fe_values.n_quadrature_points);
      for (const auto &cell : sub.dof_handler().active_cell_iterators())
        {
          fresh.apply(fe_values);
          fe_values.reinit(cell);
          const auto i = cell->active_cell_index();
          samples.x[i] = fe_values.get_quadrature_points();
          samples.values[i].resize(fields.size());
          for (unsigned int f = 0; f < fields.size(); ++f)
            {
              fe_values[displacement].get_function_values(*fields[f], v);
              samples.values[i][f] = v;
            }
        }
      return samples;
    }


    /// The cell and its neighbours across its faces (the finer ones on a
    /// refined face, the coarser one on the face of a coarser neighbour).
    std::vector<unsigned int>
    patch(const DoFHandler<2>::active_cell_iterator &cell)
    {
      std::vector<unsigned int> cells = {cell->active_cell_index()};
      for (const unsigned int f : cell->face_indices())
        if (!cell->at_boundary(f))
          {
            if (cell->face(f)->has_children())
              for (unsigned int c = 0; c < cell->face(f)->n_children(); ++c)
                cells.push_back(
                  cell->neighbor_child_on_subface(f, c)->active_cell_index());
            else
              cells.push_back(cell->neighbor(f)->active_cell_index());
          }
      return cells;
    }


    /// The least-squares fits of degree p + 1 of each field over the patch
    /// of @p cell (the pseudo-inverse of the normal equations, singular
    /// values below 1e-10 of the largest dropped: a patch that does not
    /// determine them, e.g. a cell with no neighbour, keeps the lower
    /// degrees).
    std::vector<LocalPolynomial>
    reconstruct(const DoFHandler<2>::active_cell_iterator &cell,
                const Samples                             &samples,
                const unsigned int                         degree,
                const bool                                 tensor,
                const unsigned int                         n_fields)
    {
      LocalPolynomial base;
      base.c                                 = cell->center();
      base.h                                 = cell->diameter();
      base.e                                 = exponents(degree, tensor);
      const unsigned int               n     = base.e.size();
      const std::vector<unsigned int>  cells = patch(cell);
      std::vector<std::vector<double>> rows;
      for (const unsigned int k : cells)
        for (const Point<2> &x : samples.x[k])
          {
            const double xi  = (x[0] - base.c[0]) / base.h,
                         eta = (x[1] - base.c[1]) / base.h;
            std::vector<double> row(n);
            for (unsigned int a = 0; a < n; ++a)
              row[a] = std::pow(xi, base.e[a][0]) * std::pow(eta, base.e[a][1]);
            rows.push_back(std::move(row));
          }
      LAPACKFullMatrix<double> normal(n, n);
      for (const auto &row : rows)
        for (unsigned int a = 0; a < n; ++a)
          for (unsigned int b = 0; b < n; ++b)
            normal(a, b) += row[a] * row[b];
      double largest = 0;
      for (unsigned int a = 0; a < n; ++a)
        largest = std::max(largest, normal(a, a));
      normal.compute_inverse_svd(1e-10 * largest);
      std::vector<LocalPolynomial> fits(n_fields, base);
      for (unsigned int f = 0; f < n_fields; ++f)
        for (unsigned int d = 0; d < 2; ++d)
          {
            Vector<double> rhs(n);
            unsigned int   r = 0;
            for (const unsigned int k : cells)
              for (unsigned int q = 0; q < samples.x[k].size(); ++q, ++r)
                for (unsigned int a = 0; a < n; ++a)
                  rhs(a) += rows[r][a] * samples.values[k][f][q][d];
            fits[f].coefficients[d].reinit(n);
            normal.vmult(fits[f].coefficients[d], rhs);
          }
      return fits;
    }


    /// The element's interpolation of the fits: their values at the
    /// support points of the cell's shape functions, by field.
    std::vector<std::vector<double>>
    interpolation_values(const ElasticSubproblem                   &sub,
                         const DoFHandler<2>::active_cell_iterator &cell,
                         const std::vector<LocalPolynomial>        &fits)
    {
      const FiniteElement<2>          &fe   = sub.fe();
      const std::vector<Point<2>>     &unit = fe.get_unit_support_points();
      std::vector<std::vector<double>> values(fits.size(),
                                              std::vector<double>(unit.size()));
      for (unsigned int i = 0; i < unit.size(); ++i)
        {
          const Point<2> x =
            sub.mapping().transform_unit_to_real_cell(cell, unit[i]);
          const unsigned int component = fe.system_to_component_index(i).first;
          for (unsigned int f = 0; f < fits.size(); ++f)
            values[f][i] = fits[f](x)[component];
        }
      return values;
    }


    /// z~ - I z~ at the quadrature points of @p v (the cell's own values).
    Tensor<1, 2>
    weight(const FEValuesBase<2>     &v,
           const unsigned int         q,
           const LocalPolynomial     &fit,
           const std::vector<double> &nodal)
    {
      Tensor<1, 2> w = fit(v.quadrature_point(q));
      for (unsigned int i = 0; i < nodal.size(); ++i)
        w[v.get_fe().system_to_component_index(i).first] -=
          nodal[i] * v.shape_value(i, q);
      return w;
    }


    /// The stress of the state at the points of @p v: C (eps(w) - eps*).
    std::vector<SymmetricTensor<2, 2>>
    stresses(const FEValuesBase<2>   &v,
             const ElasticSubproblem &sub,
             const Vector<double>    &w,
             const Point<2>          &inside)
    {
      const FEValuesExtractors::Vector   displacement(0);
      std::vector<SymmetricTensor<2, 2>> eps(v.n_quadrature_points);
      v[displacement].get_function_symmetric_gradients(w, eps);
      const auto        cell   = v.get_cell();
      const ElasticLaw &law    = sub.law(*cell);
      const VolumeLoad *volume = sub.volume_load();
      for (unsigned int q = 0; q < eps.size(); ++q)
        {
          if (volume != nullptr && volume->has_eigenstrain())
            eps[q] -= volume->in(*cell).eigenstrain(
              v.quadrature_point(q) + 1e-9 * (inside - v.quadrature_point(q)));
          eps[q] = law.stress(eps[q]);
        }
      return eps;
    }


    /// The cell residual f + div sigma(w) at the quadrature points.
    std::vector<Tensor<1, 2>>
    cell_residual(const FEValues<2>       &fe_values,
                  const ElasticSubproblem &sub,
                  const Vector<double>    &w)
    {
      const FEValuesExtractors::Vector displacement(0);
      std::vector<Tensor<3, 2>>        hessians(fe_values.n_quadrature_points);
      fe_values[displacement].get_function_hessians(w, hessians);
      const auto                cell   = fe_values.get_cell();
      const ElasticLaw         &law    = sub.law(*cell);
      const VolumeLoad         *volume = sub.volume_load();
      std::vector<Tensor<1, 2>> residual(hessians.size());
      for (unsigned int q = 0; q < hessians.size(); ++q)
        {
          const Point<2> &x = fe_values.quadrature_point(q);
          std::array<SymmetricTensor<2, 2>, 2> d_eps_star;
          if (volume != nullptr && volume->has_body_force())
            residual[q] = volume->in(*cell).body_force(x);
          if (volume != nullptr && volume->has_eigenstrain())
            d_eps_star = volume->in(*cell).eigenstrain_gradient(x);
          for (unsigned int j = 0; j < 2; ++j)
            {
              SymmetricTensor<2, 2> d_eps;
              const Tensor<3, 2>   &H = hessians[q];
              d_eps[0][0]             = H[0][0][j];
              d_eps[1][1]             = H[1][1][j];
              d_eps[0][1]             = 0.5 * (H[0][1][j] + H[1][0][j]);
              d_eps -= d_eps_star[j];
              const SymmetricTensor<2, 2> d_sigma = law.stress(d_eps);
              residual[q][0] += d_sigma[0][j];
              residual[q][1] += d_sigma[1][j];
            }
        }
      return residual;
    }

    /// Half the traction jump against the other side @p b, weighted, at the
    /// points of the cell's own face values @p a, added to eta[f](i).
    void
    add_jump_terms(const FEFaceValuesBase<2>              &a,
                   const FEFaceValuesBase<2>              &b,
                   const ElasticSubproblem                &sub,
                   const Vector<double>                   &w,
                   const std::vector<LocalPolynomial>     &fits,
                   const std::vector<std::vector<double>> &nodal,
                   std::vector<Vector<double>>            &eta,
                   const unsigned int                      i)
    {
      const auto sa = stresses(a, sub, w, a.get_cell()->center());
      const auto sb = stresses(b, sub, w, b.get_cell()->center());
      for (const unsigned int q : a.quadrature_point_indices())
        {
          unsigned int qb = 0;
          for (const unsigned int r : b.quadrature_point_indices())
            if (b.quadrature_point(r).distance(a.quadrature_point(q)) <
                b.quadrature_point(qb).distance(a.quadrature_point(q)))
              qb = r;
          const Tensor<1, 2> r = -0.5 * ((sa[q] - sb[qb]) * a.normal_vector(q));
          for (unsigned int f = 0; f < fits.size(); ++f)
            eta[f](i) += r * weight(a, q, fits[f], nodal[f]) * a.JxW(q);
        }
    }
  } // namespace


  namespace goal
  {
    std::vector<Vector<double>>
    weighted_residuals(const ElasticSubproblem                   &sub,
                       const unsigned int                         s,
                       const Interface                           &interface,
                       const Vector<double>                      &w,
                       const BlockVector<double>                 &mu,
                       const std::vector<bool>                   &clamped,
                       const std::vector<const Function<2> *>    &traction,
                       const std::vector<const Vector<double> *> &fields)
    {
      const auto        &tria    = sub.dof_handler().get_triangulation();
      const unsigned int nf      = fields.size();
      const bool         tensor  = sub.fe().reference_cell().is_hyper_cube();
      const unsigned int degree  = sub.fe().degree + 1;
      const Samples      samples = sample(sub, fields);
      std::vector<Vector<double>> eta(nf,
                                      Vector<double>(tria.n_active_cells()));

      const auto cell_rule =
        sub.fe().reference_cell().get_gauss_type_quadrature<2>(sub.fe().degree +
                                                               2);
      const QGauss<1>   face_rule(sub.fe().degree + 2);
      const UpdateFlags face_flags = update_values | update_gradients |
                                     update_quadrature_points |
                                     update_normal_vectors | update_JxW_values;
      FEValues<2>     fe_values(sub.mapping(),
                            sub.fe(),
                            cell_rule,
                            update_values | update_hessians |
                              update_quadrature_points | update_JxW_values);
      FEFaceValues<2> mine(sub.mapping(), sub.fe(), face_rule, face_flags),
        theirs(sub.mapping(), sub.fe(), face_rule, face_flags);
      FESubfaceValues<2> mine_sub(sub.mapping(),
                                  sub.fe(),
                                  face_rule,
                                  face_flags),
        theirs_sub(sub.mapping(), sub.fe(), face_rule, face_flags);
      const double   factor = sub.load_factor();
      Vector<double> t(2);

      for (const auto &cell : sub.dof_handler().active_cell_iterators())
        {
          const auto i     = cell->active_cell_index();
          const auto fits  = reconstruct(cell, samples, degree, tensor, nf);
          const auto nodal = interpolation_values(sub, cell, fits);
          // The cell term.
          fe_values.reinit(cell);
          const auto residual = cell_residual(fe_values, sub, w);
          for (unsigned int f = 0; f < nf; ++f)
            for (const unsigned int q : fe_values.quadrature_point_indices())
              eta[f](i) += residual[q] *
                           weight(fe_values, q, fits[f], nodal[f]) *
                           fe_values.JxW(q);
          const auto jump = [&](const FEFaceValuesBase<2> &a,
                                const FEFaceValuesBase<2> &b) {
            add_jump_terms(a, b, sub, w, fits, nodal, eta, i);
          };
          for (const unsigned int face : cell->face_indices())
            {
              if (cell->at_boundary(face))
                {
                  const types::boundary_id id = cell->face(face)->boundary_id();
                  const bool               sigma = on_sigma(cell->face(face));
                  if (!sigma && id < clamped.size() && clamped[id])
                    continue;
                  // (A side without a traction function is traction free.)
                  const Function<2> *const given =
                    !sigma && id < traction.size() ? traction[id] : nullptr;
                  mine.reinit(cell, face);
                  const auto stress = stresses(mine, sub, w, cell->center());
                  const unsigned int b =
                    sigma ? BoundaryIds::interface_of(id) : 0;
                  for (const unsigned int q : mine.quadrature_point_indices())
                    {
                      const Point<2> &x = mine.quadrature_point(q);
                      Tensor<1, 2>    load;
                      if (sigma)
                        load = interface.multiplier_traction(
                          mu, s, interface.curve(b).parameter(x), b);
                      else if (given != nullptr)
                        {
                          given->vector_value(x, t);
                          load[0] = factor * t[0];
                          load[1] = factor * t[1];
                        }
                      const Tensor<1, 2> r =
                        load - stress[q] * mine.normal_vector(q);
                      for (unsigned int f = 0; f < nf; ++f)
                        eta[f](i) +=
                          r * weight(mine, q, fits[f], nodal[f]) * mine.JxW(q);
                    }
                  continue;
                }
              const auto neighbor = cell->neighbor(face);
              if (cell->face(face)->has_children())
                for (unsigned int c = 0; c < cell->face(face)->n_children();
                     ++c)
                  {
                    const auto child = cell->neighbor_child_on_subface(face, c);
                    mine_sub.reinit(cell, face, c);
                    theirs.reinit(child, cell->neighbor_of_neighbor(face));
                    jump(mine_sub, theirs);
                  }
              else if (tensor && cell->neighbor_is_coarser(face))
                {
                  const auto [nf_face, nf_sub] =
                    cell->neighbor_of_coarser_neighbor(face);
                  mine.reinit(cell, face);
                  theirs_sub.reinit(neighbor, nf_face, nf_sub);
                  jump(mine, theirs_sub);
                }
              else
                {
                  mine.reinit(cell, face);
                  theirs.reinit(neighbor, cell->neighbor_of_neighbor(face));
                  jump(mine, theirs);
                }
            }
        }
      return eta;
    }
  } // namespace goal
} // namespace bilayer
