// Friction on the crack faces: the three outer solvers (Uzawa with theta =
// auto, the accelerated method, the active-set method) solve the same
// discrete problem by different iterations from different paths, so run to
// a tight tolerance (KKT rule, 1e-11) they must give the same solution: the
// energy, the multipliers mu_t and mu_c and the slip [u].tau at the crack
// nodes to 1e-8, each relative to its own scale (the largest |value| of the
// quantity over the crack nodes; for a slip that vanishes everywhere, the
// displacement scale). Measured: at most 2e-14 (energy), 1.0e-9 (mu_t, at
// the Tresca bound on the non-matching Q1 meshes), 6e-11 (mu_c) and 2e-10
// (slip).
//
// Scenes: Example 1 (docs/problem.md §5) with a shear traction added on
// layer 1, (s c, -c x) on the top and (-s c, c x) on the bottom, so that
// the closed part of the crack is sheared:
//  - Tresca, s = 1/2, g = 1e-3: between the all-stick (g >~ 2e-3) and the
//    all-slip (g <~ 3e-4) regimes, both stick and slip nodes occur (checked
//    on the active-set solution); the active-set method takes at most twice
//    the Newton steps of the frictionless scene (measured 4-5 against 3-4);
//  - Coulomb, s = 1, F = 0.1, 0.3, 0.5, with another material on Omega+ of
//    layer 1 (E = 80, nu = 0.2): the bimaterial couples the normal and the
//    tangential responses (the contact pressure depends on the slip), so
//    the fixed point over Tresca problems does real work (with one material
//    the bounds F mu_c do not depend on mu_t and two steps reach the
//    solution).
// each on matching traces (16 + 16 cells along Sigma for Q1, 8 + 8 for Q2)
// and non-matching ones (16 + 24, 8 + 12), polynomial degrees 1 and 2.
//
// Uniqueness of the discrete Coulomb solution: the fixed-point map
// g -> F mu_c(Tresca(g)) is a contraction for these F. Its observed factor
// (the change of the bounds at step k+1 over that at step k, from the
// progress lines "Coulomb fixed point k", over steps whose change is above
// 1e-9) is 3e-3 ... 2e-2 (F = 0.1), 1e-2 ... 6e-2 (F = 0.3) and 1e-2 ...
// 6e-2 (F = 0.5) on these meshes, the largest on the non-matching Q2 ones;
// the test asserts it below 0.1 (a contraction has one fixed point, and
// every start reaches it). Independently, the three solvers reach the same
// solution although their Tresca iterates, and so the bounds of the second
// and later steps, differ along the way.

#include <bilayer/drivers/study.h>
#include <bilayer/interface/interface_diagnostics.h>
#include <bilayer/parameters/parameters.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdlib>
#include <iomanip>
#include <iostream>
#include <regex>
#include <sstream>
#include <string>
#include <vector>

#include "friction_scenes.h"
#include "reference.h"

using namespace dealii;
using namespace bilayer;

namespace
{
  /// What is compared between the solvers.
  struct Solution
  {
    double              energy = 0;
    std::vector<double> mu_t, mu_c, slip;
    double              displacement_scale = 0;
    unsigned int        stick = 0, slip_nodes = 0;
    /// Largest ratio of successive changes of the Coulomb bounds.
    double contraction = 0;
    bool   converged   = false;
    /// The outer iterations (Newton steps of the active-set method).
    unsigned int iterations = 0;
  };

  double
  largest(const std::vector<double> &v)
  {
    double m = 0;
    for (const double x : v)
      m = std::max(m, std::abs(x));
    return m;
  }

  /// Largest |a - b| over the nodes relative to the scale of the quantity
  /// (the largest |value| of both, @p fallback where it is zero).
  double
  difference(const std::vector<double> &a,
             const std::vector<double> &b,
             const double               fallback)
  {
    if (a.size() != b.size())
      return 1;
    double d = 0;
    for (unsigned int i = 0; i < a.size(); ++i)
      d = std::max(d, std::abs(a[i] - b[i]));
    const double scale = std::max(largest(a), largest(b));
    return d / (scale > 0 ? scale : fallback);
  }

