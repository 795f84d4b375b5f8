#include <deal.II/base/quadrature_lib.h>
#include <deal.II/fe/fe_values.h>
#include <deal.II/numerics/error_estimator.h>

#include <bilayer/core/boundary_ids.h>
#include <bilayer/core/similarity_breaker.h>
#include <bilayer/core/tasks.h>
#include <bilayer/interface/interface_diagnostics.h>
#include <bilayer/postprocess/estimator.h>
#include <bilayer/postprocess/stress_divergence.h>

#include <algorithm>
#include <array>
#include <cmath>

namespace bilayer
{
  using namespace dealii;

  double
  normalisation_scale(
    const PerSubproblem<const ElasticSubproblem *> &subproblems,
    const Solutions                                &w)
  {
    double              largest   = 0;
    const Distribution *processes = nullptr;
    for (const unsigned int s : Layout::indices(subproblems.size()))
      if (subproblems[s] != nullptr)
        {
          processes = &subproblems[s]->processes();
          if (subproblems[s]->owned() && w[s].size() > 0)
            largest = std::max(largest, w[s].linfty_norm());
        }
    if (processes != nullptr)
      largest = processes->max(largest);
    if (!(largest > 0) || !std::isfinite(largest))
      return 1;
    int exponent = 0;
    std::frexp(largest, &exponent);
    return std::ldexp(1., exponent);
  }


  namespace
  {
    /// The complementarity term of a face of layer 1 on the crack, added to
    /// @p term: @p contact_weight times the complementarity of each segment
    /// of the mu_1 mesh under the face, by overlap, over @p scale.
    void
    add_crack_complementarity(const InterfaceCurve               &curve,
                              const std::vector<ContactSegment>  &contact,
                              const DoFHandler<2>::face_iterator &face,
                              const double contact_weight,
                              const double scale,
                              double      &term)
    {
      const double s0 = curve.parameter(face->vertex(0)),
                   s1 = curve.parameter(face->vertex(1));
      const double x0 = std::min(s0, s1);
      const double x1 = std::max(s0, s1);
      auto         it = std::lower_bound(contact.begin(),
                                 contact.end(),
                                 x0,
                                 [](const ContactSegment &c, const double x) {
                                   return c.b <= x;
                                 });
      for (; it != contact.end() && it->a < x1; ++it)
        {
          const double overlap = std::min(x1, it->b) - std::max(x0, it->a);
          if (overlap > 0)
            term += contact_weight * std::abs(it->complementarity) * overlap /
                    (it->b - it->a) / scale;
        }
    }


    /// The eigenstrain of @p sub, or null where it has none.
    const VolumeLoad *
    eigenstrain_of(const ElasticSubproblem &sub)
    {
      const VolumeLoad *volume = sub.volume_load();
      return volume != nullptr && volume->has_eigenstrain() ? volume : nullptr;
    }


    /// The integral over the Sigma face @p f of @p cell of
    /// |sigma(w) n - t|^2 / scale^2, t the traction of the multipliers,
    /// sigma(w) = C (eps(w) - eps* / S) with an eigenstrain (@p w and the
    /// multipliers are the solution's over @p S).
    double
    face_residual(const ElasticSubproblem                   &sub,
                  const unsigned int                         s,
                  const Interface                           &interface,
                  const Vector<double>                      &w,
                  const BlockVector<double>                 &mu,
                  const double                               S,
                  const DoFHandler<2>::active_cell_iterator &cell,
                  const unsigned int                         f,
                  FEFaceValues<2>                           &fe_face,
                  std::vector<SymmetricTensor<2, 2>>        &strain)
    {
      // The interface of the face.
      const unsigned int i =
        BoundaryIds::interface_of(cell->face(f)->boundary_id());
      const FEValuesExtractors::Vector displacement(0);
      const ElasticLaw                &law         = sub.law(*cell);
      const VolumeLoad *const          eigenstrain = eigenstrain_of(sub);
      const double                     scale       = law.energy_norm_scale();
      const CellLoad                   load =
        eigenstrain != nullptr ? eigenstrain->in(*cell) : CellLoad();
      fe_face.reinit(cell, f);
      fe_face[displacement].get_function_symmetric_gradients(w, strain);
      double sum = 0;
      for (const unsigned int q : fe_face.quadrature_point_indices())
        {
          if (eigenstrain != nullptr)
            strain[q] -= load.eigenstrain(fe_face.quadrature_point(q)) / S;
          const SymmetricTensor<2, 2> stress = law.stress(strain[q]);
          const Tensor<1, 2>          residual =
            stress * fe_face.normal_vector(q) -
            interface.multiplier_traction(mu,
                                          s,
                                          interface.curve(i).parameter(
                                            fe_face.quadrature_point(q)),
                                          i);
          sum += (residual * residual) / (scale * scale) * fe_face.JxW(q);
        }
      return sum;
    }


