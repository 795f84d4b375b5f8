// The double cantilever beam (parameter_files/dcb.prm; docs/fracture.md,
// "Fracture specimens: DCB and ELS") against beam theory.
//
// One layer, the strip (0, 40 h) x (-h, h), h = 1, Sigma at y = 0, the edge
// crack (0, a) from the free left end, the right end clamped; the left side
// of the upper arm carries the shear traction (0, +P/h), that of the lower
// arm (0, -P/h): the force P on each arm, pulling them apart. E = 1,
// nu = 0.3, plane strain, E' = E / (1 - nu^2), unit thickness b = 1.
// Beam theory with the root rotation of the arms (Kanninen 1973, the arm
// on an elastic foundation: the crack length grows by chi h, chi =
// 6^(-1/4) = 0.639):
//   G     = 12 P^2 (a + chi h)^2 / (E' b^2 h^3),
//   delta = 8 P (a + chi h)^3 / (E' b h^3),
// delta the load-point opening, the compliance whose derivative gives G
// (G = P^2 / (2 b) dC/da; the shear of the arms is in the terms of chi).
// Kanninen's chi, not Williams' shear-corrected one (chi = sqrt(E11 /
// (11 G13)) (3 - 2 (Gamma / (1 + Gamma))^2), Gamma = 1.18 sqrt(E11 E22) /
// G13, 0.905 for E11 = E22 = E, G13 = mu, nu = 0.3): the chi that makes
// the formula exact for the computed G is 0.674 ... 0.684 for a/h = 2 ...
// 20 (docs/fracture.md), Kanninen's 0.639 within 2 % of G from a/h = 3 on,
// Williams' 5 % off at a/h = 8.
// The computed opening is the work-conjugate of the traction, int t . u ds
// / P over the loaded side: by Clapeyron's theorem (the clamped side does
// no work, nor do the crack faces, open and frictionless) the work of the
// traction is -2 Pi, so delta = -2 Pi / P.
//
// Asserted at a/h = 8, 10, 14 (the clamped end 32, 30, 26 h behind the
// tip; adaptive Q2, 10 cycles from 40 cells along Sigma, the file's):
// - the runs are accepted, one tip at x = a growing towards +x;
// - G within 2 % of beam theory (the relative difference is printed,
//   rounded to 0.1 %; docs/fracture.md has a/h = 2 ... 20);
// - delta within 3 % of beam theory (printed in whole %; a constant
//   compliance of the load introduction and of the uncracked part, O(h^3)
//   against (a + chi h)^3, is not in the formula);
// - the crack is open at every crack node ([u].nu > 1e-6 of its largest
//   value: the smallest, next to the tip, is 4e-4 of it), no contact
//   multiplier;
// - mode I: by the symmetry about Sigma the sliding jump [u].tau vanishes
//   on the crack: max |[u].tau| below 1e-6 of max [u].nu (measured 1e-13
//   where the adaptive meshes of Omega- and Omega+ mirror each other, as
//   here; up to 2e-7 where the marking breaks a tie on one side only, as at
//   a/h = 12: 223 and 226 cells; Solver/Tolerance = 1e-10);
// - the mode split: G_II below 1e-3 of G where EnergyReleaseRate::G_II is
//   computed (NaN until then: the line is the same either way).

#include <cmath>
#include <iostream>

#include "beam_specimens.h"
#include "verdict.h"

using namespace beam_specimens;

namespace
{
  double
  beam_G(const double a)
  {
    const double l = a + chi() * h;
    return 12 * P * P * l * l / (E_prime * h * h * h);
  }

  double
  beam_delta(const double a)
  {
    const double l = a + chi() * h;
    return 8 * P * l * l * l / (E_prime * h * h * h);
  }

  /// The relative difference in %, rounded to 0.1.
  double
  percent(const double x, const double reference)
  {
    const double d = std::round(1000 * (x / reference - 1)) / 10;
    return d == 0 ? 0 : d; // no "-0"
  }

  /// The relative difference in whole %.
  double
  whole_percent(const double x, const double reference)
  {
    const double d = std::round(100 * (x / reference - 1));
    return d == 0 ? 0 : d;
  }
} // namespace


int
main()
{
  for (const double a : {8., 10., 14.})
    {
      const Result r = run("dcb.prm", a, 10);
      std::cout << "a/h = " << a << ": run accepted, one tip at x = a: "
                << yes(r.accepted && r.one_tip) << std::endl;
      if (!(r.accepted && r.one_tip))
        continue;
      const double delta = -2 * r.energy / P;
      std::cout << "a/h = " << a << ": G within 2 % of 12 P^2 (a + chi h)^2 "
                << "/ (E' b^2 h^3): "
                << yes(std::abs(r.G / beam_G(a) - 1) < 0.02) << " ("
                << percent(r.G, beam_G(a)) << " %)" << std::endl;
      std::cout << "a/h = " << a << ": delta = -2 Pi / P within 3 % of 8 P "
                << "(a + chi h)^3 / (E' b h^3): "
                << yes(std::abs(delta / beam_delta(a) - 1) < 0.03) << " ("
                << whole_percent(delta, beam_delta(a)) << " %)" << std::endl;
      double       opening = 0, sliding = 0;
      unsigned int closed = 0;
      for (const InterfaceNode &n : r.crack)
        {
          opening = std::max(opening, n.jump_normal);
          sliding = std::max(sliding, std::abs(n.jump_tangential));
          closed += (n.mu_c > 0);
        }
      for (const InterfaceNode &n : r.crack)
        closed += (n.jump_normal <= 1e-6 * opening);
      std::cout << "a/h = " << a << ": the crack open at every crack node "
                << "([u].nu > 1e-6 max [u].nu, no contact multiplier): "
                << yes(!r.crack.empty() && closed == 0) << std::endl;
      std::cout << "a/h = " << a << ": mode I, max |[u].tau| < 1e-6 max [u].nu "
                << "on the crack: " << yes(sliding < 1e-6 * opening)
                << std::endl;
      // The mode split of G (EnergyReleaseRate::G_I, G_II): checked where
      // it is computed; the line reads the same where it is NaN.
      const bool split =
        !std::isfinite(r.G_II) ||
        (std::abs(r.G_II) < 1e-3 * r.G && std::abs(r.G_I / r.G - 1) < 1e-3);
      std::cout << "a/h = " << a << ": G_II below 1e-3 of G where the mode "
                << "split is computed: " << yes(split) << std::endl;
    }
}
