#include <deal.II/base/quadrature_lib.h>
#include <deal.II/base/symmetric_tensor.h>
#include <deal.II/dofs/dof_handler.h>
#include <deal.II/fe/fe_values.h>

#include <bilayer/core/similarity_breaker.h>
#include <bilayer/core/tasks.h>
#include <bilayer/postprocess/domain_integral.h>
#include <bilayer/postprocess/fracture.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <map>
#include <memory>
#include <vector>

namespace bilayer
{
  using namespace dealii;

  Quadrature<2>
  subdivided_quadrature(const ReferenceCell &cell,
                        const unsigned int   n,
                        const unsigned int   m)
  {
    if (cell == ReferenceCells::Quadrilateral)
      return QIterated<2>(QGauss<1>(n), m);
    const QGaussSimplex<2> base(std::min(n, 4u));
    std::vector<Point<2>>  points;
    std::vector<double>    weights;
    const auto             add = [&](const Point<2>     &origin,
                         const Tensor<1, 2> &e0,
                         const Tensor<1, 2> &e1) {
      for (unsigned int q = 0; q < base.size(); ++q)
        {
          points.push_back(origin + base.point(q)[0] * e0 +
                           base.point(q)[1] * e1);
          weights.push_back(base.weight(q) / (m * m));
        }
    };
    const double h = 1. / m;
    for (unsigned int i = 0; i < m; ++i)
      for (unsigned int j = 0; i + j < m; ++j)
        {
          add(Point<2>(i * h, j * h),
              Tensor<1, 2>({h, 0}),
              Tensor<1, 2>({0, h}));
          if (i + j + 1 < m)
            add(Point<2>((i + 1) * h, (j + 1) * h),
                Tensor<1, 2>({-h, 0}),
                Tensor<1, 2>({0, -h}));
        }
    return Quadrature<2>(points, weights);
  }


  double
  smallest_support_radius(const std::vector<CrackTip>   &tips,
                          const std::vector<ThetaField> &fields,
                          const Point<2>                &center,
                          const double                   diameter)
  {
    const unsigned int n          = tips.size();
    double             smallest_R = 0;
    for (unsigned int t = 0; t < n; ++t)
      if (tips[t].defined() && fields[t].reaches(center, diameter))
        smallest_R = smallest_R == 0 ?
                       tips[t].support_radius :
                       std::min(smallest_R, tips[t].support_radius);
    return smallest_R;
  }


  unsigned int
  support_pieces(const double diameter, const double R)
  {
    return std::clamp<unsigned int>(std::ceil(8 * diameter / R), 1, 32);
  }


  void
  for_each_support_cell(
    const ElasticSubproblem                 &sub,
    const std::vector<CrackTip>             &tips,
    const std::vector<ThetaField>           &fields,
    const UpdateFlags                        flags,
    const std::function<void(const FEValues<2> &,
                             const DoFHandler<2>::active_cell_iterator &,
                             const Point<2> &,
                             const double)> &f)
  {
    // FEValues with the rule subdivided m x m times, by m.
    std::map<unsigned int, std::unique_ptr<FEValues<2>>> by_pieces;
    const SimilarityBreaker fresh(sub.fe().reference_cell());
    const CellExtents      &extents = sub.cell_extents();
    for (unsigned int i = 0; i < extents.size(); ++i)
      {
        // No point of a cell is farther from its centre than its
        // diameter (the vertex mean lies inside the cell).
        const Point<2> &center   = extents.center(i);
        const double    diameter = extents.diameter(i);
        const double    smallest_R =
          smallest_support_radius(tips, fields, center, diameter);
        if (smallest_R == 0)
          continue;
        const unsigned int m           = support_pieces(diameter, smallest_R);
        auto              &fe_values_m = by_pieces[m];
        if (!fe_values_m)
          fe_values_m = std::make_unique<FEValues<2>>(
            sub.mapping(),
            sub.fe(),
            subdivided_quadrature(sub.fe().reference_cell(),
                                  sub.fe().degree + 3,
                                  m),
            flags);
        FEValues<2> &fe_values = *fe_values_m;
        fresh.apply(fe_values);
        fe_values.reinit(extents.cell(i));
        f(fe_values, extents.cell(i), center, diameter);
      }
  }