    /// The Sigma terms of the squared indicators of one subproblem, added to
    /// @p eta2: the residual of the multiplier load on the Sigma faces, and
    /// on the crack faces of layer 1 the complementarity.
    void
    add_sigma_terms(const ElasticSubproblem                        &sub,
                    const unsigned int                              s,
                    const Interface                                &interface,
                    const Vector<double>                           &w,
                    const BlockVector<double>                      &mu,
                    const double                                    S,
                    const std::vector<std::vector<ContactSegment>> &contact,
                    const double         contact_weight,
                    const Quadrature<1> &face_quadrature,
                    Vector<double>      &eta2)
    {
      FEFaceValues<2>                    fe_face(sub.mapping(),
                              sub.fe(),
                              face_quadrature,
                              update_gradients | update_quadrature_points |
                                update_normal_vectors | update_JxW_values);
      std::vector<SymmetricTensor<2, 2>> strain(face_quadrature.size());
      for (const auto &cell : sub.dof_handler().active_cell_iterators())
        for (const auto f : cell->face_indices())
          if (on_sigma(cell->face(f)))
            {
              const double scale = sub.law(*cell).energy_norm_scale();
              const double sum   = face_residual(
                sub, s, interface, w, mu, S, cell, f, fe_face, strain);
              double term = cell->face(f)->diameter() / 24. * sum;
              // Layer 1 on the crack: the complementarity of the segments
              // of the mesh of the block across the interface under the
              // face, by overlap.
              const unsigned int i =
                BoundaryIds::interface_of(cell->face(f)->boundary_id());
              const InterfaceCurve &curve = interface.curve(i);
              if (interface.topology().layer(s) == Layer::first &&
                  curve.crack().contains(
                    curve.parameter(cell->face(f)->center())))
                add_crack_complementarity(curve,
                                          contact[i],
                                          cell->face(f),
                                          contact_weight,
                                          scale,
                                          term);
              eta2[cell->active_cell_index()] += term;
            }
    }


    /**
     * The cell residual of a subproblem with a VolumeLoad, added to
     * @p eta2: h_K^2 / 12 int_K |f + div sigma(w)|^2 / scale^2 dx with
     * sigma(w) = C (eps(w) - eps*), h_K the diameter of the cell, @p w the
     * solution over @p S (so are f and eps* here). The weight is 1/12 of
     * the residual estimator's h_K^2, as Kelly's h_F / 24 on the faces is
     * 1/12 of its h_F / 2. div sigma(w) = sum_j C d eps / d x_j e_j from
     * the Hessians of w (the law is linear), d eps* / d x_j from
     * VolumeLoad::eigenstrain_gradient().
     */
    void
    add_cell_residuals(const ElasticSubproblem &sub,
                       const Vector<double>    &w,
                       const double             S,
                       Vector<double>          &eta2)
    {
      const VolumeLoad *const volume = sub.volume_load();
      if (volume == nullptr)
        return;
      const FEValuesExtractors::Vector displacement(0);
      FEValues<2>                      fe_values(
        sub.mapping(),
        sub.fe(),
        sub.fe().reference_cell().get_gauss_type_quadrature<2>(sub.fe().degree +
                                                               1),
        update_hessians | update_quadrature_points | update_JxW_values);
      const SimilarityBreaker   fresh(sub.fe().reference_cell());
      std::vector<Tensor<3, 2>> hessians(fe_values.n_quadrature_points);
      for (const auto &cell : sub.dof_handler().active_cell_iterators())
        {
          fresh.apply(fe_values);
          fe_values.reinit(cell);
          fe_values[displacement].get_function_hessians(w, hessians);
          const ElasticLaw &law   = sub.law(*cell);
          const CellLoad    load  = volume->in(*cell);
          const double      scale = law.energy_norm_scale();
          double            sum   = 0;
          for (const unsigned int q : fe_values.quadrature_point_indices())
            {
              const Point<2> &x = fe_values.quadrature_point(q);
              Tensor<1, 2>    residual;
              if (volume->has_body_force())
                residual = load.body_force(x) / S;
              std::array<SymmetricTensor<2, 2>, 2> d_eps_star;
              if (volume->has_eigenstrain())
                {
                  d_eps_star = load.eigenstrain_gradient(x);
                  d_eps_star[0] /= S;
                  d_eps_star[1] /= S;
                }
              residual += stress_divergence(law, hessians[q], d_eps_star);
              sum += (residual * residual) / (scale * scale) * fe_values.JxW(q);
            }
          const double h = cell->diameter();
          eta2[cell->active_cell_index()] += h * h / 12. * sum;
        }
    }