  Solution
  solve(const std::string &scene_text, const std::string &method)
  {
    std::ostringstream log;
    const std::string  text =
      scene_text + "subsection Solver\n set Method = " + method +
      "\n set Uzawa step theta = auto\n set Stopping rule = kkt\n"
      " set Tolerance = 1e-11\n set Maximum iterations = 100000\nend\n"
      "subsection Output\n set Output directory = results\n"
      " set Write VTU = false\n set Write interface CSV = false\n"
      " set Progress interval = 0\n set Terminal output = full\nend\n";
    Study              study(scene_from_string(text, "friction_solvers"), log);
    const CycleRecord &record = study.run_cycle(0);
    Solution           s;
    s.converged          = record.result.converged;
    s.iterations         = record.result.iterations;
    s.energy             = record.energy;
    s.displacement_scale = record.report.displacement_scale;
    for (const InterfaceNode &node : interface_nodes(study.interface(),
                                                     study.solutions(),
                                                     study.multipliers()))
      if (node.on_crack)
        {
          s.mu_t.push_back(-node.tangential_force);
          s.mu_c.push_back(node.mu_c);
          s.slip.push_back(node.jump_tangential);
          s.stick += node.friction_state == FrictionState::stick;
          s.slip_nodes += node.friction_state == FrictionState::slip;
        }

    // The changes of the Coulomb bounds, step by step.
    const std::regex    line("Coulomb fixed point [0-9]+: bounds F mu_c "
                             "changed by ([-+.eE0-9]+) of");
    std::vector<double> changes;
    const std::string   output = log.str();
    for (std::sregex_iterator i(output.begin(), output.end(), line), end;
         i != end;
         ++i)
      changes.push_back(std::stod((*i)[1]));
    for (unsigned int k = 2; k < changes.size(); ++k)
      if (changes[k - 1] > 1e-9)
        s.contraction = std::max(s.contraction, changes[k] / changes[k - 1]);
    return s;
  }

  std::string
  mesh(const unsigned int degree, const bool matching)
  {
    const unsigned int n = degree == 1 ? 16 : 8;
    std::ostringstream s;
    s << "subsection Mesh\n set Cells along Sigma = " << n
      << "\n set Cells along Sigma on the plus side = "
      << (matching ? n : 3 * n / 2)
      << "\n set Polynomial degree of layer 1 = " << degree
      << "\n set Polynomial degree of layer 2 = " << degree << "\nend\n";
    return s.str();
  }
} // namespace


