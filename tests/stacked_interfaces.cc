// Stacked layers on several interfaces (docs/laminates.md): N layers
// through the thickness over a cross-section cut into regions by several
// interfaces; layer 1 carries each interface's crack (contact, glue across
// it), and each layer k >= 2 is glued to layer k - 1 along every interface,
// on both regions it separates.
//
// The scene: parameter_files/two_delaminations.prm (three regions of
// height 1 on (0, 32) x (0, 3), the cracks (0, 8) on Sigma and (0, 20) on
// interface 2, end moments on the outer arms), adaptive Q2.
//
// 1. Two identical layers, each loaded as layer 1 of the scene: swapping
//    the layers maps the admissible set onto itself, so the unique
//    minimiser has equal layers, each the one-layer solution. Every cycle's
//    energy is twice the one-layer energy (1e-10; the meshes are the same,
//    as the indicators double), G at both tips twice the one-layer G
//    (1e-8). Layer 2 is not coupled across an interface itself: its half
//    of the force across passes through the gluing to layer 1 on both
//    sides, so the largest gluing multiplier is half the largest
//    multiplier across the interfaces (1e-6).
// 2. A second layer of vanishing stiffness E_2 = e E_1 (e = 1e-4),
//    unloaded, on uniform meshes (the same for every e): Pi(e) = Pi_1 +
//    c e + d e^2 + O(e^3), so (8 Pi(e) - 6 Pi(2 e) + Pi(4 e)) / 3 agrees
//    with the one-layer energy Pi_1 to 1e-9 (relative; the solver's
//    tolerance 1e-12 bounds each energy to about 1e-11, which the weights
//    of the extrapolation multiply by 5; measured 1.4e-10) and G likewise
//    to 1e-8 (measured 2e-11); Pi(e) itself differs from Pi_1 by more than
//    round-off (1e-12) and less than 1e-3 (measured 1e-4).
// 3. Three layers of different materials (E = 1, 2, 0.5), layers 1 and 3
//    loaded: the layers stay glued along both interfaces (the layer gaps at
//    the nodes of each interface below 1e-8 of the largest trace, the
//    gluing multipliers of interface 2 carry load), and G at the tip of
//    interface 2 agrees with the fourth-order central difference of the
//    energy with that tip moved by +-0.25, +-0.5 (the meshes fitted to the
//    tips; 8 adaptive cycles) to 1e-3 of the larger G (the tip on Sigma of
//    stacked layers: tests/stacked_layers.cc).

#include <bilayer/drivers/study.h>
#include <bilayer/interface/interface_diagnostics.h>
#include <bilayer/parameters/parameters.h>

#include <algorithm>
#include <cmath>
#include <fstream>
#include <iostream>
#include <sstream>
#include <string>
#include <vector>

#include "quiet_output.h"
#include "study_outcome.h"
#include "verdict.h"

using namespace bilayer;

namespace
{
  struct Outcome : StudyOutcome
  {
    /// Over both interfaces: the largest gluing multiplier of layer 2
    /// (mu_minus, mu_plus), the largest multiplier across the interface
    /// (mu_c, mu_g), the largest layer gap and the largest trace.
    double glue = 0, across = 0, gap = 0, trace = 0;
    /// The largest gluing multiplier of layer 2 along interface 2.
    double glue_2 = 0;
  };

  Outcome
  run(const std::string &text)
  {
    std::ostringstream sink;
    Study study(scene_from_string(text + quiet_output(), "stacked_interfaces"),
                sink);
    Outcome r;
    static_cast<StudyOutcome &>(r) = study_outcome(study, study.run());
    if (!r.accepted)
      return r;
    for (unsigned int i = 0; i < study.interface().n_interfaces(); ++i)
      for (const InterfaceNode &n : interface_nodes(study.interface(),
                                                    study.solutions(),
                                                    study.multipliers(),
                                                    1e-10,
                                                    i))
        {
          const double glue = std::max(n.mu_minus.norm(), n.mu_plus.norm());
          r.glue            = std::max(r.glue, glue);
          if (i == 1)
            r.glue_2 = std::max(r.glue_2, glue);
          r.across = std::max({r.across, std::abs(n.mu_c), n.mu_g.norm()});
          r.gap =
            std::max({r.gap, n.layer_gap[0].norm(), n.layer_gap[1].norm()});
          for (const auto &t : n.trace)
            r.trace = std::max(r.trace, t.norm());
        }
    return r;
  }

