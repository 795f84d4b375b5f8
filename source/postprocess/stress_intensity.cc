// The stress intensity factors of the crack tips by the interaction
// integral (include/bilayer/postprocess/stress_intensity.h).

#include <deal.II/base/quadrature_lib.h>
#include <deal.II/fe/fe_values.h>

#include <bilayer/core/tasks.h>
#include <bilayer/postprocess/domain_integral.h>
#include <bilayer/postprocess/stress_intensity.h>

#include <cmath>
#include <map>
#include <memory>
#include <optional>
#include <string>

namespace bilayer
{
  using namespace dealii;
  using Complex = std::complex<double>;

  namespace
  {
    /// The tip's frame: x1 along the growth, x2 turned by +90 degrees.
    struct TipFrame
    {
      Point<2>     origin;
      Tensor<2, 2> R; // columns e1, e2

      explicit TipFrame(const CrackTip &tip)
        : origin(tip.point)
      {
        const Tensor<1, 2> d = tip.direction / tip.direction.norm();
        R[0][0]              = d[0];
        R[1][0]              = d[1];
        R[0][1]              = -d[1];
        R[1][1]              = d[0];
      }

      Point<2>
      local(const Point<2> &x) const
      {
        return Point<2>(transpose(R) * (x - origin));
      }

      /// A local displacement gradient in the global frame.
      Tensor<2, 2>
      global(const Tensor<2, 2> &g) const
      {
        return R * g * transpose(R);
      }
    };


    /// What a tip needs for its integrals: its field, frame, which side
    /// of its interface is the upper material, and the law of every layer
    /// there (to find cells of another material in the support).
    struct TipSetup
    {
      std::optional<InterfaceCrackField> field;
      std::unique_ptr<TipFrame>          frame;
      bool                               side_1_upper = true;
      std::string                        note;
    };


    /// Lame constants (lambda, mu) of the isotropic tangent @p C, or
    /// nothing where C is not isotropic (to 1e-10 of its largest entry).
    std::optional<std::array<double, 2>>
    lame_constants(const SymmetricTensor<4, 2> &C)
    {
      const double lambda = C[0][0][1][1], mu = C[0][1][0][1];
      const double scale =
        std::max(std::abs(C[0][0][0][0]), std::abs(C[1][1][1][1]));
      const double off = std::max({std::abs(C[0][0][0][0] - lambda - 2 * mu),
                                   std::abs(C[1][1][1][1] - lambda - 2 * mu),
                                   std::abs(C[0][0][0][1]),
                                   std::abs(C[1][1][0][1])});
      if (!(off <= 1e-10 * scale) || !(mu > 0))
        return std::nullopt;
      return std::array<double, 2>{{lambda, mu}};
    }


