// Plies of a Gmsh scene: physical surfaces inside the regions, named by
// Materials/Layer k/Ply groups (docs/laminates.md).
//
// 1. The [0/90/0] cross-ply DCB of parameter_files/cross_ply_dcb.prm as a
//    Gmsh scene (tests/cross_ply_dcb.geo: the 90 ply and the upper 0 ply two
//    surfaces of Omega+; the groups "ninety" = the 90 ply, "zero" = both 0
//    plies, one in each region), the crack (0, 20): G within 3 % of
//    corrected beam theory with the arms' laminate stiffness
//    (cross_ply_beam.h; 8 adaptive Q2 cycles).
// 2. The same laminate stated two ways: Ply groups = ninety with the 90
//    ply's law in Ply 1, and Ply groups = zero with it in Ply 2 (the cells
//    in no group). The two give every cell the same law and thermal
//    expansion, so the same discrete problem: energy and G bit for bit,
//    with a temperature change that only the 90 ply feels (its own thermal
//    expansion, read by cell: a ply group is no band of heights) and that
//    changes the energy.
// 3. Equal plies: Ply groups = ninety whose Ply 1 restates the layer's law
//    against the scene without plies: energy and G bit for bit.
// 4. A ply boundary across the crack's path: parameter_files/scarf_dcb.prm,
//    the upper arm carbon left and aluminium right of the oblique line from
//    (21, 0) to (25, 4), the tip at (20, 0). G's domain integral holds for
//    a theta that keeps every material boundary in place, so the support
//    stays below the distance 1 to the scarf: the automatic radius is half
//    of it (0.5; the outer boundary alone would allow 2), G is the same for
//    radii 0.3 and 0.9 (path independence, 1e-3 relative: the
//    discretisation error; measured 3e-4), and a radius of 2 is refused
//    naming Fracture/Support radius and the ply boundary.

#include <bilayer/drivers/study.h>
#include <bilayer/parameters/parameters.h>

#include <cmath>
#include <fstream>
#include <iostream>
#include <sstream>
#include <string>

#include "cross_ply_beam.h"
#include "quiet_output.h"
#include "scene_text.h"
#include "verdict.h"

using namespace bilayer;

namespace
{
  struct Outcome
  {
    bool        accepted = false;
    double      energy   = std::nan("");
    double      G        = std::nan("");
    double      radius   = std::nan("");
    std::string refusal;
  };

  /// Runs @p text quietly: the energy, G and the support radius of its one
  /// tip, or the refusal's message.
  Outcome
  run(const std::string &text)
  {
    std::ostringstream sink;
    Outcome            o;
    try
      {
        Study study(scene_from_string(text + quiet_output(), "gmsh_plies"),
                    sink);
        o.accepted = study.run();
        if (!o.accepted)
          {
            o.refusal = sink.str();
            return o;
          }
        o.energy         = study.records().back().energy;
        const auto &tips = study.records().back().release;
        if (tips.size() == 1)
          {
            o.G      = tips[0].G;
            o.radius = tips[0].tip.support_radius;
          }
      }
    catch (const std::exception &e)
      {
        o.refusal = e.what();
      }
    // The message as one line (deal.II wraps it).
    std::istringstream words(o.refusal);
    std::string        word, line;
    while (words >> word)
      line += (line.empty() ? "" : " ") + word;
    o.refusal = line;
    return o;
  }


  /// The 0 ply (fibres along x) as the law of Materials/Layer 1.
  const std::string zero_ply = "  set Law = orthotropic\n  set E_1 = 140\n"
                               "  set E_2 = 10\n  set E_3 = 10\n"
                               "  set nu_12 = 0.3\n  set nu_13 = 0.3\n"
                               "  set nu_23 = 0.45\n  set G_12 = 5\n";
  /// The 90 ply (fibres along z) as the entries of a Ply j subsection.
  const std::string ninety_ply =
    "   set E_1 = 10\n   set E_2 = 10\n   set E_3 = 140\n"
    "   set nu_12 = 0.45\n   set nu_13 = 0.0214285714285714\n"
    "   set nu_23 = 0.0214285714285714\n   set G_12 = 3.4482758620689655\n";

