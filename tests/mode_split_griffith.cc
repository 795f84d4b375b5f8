// The mode split G = G_I + G_II of the Griffith crack (docs/fracture.md §7).
//
// One layer (E = 1, nu = 0.3, plane strain) in (-1, 1)^2, the crack (-a, a)
// on Sigma (y = 0), a = 0.05 (a/W = 1/20), the displacement of the uniform
// state sigma_yy = sigma_n, sigma_xy = tau prescribed on the whole boundary
// (mode_split_scenes.h; adaptive Q2, 12 cycles from 20 cells along Sigma).
// In the infinite plate K_I = sigma_n sqrt(pi a), K_II = tau sqrt(pi a) and
//   G_I = (1 - nu^2) pi a sigma_n^2 / E,  G_II = (1 - nu^2) pi a tau^2 / E,
// so G_I / G = sigma_n^2 / (sigma_n^2 + tau^2) and G_II / G = tau^2 /
// (sigma_n^2 + tau^2), whatever the finite-size factor of the plate (the
// same for both modes up to the (a/W)^2 terms of the clamped square: the
// finite-size deficit of G is 0.4 % here). For the Griffith crack the
// closure integrals of the two modes have the same form (sigma_yy and
// sigma_xy ahead, the opening and the sliding behind are the same functions
// of x times sigma_n and tau), so their ratio is sigma_n^2 / tau^2 at every
// closure length: what the test sees is the discretisation error of the
// split. Asserted (both tips):
// 1. Inclined tension T at beta = 45 and 60 degrees from the crack line
//    (sigma_n = T sin^2 beta, tau = T sin beta cos beta): the runs are
//    accepted; G_I + G_II = G (relative 1e-12); G_I / G and G_II / G within
//    1 % of the ratios above; G within 1 % of G_I + G_II of the infinite
//    plate; G_I, G_II within 1.5 % of their closed forms (1 % of the ratio
//    and the finite-size deficit); the phase angle within 0.5 degrees of
//    atan(tau / sigma_n). The plate is symmetric about the crack line, so
//    the tension and the shear parts of the load are its modes: G_I is G of
//    the same plate under sigma_n alone and G_II that under tau alone, the
//    finite-size factor included (G is quadratic in the load: the runs of
//    2. and 3. under T, scaled by (sigma_n / T)^2 and (tau / T)^2): both
//    within 0.3 %.
// 2. Pure tension (tau = 0): G_II / G < 1e-3, phase angle < 1 degree.
// 3. Pure shear with the faces free (no non-penetration, no contact
//    pressure): G_I / G < 1e-3, phase angle > 89 degrees.
// 4. A closed crack: compression sigma_n = -tau and shear, non-penetration:
//    the faces touch, their opening is 0, so G_I = 0 exactly, G_II = G
//    exactly, phase angle 90; G within 1 % of (1 - nu^2) pi a tau^2 / E.
// The measured numbers are written to measured.txt in the test's directory.

#include <bilayer/postprocess/mode_split.h>

#include <cmath>
#include <fstream>
#include <iostream>
#include <string>
#include <vector>

#include "mode_split_scenes.h"
#include "verdict.h"

using namespace bilayer;

namespace
{
  constexpr double  E = 1, nu = 0.3, a = 0.05, T = 1e-3;
  const char *const measured = "measured.txt";

  struct Result
  {
    bool                           accepted = false;
    std::vector<EnergyReleaseRate> tips;
  };

  Result
  griffith(const double sigma_n, const double tau, const bool contact)
  {
    std::ostringstream sink;
    Study              study(scene_from_string(mode_split_scenes::griffith(
                                    a, E, nu, sigma_n, tau, contact, 12),
                                  "mode_split_griffith"),
                sink);
    Result             r;
    r.accepted = study.run();
    r.tips     = study.records().back().release;
    return r;
  }

  void
  check(const std::string &what, const bool ok)
  {
    std::cout << what << ": " << yes(ok) << std::endl;
  }

  bool
  sums(const Result &r)
  {
    bool ok = r.tips.size() == 2;
    for (const EnergyReleaseRate &g : r.tips)
      ok = ok && std::abs(g.G_I + g.G_II - g.G) <= 1e-12 * std::abs(g.G);
    return ok;
  }

  /// G at the first tip under the tension T alone and under the shear T
  /// alone (the faces free), from 2. and 3.
  double G_tension = 0, G_shear = 0;

