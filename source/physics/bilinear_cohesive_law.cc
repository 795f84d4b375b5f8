#include <deal.II/base/exceptions.h>

#include <bilayer/physics/cohesive_law.h>

#include <algorithm>
#include <cmath>
#include <sstream>

namespace bilayer
{
  using namespace dealii;

  namespace
  {
    /// A number as a user would write it.
    std::string
    number(const double x)
    {
      std::ostringstream out;
      out << x;
      return out.str();
    }


    /**
     * The bilinear law with the mixed-mode onset and propagation of Camanho
     * and Davila: the penalty stiffness k0 in both directions, onset
     * separations d_n0 = sigma_max / k0, d_t0 = tau_max / k0; at the
     * mixity B the onset delta_0(B) (Benzeggagh-Kenane: sqrt(d_n0^2 +
     * (d_t0^2 - d_n0^2) B^eta); power law: the quadratic criterion
     * 1 / delta_0^2 = (1 - B) / d_n0^2 + B / d_t0^2) and the final
     * separation delta_f(B) = 2 G_c(B) / (k0 delta_0(B)), so that the area
     * under the law is G_c(B); between them d = delta_f (delta_m -
     * delta_0) / (delta_m (delta_f - delta_0)).
     */
    class BilinearCohesiveLaw : public CohesiveLaw
    {
    public:
      explicit BilinearCohesiveLaw(const CohesiveProperties &p)
        : CohesiveLaw(p)
        , k0(p.penalty_stiffness)
      {
        // The law needs delta_f > delta_0 in each pure mode: 2 G_c k0 >
        // strength^2.
        for (const double B : {0., 1.})
          {
            const double d0 = onset_separation(B);
            if (!(final_separation(B) > d0))
              {
                const double s = k0 * d0;
                AssertThrow(false,
                            ExcMessage(
                              "Cohesive/Bilinear/Penalty stiffness must exceed "
                              "strength^2 / (2 G_c) = " +
                              number(s * s / (2 * toughness(B))) + " (mode " +
                              (B == 0 ? "I" : "II") +
                              "; a smaller strength or a larger toughness "
                              "also does), got " +
                              entries::number(k0)));
              }
          }
      }

      double
      initial_stiffness() const override
      {
        return k0;
      }

      double
      onset_separation(const double B) const override
      {
        const double dn = properties.normal_strength / k0,
                     dt = properties.shear_strength / k0;
        // (The pure modes alone: an extreme strength of the other mode
        // must not enter, inf times 0.)
        if (B <= 0)
          return dn;
        if (B >= 1)
          return dt;
        if (properties.criterion == CohesiveCriterion::benzeggagh_kenane)
          return std::sqrt(dn * dn + (dt * dt - dn * dn) * mixing(B));
        return 1. / std::sqrt((1 - B) / (dn * dn) + B / (dt * dt));
      }

      double
      final_separation(const double B) const
      {
        return 2 * toughness(B) / (k0 * onset_separation(B));
      }

      double
      damage(const double delta_m, const double B) const override
      {
        const double d0 = onset_separation(B), df = final_separation(B);
        if (delta_m <= d0)
          return 0.;
        if (delta_m >= df)
          return 1.;
        return df * (delta_m - d0) / (delta_m * (df - d0));
      }

      double
      dissipated_energy(const double delta_m, const double B) const override
      {
        const double d0 = onset_separation(B), df = final_separation(B);
        if (delta_m <= d0)
          return 0.;
        if (delta_m >= df)
          return toughness(B);
        // The area up to delta_m less the secant's triangle.
        const double s0   = k0 * d0;
        const double t    = s0 * (df - delta_m) / (df - d0);
        const double area = 0.5 * s0 * d0 + 0.5 * (s0 + t) * (delta_m - d0);
        return area - 0.5 * t * delta_m;
      }

      std::string
      describe() const override
      {
        std::ostringstream out;
        out << "bilinear, k0 " << k0 << ", onset " << onset_separation(0)
            << " (mode I) and " << onset_separation(1)
            << " (mode II), final separation " << final_separation(0) << " and "
            << final_separation(1);
        return out.str();
      }

    private:
      const double k0;
    };
  } // namespace


  std::unique_ptr<CohesiveLaw>
  make_bilinear_cohesive_law(const CohesiveProperties &properties)
  {
    return std::make_unique<BilinearCohesiveLaw>(properties);
  }
} // namespace bilayer
