// Stacked layers: N > 2 layers through the thickness (Materials/Number of
// layers), each glued along Sigma to the layer below it on both sides of
// Sigma; layer 1 carries the crack's contact (docs/laminates.md).
//
// The scene: Example 1 of the paper (partial_closure.prm: the square
// (-1, 1)^2, Sigma at y = 0, the crack (-0.5, 0.5), left and right sides
// clamped, layer 1 loaded by (0, c x) below and (0, -c x) on top, which
// closes one half of the crack), the active set to 1e-12.
//
// 1. A third layer of vanishing stiffness gives the two-layer result. The
//    energy of the three-layer problem is a smooth function of the third
//    layer's Young's modulus E_3 = e E_2 (the third layer follows layer 2 on
//    Sigma and adds the energy e a(w_3, w_3) / 2 with a bounded w_3; the
//    contact set does not change for small e): Pi(e) = Pi_2 + c e + O(e^2).
//    With e = 1e-6 and 2e-6 the extrapolation 2 Pi(e) - Pi(2 e) =
//    Pi_2 + O(e^2) must agree with the two-layer energy Pi_2 to 1e-10
//    relative (measured 8e-15), and G at both tips to 1e-8. Beside it,
//    Pi(e) itself must differ from Pi_2, by more than round-off (1e-12)
//    and less than 1e-4 (it differs by O(e); measured 1.1e-8).
// 2. Three identical layers, each loaded as layer 1, against one layer of
//    three times the stiffness under three times the load: by symmetry the
//    unique minimiser has equal layers (swapping two layers maps the
//    admissible set onto itself), each the one-layer solution of the
//    scaled problem, so the energies and G agree (1e-10 relative), on the
//    scene with its partly closed crack and on the same scene glued
//    everywhere (no crack: the stack is a single body of stiffness 3 E).
//    Measured 1e-15 (both). With the energy of the layers above 2 left out
//    of the sum, these and check 3 fail (0.33 and 0.19).
// 3. Five layers of different materials, layers 1 and 3 loaded: G at the
//    left tip (the open one) against the fourth-order central difference
//    of the energy against that crack end's position a (+- h, +- 2h,
//    h = 1/32, 64 cells along Sigma: a vertex at each shifted tip):
//    within 2e-3 of G (measured 7e-4; the difference is O(h^4) and G's
//    discretisation error on this mesh dominates).

#include <bilayer/drivers/study.h>
#include <bilayer/parameters/parameters.h>

#include <cmath>
#include <cstdlib>
#include <iomanip>
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
    bool                accepted = false;
    double              energy   = std::nan("");
    std::vector<double> G;
  };

  /// Runs the scene @p text quietly.
  Outcome
  run(const std::string &text)
  {
    std::ostringstream sink;
    Study   study(scene_from_string(text + quiet_output(), "stacked_layers"),
                sink);
    Outcome o;
    o.accepted = study.run();
    if (!o.accepted)
      {
        std::cout << sink.str();
        return o;
      }
    o.energy = study.records().back().energy;
    for (const auto &r : study.records().back().release)
      o.G.push_back(r.G);
    return o;
  }

  /// Example 1 with @p layers (the Materials and Loads sections) and the
  /// crack (@p crack_start, 0.5) or none.
  std::string
  scene(const std::string &layers,
        const bool         crack       = true,
        const double       crack_start = -0.5,
        const unsigned int cells       = 16)
  {
    std::ostringstream s;
    s << std::setprecision(17);
    s << "subsection Geometry\n set Lower left corner = -1, -1\n"
         " set Upper right corner = 1, 1\n set Height of Sigma = 0\n"
      << (crack ? " set Crack interval on Sigma = " +
                    std::to_string(crack_start) + ", 0.5\n" :
                  " set Crack interval on Sigma = 0, 0\n")
      << " set Clamped sides = left, right\nend\n"
         "subsection Mesh\n set Cells along Sigma = "
      << cells
      << "\n set Number of cycles = 1\nend\n"
         "subsection Contact\n set Multiplier bound p = 1e7\nend\n"
         "subsection Solver\n set Method = active set\n"
         " set Tolerance = 1e-12\nend\n"
         "subsection Fracture\n set Energy release rate = "
      << (crack ? "true" : "false") << "\nend\n"
      << layers;
    return s.str();
  }

  std::string
  material(const unsigned int k, const double E, const double nu)
  {
    std::ostringstream s;
    s << std::setprecision(17) << " subsection Layer " << k
      << "\n  set Young's modulus = " << E << "\n  set Poisson's ratio = " << nu
      << "\n end\n";
    return s.str();
  }

  /// Loads/Layer k with the traction c x of Example 1 times @p factor.
  std::string
  load(const unsigned int k, const double factor)
  {
    std::ostringstream s;
    s << std::setprecision(17) << " subsection Layer " << k
      << "\n  set Traction on bottom side = 0; " << factor
      << " * 0.078125 * x\n  set Traction on top side = 0; " << -factor
      << " * 0.078125 * x\n end\n";
    return s.str();
  }

  /// The measured numbers go to stderr with BILAYER_TEST_DIAGNOSTICS set.
  const bool diagnostics = std::getenv("BILAYER_TEST_DIAGNOSTICS") != nullptr;

  double
  relative(const double a, const double b)
  {
    return std::abs(a - b) / std::max(std::abs(a), std::abs(b));
  }

  bool
  same_G(const Outcome &a, const Outcome &b, const double tol)
  {
    if (a.G.size() != b.G.size() || a.G.empty())
      return false;
    for (unsigned int t = 0; t < a.G.size(); ++t)
      if (!(relative(a.G[t], b.G[t]) <= tol))
        return false;
    return true;
  }
} // namespace


