#include <deal.II/base/exceptions.h>

#include <bilayer/physics/cohesive_law.h>

#include <cmath>
#include <sstream>

namespace bilayer
{
  using namespace dealii;

  namespace
  {
    /**
     * The exponential law (Xu-Needleman type, uncoupled into one effective
     * separation): t = k0 delta exp(-delta / delta_c), so d = 1 -
     * exp(-delta_m / delta_c). In pure mode I the peak is sigma_max at
     * delta_c, and the area G_Ic = e sigma_max delta_c: k0 = e^2
     * sigma_max^2 / G_Ic. At the mixity B, delta_c(B) = sqrt(G_c(B) / k0),
     * the area under the law being k0 delta_c^2 = G_c(B). The law has no
     * final separation: a point is fully damaged (a crack) once the
     * energy it still holds, k0 delta_c^2 (1 + x + x^2 / 2) exp(-x) with
     * x = delta_m / delta_c, is below 1e-6 G_c(B) (x >= x_full = 20.9,
     * where it is 2e-7 G_c(B) and the traction 5e-8 of the peak).
     */
    class ExponentialCohesiveLaw : public CohesiveLaw
    {
    public:
      explicit ExponentialCohesiveLaw(const CohesiveProperties &p)
        : CohesiveLaw(p)
        , k0(std::exp(2.) * p.normal_strength * p.normal_strength /
             p.mode_i_toughness)
      {}

      double
      initial_stiffness() const override
      {
        return k0;
      }

      double
      onset_separation(const double B) const override
      {
        return std::sqrt(toughness(B) / k0);
      }

      double
      damage(const double delta_m, const double B) const override
      {
        const double x = delta_m / onset_separation(B);
        return x >= x_full ? 1. : 1. - std::exp(-x);
      }

      double
      dissipated_energy(const double delta_m, const double B) const override
      {
        const double x = delta_m / onset_separation(B);
        if (x >= x_full)
          return toughness(B);
        return toughness(B) * (1. - (1. + x + 0.5 * x * x) * std::exp(-x));
      }

      std::string
      describe() const override
      {
        std::ostringstream out;
        out << "exponential, k0 " << k0 << ", delta_c " << onset_separation(0)
            << " (mode I) and " << onset_separation(1) << " (mode II)";
        return out.str();
      }

    private:
      const double k0;
      /// Past (1 + x + x^2 / 2) exp(-x) = 1e-6.
      static constexpr double x_full = 20.9;
    };
  } // namespace


  std::unique_ptr<CohesiveLaw>
  make_exponential_cohesive_law(const CohesiveProperties &properties)
  {
    return std::make_unique<ExponentialCohesiveLaw>(properties);
  }
} // namespace bilayer
