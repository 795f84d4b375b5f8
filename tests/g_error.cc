// The error bar dG of the energy release rate (fracture.h,
// g_error_from_cycles() and set_g_error()) on sequences with a known limit:
//
// - geometric convergence G_k = G + c rho^k (rho = 0.2, 0.5, 0.8, both
//   signs of c): dG = max(d1, d2, d3, d1 r / (1 - r)) bounds the error
//   |G_k - G| from cycle 1 on (on cycle 1, 2 d1 = 2 c (1 - rho) >= c rho
//   for rho <= 2/3), and from cycle 3 on its effectivity is exactly
//   max(1, (1 - rho) / rho^3) (Aitken's remainder d1 r / (1 - r) is the
//   exact error; d3 = d1 / rho^2);
// - oscillating convergence G_k = G + c (-rho)^k: dG = d3 = c rho^(k-3)
//   (1 + rho) from cycle 3 on, effectivity (1 + rho) / rho^3;
// - non-monotone sequences whose last change is zero or changes sign, or
//   that do not contract: dG is the largest change, not zero;
// - no estimate on cycle 0, nor after a cycle where G was not reported
//   (NaN);
// - set_g_error(): the larger of the sequence's estimate and |G(R) -
//   G(R/2)|, naming the estimators; NaN and "none: ..." where neither exists.

#include <bilayer/postprocess/fracture.h>

#include <algorithm>
#include <cmath>
#include <iostream>
#include <limits>
#include <string>
#include <vector>

#include "verdict.h"

using namespace bilayer;

namespace
{
  const double not_a_number = std::numeric_limits<double>::quiet_NaN();

  /// The worst (smallest, largest) effectivity dG / |G_k - G| over the
  /// cycles from @p first on of G_k = G + c q^k, k = 0 .. n-1.
  std::pair<double, double>
  effectivity(const double       G,
              const double       c,
              const double       q,
              const unsigned int n,
              const unsigned int first)
  {
    double              low = std::numeric_limits<double>::max(), high = 0;
    std::vector<double> sequence;
    for (unsigned int k = 0; k < n; ++k)
      {
        sequence.push_back(G + c * std::pow(q, k));
        if (k < first)
          continue;
        const double e =
          g_error_from_cycles(sequence) / std::abs(sequence.back() - G);
        low  = std::min(low, e);
        high = std::max(high, e);
      }
    return {low, high};
  }
} // namespace


int
main()
{
  const double G = 2.5e-7;
  for (const double rho : {0.2, 0.5, 0.8})
    for (const double c : {1e-8, -3e-8})
      {
        const std::string name = "geometric, rho = " + std::to_string(rho) +
                                 (c > 0 ? ", c > 0" : ", c < 0");
        const double expected = std::max(1., (1 - rho) / std::pow(rho, 3));
        const auto   e        = effectivity(G, c, rho, 10, 3);
        std::cout << name
                  << ": from cycle 3 on, effectivity max(1, (1 - rho) / "
                     "rho^3) (to 1e-6): "
                  << yes(std::abs(e.first / expected - 1) < 1e-6 &&
                         std::abs(e.second / expected - 1) < 1e-6)
                  << std::endl;
        if (rho <= 2. / 3)
          std::cout << name << ": from cycle 1 on, dG bounds the error: "
                    << yes(effectivity(G, c, rho, 10, 1).first >= 1 - 1e-12)
                    << std::endl;
      }
  for (const double rho : {0.2, 0.5, 0.8})
    {
      const double expected = (1 + rho) / std::pow(rho, 3);
      const auto   e        = effectivity(G, 1e-8, -rho, 10, 3);
      std::cout << "oscillating, rho = " << rho
                << ": from cycle 3 on, effectivity (1 + rho) / rho^3 (to "
                   "1e-6): "
                << yes(std::abs(e.first / expected - 1) < 1e-6 &&
                       std::abs(e.second / expected - 1) < 1e-6)
                << std::endl;
    }

  // A last change of zero, and a change of sign, after a change of 0.1.
  const double flat = g_error_from_cycles({1.0, 1.1, 1.1});
  std::cout << "non-monotone, the last change zero: dG = 0.1, not zero: "
            << yes(std::abs(flat - 0.1) < 1e-12) << std::endl;
  const double turn = g_error_from_cycles({1.0, 1.2, 1.19});
  std::cout << "non-monotone, the last change of the other sign: dG = 0.2: "
            << yes(std::abs(turn - 0.2) < 1e-12) << std::endl;
  const double flat3 = g_error_from_cycles({1.0, 1.3, 1.3, 1.3});
  std::cout << "two changes of zero after one of 0.3: dG = 0.3: "
            << yes(std::abs(flat3 - 0.3) < 1e-12) << std::endl;
  // Not contracting: the largest change.
  const double growing = g_error_from_cycles({1.0, 1.1, 1.3});
  std::cout << "monotone, not contracting: dG = the last change 0.2: "
            << yes(std::abs(growing - 0.2) < 1e-12) << std::endl;
  // Only the last four values count.
  const double old = g_error_from_cycles({0.0, 1.0, 1.1, 1.2, 1.3});
  std::cout << "a change five cycles back is forgotten: dG = 0.1: "
            << yes(std::abs(old - 0.1) < 1e-12) << std::endl;

  std::cout << "cycle 0: no estimate (NaN): "
            << yes(std::isnan(g_error_from_cycles({1.0}))) << std::endl;
  std::cout << "G not reported on the cycle before: no estimate (NaN): "
            << yes(std::isnan(g_error_from_cycles({1.0, not_a_number, 1.1})))
            << std::endl;
  std::cout << "G not reported on cycle 0: twice the change after it: "
            << yes(std::abs(g_error_from_cycles({not_a_number, 1.0, 1.1}) -
                            0.2) < 1e-12)
            << std::endl;

  // set_g_error(): both estimators, one, none.
  EnergyReleaseRate g;
  g.tip.support_radius = 0.25;
  g.G                  = 1.0;
  g.G_half_support     = 1.003;
  set_g_error(g, 0.001);
  std::cout << "both estimators: the larger (support radius 0.003), named: "
            << yes(std::abs(g.error - 0.003) < 1e-12 &&
                   g.error_estimate == "cycles and support radius")
            << std::endl;
  set_g_error(g, 0.01);
  std::cout << "both estimators: the larger (cycles 0.01): "
            << yes(std::abs(g.error - 0.01) < 1e-12) << std::endl;
  set_g_error(g, not_a_number);
  std::cout << "cycle 0: the support radius alone: "
            << yes(std::abs(g.error - 0.003) < 1e-12 &&
                   g.error_estimate == "support radius")
            << std::endl;
  g.G_half_support = not_a_number;
  set_g_error(g, 0.01);
  std::cout << "R/2 unresolved: the cycles alone: "
            << yes(std::abs(g.error - 0.01) < 1e-12 &&
                   g.error_estimate == "cycles")
            << std::endl;
  set_g_error(g, not_a_number);
  std::cout << "neither: NaN and a reason: "
            << yes(std::isnan(g.error) &&
                   g.error_estimate.rfind("none: ", 0) == 0)
            << std::endl;
  g.G          = not_a_number;
  g.unresolved = "too few cells";
  set_g_error(g, 0.01);
  std::cout << "G not reported: no error bar: "
            << yes(std::isnan(g.error) &&
                   g.error_estimate.rfind("none: ", 0) == 0)
            << std::endl;
}