  /// The cross-ply DCB of tests/cross_ply_dcb.geo with the Materials
  /// section's layer entries @p plies and the Loads section's @p loads.
  std::string
  cross_ply(const std::string &plies, const std::string &loads = "")
  {
    return "subsection Geometry\n set Gmsh file = " + std::string(SOURCE_DIR) +
           "/cross_ply_dcb.geo\n set Clamped sides = right\nend\n"
           "subsection Mesh\n set Polynomial degree of layer 1 = 2\n"
           " set Refinement = adaptive\n set Refinement fraction = 0.8\n"
           " set Number of cycles = 8\nend\n"
           "subsection Materials\n set Number of layers = 1\n"
           " subsection Layer 1\n" +
           zero_ply + plies +
           " end\nend\n"
           "subsection Loads\n set Constants = P = 1e-3\n" +
           loads +
           " subsection Layer 1\n"
           "  set Traction on left = 0; y > 0 ? P/2 : -P\n end\nend\n"
           "subsection Contact\n set Non-penetration on the crack = true\n"
           "end\n"
           "subsection Solver\n set Method = active set\n"
           " set Tolerance = 1e-10\nend\n"
           "subsection Fracture\n set Energy release rate = true\nend\n";
  }
} // namespace


int
main()
{
  // 1. Beam theory.
  const Outcome a =
    run(cross_ply("  set Ply groups = ninety\n  subsection Ply 1\n" +
                  ninety_ply + "  end\n"));
  const double reference = cross_ply_beam::cross_ply_G(20);
  std::cout << "cross-ply DCB (Gmsh plies): accepted, one tip: "
            << yes(a.accepted && std::isfinite(a.G)) << std::endl;
  std::cout << "cross-ply DCB (Gmsh plies): G within 3 % of corrected beam "
               "theory: "
            << yes(std::abs(a.G / reference - 1) < 0.03) << std::endl;

  // 2. The 90 ply as a group or as the cells in none; heated.
  const std::string heat     = " set Temperature change = 100\n";
  const Outcome     by_group = run(
    cross_ply("  set Ply groups = ninety\n  subsection Ply 1\n" + ninety_ply +
                "   set Thermal expansion = 3e-5, 3e-5, 0\n"
                    "  end\n",
              heat));
  const Outcome by_rest =
    run(cross_ply("  set Ply groups = zero\n  subsection Ply 2\n" + ninety_ply +
                    "   set Thermal expansion = 3e-5, 3e-5, 0\n"
                    "  end\n",
                  heat));
  std::cout << "the 90 ply as group 1 or as the cells in no group: the same "
               "energy and G, bit for bit: "
            << yes(by_group.accepted && by_rest.accepted &&
                   by_group.energy == by_rest.energy && by_group.G == by_rest.G)
            << std::endl;
  std::cout << "the 90 ply's own thermal expansion changes the energy: "
            << yes(std::abs(by_group.energy / a.energy - 1) > 1e-3)
            << std::endl;

  // 3. Equal plies.
  const Outcome equal = run(cross_ply(
    "  set Ply groups = ninety\n  subsection Ply 1\n   set E_1 = 140\n"
    "  end\n"));
  const Outcome none  = run(cross_ply(""));
  std::cout << "a ply group of the layer's own law: the energy and G of the "
               "scene without plies, bit for bit: "
            << yes(equal.accepted && none.accepted &&
                   equal.energy == none.energy && equal.G == none.G)
            << std::endl;

  // 4. The scarf across the crack's path.
  std::string scarf =
    file_text(std::string(SOURCE_DIR) + "/../parameter_files/scarf_dcb.prm");
  const std::string file = "set Gmsh file     = scarf_dcb.geo";
  scarf.replace(scarf.find(file),
                file.size(),
                "set Gmsh file = " + std::string(SOURCE_DIR) +
                  "/../parameter_files/scarf_dcb.geo");
  const Outcome automatic = run(scarf);
  const auto    radius    = [&](const double R) {
    std::ostringstream s;
    s << "subsection Fracture\n set Support radius = " << R << "\nend\n";
    return run(scarf + s.str());
  };
  const Outcome small = radius(0.3), large = radius(0.9), beyond = radius(2);
  std::cout << "scarf: the automatic support radius is half the distance 1 "
               "to the scarf: "
            << yes(automatic.accepted && automatic.radius == 0.5) << std::endl;
  std::cout << "scarf: G for the support radii 0.3, 0.5 and 0.9 the same "
               "within 1e-3: "
            << yes(small.accepted && large.accepted &&
                   std::abs(small.G / automatic.G - 1) < 1e-3 &&
                   std::abs(large.G / automatic.G - 1) < 1e-3)
            << std::endl;
  std::cout << "scarf: a support radius that reaches the scarf is refused "
               "naming the entry and the ply boundary: "
            << yes(!beyond.accepted &&
                   beyond.refusal.find("Fracture/Support radius = 2") !=
                     std::string::npos &&
                   beyond.refusal.find("a ply boundary") != std::string::npos)
            << std::endl;
}
