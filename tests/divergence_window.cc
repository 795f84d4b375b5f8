// The growth test of the first-order iterations' divergence test
// (GrowthWindow) on given sequences of increments, for the window of each
// method.
//
// A converging sequence may be far from monotone: the accelerated
// iteration's increments oscillate with the momentum, and a single small
// increment makes every later one large against the smallest so far. Such
// sequences, decreasing from one window to the next, must never count as
// growth, although the rule of the factor over the smallest value alone
// would fire on them. A geometric growth must count, within 2 w values
// (w the window) of exceeding the factor, with or without an oscillation on
// top.

#include <bilayer/solvers/first_order_iteration.h>

#include <algorithm>
#include <cmath>
#include <functional>
#include <iostream>
#include <limits>
#include <string>

#include "verdict.h"

using namespace bilayer;

namespace
{
  const double factor = 1000;

  // The first index at which @p v exceeds factor times its smallest value
  // before, or n.
  unsigned int
  first_above_factor(const std::function<double(unsigned int)> &v,
                     const unsigned int                         n)
  {
    double min_value = std::numeric_limits<double>::max();
    for (unsigned int k = 0; k < n; ++k)
      {
        if (v(k) > factor * min_value)
          return k;
        min_value = std::min(min_value, v(k));
      }
    return n;
  }

  // The first index at which GrowthWindow fires, or n.
  unsigned int
  first_growth(const std::function<double(unsigned int)> &v,
               const unsigned int                         n,
               const unsigned int                         window)
  {
    GrowthWindow growth(factor, window);
    for (unsigned int k = 0; k < n; ++k)
      if (growth.add(v(k)))
        return k;
    return n;
  }

} // namespace

int
main()
{
  const double       pi = std::acos(-1.);
  const unsigned int n  = 20000;
  // Converging: a dip of 1e-4 every 7 steps on a geometric decrease.
  const auto dips = [](const unsigned int k) {
    return std::pow(0.999, k) * (k % 7 == 0 ? 1e-4 : 1.);
  };
  // Converging: after 30 values (past the first windows) an oscillation of
  // period p down to 1e-4 of its mean; with p the window, each window holds
  // one period and the windows decrease.
  const auto wave = [pi](const unsigned int p) {
    return [pi, p](const unsigned int k) {
      return std::pow(0.999, k) *
             (k < 30 ? 2. : 1.0001 + std::cos(2 * pi * (k - 30.) / p));
    };
  };
  // Growing: a decrease, then a geometric growth of ratio 1.3.
  const auto grows = [](const unsigned int k) {
    return 1e-3 * std::pow(0.5, k) + 1e-12 * std::pow(1.3, k);
  };
  // Growing with an oscillation on top.
  const auto grows_wave = [](const unsigned int k) {
    return 1e-12 * std::pow(1.3, k) * (1.5 + std::cos(k));
  };

  std::cout << "the factor over the smallest value alone fires on the "
               "converging sequences with dips to 1e-4: "
            << yes(first_above_factor(dips, n) < n &&
                   first_above_factor(wave(DivergenceTest::accelerated_window),
                                      n) < n)
            << std::endl;
  for (const auto &[name, window] :
       {std::make_pair(std::string("Uzawa"), DivergenceTest::uzawa_window),
        std::make_pair(std::string("accelerated"),
                       DivergenceTest::accelerated_window)})
    {
      std::cout << name << ": converging with dips is not growth: "
                << yes(first_growth(dips, n, window) == n) << std::endl
                << name << ": converging oscillation is not growth: "
                << yes(first_growth(wave(window), n, window) == n) << std::endl;
      for (const auto &[what, v] :
           {std::make_pair(std::string("geometric growth"),
                           std::function<double(unsigned int)>(grows)),
            std::make_pair(std::string("oscillating geometric growth"),
                           std::function<double(unsigned int)>(grows_wave))})
        {
          const unsigned int k0 = first_above_factor(v, 200);
          const unsigned int k1 = first_growth(v, 200, window);
          const unsigned int w  = std::max(window, k1 / 10);
          std::cout << name << ": " << what
                    << " is growth within 2 w values of the factor: "
                    << yes(k0 < 200 && k1 < 200 && k1 >= k0 && k1 <= k0 + 2 * w)
                    << std::endl;
        }
    }
}
