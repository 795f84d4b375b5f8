// Hard cases that the mathematics decides (the fast part of
// scripts/hard_cases, with the active-set solver on 16 cells along Sigma):
//  - material contrast E2/E1 = 1e-3 and 1e3: the minimum of
//    1/2 a(u,u) - l(u) over the same convex set grows with the stiffness,
//    so Pi(soft layer 2) < Pi(Example 1) < Pi(stiff layer 2);
//  - nearly incompressible layers (nu = 0.499): Q1 locks (compliance far
//    below that of Q2 on twice the cells), Q2 does not;
//  - full closure (the reversed load of Example 2): contact pressure at
//    every crack node, and the linear problem interpenetrates at every one;
//  - crack length: the admissible set grows with the crack, so Pi falls as
//    the crack lengthens (no crack, 0.5, 1, 1.5);
//  - load scale 1e-6 and 1e3: the problem is positively homogeneous, Pi
//    scales with s^2 and the (scale-invariant) Newton count is unchanged;
//  - a bound p below the contact pressure: the run is refused, with a note
//    naming the parameter, and the constraint violation falls as p grows
//    (estimate (12) of docs/problem.md).
//  - a KKT tolerance of 1e-16, below the round-off of the relative residual
//    (about the machine epsilon): the run is refused within 15 Newton steps
//    (not at the 50-step limit), the message naming the stagnation;
//  - Young's moduli 5e5 apart with the settings of
//    parameter_files/template.prm (adaptive Q2, warm starts, inexact Newton
//    steps): every cycle converges, to the energy that exact Newton steps
//    give (the discrete problem has one solution).

#include <bilayer/drivers/study.h>
#include <bilayer/parameters/parameters.h>

#include <cmath>
#include <fstream>
#include <iostream>
#include <sstream>
#include <string>

#include "reference.h"

using namespace dealii;
using namespace bilayer;

namespace
{
  std::ostringstream quiet;

  const std::string common =
    "subsection Mesh\n set Cells along Sigma = 16\nend\n"
    "subsection Solver\n set Method = active set\n set Tolerance = 1e-10\n"
    "end\n"
    "subsection Output\n set Output directory = results\n"
    " set Write VTU = false\n set Write interface CSV = false\n"
    " set Terminal output = checks\nend\n";

  // The last cycle of a one-cycle study of Example 1 (or of @p loads) with
  // the extra entries @p text.
  CycleRecord
  run(const std::string &text,
      const std::string &loads = std::string(example1_loads))
  {
    Study study(scene_from_string(common + loads + text, "hard"), quiet);
    return study.run_cycle(0);
  }

  std::string
  materials(const std::string &entries)
  {
    return "subsection Materials\n" + entries + "end\n";
  }

  const std::string closing =
    "subsection Loads\n set Constants = c = 1e-3*mu1\n"
    " subsection Layer 1\n"
    "  set Traction on bottom side = 0; c\n"
    "  set Traction on top side = 0; -c\n end\nend\n";
} // namespace