    /**
     * The part of Kelly's squared indicator of the cell of @p a from its
     * face (or subface) @p a against the neighbour's @p b, as Kelly's
     * (deal.II's cell_diameter_over_24: h_K / 24 int_F |[grad w n]|^2), and
     * the same of the traction jump [sigma(w) n] / s, sigma(w) = C (eps(w) -
     * eps* / S) with each side's law (@p la, @p lb) and eigenstrain, s the
     * smaller energy-norm scale of the two: {gradient term, traction term}.
     */
    std::array<double, 2>
    face_jumps(const FEFaceValuesBase<2> &a,
               const FEFaceValuesBase<2> &b,
               const ElasticLaw          &la,
               const ElasticLaw          &lb,
               const Vector<double>      &w,
               const VolumeLoad          *eigenstrain,
               const double               S)
    {
      const FEValuesExtractors::Vector displacement(0);
      std::vector<Tensor<2, 2>>        grad_a(a.n_quadrature_points),
        grad_b(b.n_quadrature_points);
      a[displacement].get_function_gradients(w, grad_a);
      b[displacement].get_function_gradients(w, grad_b);
      const double scale =
        std::min(la.energy_norm_scale(), lb.energy_norm_scale());
      // Each side's eigenstrain: read just inside its own cell.
      const auto inside = [](const FEFaceValuesBase<2> &v, const Point<2> &p) {
        return p + 1e-9 * (v.get_cell()->center() - p);
      };
      std::array<double, 2> sum = {{0, 0}};
      for (const unsigned int q : a.quadrature_point_indices())
        {
          const Point<2> &x  = a.quadrature_point(q);
          unsigned int    qb = 0;
          for (const unsigned int r : b.quadrature_point_indices())
            if (b.quadrature_point(r).distance(x) <
                b.quadrature_point(qb).distance(x))
              qb = r;
          const Tensor<1, 2>   &n     = a.normal_vector(q);
          SymmetricTensor<2, 2> eps_a = symmetrize(grad_a[q]),
                                eps_b = symmetrize(grad_b[qb]);
          if (eigenstrain != nullptr)
            {
              eps_a -=
                eigenstrain->in(*a.get_cell()).eigenstrain(inside(a, x)) / S;
              eps_b -=
                eigenstrain->in(*b.get_cell()).eigenstrain(inside(b, x)) / S;
            }
          const Tensor<1, 2> gradient = (grad_a[q] - grad_b[qb]) * n;
          const Tensor<1, 2> traction =
            (la.stress(eps_a) * n - lb.stress(eps_b) * n) / scale;
          sum[0] += (gradient * gradient) * a.JxW(q);
          sum[1] += (traction * traction) * a.JxW(q);
        }
      return sum;
    }