int
main()
{
  // mu1 = 200 / (2 (1 + 0.28)) = 78.125 on Omega- of layer 1 (c = 1e-3 mu1
  // written as a number: mu1 differs between the sides of the bimaterial).
  const std::string tresca = friction_scenes::shear_loads("0.5", "1e-3*mu1") +
                             "subsection Contact\n set Friction = tresca\n"
                             " set Friction bound = 1e-3\nend\n";
  const std::string bimaterial =
    friction_scenes::shear_loads("1", "0.078125") +
    "subsection Materials\n subsection Layer 1\n  subsection Omega+\n"
    "   set Young's modulus = 80\n   set Poisson's ratio = 0.2\n"
    "  end\n end\nend\n";
  std::vector<std::pair<std::string, std::string>> scenes = {
    {"tresca g=1e-3", tresca}};
  for (const char *F : {"0.1", "0.3", "0.5"})
    scenes.emplace_back(std::string("coulomb F=") + F,
                        bimaterial +
                          "subsection Contact\n set Friction = coulomb\n"
                          " set Friction coefficient = " +
                          F + "\nend\n");

  for (const auto &[name, text] : scenes)
    for (const unsigned int degree : {1u, 2u})
      for (const bool matching : {true, false})
        {
          const std::string             scene = mesh(degree, matching) + text;
          const std::array<Solution, 3> s     = {{solve(scene, "active set"),
                                                  solve(scene, "uzawa"),
                                                  solve(scene, "accelerated")}};
          double worst_energy = 0, worst_mu_t = 0, worst_mu_c = 0,
                 worst_slip = 0, contraction = 0;
          bool converged = true;
          for (const Solution &x : s)
            {
              converged   = converged && x.converged;
              contraction = std::max(contraction, x.contraction);
            }
          for (unsigned int i = 1; i < 3; ++i)
            {
              worst_energy        = std::max(worst_energy,
                                      std::abs(s[i].energy - s[0].energy) /
                                        std::abs(s[0].energy));
              const double stress = std::max(largest(s[0].mu_c), 1e-300);
              worst_mu_t =
                std::max(worst_mu_t, difference(s[0].mu_t, s[i].mu_t, stress));
              worst_mu_c =
                std::max(worst_mu_c, difference(s[0].mu_c, s[i].mu_c, stress));
              worst_slip = std::max(worst_slip,
                                    difference(s[0].slip,
                                               s[i].slip,
                                               s[0].displacement_scale));
            }
          std::cout << name << ", Q" << degree
                    << (matching ? ", matching" : ", non-matching")
                    << ": converged: " << yes(converged)
                    << "; energy, mu_t, mu_c, slip agree to 1e-8: "
                    << yes(worst_energy <= 1e-8 && worst_mu_t <= 1e-8 &&
                           worst_mu_c <= 1e-8 && worst_slip <= 1e-8);
          if (name.rfind("tresca", 0) == 0)
            {
              // The box of the friction multipliers should cost the
              // semismooth Newton method few steps: at most twice those of
              // the frictionless scene (docs/performance.md, "Friction:
              // Newton steps and the Coulomb fixed point").
              const Solution frictionless =
                solve(mesh(degree, matching) +
                        friction_scenes::shear_loads("0.5", "1e-3*mu1"),
                      "active set");
              std::cout << "; stick and slip nodes: "
                        << yes(s[0].stick > 0 && s[0].slip_nodes > 0)
                        << "; Newton steps at most twice the frictionless: "
                        << yes(s[0].iterations <= 2 * frictionless.iterations);
              if (std::getenv("BILAYER_TEST_DIAGNOSTICS") != nullptr)
                std::cerr << "Newton steps " << s[0].iterations
                          << ", frictionless " << frictionless.iterations
                          << std::endl;
            }
          else
            std::cout << "; fixed point contracts by < 0.1: "
                      << yes(contraction > 0 && contraction < 0.1);
          std::cout << std::endl;
          if (std::getenv("BILAYER_TEST_DIAGNOSTICS") != nullptr)
            std::cerr << name << " Q" << degree << " " << matching
                      << std::setprecision(3) << ": energy " << worst_energy
                      << ", mu_t " << worst_mu_t << ", mu_c " << worst_mu_c
                      << ", slip " << worst_slip << ", stick/slip nodes "
                      << s[0].stick << "/" << s[0].slip_nodes
                      << ", contraction " << contraction << std::endl;
        }

  // Finer meshes (the sheared scene of scripts/friction_newton): the Newton
  // steps with Tresca friction stay within twice the frictionless ones.
  for (const unsigned int n : {64u, 128u})
    {
      const std::string cells =
        "subsection Mesh\n set Cells along Sigma = " + std::to_string(n) +
        "\nend\n";
      const Solution with =
        solve(cells + friction_scenes::shear_loads("0.5", "1e-3*mu1") +
                "subsection Contact\n set Friction = tresca\n"
                " set Friction bound = 1.5e-3\nend\n",
              "active set");
      const Solution without =
        solve(cells + friction_scenes::shear_loads("0.5", "1e-3*mu1"),
              "active set");
      std::cout << "tresca g=1.5e-3, " << n
                << " cells along Sigma, active set: converged: "
                << yes(with.converged && without.converged)
                << "; stick and slip nodes: "
                << yes(with.stick > 0 && with.slip_nodes > 0)
                << "; Newton steps at most twice the frictionless: "
                << yes(with.iterations <= 2 * without.iterations) << std::endl;
    }
}