  namespace
  {
    /// int sigma : (grad u grad theta) - W div theta dx of @p field over the
    /// cell of @p fe_values, grad u at its quadrature points @p grad_u.
    double
    cell_integral(const FEValues<2>               &fe_values,
                  const std::vector<Tensor<2, 2>> &grad_u,
                  const ElasticLaw                &law,
                  const ThetaField                &field)
    {
      double sum = 0;
      for (const unsigned int q : fe_values.quadrature_point_indices())
        {
          const Tensor<2, 2> grad_theta =
            field.gradient(fe_values.quadrature_point(q));
          const SymmetricTensor<2, 2> eps            = symmetrize(grad_u[q]);
          const SymmetricTensor<2, 2> stress         = law.stress(eps);
          const double                energy_density = 0.5 * (stress * eps);
          sum += (scalar_product(Tensor<2, 2>(stress), grad_u[q] * grad_theta) -
                  energy_density * trace(grad_theta)) *
                 fe_values.JxW(q);
        }
      return sum;
    }


    /**
     * The same with the volume terms of @p volume, the load of the cell of
     * the subproblem's load @p whole (docs/fracture.md, "Body
     * forces and eigenstrains"), the loads fixed in space:
     *   int sigma : (grad u grad theta) - W div theta
     *       + sigma : ((grad eps*) theta) + (f . u) div theta
     *       + ((grad f) theta) . u dx,
     * sigma = C (eps(u) - eps*), W = (eps(u) - eps*) : sigma / 2, @p u the
     * values of the displacement at the quadrature points.
     */
    double
    cell_integral(const FEValues<2>               &fe_values,
                  const std::vector<Tensor<2, 2>> &grad_u,
                  const std::vector<Tensor<1, 2>> &u,
                  const ElasticLaw                &law,
                  const VolumeLoad                &whole,
                  const CellLoad                  &volume,
                  const ThetaField                &field)
    {
      const bool eigenstrain = whole.has_eigenstrain();
      const bool body_force  = whole.has_body_force();
      double     sum         = 0;
      for (const unsigned int q : fe_values.quadrature_point_indices())
        {
          const Point<2>       &x          = fe_values.quadrature_point(q);
          const Tensor<2, 2>    grad_theta = field.gradient(x);
          const Tensor<1, 2>    theta      = field.value(x);
          SymmetricTensor<2, 2> elastic    = symmetrize(grad_u[q]);
          if (eigenstrain)
            elastic -= volume.eigenstrain(x);
          const SymmetricTensor<2, 2> stress = law.stress(elastic);
          double                      integrand =
            scalar_product(Tensor<2, 2>(stress), grad_u[q] * grad_theta) -
            law.energy_density(elastic) * trace(grad_theta);
          if (eigenstrain)
            {
              // (grad eps*) theta = sum_j d eps* / d x_j theta_j.
              const auto d_eps = volume.eigenstrain_gradient(x);
              integrand += stress * (d_eps[0] * theta[0] + d_eps[1] * theta[1]);
            }
          if (body_force)
            integrand += (volume.body_force(x) * u[q]) * trace(grad_theta) +
                         (volume.body_force_gradient(x) * theta) * u[q];
          sum += integrand * fe_values.JxW(q);
        }
      return sum;
    }


    /// The domain integral of subproblem @p sub (solution @p u) at each tip.
    void
    subproblem_integrals(const ElasticSubproblem       &sub,
                         const Vector<double>          &u,
                         const std::vector<CrackTip>   &tips,
                         const std::vector<ThetaField> &fields,
                         Vector<double>                &integral)
    {
      const unsigned int n = tips.size();
      integral.reinit(n);
      const FEValuesExtractors::Vector displacement(0);
      const VolumeLoad *const          volume = sub.volume_load();
      std::vector<Tensor<2, 2>>        grad_u;
      std::vector<Tensor<1, 2>>        u_values;
      for_each_support_cell(
        sub,
        tips,
        fields,
        update_gradients | update_quadrature_points | update_JxW_values |
          (volume != nullptr ? update_values : update_default),
        [&](const FEValues<2>                         &fe_values,
            const DoFHandler<2>::active_cell_iterator &cell,
            const Point<2>                            &center,
            const double                               diameter) {
          grad_u.resize(fe_values.n_quadrature_points);
          fe_values[displacement].get_function_gradients(u, grad_u);
          if (volume != nullptr)
            {
              u_values.resize(fe_values.n_quadrature_points);
              fe_values[displacement].get_function_values(u, u_values);
            }
          const ElasticLaw &law = sub.law(*cell);
          for (unsigned int t = 0; t < n; ++t)
            if (tips[t].defined() && fields[t].reaches(center, diameter))
              integral(t) +=
                volume == nullptr ?
                  cell_integral(fe_values, grad_u, law, fields[t]) :
                  cell_integral(fe_values,
                                grad_u,
                                u_values,
                                law,
                                *volume,
                                volume->in(*cell),
                                fields[t]);
        });
    }