    TipSetup
    setup(const PerSubproblem<const ElasticSubproblem *> &subproblems,
          const Interface                                &interface,
          const EnergyReleaseRate                        &g)
    {
      TipSetup        s;
      const CrackTip &tip = g.tip;
      if (!std::isfinite(g.G))
        {
          s.note = "G is not reported at this tip";
          return s;
        }
      if (tip.curved())
        {
          s.note = "K is computed at tips on straight interfaces only (here "
                   "G and its closure split)";
          return s;
        }
      if (interface.contact_parameters().frictional())
        {
          s.note = "K is not computed with friction on the crack faces "
                   "(here G and its closure split)";
          return s;
        }
      const Topology &topology = interface.topology();
      const unsigned  i        = tip.interface;
      // The summed Lame constants of the layers on each side.
      std::array<std::array<double, 2>, 2> side_lame = {};
      for (unsigned int side = 0; side < 2; ++side)
        {
          // lambda / mu of the first layer of the side (dimensionless).
          std::optional<double> ratio;
          for (const unsigned int l : Layout::indices(topology.n_slots()))
            {
              const ElasticSubproblem *sub =
                subproblems[topology.index(static_cast<Layer>(l),
                                           topology.regions_of(i)[side])];
              if (sub == nullptr)
                continue;
              const auto lame =
                lame_constants(sub->interface_law(i, tip.point).tangent());
              if (!lame)
                {
                  s.note = "K needs isotropic layers at the tip (an "
                           "anisotropic one here: G and its closure split)";
                  return s;
                }
              const double r = (*lame)[0] / (*lame)[1];
              if (ratio &&
                  std::abs(r - *ratio) > 1e-10 * std::max(1., std::abs(*ratio)))
                {
                  s.note = "K needs the layers on each side of the tip to "
                           "have one Poisson's ratio (here they differ: G "
                           "and its closure split)";
                  return s;
                }
              ratio = r;
              side_lame[side][0] += (*lame)[0];
              side_lame[side][1] += (*lame)[1];
            }
        }
      s.frame = std::make_unique<TipFrame>(tip);
      // nu points from side 0 into side 1.
      const Tensor<1, 2> nu = interface.curve(i).normal(tip.s);
      s.side_1_upper = nu[0] * s.frame->R[0][1] + nu[1] * s.frame->R[1][1] > 0;
      const unsigned int up = s.side_1_upper ? 1 : 0, low = 1 - up;
      const auto         kappa = [](const std::array<double, 2> &lame) {
        return (lame[0] + 3 * lame[1]) / (lame[0] + lame[1]);
      };
      s.field.emplace(side_lame[up][1],
                      kappa(side_lame[up]),
                      side_lame[low][1],
                      kappa(side_lame[low]));
      return s;
    }


    /// The computed field at a point of the support: its gradient, its
    /// stress sigma(w) = C (eps(w) - eps*) and theta there.
    struct PointState
    {
      Point<2>              x;
      Tensor<2, 2>          grad_w;
      SymmetricTensor<2, 2> stress_w;
      Tensor<1, 2>          theta;
      Tensor<2, 2>          grad_theta;
    };


    /**
     * The integrand of the interaction integral at @p p: the mixed part of
     * the domain integral of G between the computed field and the
     * auxiliary one (grad a, a), both in the global frame, with the volume
     * loads of the cell.
     */
    double
    interaction_density(const ElasticLaw   &law,
                        const PointState   &p,
                        const Tensor<2, 2> &grad_a,
                        const Tensor<1, 2> &a,
                        const VolumeLoad   *whole,
                        const CellLoad     &volume)
    {
      const SymmetricTensor<2, 2> eps_a    = symmetrize(grad_a);
      const SymmetricTensor<2, 2> stress_a = law.stress(eps_a);
      double                      density =
        scalar_product(Tensor<2, 2>(p.stress_w), grad_a * p.grad_theta) +
        scalar_product(Tensor<2, 2>(stress_a), p.grad_w * p.grad_theta) -
        (p.stress_w * eps_a) * trace(p.grad_theta);
      if (whole != nullptr && whole->has_eigenstrain())
        {
          const auto d_eps = volume.eigenstrain_gradient(p.x);
          density += stress_a * (d_eps[0] * p.theta[0] + d_eps[1] * p.theta[1]);
        }
      if (whole != nullptr && whole->has_body_force())
        density += (volume.body_force(p.x) * a) * trace(p.grad_theta) +
                   (volume.body_force_gradient(p.x) * p.theta) * a;
      return density;
    }


    /// Whether the tangents @p A and @p B agree to 1e-12 of their largest
    /// entry.
    bool
    same_law(const SymmetricTensor<4, 2> &A, const SymmetricTensor<4, 2> &B)
    {
      double largest = 0, difference = 0;
      for (unsigned int i = 0; i < 2; ++i)
        for (unsigned int j = 0; j < 2; ++j)
          for (unsigned int k = 0; k < 2; ++k)
            for (unsigned int l = 0; l < 2; ++l)
              {
                largest = std::max(
                  {largest, std::abs(A[i][j][k][l]), std::abs(B[i][j][k][l])});
                difference =
                  std::max(difference, std::abs(A[i][j][k][l] - B[i][j][k][l]));
              }
      return difference <= 1e-12 * largest;
    }


