// Interfaces of Gmsh scenes (docs/laminates.md, "Interfaces of Gmsh
// scenes"): regions 'Omega-', 'Omega+', 'Region 3', ... and interfaces
// 'Sigma'/'crack', 'Sigma 2'/'crack 2', ... read from the file's physical
// groups.
//
// 1. The same discrete problem: tests/two_delaminations.geo meshes the
//    beam of parameter_files/two_delaminations.prm with the rectangle
//    scene's cells of cycle 0 (three regions, two interfaces, the cracks
//    (0, 8) on Sigma and (0, 20) on interface 2). Both scenes (adaptive
//    Q2, 5 cycles) build the same meshes, so every cycle's energy agrees to
//    1e-10 and G at both tips to 1e-8 (round-off: the cells are numbered
//    differently), and each tip lies on the same interface.
// 2. A ply drop (parameter_files/ply_drop.prm): plies (0, 60) x (0, 1) and
//    (0, 60) x (1, 2), a third ply (20, 60) x (2, 3) whose end at x = 20
//    delaminates along interface 2 to x = a = 35; the right end clamped,
//    the axial force P (uniform traction) on the left end of the two plies.
//    Uniform tension and pure bending are exact plane-strain solutions, so
//    G is the energy per unit length of the beam behind the tip minus that
//    ahead (E' = E / (1 - nu^2)): behind, the two plies carry N = P on
//    their centroid (A = 2); ahead, the three carry N = P at y = 1, the
//    moment P e about their centroid y = 1.5 (e = 1/2, A = 3, I = 27/12):
//    G = P^2 / (2 E') (1/2 - 1/3 - e^2 / I), within 1 %. The tip is the one
//    tip of the scene, on interface 2 (Sigma is glued everywhere).
// 3. G against the energy: the fourth-order central difference of Pi with
//    the tip moved to a = 35 -+ 1, -+ 2 (each a scene of its own .geo)
//    agrees with the domain integral to 1e-3.
// 4. Crack growth on interface 2 of the Gmsh scene: the ply drop on the
//    uniform Q2 mesh of cells 0.25 (three global cycles), quasi-static
//    growth under the load factors 1, 1.5 with the toughness G_c = 1e-8
//    for x < 37.9 (1 beyond). The driver's exact onset is sqrt(G_c / G(1))
//    (G ~ lambda^2; G(1) of a static run with the tip at 35: 1e-9), and at
//    every onset G = G_c (1e-8). Tension and bending behind and ahead of
//    the tip are a steady state (part 2): after each step of growth G
//    stays within 1e-3 of G_c (measured 3.6e-4: the discrete G drifts by
//    3.5e-4 per cell on this mesh, 1e-4 over 3 units on cells of 0.125).
//    The tip stops at (38, 2), the first vertex of the tough part, and the
//    state at the load factor 1 after the growth is the static equilibrium
//    of the .geo with the tip at x = 38 (the same mesh: G to 1e-8).

#include <bilayer/drivers/study.h>
#include <bilayer/parameters/parameters.h>

#include <cmath>
#include <fstream>
#include <iostream>
#include <sstream>
#include <string>
#include <vector>

#include "quiet_output.h"
#include "scene_text.h"
#include "study_outcome.h"
#include "verdict.h"

using namespace bilayer;

namespace
{
  using Outcome = StudyOutcome;

  Outcome
  run(const std::string &text)
  {
    std::ostringstream sink;
    Study study(scene_from_string(text + quiet_output(), "gmsh_interfaces"),
                sink);
    return study_outcome(study, study.run());
  }


  /// The scene parameter_files/ply_drop.prm with the tip at x = @p a (its
  /// .geo written into the working directory with that a).
  std::string
  ply_drop(const int a);

  /// ply_drop(@p a) on the uniform Q2 mesh of cells 0.25 (three global
  /// cycles), with @p fracture (entries of subsection Fracture).
  std::string
  uniform_ply_drop(const int a, const std::string &fracture)
  {
    return ply_drop(a) +
           "subsection Mesh\n set Refinement = global\n"
           " set Number of cycles = 3\nend\n"
           "subsection Fracture\n" +
           fracture + "end\n";
  }

  std::string
  ply_drop(const int a)
  {
    const std::string dir = std::string(SOURCE_DIR) + "/../parameter_files/";
    const std::string geo = "ply_drop_" + std::to_string(a) + ".geo";
    std::ofstream(geo) << replace_line(file_text(dir + "ply_drop.geo"),
                                       "  a = 35;",
                                       "  a = " + std::to_string(a) + ";");
    return replace_line(file_text(dir + "ply_drop.prm"),
                        "  set Gmsh file",
                        "  set Gmsh file = " + geo);
  }
} // namespace