    /**
     * On the faces between plies of different laws, where the gradient of
     * the solution jumps and its traction does not, Kelly's term is replaced
     * by the same term of the traction jump (face_jumps()): the squared
     * indicator of each cell with such a face becomes h_K / 24 times the
     * sum over its interior faces of the traction term on those faces and
     * Kelly's gradient term on the others (all in double precision:
     * Kelly's own indicators are single precision). Elsewhere, and without
     * such plies, @p eta2 stays as it is, bit for bit. The faces as Kelly
     * takes them: a whole face against a neighbour of the same level, a
     * subface against each finer neighbour, a face against the subface of a
     * coarser neighbour.
     */
    void
    replace_ply_face_terms(const ElasticSubproblem &sub,
                           const Vector<double>    &w,
                           const double             S,
                           const Quadrature<1>     &quadrature,
                           Vector<double>          &eta2)
    {
      const PlyLaws                 &laws = sub.laws();
      const unsigned int             n    = laws.size();
      std::vector<std::vector<bool>> differ(n, std::vector<bool>(n, false));
      bool                           any = false;
      for (unsigned int i = 0; i < n; ++i)
        for (unsigned int j = 0; j < n; ++j)
          {
            differ[i][j] = laws.law(i).tangent() != laws.law(j).tangent();
            any          = any || differ[i][j];
          }
      if (!any)
        return;
      const UpdateFlags flags = update_gradients | update_quadrature_points |
                                update_normal_vectors | update_JxW_values;
      FEFaceValues<2> mine(sub.mapping(), sub.fe(), quadrature, flags),
        theirs(sub.mapping(), sub.fe(), quadrature, flags);
      const bool quads = sub.fe().reference_cell().is_hyper_cube();
      std::unique_ptr<FESubfaceValues<2>> mine_sub, theirs_sub;
      if (quads)
        {
          mine_sub   = std::make_unique<FESubfaceValues<2>>(sub.mapping(),
                                                          sub.fe(),
                                                          quadrature,
                                                          flags);
          theirs_sub = std::make_unique<FESubfaceValues<2>>(sub.mapping(),
                                                            sub.fe(),
                                                            quadrature,
                                                            flags);
        }
      const VolumeLoad *const eigenstrain = eigenstrain_of(sub);
      for (const auto &cell : sub.dof_handler().active_cell_iterators())
        {
          const unsigned int ply = laws.ply(*cell);
          // Whether the cell has a face on a ply of another law.
          bool touches = false;
          for (const unsigned int f : cell->face_indices())
            if (!cell->at_boundary(f))
              {
                if (quads && cell->face(f)->has_children())
                  for (unsigned int c = 0; c < cell->face(f)->n_children(); ++c)
                    touches =
                      touches ||
                      differ[ply]
                            [laws.ply(*cell->neighbor_child_on_subface(f, c))];
                else
                  touches =
                    touches || differ[ply][laws.ply(*cell->neighbor(f))];
              }
          if (!touches)
            continue;
          double     sum = 0;
          const auto add = [&](const FEFaceValuesBase<2> &a,
                               const FEFaceValuesBase<2> &b,
                               const unsigned int         ply_b) {
            const auto s = face_jumps(
              a, b, laws.law(ply), laws.law(ply_b), w, eigenstrain, S);
            sum += s[differ[ply][ply_b] ? 1 : 0];
          };
          for (const unsigned int f : cell->face_indices())
            {
              if (cell->at_boundary(f))
                continue;
              const auto neighbor = cell->neighbor(f);
              if (quads && cell->face(f)->has_children())
                for (unsigned int c = 0; c < cell->face(f)->n_children(); ++c)
                  {
                    const auto child = cell->neighbor_child_on_subface(f, c);
                    mine_sub->reinit(cell, f, c);
                    theirs.reinit(child, cell->neighbor_of_neighbor(f));
                    add(*mine_sub, theirs, laws.ply(*child));
                  }
              else if (quads && cell->neighbor_is_coarser(f))
                {
                  const auto [face, subface] =
                    cell->neighbor_of_coarser_neighbor(f);
                  mine.reinit(cell, f);
                  theirs_sub->reinit(neighbor, face, subface);
                  add(mine, *theirs_sub, laws.ply(*neighbor));
                }
              else
                {
                  mine.reinit(cell, f);
                  theirs.reinit(neighbor, cell->neighbor_of_neighbor(f));
                  add(mine, theirs, laws.ply(*neighbor));
                }
            }
          eta2[cell->active_cell_index()] = cell->diameter() / 24 * sum;
        }
    }


    /// The squared indicators of subproblem @p s, by active cell: Kelly's,
    /// with a VolumeLoad the cell residual, and with @p interface_terms the
    /// Sigma terms.
    void
    squared_indicators(const ElasticSubproblem   &sub,
                       const unsigned int         s,
                       const Interface           &interface,
                       const Vector<double>      &w,
                       const BlockVector<double> &mu,
                       const double               S,
                       const std::vector<std::vector<ContactSegment>> &contact,
                       const bool      interface_terms,
                       const double    contact_weight,
                       Vector<double> &eta2)
    {
      const auto &tria = sub.dof_handler().get_triangulation();
      eta2.reinit(tria.n_active_cells());

      Vector<float> kelly(tria.n_active_cells());
      const auto    face_quadrature =
        ReferenceCells::Line.get_gauss_type_quadrature<1>(sub.fe().degree + 1);
      KellyErrorEstimator<2>::estimate(
        sub.mapping(), sub.dof_handler(), face_quadrature, {}, w, kelly);
      for (unsigned int i = 0; i < kelly.size(); ++i)
        eta2[i] = double(kelly[i]) * kelly[i];
      replace_ply_face_terms(sub, w, S, face_quadrature, eta2);
      add_cell_residuals(sub, w, S, eta2);
      if (!interface_terms)
        return;
      add_sigma_terms(sub,
                      s,
                      interface,
                      w,
                      mu,
                      S,
                      contact,
                      contact_weight,
                      face_quadrature,
                      eta2);
    }


