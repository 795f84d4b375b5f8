// Quasi-static growth with mode-dependent toughness (Fracture/Mixed-mode
// law = power law, Benzeggagh-Kenane; docs/fracture.md sections 7 and 9):
// Example 1 under a shear traction as well (top (c, -c x), bottom (-c, c x)
// on layer 1), whose open tip (tip 1) grows in mixed mode, with G_Ic =
// g0 (1 + 8 (|x| - 0.5)) rising along Sigma and G_IIc = 4 G_Ic.
//
// Under proportional loading G_I and G_II scale with lambda^2 and the mode
// mix does not change, so the critical load of a crack of length l follows
// from G_I(l; 1) and G_II(l; 1) of a sweep:
//   power law: lambda_c = [(G_I/G_Ic)^a + (G_II/G_IIc)^a]^(-1/(2a)),
//   BK:        lambda_c = sqrt((G_Ic + (G_IIc - G_Ic) (G_II/G)^eta) / G),
// computed here from the sweep's split. Every onset of the quasi-static runs
// (exact onsets) must be at a swept crack length with that load (1e-6),
// the criterion 1 there (1e-8) and the phase angle of the sweep (1e-8
// degrees).

#include <bilayer/drivers/study.h>
#include <bilayer/parameters/parameters.h>

#include <cmath>
#include <iomanip>
#include <iostream>
#include <map>
#include <sstream>

#include "verdict.h"

using namespace dealii;
using namespace bilayer;

namespace
{
  std::string
  scene_text(const std::string &growth,
             const std::string &law,
             const double       exponent,
             const double       g0,
             const std::string &directory)
  {
    std::ostringstream s;
    s << std::setprecision(17)
      << "subsection Mesh\n set Cells along Sigma = 32\nend\n"
         "subsection Loads\n set Constants = c = 1e-3*mu1\n"
         " set Load factor = "
      << (growth == "sweep" ? "1" : "0.5:0.5:8")
      << "\n subsection Layer 1\n"
         "  set Traction on top side = c; -c*x\n"
         "  set Traction on bottom side = -c; c*x\n end\nend\n"
         "subsection Solver\n set Method = active set\n"
         " set Tolerance = 1e-12\nend\n"
         "subsection Fracture\n set Crack growth = "
      << growth << "\n set Growing tips = 1\n set Mixed-mode law = " << law
      << "\n set Mixed-mode exponent = " << exponent
      << "\n set Toughness = " << g0
      << "*(1 + 8*(abs(x) - 0.5))\n set Mode II toughness = " << 4 * g0
      << "*(1 + 8*(abs(x) - 0.5))\nend\n"
         "subsection Output\n set Output directory = "
      << directory
      << "\n set Write VTU = false\n set Write interface CSV = false\n"
         " set Terminal output = checks\nend\n";
    return s.str();
  }

  void
  check(const std::string &what, const bool ok)
  {
    std::cout << "  " << what << ": " << yes(ok) << std::endl;
  }

  long
  key(const double length)
  {
    return std::lround(length * 1e6);
  }

  /// lambda_c of the law at G_I, G_II (at lambda = 1) and G_Ic (G_IIc =
  /// 4 G_Ic).
  double
  critical(const bool   power,
           const double a,
           const double G_I,
           const double G_II,
           const double G_Ic)
  {
    const double G_IIc = 4 * G_Ic, G = G_I + G_II;
    if (power)
      return std::pow(std::pow(G_I / G_Ic, a) + std::pow(G_II / G_IIc, a),
                      -1 / (2 * a));
    return std::sqrt((G_Ic + (G_IIc - G_Ic) * std::pow(G_II / G, a)) / G);
  }
} // namespace

int
main()
{
  std::ostringstream quiet;
  Study              sweep(
    scene_from_string(scene_text("sweep", "mode independent", 1, 1, "r_sweep"),
                      "mixed_mode_growth"),
    quiet);
  std::cout << "sweep accepted: " << yes(sweep.run_growth()) << std::endl;
  // The split of tip 1 at every swept length.
  std::map<long, GrowthTip> swept;
  for (const GrowthStep &step : sweep.growth())
    if (step.tips[0].present && std::isfinite(step.tips[0].G))
      swept[key(step.crack_length)] = step.tips[0];
  const GrowthTip &first = swept.begin()->second;
  std::cout << "mixed mode at the initial tip (G_II / G in (0.05, 0.95)): "
            << yes(first.G_II / first.G > 0.05 && first.G_II / first.G < 0.95)
            << std::endl;

  for (const bool power : {true, false})
    {
      const double      a   = power ? 2 : 1.5;
      const std::string law = power ? "power law" : "Benzeggagh-Kenane";
      std::cout << law << ", exponent " << a << std::endl;
      const auto G_Ic = [](const GrowthTip &tip, const double g0) {
        return g0 * (1 + 8 * (std::abs(tip.point[0]) - 0.5));
      };
      // g0 so that the first onset is at lambda = 1.7 (lambda_c ~ sqrt(g0)).
      const double g0 = std::pow(
        1.7 / critical(power, a, first.G_I, first.G_II, G_Ic(first, 1)), 2);
      Study run(
        scene_from_string(scene_text("quasi-static", law, a, g0, "r_" + law),
                          "mixed_mode_growth"),
        quiet);
      check("quasi-static accepted", run.run_growth());
      unsigned int onsets = 0, unknown = 0;
      double       worst_load = 0, worst_f = 0, worst_angle = 0;
      for (const GrowthStep &step : run.growth())
        if (step.kind == "onset")
          {
            ++onsets;
            const auto found = swept.find(key(step.crack_length));
            if (found == swept.end())
              {
                ++unknown;
                continue;
              }
            const GrowthTip &s = found->second, &t = step.tips[0];
            worst_load =
              std::max(worst_load,
                       std::abs(
                         step.load_factor /
                           critical(power, a, s.G_I, s.G_II, G_Ic(s, g0)) -
                         1));
            worst_f = std::max(worst_f, std::abs(t.criterion - 1));
            const double angle_s =
              std::atan2(std::sqrt(s.G_II), std::sqrt(s.G_I));
            const double angle_t =
              std::atan2(std::sqrt(t.G_II), std::sqrt(t.G_I));
            worst_angle =
              std::max(worst_angle, std::abs(angle_s - angle_t) * 180 / M_PI);
          }
      check("at least 3 onsets", onsets >= 3);
      check("every onset at a swept crack length", unknown == 0);
      check("onsets = the law's lambda_c from the sweep's G_I, G_II to 1e-6",
            worst_load < 1e-6);
      check("criterion 1 at every onset to 1e-8", worst_f < 1e-8);
      check("the sweep's phase angle at every onset to 1e-8 degrees",
            worst_angle < 1e-8);
    }
}