    /**
     * The interaction integrals of subproblem @p sub (region @p region,
     * solution @p u) at every tip that has a field and whose interface
     * borders the region: entries 3t and 3t + 1 for K_aux = 1 and i, entry
     * 3t + 2 the number of cells in the support whose material is not the
     * tip's.
     */
    void
    subproblem_interactions(const ElasticSubproblem       &sub,
                            const Topology                &topology,
                            const unsigned int             region,
                            const Vector<double>          &u,
                            const std::vector<CrackTip>   &tips,
                            const std::vector<ThetaField> &fields,
                            const std::vector<TipSetup>   &setups,
                            Vector<double>                &integral)
    {
      const unsigned int n = tips.size();
      integral.reinit(3 * n);
      // The tips this subproblem sees, with the material of each.
      std::vector<CrackTip>              seen(n);
      std::vector<SymmetricTensor<4, 2>> tip_law(n);
      std::vector<bool>                  upper(n);
      bool                               any = false;
      for (unsigned int t = 0; t < n; ++t)
        if (setups[t].field && topology.joins(tips[t].interface, region))
          {
            seen[t] = tips[t];
            tip_law[t] =
              sub.interface_law(tips[t].interface, tips[t].point).tangent();
            const bool side_1 =
              topology.regions_of(tips[t].interface)[1] == region;
            upper[t] = side_1 == setups[t].side_1_upper;
            any      = true;
          }
      if (!any)
        return;
      const FEValuesExtractors::Vector displacement(0);
      const VolumeLoad *const          volume = sub.volume_load();
      const bool                       has_volume_terms =
        volume != nullptr &&
        (volume->has_eigenstrain() || volume->has_body_force());
      std::vector<Tensor<2, 2>> grad_w;
      for_each_support_cell(
        sub,
        seen,
        fields,
        update_gradients | update_quadrature_points | update_JxW_values,
        [&](const FEValues<2>                         &fe_values,
            const DoFHandler<2>::active_cell_iterator &cell,
            const Point<2>                            &center,
            const double                               diameter) {
          grad_w.resize(fe_values.n_quadrature_points);
          fe_values[displacement].get_function_gradients(u, grad_w);
          const ElasticLaw &law = sub.law(*cell);
          const CellLoad    cell_load =
            volume != nullptr ? volume->in(*cell) : CellLoad();
          for (unsigned int t = 0; t < n; ++t)
            {
              if (!seen[t].defined() || !fields[t].reaches(center, diameter))
                continue;
              if (!same_law(law.tangent(), tip_law[t]))
                {
                  integral(3 * t + 2) += 1;
                  continue;
                }
              const TipFrame &frame = *setups[t].frame;
              for (const unsigned int q : fe_values.quadrature_point_indices())
                {
                  const Point<2> &x = fe_values.quadrature_point(q);
                  if ((x - tips[t].point).norm() >= tips[t].support_radius)
                    continue;
                  // Without volume loads the integrand vanishes where
                  // theta is a translation (r <= R/2 on a straight tip).
                  PointState p;
                  p.x          = x;
                  p.grad_theta = fields[t].gradient(x);
                  if (!has_volume_terms && p.grad_theta.norm_square() == 0)
                    continue;
                  p.theta                       = fields[t].value(x);
                  p.grad_w                      = grad_w[q];
                  SymmetricTensor<2, 2> elastic = symmetrize(grad_w[q]);
                  if (volume != nullptr && volume->has_eigenstrain())
                    elastic -= cell_load.eigenstrain(x);
                  p.stress_w = law.stress(elastic);
                  std::array<Tensor<1, 2>, 2> a_local;
                  std::array<Tensor<2, 2>, 2> grad_local;
                  setups[t].field->unit_displacements(frame.local(x),
                                                      upper[t],
                                                      a_local,
                                                      grad_local);
                  for (unsigned int k = 0; k < 2; ++k)
                    integral(3 * t + k) +=
                      interaction_density(law,
                                          p,
                                          frame.global(grad_local[k]),
                                          frame.R * a_local[k],
                                          volume,
                                          cell_load) *
                      fe_values.JxW(q);
                }
            }
        });
    }