  /// parameter_files/two_delaminations.prm with the cracks ending at
  /// @p a1 (Sigma) and @p a2 (interface 2), @p cycles cycles, and @p extra
  /// appended.
  std::string
  scene(const std::string &extra,
        const unsigned int cycles,
        const double       a1 = 8,
        const double       a2 = 20)
  {
    std::ifstream      in(std::string(SOURCE_DIR) +
                     "/../parameter_files/two_delaminations.prm");
    std::ostringstream text;
    text.precision(17);
    text << in.rdbuf()
         << "subsection Geometry\n set Crack interval on Sigma = 0, " << a1
         << "\n set Interfaces above Sigma = 2: 0, " << a2
         << "\nend\nsubsection Mesh\n set Number of cycles = " << cycles
         << "\nend\n"
         << extra;
    return text.str();
  }

  /// The layers 2 and 3 (when @p layers is 3) with the laws E_k, nu_k; the
  /// end moments of the scene on the layers of @p loaded.
  std::string
  layers(const unsigned int               n,
         const std::vector<double>       &E,
         const std::vector<double>       &nu,
         const std::vector<unsigned int> &loaded)
  {
    std::ostringstream s;
    s.precision(17);
    s << "subsection Materials\n set Number of layers = " << n << "\n";
    for (unsigned int k = 0; k < n; ++k)
      s << " subsection Layer " << k + 1 << "\n  set Young's modulus = " << E[k]
        << "\n  set Poisson's ratio = " << nu[k] << "\n end\n";
    s << "end\nsubsection Mesh\n";
    // (Layers above 2 take the degree of layer 2.)
    s << " set Polynomial degree of layer 2 = 2\n";
    s << "end\nsubsection Loads\n";
    for (unsigned int k = 1; k <= n; ++k)
      s << " subsection Layer " << k << "\n  set Traction on left side = "
        << (std::count(loaded.begin(), loaded.end(), k) > 0 ?
              "(y < 1 ? -12*M*(y - 0.5) : (y > 2 ? 12*M*(y - 2.5) : 0)); 0" :
              "0; 0")
        << "\n end\n";
    s << "end\n";
    return s.str();
  }

  bool
  relative(const double a, const double b, const double tol)
  {
    return std::abs(a - b) <= tol * std::abs(b);
  }
} // namespace


