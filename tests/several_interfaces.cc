// Several interfaces (Geometry/Interfaces above Sigma): regions stacked in
// the plane, each interface with its own crack, tips and G.
//
// 1. Two delaminations at different depths of a homogeneous beam
//    (parameter_files/two_delaminations.prm: three sublaminates of height
//    1, cracks (0, 8) on Sigma and (0, 20) on interface 2, end moments M
//    and -M on the outer arms). Pure bending is an exact plane-strain
//    solution, so the J-integral gives each G exactly as the beam energy
//    per unit length behind the tip minus that ahead (the steady state):
//      G_1 = M^2 / (2 E') (1 / I_1 - 1 / I_12),
//      G_2 = M^2 / (2 E') (1 / I_12 + 1 / I_1),
//    I_1 = 1/12, I_12 = 8/12. Asserted: the run accepted; two tips, tip 1
//    at x = 8 on interface 1, tip 2 at x = 20 on interface 2, both
//    growing towards +x; each G within 0.5 % of its formula and within its
//    own error bar dG of it (measured: -0.06 % and -0.02 %, dG 0.2 % and
//    0.3 %); both cracks open (no contact multiplier).
// 2. G at every tip of every interface against the fourth-order central
//    difference of the energy with that tip moved by +-delta, +-2 delta
//    (delta = 0.25, the meshes fitted to the tips; 12 adaptive cycles):
//    within 1e-3 of the larger G (measured 3.9e-4 and 2.6e-4).
// 3. A glued interface changes nothing: the same beam with interface 2
//    glued everywhere against the two-region beam with a ply height at
//    y = 2 (the same material above and below it, so the same meshes and
//    the same stiffness): energies to 1e-9 and G at the tip of Sigma to
//    1e-6 (relative), on uniform Q2 meshes.

#include <bilayer/drivers/study.h>
#include <bilayer/interface/interface_diagnostics.h>
#include <bilayer/parameters/parameters.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <fstream>
#include <iostream>
#include <sstream>
#include <string>
#include <vector>

#include "quiet_output.h"
#include "verdict.h"

using namespace bilayer;

namespace
{
  struct Outcome
  {
    bool                           accepted = false;
    double                         energy   = std::nan("");
    std::vector<EnergyReleaseRate> release;
    /// Every crack node of every interface open, no contact multiplier.
    bool open = true;
  };

  /// The text of parameter_files/two_delaminations.prm.
  std::string
  shipped_scene()
  {
    std::ifstream      in(std::string(SOURCE_DIR) +
                     "/../parameter_files/two_delaminations.prm");
    std::ostringstream text;
    text << in.rdbuf();
    return text.str();
  }

  Outcome
  run(const std::string &text)
  {
    std::ostringstream sink;
    Study study(scene_from_string(text + quiet_output(), "several_interfaces"),
                sink);
    Outcome r;
    r.accepted = study.run();
    if (!r.accepted)
      return r;
    r.energy  = study.records().back().energy;
    r.release = study.records().back().release;
    for (unsigned int i = 0; i < study.interface().n_interfaces(); ++i)
      for (const InterfaceNode &n : interface_nodes(study.interface(),
                                                    study.solutions(),
                                                    study.multipliers(),
                                                    1e-6,
                                                    i))
        if (n.on_crack)
          r.open = r.open && n.mu_c == 0 && n.jump_normal > 0;
    return r;
  }

  /// The shipped scene with the cracks (0, @p a1) and (0, @p a2) on
  /// @p cycles cycles.
  Outcome
  delaminations(const double a1, const double a2, const unsigned int cycles)
  {
    std::ostringstream s;
    s.precision(17);
    s << shipped_scene() << "subsection Geometry\n"
      << " set Crack interval on Sigma = 0, " << a1
      << "\n set Interfaces above Sigma = 2: 0, " << a2 << "\nend\n"
      << "subsection Mesh\n set Number of cycles = " << cycles << "\nend\n";
    return run(s.str());
  }

  void
  beam_theory()
  {
    const Outcome r       = delaminations(8, 20, 12);
    const double  E_prime = 1 / (1 - 0.3 * 0.3), M = 1e-3;
    const double  I_1 = 1. / 12, I_12 = 8. / 12;
    const double  G_1 = M * M / (2 * E_prime) * (1 / I_1 - 1 / I_12),
                 G_2  = M * M / (2 * E_prime) * (1 / I_12 + 1 / I_1);
    std::cout << "two delaminations: accepted: " << yes(r.accepted) << "\n";
    const bool tips =
      r.release.size() == 2 && r.release[0].tip.interface == 0 &&
      r.release[1].tip.interface == 1 &&
      std::abs(r.release[0].tip.point[0] - 8) < 1e-12 &&
      std::abs(r.release[1].tip.point[0] - 20) < 1e-12 &&
      std::abs(r.release[1].tip.point[1] - 2) < 1e-12 &&
      r.release[0].tip.direction[0] == 1 && r.release[1].tip.direction[0] == 1;
    std::cout << "two delaminations: tip 1 at x = 8 on interface 1, tip 2 at "
                 "x = 20 on interface 2, both growing towards +x: "
              << yes(tips) << "\n";
    if (!tips)
      return;
    for (unsigned int t = 0; t < 2; ++t)
      {
        const EnergyReleaseRate &g     = r.release[t];
        const double             exact = t == 0 ? G_1 : G_2;
        if (std::getenv("BILAYER_TEST_DIAGNOSTICS"))
          std::cerr << "tip " << t + 1 << ": G " << g.G << " exact " << exact
                    << " relative " << (g.G - exact) / exact << " dG "
                    << g.error << "\n";
        std::cout << "two delaminations, tip " << t + 1
                  << ": G within 0.5 % of beam theory and within its error "
                     "bar of it: "
                  << yes(std::abs(g.G - exact) <= 5e-3 * exact &&
                         std::abs(g.G - exact) <= g.error)
                  << "\n";
      }
    std::cout << "two delaminations: both cracks open: " << yes(r.open) << "\n";
  }