    /// The domain integrals of all subproblems, shared and added to G.
    void
    add_domain_integrals(
      const PerSubproblem<const ElasticSubproblem *> &subproblems,
      const Solutions                                &w,
      const std::vector<CrackTip>                    &tips,
      const std::vector<ThetaField>                  &fields,
      std::vector<EnergyReleaseRate>                 &result)
    {
      const unsigned int            n = tips.size();
      PerSubproblem<Vector<double>> integrals(subproblems.size());
      Tasks                         tasks;
      for (const unsigned int s : Layout::indices(subproblems.size()))
        if (subproblems[s] != nullptr && subproblems[s]->owned())
          tasks.add([&, s]() {
            subproblem_integrals(
              *subproblems[s], w[s], tips, fields, integrals[s]);
          });
      tasks.join_all();
      for (const unsigned int s : Layout::indices(subproblems.size()))
        if (subproblems[s] != nullptr)
          {
            if (!subproblems[s]->owned())
              integrals[s].reinit(n);
            subproblems[s]->processes().share(s, integrals[s]);
            for (unsigned int t = 0; t < n; ++t)
              result[t].G += integrals[s](t);
          }
    }


    /// The contact term of each tip on a curved crack, into its contact.
    void
    add_contact_terms(const Interface                &interface,
                      const Solutions                &w,
                      const BlockVector<double>      &mu,
                      const std::vector<CrackTip>    &tips,
                      const std::vector<ThetaField>  &fields,
                      std::vector<EnergyReleaseRate> &result)
    {
      // The contact term on a curved crack: -sign int psi kappa mu_c [u].tau
      // over the segments of the mesh of mu_1 (Gauss quadrature, the
      // multiplier and the jump interpolated from its nodes).
      const unsigned int n              = tips.size();
      bool               curved_contact = false;
      for (const CrackTip &tip : tips)
        curved_contact = curved_contact || (tip.defined() && tip.curved());
      if (curved_contact && interface.contact_parameters().non_penetration)
        {
          const MultiplierSpace &space = interface.space();
          std::vector<double>    shape;
          for (unsigned int t = 0; t < n; ++t)
            if (tips[t].defined() && tips[t].curved())
              {
                // The block across the tip's interface.
                const unsigned int    b     = tips[t].interface;
                const InterfaceCurve &curve = interface.curve(b);
                Vector<double>        tm, tp;
                interface.coupling().crack_face_traces(w, tm, tp, b);
                const auto     &bp = space.breakpoints(b);
                const QGauss<1> gauss(space.degree(b) + 2);
                for (unsigned int e = 0; e + 1 < bp.size(); ++e)
                  {
                    const double mid = 0.5 * (bp[e] + bp[e + 1]);
                    if (!curve.crack().contains(mid) ||
                        !fields[t].reaches(curve.point(mid), bp[e + 1] - bp[e]))
                      continue;
                    for (unsigned int q = 0; q < gauss.size(); ++q)
                      {
                        const double s_q =
                          bp[e] + gauss.point(q)[0] * (bp[e + 1] - bp[e]);
                        space.shape_values(b, s_q, shape);
                        double mu_c = 0, jump = 0;
                        for (unsigned int i = 0; i < shape.size(); ++i)
                          {
                            const unsigned int a = space.node(e, i, b);
                            mu_c +=
                              shape[i] * space.contact_multiplier(mu, a, b);
                            jump += shape[i] *
                                    (tp(Layout::entry(a, Layout::tangential)) -
                                     tm(Layout::entry(a, Layout::tangential)));
                          }
                        const Point<2> x = curve.point(s_q);
                        // kappa: d tau / ds = kappa nu, towards the centre.
                        const double kappa =
                          fields[t].curvature(x, curve.normal(s_q));
                        result[t].contact -=
                          tips[t].sign *
                          fields[t].cutoff((x - tips[t].point).norm()) * kappa *
                          mu_c * jump * gauss.weight(q) * (bp[e + 1] - bp[e]);
                      }
                  }
              }
        }
    }