    /// The energy of the squared indicators @p eta2 of @p sub: each times
    /// the energy-norm scale of its cell's law.
    double
    energy_of_indicators(const ElasticSubproblem &sub,
                         const Vector<double>    &eta2)
    {
      if (sub.laws().uniform_energy_norm_scale())
        return sub.laws().law(0).energy_norm_scale() * eta2.l1_norm();
      double sum = 0;
      for (const auto &cell : sub.dof_handler().active_cell_iterators())
        sum += sub.law(*cell).energy_norm_scale() *
               std::abs(eta2[cell->active_cell_index()]);
      return sum;
    }


    /// The indicators of each subdomain: the squared indicators of its
    /// subproblems, sent to all processes and summed in the order of the
    /// subproblems, square root times @p S; their energies are added to
    /// @p energy_estimate.
    std::vector<Vector<double>>
    subdomain_indicators(
      const Topology                                 &topology,
      const PerSubproblem<const ElasticSubproblem *> &subproblems,
      PerSubproblem<Vector<double>>                  &squared,
      const double                                    S,
      double                                         &energy_estimate)
    {
      std::vector<Vector<double>> eta(topology.n_regions());
      for (const unsigned int r : Layout::indices(topology.n_regions()))
        {
          Vector<double> sum;
          for (unsigned int s = topology.index(Layer::first, r);
               s < subproblems.size();
               s += topology.n_regions())
            if (subproblems[s] != nullptr)
              {
                if (!subproblems[s]->owned())
                  squared[s].reinit(subproblems[s]
                                      ->dof_handler()
                                      .get_triangulation()
                                      .n_active_cells());
                subproblems[s]->processes().share(s, squared[s]);
                energy_estimate +=
                  energy_of_indicators(*subproblems[s], squared[s]);
                if (sum.size() == 0)
                  sum = squared[s];
                else
                  sum += squared[s];
              }
          auto &eta_sd = eta[r];
          eta_sd.reinit(sum.size());
          for (unsigned int i = 0; i < sum.size(); ++i)
            eta_sd[i] = std::sqrt(sum[i]) * S;
        }
      return eta;
    }
  } // namespace


  std::vector<Vector<double>>
  estimate_error(const PerSubproblem<const ElasticSubproblem *> &subproblems,
                 const Interface                                &interface,
                 const Solutions                                &w_in,
                 const BlockVector<double>                      &mu_in,
                 const bool   interface_terms,
                 const double contact_weight,
                 double      *global_estimate)
  {
    // The problem is linear in the loads (and the constraints positively
    // homogeneous): the indicators of the solution scaled by a power of
    // two S are computed from the solution divided by S, exactly (the
    // division is exact), in the range where Kelly's single precision
    // indicators and the squares below cannot overflow or underflow, and
    // multiplied by S at the end.
    const double S = normalisation_scale(subproblems, w_in);
    Solutions    w = w_in;
    for (auto &v : w)
      v /= S;
    BlockVector<double> mu = mu_in;
    mu /= S;

    // The squared indicator of each subproblem, evaluated by its owner
    // (the whole solution is needed) and sent to all processes, then
    // summed per subdomain in the order of the subproblems.
    PerSubproblem<Vector<double>> squared(subproblems.size());
    // Per interface.
    std::vector<std::vector<ContactSegment>> contact(interface.n_interfaces());
    if (interface_terms)
      for (const unsigned int i : Layout::indices(contact.size()))
        contact[i] = contact_residual(interface, w, mu, i);
    // The subproblems as parallel tasks (each writes its own squared[s]).
    Tasks tasks;
    for (const unsigned int s : Layout::indices(subproblems.size()))
      if (subproblems[s] != nullptr && subproblems[s]->owned())
        tasks.add([&, s]() {
          squared_indicators(*subproblems[s],
                             s,
                             interface,
                             w[s],
                             mu,
                             S,
                             contact,
                             interface_terms,
                             contact_weight,
                             squared[s]);
        });
    tasks.join_all();

    double                      energy_estimate = 0;
    std::vector<Vector<double>> eta             = subdomain_indicators(
      interface.topology(), subproblems, squared, S, energy_estimate);
    if (global_estimate != nullptr)
      *global_estimate = std::sqrt(energy_estimate) * S;
    return eta;
  }
} // namespace bilayer