int
main()
{
  const Outcome one = run(scene("", 5));

  // 1. Two identical layers, both loaded.
  {
    const Outcome two = run(scene(layers(2, {1, 1}, {0.3, 0.3}, {1, 2}), 5));
    bool twice = one.accepted && two.accepted && one.energies.size() == 5 &&
                 two.energies.size() == 5;
    for (unsigned int k = 0; twice && k < 5; ++k)
      twice = relative(two.energies[k], 2 * one.energies[k], 1e-10);
    std::cout << "two identical layers: every cycle's energy is twice the "
                 "one-layer energy (1e-10): "
              << yes(twice) << std::endl;
    bool G = two.release.size() == 2 && one.release.size() == 2;
    for (unsigned int t = 0; G && t < 2; ++t)
      G = two.release[t].tip.interface == t &&
          relative(two.release[t].G, 2 * one.release[t].G, 1e-8);
    std::cout << "two identical layers: G at the tip of each interface is "
                 "twice the one-layer G (1e-8): "
              << yes(G) << std::endl;
    std::cout << "two identical layers: the gluing multipliers carry layer "
                 "2's half of the force across the interfaces (the largest "
                 "is half the largest across them, 1e-6): "
              << yes(two.accepted && two.across > 0 &&
                     relative(two.glue, two.across / 2, 1e-6))
              << std::endl;
  }

  // 2. A second layer of vanishing stiffness (uniform meshes, the same
  // for every e).
  {
    const std::string uniform =
      "subsection Mesh\n set Refinement = global\nend\n"
      "subsection Solver\n set Tolerance = 1e-12\nend\n";
    const Outcome        reference = run(scene(uniform, 3));
    const double         e         = 1e-4;
    std::vector<Outcome> r;
    for (const double k : {1., 2., 4.})
      r.push_back(
        run(scene(layers(2, {1, k * e}, {0.3, 0.3}, {1}) + uniform, 3)));
    bool ok = reference.accepted && reference.release.size() == 2;
    for (const Outcome &o : r)
      ok = ok && o.accepted && o.release.size() == 2;
    // (8 Pi(e) - 6 Pi(2 e) + Pi(4 e)) / 3 = Pi_1 + O(e^3).
    const auto extrapolate = [&](const auto &value) {
      return (8 * value(r[0]) - 6 * value(r[1]) + value(r[2])) / 3;
    };
    const double Pi_1 = reference.energies.back();
    bool         same =
      ok &&
      relative(extrapolate([](const Outcome &o) { return o.energies.back(); }),
               Pi_1,
               1e-9);
    for (unsigned int t = 0; same && t < 2; ++t)
      same =
        relative(extrapolate([t](const Outcome &o) { return o.release[t].G; }),
                 reference.release[t].G,
                 1e-8);
    std::cout << "a second layer of stiffness e E_1: the extrapolation to "
                 "e = 0 of the energy equals the one-layer energy (1e-9), "
                 "of G likewise (1e-8): "
              << yes(same) << std::endl;
    const double change = ok ? std::abs(r[0].energies.back() / Pi_1 - 1) : 0;
    std::cout << "a second layer of stiffness e E_1: Pi(e) differs from the "
                 "one-layer energy by more than 1e-12 and less than 1e-3: "
              << yes(change > 1e-12 && change < 1e-3) << std::endl;
  }

  // 3. Three layers of different materials, layers 1 and 3 loaded.
  {
    const std::string  stack = layers(3, {1, 2, 0.5}, {0.3, 0.2, 0.35}, {1, 3});
    const unsigned int cycles = 8;
    const double       a1 = 8, a2 = 20, delta = 0.25;
    const Outcome      base     = run(scene(stack, cycles, a1, a2));
    bool               accepted = base.accepted && base.release.size() == 2;
    std::cout << "three layers: glued along both interfaces (layer gaps "
                 "below 1e-8 of the largest trace; interface 2's gluing "
                 "multipliers carry load): "
              << yes(accepted && base.gap <= 1e-8 * base.trace &&
                     base.glue_2 > 1e-3 * base.across)
              << std::endl;
    double G_max = 0;
    for (const auto &tip : base.release)
      G_max = std::max(G_max, std::abs(tip.G));
    for (unsigned int t = 1; accepted && t < 2; ++t)
      {
        const auto energy = [&](const int k) {
          const Outcome r = t == 0 ?
                              run(scene(stack, cycles, a1 + k * delta, a2)) :
                              run(scene(stack, cycles, a1, a2 + k * delta));
          accepted        = accepted && r.accepted;
          return r.energies.empty() ? std::nan("") : r.energies.back();
        };
        const double fd =
          -(8 * (energy(1) - energy(-1)) - (energy(2) - energy(-2))) /
          (12 * delta);
        std::cout << "three layers, tip " << t + 1 << " (interface " << t + 1
                  << "): the difference of the energy agrees with G to 1e-3 "
                     "of the larger G: "
                  << yes(std::abs(fd - base.release[t].G) <= 1e-3 * G_max)
                  << std::endl;
      }
    std::cout << "three layers: every run accepted: " << yes(accepted)
              << std::endl;
  }
}