int
main()
{
  const CycleRecord ex1 = run("");

  const CycleRecord soft =
    run(materials(" subsection Layer 2\n  set Young's modulus = 0.2\n end\n"));
  const CycleRecord stiff = run(
    materials(" subsection Layer 2\n  set Young's modulus = 200000\n end\n"));
  std::cout << "contrast 1e-3 and 1e3: accepted: "
            << yes(soft.accepted() && stiff.accepted())
            << ", Pi(soft) < Pi(Ex. 1) < Pi(stiff): "
            << yes(soft.energy < ex1.energy && ex1.energy < stiff.energy)
            << std::endl;

  const std::string nu = " subsection Layer 1\n  set Poisson's ratio = 0.499\n"
                         " end\n subsection Layer 2\n"
                         "  set Poisson's ratio = 0.499\n end\n";
  const auto degree    = [](const unsigned int k, const unsigned int cells) {
    return "subsection Mesh\n set Polynomial degree of layer 1 = " +
           std::to_string(k) +
           "\n set Polynomial degree of layer 2 = " + std::to_string(k) +
           "\n set Cells along Sigma = " + std::to_string(cells) + "\nend\n";
  };
  const double q1  = run(materials(nu) + degree(1, 16)).energy;
  const double q2  = run(materials(nu) + degree(2, 16)).energy;
  const double ref = run(materials(nu) + degree(2, 32)).energy;
  std::cout << "nu = 0.499: Q1 locks (compliance < 0.9 of Q2 on 32 cells): "
            << yes(q1 / ref < 0.9)
            << ", Q2 does not (> 0.95): " << yes(q2 / ref > 0.95) << std::endl;

  {
    Study      closed(scene_from_string(common + closing, "closed"), quiet);
    const bool accepted = closed.run_cycle(0).accepted();
    Study      linear(scene_from_string(common + closing +
                                     "subsection Contact\n set Non-penetration "
                                          "on the crack = false\nend\n",
                                   "linear"),
                 quiet);
    linear.run_cycle(0);
    const auto   open = normal_opening(linear.interface(), linear.solutions());
    bool         pressed = true, penetrates = true;
    unsigned int n = 0;
    for (unsigned int a = 0; a < closed.interface().space().n_nodes(); ++a)
      if (closed.interface().space().on_crack(a))
        {
          ++n;
          pressed =
            pressed &&
            closed.interface().space().contact_multiplier(closed.multipliers(),
                                                          a) > 0;
        }
    for (unsigned int a = 0; a < linear.interface().space().n_nodes(); ++a)
      if (linear.interface().space().on_crack(a))
        penetrates = penetrates && open[a] < 0;
    std::cout << "full closure: accepted: " << yes(accepted)
              << ", mu_c > 0 at all " << n << " crack nodes: " << yes(pressed)
              << ", the linear problem interpenetrates at all: "
              << yes(penetrates) << std::endl;
  }

  double previous = 0;
  bool   falls    = true;
  for (const std::string crack :
       {"0, 0", "-0.25, 0.25", "-0.5, 0.5", "-0.75, 0.75"})
    {
      const double pi = run("subsection Geometry\n set Crack interval on "
                            "Sigma = " +
                            crack + "\nend\n")
                          .energy;
      falls    = falls && (crack == "0, 0" || pi <= previous);
      previous = pi;
    }
  std::cout << "Pi falls as the crack lengthens (0, 0.5, 1, 1.5): "
            << yes(falls) << std::endl;

  for (const std::string s : {"1e-6", "1e3"})
    {
      const CycleRecord r =
        run("",
            "subsection Loads\n set Constants = c = 1e-3*mu1*" + s +
              "\n subsection Layer 1\n  set Traction on bottom side = 0; c*x\n"
              "  set Traction on top side = 0; -c*x\n end\nend\n");
      const double scale = std::stod(s);
      std::cout << "load x " << s << ": Pi = s^2 Pi(Ex. 1) to 1e-6: "
                << yes(std::abs(r.energy / (scale * scale * ex1.energy) - 1) <
                       1e-6)
                << ", same Newton steps: "
                << yes(r.result.iterations == ex1.result.iterations)
                << std::endl;
    }

  std::vector<double> violation;
  bool                refused = true, named = true;
  for (const std::string p : {"0.0025", "0.005", "0.01"})
    {
      const CycleRecord r =
        run("subsection Contact\n set Multiplier bound p = " + p + "\nend\n");
      violation.push_back(r.report.relative_constraint_violation);
      refused = refused && !r.accepted();
      named   = named && r.failure().find("Contact/Multiplier bound p") !=
                         std::string::npos;
    }
  std::cout << "bound p = 0.0025, 0.005, 0.01 below the contact pressure: "
               "refused: "
            << yes(refused) << ", named: " << yes(named)
            << ", violation falls as p grows: "
            << yes(violation[0] > violation[1] && violation[1] > violation[2])
            << std::endl;

  {
    const CycleRecord r =
      run("subsection Solver\n set Tolerance = 1e-16\nend\n");
    std::cout << "tolerance 1e-16 below round-off: refused: "
              << yes(!r.accepted())
              << ", within 15 Newton steps: " << yes(r.result.iterations <= 15)
              << ", stagnation named: "
              << yes(r.failure().find("stagnates") != std::string::npos &&
                     r.failure().find("raise Solver/Tolerance") !=
                       std::string::npos)
              << std::endl;
  }

  {
    std::ifstream file(SOURCE_DIR "/../parameter_files/template.prm");
    AssertThrow(file, ExcMessage("cannot read parameter_files/template.prm"));
    std::stringstream text;
    text << file.rdbuf();
    const std::string scene =
      text.str() +
      materials(" subsection Layer 2\n  set Young's modulus = 1e8\n end\n") +
      "subsection Output\n set Write VTU = false\n set Write interface CSV = "
      "false\n set Terminal output = checks\nend\n";
    const auto energies = [&](const std::string &inner, bool &accepted) {
      Study               study(scene_from_string(scene +
                                      "subsection Solver\n subsection Active "
                                                    "set\n  set Inner tolerance = " +
                                      inner + "\n end\nend\n",
                                    "contrast"),
                  quiet);
      std::vector<double> pi;
      accepted = true;
      for (unsigned int cycle = 0; cycle < 3; ++cycle)
        {
          const CycleRecord r = study.run_cycle(cycle);
          accepted            = accepted && r.accepted();
          pi.push_back(r.energy);
        }
      return pi;
    };
    bool       inexact_accepted, exact_accepted;
    const auto inexact = energies("1e-2", inexact_accepted);
    const auto exact   = energies("1e-14", exact_accepted);
    bool       same    = true;
    for (unsigned int c = 0; c < 3; ++c)
      same = same && std::abs(inexact[c] / exact[c] - 1) < 1e-8;
    std::cout << "moduli 5e5 apart, the template's settings, 3 adaptive "
                 "cycles: accepted: "
              << yes(inexact_accepted && exact_accepted)
              << ", the energies of exact Newton steps (1e-8): " << yes(same)
              << std::endl;
  }
}