    /**
     * The crack faces' part of the interaction integrals of tip @p t with
     * the auxiliary fields K_aux = 1 and i: the contact pressure mu_c
     * (layer 1's faces) against the auxiliary faces' opening,
     *   - int_{gamma_c} psi mu_c d/dx1 (a_upper - a_lower).e2 ds,
     * over the crack segments of the mesh of the tip's multiplier block in
     * the support (Gauss rule; on a segment that ends at the tip in the
     * variable sqrt(r), where the opening's derivative goes as r^(-1/2)).
     */
    std::array<double, 2>
    face_terms(const Interface           &interface,
               const BlockVector<double> &mu,
               const CrackTip            &tip,
               const ThetaField          &field,
               const TipSetup            &setup)
    {
      std::array<double, 2> sum = {{0, 0}};
      if (!interface.contact_parameters().non_penetration)
        return sum;
      const MultiplierSpace &space = interface.space();
      const unsigned int     b     = tip.interface;
      const InterfaceCurve  &curve = interface.curve(b);
      const auto            &bp    = space.breakpoints(b);
      const QGauss<1>        gauss(space.degree(b) + 3);
      std::vector<double>    shape, nodal;
      for (unsigned int e = 0; e + 1 < bp.size(); ++e)
        {
          const double h   = bp[e + 1] - bp[e];
          const double mid = 0.5 * (bp[e] + bp[e + 1]);
          if (!curve.crack().contains(mid) ||
              !field.reaches(curve.point(mid), h))
            continue;
          // The end at the tip, if any, is where the graded rule starts.
          const bool   at_start = std::abs(bp[e] - tip.s) <= 1e-9 * h;
          const bool   at_end   = std::abs(bp[e + 1] - tip.s) <= 1e-9 * h;
          const double from     = at_end ? bp[e + 1] : bp[e];
          const double to       = at_end ? bp[e] : bp[e + 1];
          // mu_c at the nodes of the segment; at a node off the crack (the
          // tip: glued, its multiplier the gluing one) the faces still
          // carry the pressure of the crack nodes next to it, their mean
          // (as in the friction term of G).
          const unsigned int n_nodes     = space.degree(b) + 1;
          double             crack_sum   = 0;
          unsigned int       crack_count = 0;
          nodal.assign(n_nodes, 0.);
          for (unsigned int i = 0; i < n_nodes; ++i)
            if (space.on_crack(space.node(e, i, b), b))
              {
                nodal[i] = space.contact_multiplier(mu, space.node(e, i, b), b);
                crack_sum += nodal[i];
                ++crack_count;
              }
          for (unsigned int i = 0; i < n_nodes; ++i)
            if (!space.on_crack(space.node(e, i, b), b) && crack_count > 0)
              nodal[i] = crack_sum / crack_count;
          for (unsigned int q = 0; q < gauss.size(); ++q)
            {
              const double xi     = gauss.point(q)[0];
              const bool   graded = at_start || at_end;
              const double s_q = from + (to - from) * (graded ? xi * xi : xi);
              const double ds  = gauss.weight(q) * h * (graded ? 2 * xi : 1.);
              space.shape_values(b, s_q, shape);
              double mu_c = 0;
              for (unsigned int i = 0; i < shape.size(); ++i)
                mu_c += shape[i] * nodal[i];
              const Point<2> x = curve.point(s_q);
              const double   r = (x - tip.point).norm();
              if (mu_c == 0 || r >= tip.support_radius)
                continue;
              const Point<2> on(setup.frame->local(x)[0], 0.);
              for (unsigned int k = 0; k < 2; ++k)
                {
                  const Complex K_aux = k == 0 ? Complex(1, 0) : Complex(0, 1);
                  Tensor<1, 2>  a_u, a_l;
                  Tensor<2, 2>  g_u, g_l;
                  setup.field->displacement(on, true, K_aux, a_u, g_u);
                  setup.field->displacement(on, false, K_aux, a_l, g_l);
                  sum[k] -=
                    field.cutoff(r) * mu_c * (g_u[1][0] - g_l[1][0]) * ds;
                }
            }
        }
      return sum;
    }
  } // namespace