  void
  finite_differences()
  {
    const double       a1 = 8, a2 = 20, delta = 0.25;
    const unsigned int cycles   = 12;
    const Outcome      base     = delaminations(a1, a2, cycles);
    bool               accepted = base.accepted && base.release.size() == 2;
    if (!accepted)
      {
        std::cout << "finite differences: base run accepted: NO\n";
        return;
      }
    const double G_max =
      std::max(std::abs(base.release[0].G), std::abs(base.release[1].G));
    for (unsigned int t = 0; t < 2; ++t)
      {
        // Tip t moved by k delta in its direction of growth (+x).
        const auto energy = [&](const int k) {
          const Outcome r = t == 0 ? delaminations(a1 + k * delta, a2, cycles) :
                                     delaminations(a1, a2 + k * delta, cycles);
          accepted        = accepted && r.accepted;
          return r.energy;
        };
        const double fd =
          -(8 * (energy(1) - energy(-1)) - (energy(2) - energy(-2))) /
          (12 * delta);
        if (std::getenv("BILAYER_TEST_DIAGNOSTICS"))
          std::cerr << "tip " << t + 1 << ": finite difference " << fd
                    << " domain integral " << base.release[t].G
                    << " relative to the larger G "
                    << (fd - base.release[t].G) / G_max << "\n";
        std::cout << "finite differences, tip " << t + 1 << " (interface "
                  << t + 1
                  << "): -dPi/da agrees with the domain integral to 1e-3 "
                     "of the larger G: "
                  << yes(std::abs(fd - base.release[t].G) <= 1e-3 * G_max)
                  << "\n";
      }
    std::cout << "finite differences: every run accepted: " << yes(accepted)
              << "\n";
  }

  void
  glued_interface()
  {
    const std::string common =
      "subsection Geometry\n set Lower left corner = 0, 0\n"
      " set Upper right corner = 32, 3\n set Height of Sigma = 1\n"
      " set Crack interval on Sigma = 0, 8\n set Clamped sides = right\n"
      "end\nsubsection Mesh\n set Cells along Sigma = 32\n"
      " set Polynomial degree of layer 1 = 2\n set Number of cycles = 2\n"
      "end\nsubsection Loads\n set Constants = M = 1e-3\n"
      " subsection Layer 1\n  set Traction on left side = (y < 1 ? "
      "-12*M*(y - 0.5) : (y > 2 ? 12*M*(y - 2.5) : 0)); 0\n end\nend\n"
      "subsection Solver\n set Method = active set\n set Tolerance = 1e-11\n"
      " subsection Active set\n  set Inner tolerance = 1e-8\n end\nend\n";
    const std::string material =
      "subsection Materials\n set Number of layers = 1\n"
      " subsection Layer 1\n  set Young's modulus = 1\n"
      "  set Poisson's ratio = 0.3\n";
    const Outcome three =
      run(common + material +
          " end\nend\nsubsection Geometry\n set Interfaces above Sigma = 2\n"
          "end\n");
    const Outcome two =
      run(common + material + "  set Ply heights = 2\n" + " end\nend\n");
    const bool both = three.accepted && two.accepted &&
                      three.release.size() == 1 && two.release.size() == 1;
    std::cout << "glued interface: both runs accepted, one tip each: "
              << yes(both) << "\n";
    if (!both)
      return;
    if (std::getenv("BILAYER_TEST_DIAGNOSTICS"))
      std::cerr << "glued: energies " << three.energy << " " << two.energy
                << " G " << three.release[0].G << " " << two.release[0].G
                << "\n";
    std::cout << "glued interface: the energy of the two-region beam to 1e-9: "
              << yes(std::abs(three.energy - two.energy) <=
                     1e-9 * std::abs(two.energy))
              << "\n";
    std::cout << "glued interface: G at the tip of Sigma to 1e-6: "
              << yes(std::abs(three.release[0].G - two.release[0].G) <=
                     1e-6 * std::abs(two.release[0].G))
              << "\n";
  }
} // namespace


int
main()
{
  beam_theory();
  finite_differences();
  glued_interface();
  return 0;
}
