#include <deal.II/base/exceptions.h>

#include <bilayer/physics/cohesive_law.h>

#include <cmath>

namespace bilayer
{
  using namespace dealii;

  std::unique_ptr<CohesiveLaw>
  make_bilinear_cohesive_law(const CohesiveProperties &properties);
  std::unique_ptr<CohesiveLaw>
  make_exponential_cohesive_law(const CohesiveProperties &properties);


  double
  CohesiveLaw::mixing(const double B) const
  {
    return std::pow(std::max(B, 0.), properties.exponent);
  }


  double
  CohesiveLaw::toughness(const double B) const
  {
    const double g1 = properties.mode_i_toughness,
                 g2 = properties.mode_ii_toughness;
    if (B <= 0)
      return g1;
    if (B >= 1)
      return g2;
    if (properties.criterion == CohesiveCriterion::benzeggagh_kenane)
      return g1 + (g2 - g1) * mixing(B);
    // ((1 - B) G / G_Ic)^a + (B G / G_IIc)^a = 1.
    const double a = properties.exponent;
    return std::pow(std::pow((1 - B) / g1, a) + std::pow(B / g2, a), -1 / a);
  }


  std::unique_ptr<CohesiveLaw>
  make_cohesive_law(const CohesiveProperties &properties)
  {
    switch (properties.type)
      {
        case CohesiveLawType::bilinear:
          return make_bilinear_cohesive_law(properties);
        case CohesiveLawType::exponential:
          return make_exponential_cohesive_law(properties);
        default:
          return nullptr;
      }
  }
} // namespace bilayer