int
main()
{
  std::cout << std::scientific << std::setprecision(1);

  // 1. A vanishing third layer.
  {
    const auto stack = [](const unsigned int n, const double e) {
      std::string m =
        "subsection Materials\n set Number of layers = " + std::to_string(n) +
        "\n" + material(1, 200, 0.28) + material(2, 112, 0.32);
      if (n == 3)
        m += material(3, e * 112, 0.3);
      return scene(m + "end\nsubsection Loads\n" + load(1, 1) + "end\n");
    };
    const double  e   = 1e-6;
    const Outcome two = run(stack(2, 0)), soft = run(stack(3, e)),
                  softer = run(stack(3, 2 * e));
    const bool ok =
      two.accepted && soft.accepted && softer.accepted && two.G.size() == 2;
    std::cout << "a vanishing third layer: accepted, two tips: " << yes(ok)
              << '\n';
    if (ok)
      {
        const double extrapolated = 2 * soft.energy - softer.energy;
        Outcome      G0           = soft;
        for (unsigned int t = 0; t < G0.G.size(); ++t)
          G0.G[t] = 2 * soft.G[t] - softer.G[t];
        const double d = relative(extrapolated, two.energy);
        std::cout << "a vanishing third layer: the energy extrapolated to "
                     "E_3 = 0 is the two-layer energy (1e-10): "
                  << yes(d <= 1e-10) << '\n';
        std::cout << "a vanishing third layer: G extrapolated to E_3 = 0 is "
                     "the two-layer G at both tips (1e-8): "
                  << yes(same_G(G0, two, 1e-8)) << '\n';
        std::cout << "a vanishing third layer: E_3 = 1e-6 E_2 changes the "
                     "energy, by more than 1e-12 and less than 1e-4: "
                  << yes(relative(soft.energy, two.energy) > 1e-12 &&
                         relative(soft.energy, two.energy) < 1e-4)
                  << '\n';
        if (diagnostics)
          std::cerr << "vanishing layer: extrapolated " << d << ", Pi(e) "
                    << relative(soft.energy, two.energy) << '\n';
      }
  }

  // 2. Three identical layers against one layer of three times the
  // stiffness and the load.
  for (const bool crack : {true, false})
    {
      const std::string m3 =
        "subsection Materials\n set Number of layers = 3\n" +
        material(1, 200, 0.28) + material(2, 200, 0.28) +
        material(3, 200, 0.28) + "end\nsubsection Loads\n" + load(1, 1) +
        load(2, 1) + load(3, 1) + "end\n";
      const std::string m1 = "subsection Materials\n set Number of layers = "
                             "1\n" +
                             material(1, 600, 0.28) +
                             "end\nsubsection Loads\n" + load(1, 3) + "end\n";
      const Outcome three = run(scene(m3, crack)), one = run(scene(m1, crack));
      const std::string what = crack ?
                                 "three identical layers with the crack" :
                                 "three identical layers glued everywhere";
      const bool        ok   = three.accepted && one.accepted;
      std::cout << what << ": accepted: " << yes(ok) << '\n';
      if (ok)
        {
          std::cout << what
                    << ": the energy of one layer of three times the "
                       "stiffness and the load (1e-10): "
                    << yes(relative(three.energy, one.energy) <= 1e-10) << '\n';
          if (crack)
            std::cout << what << ": its G at both tips (1e-10): "
                      << yes(three.G.size() == 2 && same_G(three, one, 1e-10))
                      << '\n';
          if (diagnostics)
            std::cerr << what << ": " << relative(three.energy, one.energy)
                      << '\n';
        }
    }

  // 3. G of a five-layer stack against the difference of the energy.
  {
    std::string  m     = "subsection Materials\n set Number of layers = 5\n";
    const double E[5]  = {200, 112, 70, 150, 90};
    const double nu[5] = {0.28, 0.32, 0.33, 0.3, 0.25};
    for (unsigned int k = 1; k <= 5; ++k)
      m += material(k, E[k - 1], nu[k - 1]);
    m += "end\nsubsection Loads\n" + load(1, 1) + load(3, 0.5) + "end\n";
    const double h = 1. / 32;
    // The crack (a, 0.5) with a = -0.5 + k h: 64 cells along Sigma put a
    // vertex at every a.
    std::vector<double> energies;
    Outcome             centre;
    bool                ok = true;
    for (const int k : {-2, -1, 1, 2, 0})
      {
        const Outcome o = run(scene(m, true, -0.5 + k * h, 64));
        ok              = ok && o.accepted;
        if (k == 0)
          centre = o;
        else
          energies.push_back(o.energy);
      }
    ok = ok && centre.G.size() == 2;
    std::cout << "five layers: accepted, two tips: " << yes(ok) << '\n';
    if (ok)
      {
        // The left tip moves to a: the crack grows as a decreases, so
        // G = dPi/da (fourth-order central difference).
        const double dPi =
          (energies[0] - 8 * energies[1] + 8 * energies[2] - energies[3]) /
          (12 * h);
        const double d = relative(dPi, centre.G[0]);
        std::cout << "five layers: G at the left tip within 2e-3 of the "
                     "fourth-order difference of the energy: "
                  << yes(d <= 2e-3) << '\n';
        if (diagnostics)
          std::cerr << "five layers: G " << centre.G[0] << " dPi/da " << dPi
                    << " (" << d << ")\n";
      }
  }
  return 0;
}
