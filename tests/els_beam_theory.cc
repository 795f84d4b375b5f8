// The end-loaded split (parameter_files/els.prm, ISO 15114; docs/fracture.md,
// "Fracture specimens: DCB and ELS") against beam theory.
//
// One layer, the strip (0, 40 h) x (-h, h), h = 1, Sigma at y = 0, the edge
// crack (0, a) from the free left end, the uncracked right end clamped; the
// whole left side carries the downward shear traction (0, -P/(2h)): the
// transverse force P on the two arms together. E = 1, nu = 0.3, plane
// strain, E' = E / (1 - nu^2), unit thickness b = 1, frictionless contact
// on the crack. The arms bend together, each with P/2, and slide over each
// other: mode II. Beam theory with Wang and Williams' root rotation
// 0.42 chi h (chi = 6^(-1/4), Kanninen's, as for the DCB):
//   G = 9 P^2 (a + 0.42 chi h)^2 / (4 E' b^2 h^3).
// The scene is symmetric under the reflection y -> -y with u_x odd and u_y
// even in y (the load t_y is even, the clamp and the strip symmetric), so
// u_y(x, 0+) = u_y(x, 0-): the normal jump vanishes on the crack without
// any contact pressure; the faces touch and do not press (the run without
// non-penetration is the same).
//
// Asserted at a/h = 8, 10, 14 (adaptive Q2, 14 cycles from 40 cells along
// Sigma, the file's: the whole bent strip draws refinement away from the
// tip, and G settles to about 0.3 % from the 12th cycle on):
// - the runs are accepted, one tip at x = a growing towards +x;
// - G within 3 % of beam theory (the relative difference printed, rounded to
//   0.1 %; docs/fracture.md has a/h = 2 ... 20);
// - mode II: the normal jump on the crack below 1e-6 of the largest sliding
//   jump (measured up to 1e-8; Solver/Tolerance = 1e-10), and the faces
//   do not press: the contact multiplier below 1e-6 P/h at every crack node;
// - the faces slide: the sliding jump at the mouth within 3 % of beam
//   theory, 3 P (a + 0.42 chi h)^2 / (E' b h^2) (each arm's end rotates by
//   (P/2) a^2 / (2 E' I), I = b h^3 / 12, and the faces lie h/2 from the
//   arms' axes on opposite sides; the root correction as in G);
// - the mode split: G_I below 1e-3 of G where EnergyReleaseRate::G_I is
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
    const double l = a + 0.42 * chi() * h;
    return 9 * P * P * l * l / (4 * E_prime * h * h * h);
  }

  /// The relative difference in %, rounded to 0.1.
  double
  percent(const double x, const double reference)
  {
    const double d = std::round(1000 * (x / reference - 1)) / 10;
    return d == 0 ? 0 : d; // no "-0"
  }
} // namespace


int
main()
{
  for (const double a : {8., 10., 14.})
    {
      const Result r = run("els.prm", a, 14);
      std::cout << "a/h = " << a << ": run accepted, one tip at x = a: "
                << yes(r.accepted && r.one_tip) << std::endl;
      if (!(r.accepted && r.one_tip))
        continue;
      std::cout << "a/h = " << a << ": G within 3 % of 9 P^2 (a + 0.42 chi "
                << "h)^2 / (4 E' b^2 h^3): "
                << yes(std::abs(r.G / beam_G(a) - 1) < 0.03) << " ("
                << percent(r.G, beam_G(a)) << " %)" << std::endl;
      double opening = 0, sliding = 0, pressure = 0;
      for (const InterfaceNode &n : r.crack)
        {
          opening  = std::max(opening, std::abs(n.jump_normal));
          sliding  = std::max(sliding, std::abs(n.jump_tangential));
          pressure = std::max(pressure, n.mu_c);
        }
      std::cout << "a/h = " << a << ": mode II, max |[u].nu| < 1e-6 max "
                << "|[u].tau| on the crack: "
                << yes(!r.crack.empty() && opening < 1e-6 * sliding)
                << std::endl;
      std::cout << "a/h = " << a << ": the faces touch without pressing, "
                << "mu_c < 1e-6 P/h: " << yes(pressure < 1e-6 * P / h)
                << std::endl;
      const double l     = a + 0.42 * chi() * h,
                   mouth = 3 * P * l * l / (E_prime * h * h);
      std::cout << "a/h = " << a << ": the faces slide, |[u].tau| at the "
                << "mouth within 3 % of 3 P (a + 0.42 chi h)^2 / (E' b h^2): "
                << yes(std::abs(std::abs(r.mouth_sliding) / mouth - 1) < 0.03)
                << " (" << percent(std::abs(r.mouth_sliding), mouth) << " %)"
                << std::endl;
      // The mode split of G (EnergyReleaseRate::G_I, G_II): checked where
      // it is computed; the line reads the same where it is NaN.
      const bool split =
        !std::isfinite(r.G_I) ||
        (std::abs(r.G_I) < 1e-3 * r.G && std::abs(r.G_II / r.G - 1) < 1e-3);
      std::cout << "a/h = " << a << ": G_I below 1e-3 of G where the mode "
                << "split is computed: " << yes(split) << std::endl;
    }
}