  void
  stress_intensity_factors(
    const PerSubproblem<const ElasticSubproblem *> &subproblems,
    const Interface                                &interface,
    const Solutions                                &w,
    const BlockVector<double>                      &mu,
    const double                                    reference_length,
    std::vector<EnergyReleaseRate>                 &release)
  {
    const unsigned int      n = release.size();
    std::vector<CrackTip>   tips;
    std::vector<ThetaField> fields;
    std::vector<TipSetup>   setups;
    bool                    any = false;
    for (unsigned int t = 0; t < n; ++t)
      {
        tips.push_back(release[t].tip);
        fields.emplace_back(release[t].tip);
        setups.push_back(setup(subproblems, interface, release[t]));
        any = any || setups.back().field.has_value();
      }
    // Volume integrals by the owners of the subproblems, shared.
    const Topology               &topology = interface.topology();
    Vector<double>                total(3 * n);
    PerSubproblem<Vector<double>> integrals(subproblems.size());
    Tasks                         tasks;
    for (const unsigned int s : Layout::indices(subproblems.size()))
      if (any && subproblems[s] != nullptr && subproblems[s]->owned())
        tasks.add([&, s]() {
          subproblem_interactions(*subproblems[s],
                                  topology,
                                  topology.region(s),
                                  w[s],
                                  tips,
                                  fields,
                                  setups,
                                  integrals[s]);
        });
    tasks.join_all();
    for (const unsigned int s : Layout::indices(subproblems.size()))
      if (any && subproblems[s] != nullptr)
        {
          if (integrals[s].size() != 3 * n)
            integrals[s].reinit(3 * n);
          subproblems[s]->processes().share(s, integrals[s]);
          total += integrals[s];
        }

    const double nan = std::numeric_limits<double>::quiet_NaN();
    for (unsigned int t = 0; t < n; ++t)
      {
        EnergyReleaseRate &g = release[t];
        g.K_I = g.K_II = g.K_magnitude = g.K_phase_angle = g.oscillation_index =
          g.reference_length = g.G_from_K = nan;
        g.K_note                          = setups[t].note;
        if (!setups[t].field)
          continue;
        if (total(3 * t + 2) > 0)
          {
            g.K_note = "the support of theta holds another material than "
                       "the tip's (a ply boundary): K is not computed; a "
                       "smaller Fracture/Support radius keeps it out";
            continue;
          }
        const auto face =
          face_terms(interface, mu, tips[t], fields[t], setups[t]);
        const InterfaceCrackField &field = *setups[t].field;
        const Complex              K =
          0.5 * field.modulus() *
          Complex(total(3 * t) + face[0], total(3 * t + 1) + face[1]);
        g.oscillation_index   = field.epsilon();
        g.K_magnitude         = std::abs(K);
        g.G_from_K            = std::norm(K) / field.modulus();
        const bool oscillates = std::abs(field.epsilon()) > 1e-12;
        if (oscillates && reference_length == 0)
          {
            g.K_note = "the materials differ across the tip (eps = " +
                       std::to_string(field.epsilon()) +
                       "): K_I, K_II and the phase angle need "
                       "Fracture/Reference length";
            continue;
          }
        const Complex KL =
          oscillates ?
            K * std::exp(
                  Complex(0, field.epsilon() * std::log(reference_length))) :
            K;
        g.K_I           = KL.real();
        g.K_II          = KL.imag();
        g.K_phase_angle = std::atan2(KL.imag(), KL.real()) * 180 / M_PI;
        if (reference_length > 0)
          g.reference_length = reference_length;
      }
  }
} // namespace bilayer