    /**
     * The friction term of each tip, into its friction (docs/fracture.md
     * §6): int mu_t theta_s d/ds (u- - u+).tau ds + on curved pieces
     * int sign psi kappa mu_t [u].nu ds (the companion of the contact
     * term), the jumps in the node frames, over
     * the crack segments of the mesh of mu_1 that the support of theta
     * reaches (Gauss quadrature; mu_t interpolated from the friction
     * components, at a tip the mean of the crack nodes of its segment, 0 at
     * corners; the jumps from the nodes).
     */
    void
    add_friction_terms(const Interface                &interface,
                       const Solutions                &w,
                       const BlockVector<double>      &mu,
                       const std::vector<CrackTip>    &tips,
                       const std::vector<ThetaField>  &fields,
                       std::vector<EnergyReleaseRate> &result)
    {
      if (!interface.contact_parameters().frictional())
        return;
      const MultiplierSpace &space = interface.space();
      std::vector<double>    shape, derivative, nodal_mu_t;
      for (unsigned int t = 0; t < tips.size(); ++t)
        if (tips[t].defined())
          {
            // The block across the tip's interface.
            const unsigned int    mu_1  = tips[t].interface;
            const InterfaceCurve &curve = interface.curve(mu_1);
            Vector<double>        tm, tp;
            interface.coupling().crack_face_traces(w, tm, tp, mu_1);
            const auto mu_t = [&](const unsigned int a) {
              return space.friction_bound(a, mu_1) > 0 ?
                       mu.block(mu_1)(Layout::entry(a, Layout::tangential)) :
                       0.;
            };
            const auto     &bp = space.breakpoints(mu_1);
            const QGauss<1> gauss(space.degree(mu_1) + 2);
            for (unsigned int e = 0; e + 1 < bp.size(); ++e)
              {
                const double h   = bp[e + 1] - bp[e];
                const double mid = 0.5 * (bp[e] + bp[e + 1]);
                if (!curve.crack().contains(mid) ||
                    !fields[t].reaches(curve.point(mid), h))
                  continue;
                // mu_t at the nodes of the segment. At a node off the crack
                // (a tip: glued, its multiplier the gluing one) the faces
                // still carry the force of the crack nodes next to it: there
                // mu_t is the mean of the segment's friction nodes, not 0,
                // which would miss the work of that force against the slip
                // d/ds (u- - u+).tau ~ r^(-1/2) of the last segment (an
                // error of order sqrt(h) at the tip).
                const unsigned int n_nodes     = space.degree(mu_1) + 1;
                double             crack_sum   = 0;
                unsigned int       crack_count = 0;
                nodal_mu_t.resize(n_nodes);
                for (unsigned int i = 0; i < n_nodes; ++i)
                  {
                    const unsigned int a = space.node(e, i, mu_1);
                    nodal_mu_t[i]        = mu_t(a);
                    if (space.friction_node(a, mu_1))
                      {
                        crack_sum += nodal_mu_t[i];
                        ++crack_count;
                      }
                  }
                for (unsigned int i = 0; i < n_nodes; ++i)
                  if (!space.on_crack(space.node(e, i, mu_1), mu_1) &&
                      crack_count > 0)
                    nodal_mu_t[i] = crack_sum / crack_count;
                for (unsigned int q = 0; q < gauss.size(); ++q)
                  {
                    const double s_q = bp[e] + gauss.point(q)[0] * h;
                    space.shape_values(mu_1, s_q, shape, derivative);
                    double m = 0, d_jump_t = 0, jump_n = 0;
                    for (unsigned int i = 0; i < shape.size(); ++i)
                      {
                        const unsigned int a = space.node(e, i, mu_1);
                        const unsigned int x = Layout::entry(a, 0),
                                           y = Layout::entry(a, 1);
                        m += shape[i] * nodal_mu_t[i];
                        d_jump_t += derivative[i] * (tm(x) - tp(x));
                        jump_n += shape[i] * (tp(y) - tm(y));
                      }
                    const Point<2> x = curve.point(s_q);
                    const double   psi =
                      fields[t].cutoff((x - tips[t].point).norm());
                    double density = m * tips[t].sign * psi * d_jump_t;
                    if (tips[t].curved())
                      density += tips[t].sign * psi *
                                 fields[t].curvature(x, curve.normal(s_q)) * m *
                                 jump_n;
                    result[t].friction += density * gauss.weight(q) * h;
                  }
              }
          }
    }
  } // namespace


  std::vector<EnergyReleaseRate>
  energy_release_rates(
    const PerSubproblem<const ElasticSubproblem *> &subproblems,
    const Interface                                &interface,
    const Solutions                                &w,
    const BlockVector<double>                      &mu,
    const std::vector<CrackTip>                    &tips)
  {
    const unsigned int             n = tips.size();
    std::vector<EnergyReleaseRate> result(n);
    std::vector<ThetaField>        fields;
    for (unsigned int t = 0; t < n; ++t)
      {
        result[t].tip = tips[t];
        fields.emplace_back(tips[t]);
      }

    // The domain integral of each subproblem at each tip, by its owner.
    add_domain_integrals(subproblems, w, tips, fields, result);
    // The contact term on a curved crack.
    add_contact_terms(interface, w, mu, tips, fields, result);
    // The work of the friction force on the crack faces.
    add_friction_terms(interface, w, mu, tips, fields, result);

    for (EnergyReleaseRate &r : result)
      if (r.tip.defined())
        r.G += r.contact + r.friction;
      else
        r.G = std::numeric_limits<double>::quiet_NaN();
    return result;
  }
} // namespace bilayer