int
main()
{
  // 1. The two delaminations, rectangle and Gmsh.
  {
    const std::string rectangle =
      file_text(std::string(SOURCE_DIR) +
                "/../parameter_files/two_delaminations.prm") +
      "subsection Mesh\n set Number of cycles = 5\nend\n";
    std::string gmsh =
      replace_line(rectangle,
                   "  set Lower left corner",
                   "  set Gmsh file = " + std::string(SOURCE_DIR) +
                     "/two_delaminations.geo");
    for (const std::string key : {"  set Upper right corner",
                                  "  set Height of Sigma",
                                  "  set Crack interval on Sigma",
                                  "  set Interfaces above Sigma",
                                  "  set Fit crack tips"})
      gmsh = replace_line(gmsh, key, "");
    gmsh            = replace_line(gmsh,
                        "    set Traction on left side",
                        "    set Traction on left = (y < 1 ? -12*M*(y - "
                                   "0.5) : (y > 2 ? 12*M*(y - 2.5) : 0)); 0");
    const Outcome r = run(rectangle), g = run(gmsh);
    bool same_energies = r.accepted && g.accepted && r.energies.size() == 5 &&
                         g.energies.size() == r.energies.size();
    for (unsigned int k = 0; same_energies && k < r.energies.size(); ++k)
      same_energies = std::abs(g.energies[k] - r.energies[k]) <=
                      1e-10 * std::abs(r.energies[k]);
    std::cout << "two delaminations: both runs accepted, every cycle's "
                 "energy of the Gmsh scene equals the rectangle's to 1e-10: "
              << yes(same_energies) << std::endl;
    bool same_tips = r.release.size() == 2 && g.release.size() == 2;
    for (unsigned int t = 0; same_tips && t < 2; ++t)
      same_tips =
        g.release[t].tip.interface == t && r.release[t].tip.interface == t &&
        g.release[t].tip.point.distance(r.release[t].tip.point) < 1e-12 &&
        std::abs(g.release[t].G - r.release[t].G) <=
          1e-8 * std::abs(r.release[t].G);
    std::cout << "two delaminations: tip t on interface t, G of both tips "
                 "equal to 1e-8: "
              << yes(same_tips) << std::endl;
  }

  // 2. The ply drop against beam theory.
  const Outcome base = run(ply_drop(35));
  {
    const double E = 1, nu = 0.3, P = 1e-3, e = 0.5, I = 27. / 12;
    const double E_prime = E / (1 - nu * nu);
    const double G_beam = P * P / (2 * E_prime) * (1. / 2 - 1. / 3 - e * e / I);
    const bool   one_tip = base.accepted && base.release.size() == 1 &&
                         base.release[0].tip.interface == 1 &&
                         base.release[0].tip.point.distance({35, 2}) < 1e-12;
    std::cout << "ply drop: accepted, one tip, at (35, 2) on interface 2: "
              << yes(one_tip) << std::endl;
    std::cout << "ply drop: G within 1 % of P^2 / (2 E') (1/2 - 1/3 - e^2 / "
                 "I): "
              << yes(one_tip && std::abs(base.release[0].G / G_beam - 1) < 0.01)
              << std::endl;

    // 3. Finite differences of the energy.
    bool       accepted = one_tip;
    const auto energy   = [&](const int a) {
      const Outcome r = run(ply_drop(a));
      accepted        = accepted && r.accepted && !r.energies.empty();
      return r.energies.empty() ? std::nan("") : r.energies.back();
    };
    const double fd =
      -(8 * (energy(36) - energy(34)) - (energy(37) - energy(33))) / 12;
    std::cout << "ply drop: the fourth-order difference of Pi over a = 33 "
                 "... 37 agrees with G to 1e-3: "
              << yes(accepted && std::abs(fd - base.release[0].G) <=
                                   1e-3 * std::abs(base.release[0].G))
              << std::endl;
  }

  // 4. Crack growth on interface 2.
  {
    const double       G_c = 1e-8;
    std::ostringstream sink;
    // G(1) with the tip at x = 35 and at x = 38, static runs on the mesh of
    // the growth.
    const auto static_G = [&](const int a) {
      Study study(scene_from_string(uniform_ply_drop(a, "") + quiet_output(),
                                    "gmsh_interfaces"),
                  sink);
      const bool  solved = study.run();
      const auto &tips   = study.records().back().release;
      return solved && tips.size() == 1 ? tips[0].G : std::nan("");
    };
    const double G_35 = static_G(35), G_38 = static_G(38);
    Study        growth(scene_from_string(
                   uniform_ply_drop(35,
                                    " set Crack growth = quasi-static\n"
                                           " set Toughness = x < 37.9 ? 1e-8 : 1\n") +
                     "subsection Loads\n set Load factor = 1, 1.5\nend\n" +
                     quiet_output(),
                   "gmsh_interfaces"),
                 sink);
    const bool   accepted = growth.run_growth();
    const auto  &steps    = growth.growth();
    const bool   one_tip =
      accepted && !steps.empty() && steps[0].tips.size() == 1;
    std::cout << "ply drop growth: accepted, one tip: " << yes(one_tip)
              << std::endl;
    if (!one_tip)
      return 0;
    bool   exact = true, nearly_steady = true;
    double G_grown_at_1 = std::nan("");
    for (const GrowthStep &step : steps)
      {
        const double G = step.tips[0].G;
        if (step.kind == "onset")
          exact = exact && std::abs(G / G_c - 1) < 1e-8;
        if (step.kind == "growth")
          nearly_steady = nearly_steady && std::abs(G / G_c - 1) < 1e-3;
        if (step.kind == "load" && step.load_factor == 1)
          G_grown_at_1 = G;
      }
    std::cout << "ply drop growth: the first step is the exact onset "
                 "sqrt(G_c / G(1)) (1e-9), G = G_c at every onset (1e-8): "
              << yes(steps[0].kind == "onset" &&
                     std::abs(steps[0].load_factor / std::sqrt(G_c / G_35) -
                              1) < 1e-9 &&
                     exact)
              << std::endl;
    std::cout << "ply drop growth: G after every step of growth within 1e-3 "
                 "of G_c (a steady state: G independent of the length): "
              << yes(nearly_steady) << std::endl;
    std::cout << "ply drop growth: the tip stops at the tough part, at "
                 "(38, 2) on interface 2: "
              << yes(steps.back().tips[0].point.distance({38, 2}) < 1e-9)
              << std::endl;
    std::cout << "ply drop growth: at the load factor 1 the grown state is the "
                 "static equilibrium of the scene with the tip at x = 38 "
                 "(G, 1e-8): "
              << yes(std::abs(G_grown_at_1 / G_38 - 1) < 1e-8) << std::endl;
  }
}
