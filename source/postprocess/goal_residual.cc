// The weighted residual of the goal-oriented estimates: the patchwise
// reconstruction of degree p + 1 of a field, and the residual of the state
// of a subproblem against its interpolation error (docs/fracture.md §11).

#include <deal.II/base/quadrature_lib.h>
#include <deal.II/fe/fe_values.h>
#include <deal.II/lac/lapack_full_matrix.h>

#include <bilayer/core/boundary_ids.h>
#include <bilayer/core/similarity_breaker.h>
#include <bilayer/postprocess/goal_estimate.h>
#include <bilayer/postprocess/stress_divergence.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <functional>
#include <map>

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
      // (LocalPolynomial::basis() holds the powers up to 7.)
      AssertThrow(k <= 7, ExcMessage("reconstruction degree above 7"));
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
      /// The tips whose near-tip functions enrich the fit (none: a plain
      /// polynomial).
      std::vector<goal::TipFrame>   tips;
      std::array<Vector<double>, 2> coefficients;

      /// The basis functions at @p x into @p b: the monomials, then per
      /// tip (r/h)^(1/2) (cos, sin)(theta/2) and (cos, sin)(3 theta/2),
      /// theta the angle from the direction of growth (the r^(1/2) terms
      /// of the Williams expansion, each component).
      void
      basis(const Point<2> &x, std::vector<double> &b) const
      {
        const double          xi = (x[0] - c[0]) / h, eta = (x[1] - c[1]) / h;
        std::array<double, 8> px, py;
        px[0] = py[0] = 1;
        for (unsigned int k = 1; k < px.size(); ++k)
          {
            px[k] = px[k - 1] * xi;
            py[k] = py[k - 1] * eta;
          }
        b.resize(e.size() + 4 * tips.size());
        for (unsigned int k = 0; k < e.size(); ++k)
          b[k] = px[e[k][0]] * py[e[k][1]];
        for (unsigned int t = 0; t < tips.size(); ++t)
          {
            const Tensor<1, 2>  r = x - tips[t].point;
            const Tensor<1, 2> &d = tips[t].direction;
            const double  theta = std::atan2(d[0] * r[1] - d[1] * r[0], d * r);
            const double  root  = std::sqrt(r.norm() / h);
            double *const f     = &b[e.size() + 4 * t];
            f[0]                = root * std::cos(theta / 2);
            f[1]                = root * std::sin(theta / 2);
            f[2]                = root * std::cos(1.5 * theta);
            f[3]                = root * std::sin(1.5 * theta);
          }
      }

      /// The field at a point whose basis values are @p b.
      Tensor<1, 2>
      operator()(const std::vector<double> &b) const
      {
        Tensor<1, 2> v;
        for (unsigned int k = 0; k < b.size(); ++k)
          {
            v[0] += coefficients[0](k) * b[k];
            v[1] += coefficients[1](k) * b[k];
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
    /// of @p cell, enriched at a tip with its near-tip functions (the
    /// pseudo-inverse of the normal equations of the columns scaled to unit
    /// norm, singular values below 1e-8 dropped, i.e. directions the
    /// samples determine to less than 1e-4 of the best: a patch that does
    /// not determine them, e.g. a cell with no neighbour, or near-tip
    /// functions that the polynomials nearly represent, keep the rest).
    /// The scaled pseudo-inverse of the normal equations of one patch
    /// shape: the patches of a mesh that equal each other up to a
    /// translation and a scaling (most of a structured or uniformly refined
    /// mesh) share it.
    struct PatchSolver
    {
      std::vector<double>      scale;
      LAPACKFullMatrix<double> inverse;
    };
    using PatchSolvers = std::map<std::vector<std::int64_t>, PatchSolver>;


    std::vector<LocalPolynomial>
    reconstruct(const DoFHandler<2>::active_cell_iterator &cell,
                const Samples                             &samples,
                const unsigned int                         degree,
                const bool                                 tensor,
                const unsigned int                         n_fields,
                const std::vector<goal::TipFrame>         &tips,
                PatchSolvers                              &solvers)
    {
      LocalPolynomial base;
      base.c = cell->center();
      base.h = cell->diameter();
      base.e = exponents(degree, tensor);
      for (const goal::TipFrame &tip : tips)
        if (cell->center().distance(tip.point) <
            goal::enrichment_radius * base.h)
          base.tips.push_back(tip);
      const unsigned int               n = base.e.size() + 4 * base.tips.size();
      const std::vector<unsigned int>  cells = patch(cell);
      std::vector<std::vector<double>> rows;
      std::vector<std::int64_t>        shape;
      for (const unsigned int k : cells)
        for (const Point<2> &x : samples.x[k])
          {
            rows.emplace_back();
            base.basis(x, rows.back());
            for (unsigned int d = 0; d < 2; ++d)
              shape.push_back(std::llround((x[d] - base.c[d]) / base.h * 1e9));
          }
      // (Enriched patches depend on the tip: not shared.)
      PatchSolver  own;
      PatchSolver *solver = &own;
      bool         known  = false;
      if (base.tips.empty())
        {
          const auto [entry, inserted] = solvers.try_emplace(shape);
          solver                       = &entry->second;
          known                        = !inserted;
        }
      if (!known)
        {
          // The normal equations of the columns scaled to unit norm.
          solver->scale.assign(n, 0.);
          for (const auto &row : rows)
            for (unsigned int a = 0; a < n; ++a)
              solver->scale[a] += row[a] * row[a];
          for (double &c : solver->scale)
            c = c > 0 ? 1 / std::sqrt(c) : 0;
          LAPACKFullMatrix<double> &normal = solver->inverse;
          normal.reinit(n, n);
          for (const auto &row : rows)
            for (unsigned int a = 0; a < n; ++a)
              for (unsigned int b = 0; b < n; ++b)
                normal(a, b) +=
                  row[a] * solver->scale[a] * row[b] * solver->scale[b];
          normal.compute_inverse_svd(1e-8);
        }
      const std::vector<double>   &scale = solver->scale;
      std::vector<LocalPolynomial> fits(n_fields, base);
      Vector<double>               rhs(n);
      for (unsigned int f = 0; f < n_fields; ++f)
        for (unsigned int d = 0; d < 2; ++d)
          {
            rhs            = 0;
            unsigned int r = 0;
            for (const unsigned int k : cells)
              for (unsigned int q = 0; q < samples.x[k].size(); ++q, ++r)
                for (unsigned int a = 0; a < n; ++a)
                  rhs(a) += rows[r][a] * scale[a] * samples.values[k][f][q][d];
            fits[f].coefficients[d].reinit(n);
            solver->inverse.vmult(fits[f].coefficients[d], rhs);
            for (unsigned int a = 0; a < n; ++a)
              fits[f].coefficients[d](a) *= scale[a];
          }
      return fits;
    }


    /// The element's interpolation of the fits: their values at the
    /// support points of the cell's shape functions (@p at: FEValues on
    /// the unit support points, reinitialised on the cell), by field.
    std::vector<std::vector<double>>
    interpolation_values(const FEValues<2>                  &at,
                         const std::vector<LocalPolynomial> &fits)
    {
      const FiniteElement<2>          &fe = at.get_fe();
      const unsigned int               n  = at.n_quadrature_points;
      std::vector<std::vector<double>> values(fits.size(),
                                              std::vector<double>(n));
      std::vector<double>              b;
      for (unsigned int i = 0; i < n; ++i)
        {
          fits[0].basis(at.quadrature_point(i), b);
          const unsigned int component = fe.system_to_component_index(i).first;
          for (unsigned int f = 0; f < fits.size(); ++f)
            values[f][i] = fits[f](b)[component];
        }
      return values;
    }


    /// z~ - I z~ of each field at the quadrature point @p q of @p v (the
    /// cell's own values), into @p w.
    void
    weights(const FEValuesBase<2>                  &v,
            const unsigned int                      q,
            const std::vector<LocalPolynomial>     &fits,
            const std::vector<std::vector<double>> &nodal,
            std::vector<Tensor<1, 2>>              &w)
    {
      thread_local std::vector<double> b;
      fits[0].basis(v.quadrature_point(q), b);
      w.resize(fits.size());
      for (unsigned int f = 0; f < fits.size(); ++f)
        {
          w[f] = fits[f](b);
          for (unsigned int i = 0; i < nodal[f].size(); ++i)
            w[f][v.get_fe().system_to_component_index(i).first] -=
              nodal[f][i] * v.shape_value(i, q);
        }
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
          residual[q] += stress_divergence(law, hessians[q], d_eps_star);
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
      std::vector<Tensor<1, 2>> omega;
      for (const unsigned int q : a.quadrature_point_indices())
        {
          unsigned int qb = 0;
          for (const unsigned int r : b.quadrature_point_indices())
            if (b.quadrature_point(r).distance(a.quadrature_point(q)) <
                b.quadrature_point(qb).distance(a.quadrature_point(q)))
              qb = r;
          const Tensor<1, 2> r = -0.5 * ((sa[q] - sb[qb]) * a.normal_vector(q));
          weights(a, q, fits, nodal, omega);
          for (unsigned int f = 0; f < fits.size(); ++f)
            eta[f](i) += r * omega[f] * a.JxW(q);
        }
    }

    /// The side residual g - sigma n (g = @p load, the traction given on
    /// the side or the multipliers' on an interface), weighted, at the
    /// points of the cell's face values @p v, added to eta[f](i).
    void
    add_side_terms(const FEFaceValuesBase<2>                           &v,
                   const ElasticSubproblem                             &sub,
                   const Vector<double>                                &w,
                   const std::function<Tensor<1, 2>(const Point<2> &)> &load,
                   const std::vector<LocalPolynomial>                  &fits,
                   const std::vector<std::vector<double>>              &nodal,
                   std::vector<Vector<double>>                         &eta,
                   const unsigned int                                   i)
    {
      const auto stress = stresses(v, sub, w, v.get_cell()->center());
      std::vector<Tensor<1, 2>> omega;
      for (const unsigned int q : v.quadrature_point_indices())
        {
          const Tensor<1, 2> r =
            load(v.quadrature_point(q)) - stress[q] * v.normal_vector(q);
          weights(v, q, fits, nodal, omega);
          for (unsigned int f = 0; f < fits.size(); ++f)
            eta[f](i) += r * omega[f] * v.JxW(q);
        }
    }

    /// The cell residual f + div sigma(w), weighted, at the points of
    /// @p v, added to eta[f](K).
    void
    add_cell_terms(const FEValues<2>                      &v,
                   const ElasticSubproblem                &sub,
                   const Vector<double>                   &w,
                   const std::vector<LocalPolynomial>     &fits,
                   const std::vector<std::vector<double>> &nodal,
                   std::vector<Vector<double>>            &eta)
    {
      const auto                residual = cell_residual(v, sub, w);
      const auto                i        = v.get_cell()->active_cell_index();
      std::vector<Tensor<1, 2>> omega;
      for (const unsigned int q : v.quadrature_point_indices())
        {
          weights(v, q, fits, nodal, omega);
          for (unsigned int f = 0; f < fits.size(); ++f)
            eta[f](i) += residual[q] * omega[f] * v.JxW(q);
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
                       const std::vector<const Vector<double> *> &fields,
                       const std::vector<TipFrame>               &tips)
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
      PatchSolvers   solvers;
      FEValues<2>    support_points(sub.mapping(),
                                 sub.fe(),
                                 Quadrature<2>(
                                   sub.fe().get_unit_support_points()),
                                 update_quadrature_points);

      for (const auto &cell : sub.dof_handler().active_cell_iterators())
        {
          const auto i = cell->active_cell_index();
          const auto fits =
            reconstruct(cell, samples, degree, tensor, nf, tips, solvers);
          support_points.reinit(cell);
          const auto nodal = interpolation_values(support_points, fits);
          fe_values.reinit(cell);
          add_cell_terms(fe_values, sub, w, fits, nodal, eta);
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
                  const unsigned int b =
                    sigma ? BoundaryIds::interface_of(id) : 0;
                  add_side_terms(
                    mine,
                    sub,
                    w,
                    [&](const Point<2> &x) {
                      Tensor<1, 2> load;
                      if (sigma)
                        load = interface.multiplier_traction(
                          mu, s, interface.curve(b).parameter(x), b);
                      else if (given != nullptr)
                        {
                          given->vector_value(x, t);
                          load[0] = factor * t[0];
                          load[1] = factor * t[1];
                        }
                      return load;
                    },
                    fits,
                    nodal,
                    eta,
                    i);
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