  void
  inclined(const int beta)
  {
    const double b = beta * M_PI / 180, sigma_n = T * std::sin(b) * std::sin(b),
                 tau  = T * std::sin(b) * std::cos(b);
    const double GI0  = mode_split_scenes::infinite_plate(a, E, nu, sigma_n),
                 GII0 = mode_split_scenes::infinite_plate(a, E, nu, tau);
    const double      phase0 = std::atan(tau / sigma_n) * 180 / M_PI;
    const Result      r      = griffith(sigma_n, tau, true);
    const std::string name = "inclined tension, beta = " + std::to_string(beta);
    check(name + ": run accepted, two tips", r.accepted && r.tips.size() == 2);
    if (r.tips.size() != 2)
      return;
    check(name + ": G_I + G_II = G (1e-12)", sums(r));
    bool ratio = true, G = true, parts = true, phase = true, modes = true;
    for (const EnergyReleaseRate &g : r.tips)
      {
        ratio = ratio &&
                std::abs(g.G_I / g.G / (GI0 / (GI0 + GII0)) - 1) <= 0.01 &&
                std::abs(g.G_II / g.G / (GII0 / (GI0 + GII0)) - 1) <= 0.01;
        G     = G && std::abs(g.G / (GI0 + GII0) - 1) <= 0.01;
        parts = parts && std::abs(g.G_I / GI0 - 1) <= 0.015 &&
                std::abs(g.G_II / GII0 - 1) <= 0.015;
        phase = phase && std::abs(g.phase_angle - phase0) <= 0.5;
        const double GI_plate  = G_tension * std::pow(sigma_n / T, 2),
                     GII_plate = G_shear * std::pow(tau / T, 2);
        modes = modes && std::abs(g.G_I / GI_plate - 1) <= 3e-3 &&
                std::abs(g.G_II / GII_plate - 1) <= 3e-3;
        std::ofstream(measured, std::ios::app)
          << std::setprecision(6) << name << ", tip at x = " << g.tip.point[0]
          << ": G / G_closed = " << g.G / (GI0 + GII0)
          << ", G_I / G = " << g.G_I / g.G << " (exact " << GI0 / (GI0 + GII0)
          << "), G_II / G = " << g.G_II / g.G
          << ", G_I / G_I,closed = " << g.G_I / GI0
          << ", G_II / G_II,closed = " << g.G_II / GII0 << ", phase angle "
          << g.phase_angle << " (exact " << phase0 << "), closure length "
          << g.mode_split_length << ", G_I / G_I,plate = " << g.G_I / GI_plate
          << ", G_II / G_II,plate = " << g.G_II / GII_plate << std::endl;
      }
    check(name + ": G_I / G and G_II / G within 1 % of the exact ratios",
          ratio);
    check(name + ": G within 1 % of the infinite plate's", G);
    check(name + ": G_I and G_II within 1.5 % of their closed forms", parts);
    check(name + ": phase angle within 0.5 degrees", phase);
    check(name + ": G_I and G_II within 0.3 % of G under sigma_n alone and tau "
                 "alone",
          modes);
  }
} // namespace


int
main()
{
  std::ofstream(measured, std::ios::trunc) << "";

  // Pure tension: mode I.
  {
    const Result r  = griffith(T, 0, true);
    bool         ok = r.accepted && sums(r);
    for (const EnergyReleaseRate &g : r.tips)
      {
        ok        = ok && g.G > 0 && g.G_II / g.G < 1e-3 && g.phase_angle < 1;
        G_tension = r.tips[0].G;
        std::ofstream(measured, std::ios::app)
          << "pure tension: G_II / G = " << g.G_II / g.G << ", phase angle "
          << g.phase_angle << std::endl;
      }
    check("pure tension: G_II / G < 1e-3, phase angle < 1 degree", ok);
  }
  // Pure shear, the faces free: mode II.
  {
    const Result r  = griffith(0, T, false);
    bool         ok = r.accepted && sums(r);
    for (const EnergyReleaseRate &g : r.tips)
      {
        ok      = ok && g.G > 0 && g.G_I / g.G < 1e-3 && g.phase_angle > 89;
        G_shear = r.tips[0].G;
        std::ofstream(measured, std::ios::app)
          << "pure shear, free faces: G_I / G = " << g.G_I / g.G
          << ", phase angle " << g.phase_angle << std::endl;
      }
    check("pure shear, free faces: G_I / G < 1e-3, phase angle > 89 degrees",
          ok);
  }
  inclined(45);
  inclined(60);
  // A closed crack under compression and shear.
  {
    const Result r   = griffith(-T, T, true);
    const double GII = mode_split_scenes::infinite_plate(a, E, nu, T);
    bool         ok = r.accepted && r.tips.size() == 2, G = ok;
    for (const EnergyReleaseRate &g : r.tips)
      {
        ok = ok && g.G_I == 0 && g.G_II == g.G && g.phase_angle == 90;
        G  = G && std::abs(g.G / GII - 1) <= 0.01;
        std::ofstream(measured, std::ios::app)
          << "closed crack: G_I = " << g.G_I << ", G_II / G = " << g.G_II / g.G
          << ", G / G_II,closed = " << g.G / GII << std::endl;
      }
    check("closed crack: G_I = 0, G_II = G exactly, phase angle 90", ok);
    check("closed crack: G within 1 % of (1 - nu^2) pi a tau^2 / E", G);
  }
}
