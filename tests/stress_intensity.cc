// The stress intensity factors by the interaction integral
// (stress_intensity_factors(), docs/fracture.md §10) against closed forms.
//
// The crack (-a, a) on Sigma (y = 0) in (-1, 1)^2, one layer, plane strain,
// the displacement of a piecewise uniform remote state prescribed on the
// whole boundary: sigma_yy = s and sigma_xy = t in both materials,
// sigma_xx = q in the lower one and the strain eps_xx continuous across
// Sigma (u = (eps_xx x + gamma y, eps_yy y), eps_yy and gamma per side,
// from the compliances computed here). Adaptive Q2, 12 cycles from 20
// cells along Sigma, the tips fitted to vertices. As a/W -> 0 this is the
// crack in the infinite plate: for one material K_I = s sqrt(pi a),
// K_II = t sqrt(pi a); between two materials (Rice 1988)
//   K = (s + i t) (1 + 2 i eps) sqrt(pi a) (2 a)^(-i eps)
// at each tip, eps its own oscillation index (the material above the
// crack line in the tip's frame is material 1), reported as K L^(i eps).
// The fixed-grip deficit is analytic in (a/W)^2: with r = K / K_closed
// (complex) at a/W = 1/20 and 1/40, Richardson's (4 r(1/40) - r(1/20)) / 3.
// Asserted, at both tips:
// 1. mode I (s = 1e-3): |r - 1| <= 1 % at 1/40 and the extrapolation
//    within 2e-3; K_II / K_I <= 1e-6;
// 2. the closed crack under compression and shear (s = -5e-3,
//    t = 1e-3): K_II as in 1.; |K_I| <= 1e-3 K_II (the contact pressure's
//    face term; without it K_I = -3.9 K_II);
// 3. the crack inclined at 60 degrees to a uniaxial tension sigma = 1e-3
//    (q = sigma cos^2, s = sigma sin^2, t = sigma sin cos): K_I and K_II
//    as in 1.;
// 4. between two materials (E = 1, nu = 0.3 below; E = 10, nu = 0.2
//    above; eps = -+0.0721), s = 1e-3, t = 5e-4, L = 0.1: |r - 1| <= 1 %
//    and arg r <= 0.5 degrees at 1/40, extrapolated within 2e-3 and 0.2
//    degrees; with L = 0.01 the phase angle moves by eps ln(0.1) at each
//    tip (1e-9 degrees) and |K| stays;
// 5. G from K (|K|^2 / (E* cosh^2(pi eps))) equals the domain-integral G
//    within 2e-3 at every tip of every run (measured at most 1.2e-3);
// 6. notes instead of numbers: between two materials without a reference
//    length (K_I NaN, |K| and eps reported, the note names the entry); an
//    orthotropic layer (the note says anisotropic).
// The numbers are written to measured.txt in the test's directory.

#include <bilayer/drivers/study.h>
#include <bilayer/parameters/parameters.h>

#include <cmath>
#include <complex>
#include <fstream>
#include <iomanip>
#include <iostream>
#include <sstream>
#include <string>
#include <vector>

#include "plane_strain.h"
#include "verdict.h"

using namespace bilayer;
using Complex = std::complex<double>;

namespace
{
  using Material = PlaneStrain;

  struct Load
  {
    double q, s, t; // sigma_xx below, sigma_yy, sigma_xy
  };

  std::ofstream measured("measured.txt");

  std::string
  scene(const double       a,
        const Material    &below,
        const Material    &above,
        const Load        &load,
        const double       L,
        const unsigned int cycles = 12,
        const std::string &extra  = "")
  {
    const double       exx       = below.b11() * load.q + below.b12() * load.s;
    const double       q_above   = (exx - above.b12() * load.s) / above.b11();
    const double       eyy_below = below.b12() * load.q + below.b11() * load.s;
    const double       eyy_above = above.b12() * q_above + above.b11() * load.s;
    std::ostringstream p;
    p << std::setprecision(17) << "subsection Geometry\n"
      << " set Crack interval on Sigma = " << -a << ", " << a
      << "\n set Clamped sides = left, right, bottom, top\nend\n"
      << "subsection Materials\n set Number of layers = 1\n"
      << " subsection Layer 1\n  subsection Omega-\n   set Young's modulus = "
      << below.E << "\n   set Poisson's ratio = " << below.nu
      << "\n  end\n  subsection Omega+\n   set Young's modulus = " << above.E
      << "\n   set Poisson's ratio = " << above.nu << "\n  end\n"
      << extra << " end\nend\n"
      << "subsection Loads\n subsection Layer 1\n"
      << "  set Prescribed displacement = " << exx << "*x + (y > 0 ? "
      << load.t / above.mu() << " : " << load.t / below.mu() << ")*y; (y > 0 ? "
      << eyy_above << " : " << eyy_below << ")*y\n end\nend\n"
      << "subsection Mesh\n set Cells along Sigma = 20\n"
      << " set Fit crack tips = true\n"
      << " set Polynomial degree of layer 1 = 2\n"
      << " set Refinement = adaptive\n set Refinement fraction = 0.8\n"
      << " set Number of cycles = " << cycles << "\nend\n"
      << "subsection Contact\n set Non-penetration on the crack = true\nend\n"
      << "subsection Fracture\n set Reference length = " << L << "\nend\n"
      << "subsection Solver\n set Method = active set\n"
      << " set Tolerance = 1e-10\nend\n"
      << "subsection Output\n set Output directory = results\n"
      << " set Write VTU = false\n set Write interface CSV = false\n"
      << " set Terminal output = checks\nend\n";
    return p.str();
  }

  std::vector<EnergyReleaseRate>
  run(const std::string &text, const std::string &name, bool &accepted)
  {
    std::ostringstream sink;
    Study              study(scene_from_string(text, name), sink);
    accepted = study.run() && study.records().back().release.size() == 2;
    return study.records().back().release;
  }

  /// Rice's K L^(i eps) of the crack (-a, a) under (s, t) at a tip of
  /// oscillation index eps.
  Complex
  closed_form(const double a,
              const Load  &load,
              const double eps,
              const double L)
  {
    const double turn = eps == 0 ? 0 : eps * std::log(L / (2 * a));
    return Complex(load.s, load.t) * Complex(1, 2 * eps) * std::sqrt(M_PI * a) *
           std::exp(Complex(0, turn));
  }

  void
  check(const std::string &what, const bool ok)
  {
    std::cout << what << ": " << yes(ok) << std::endl;
  }

  double worst_g_from_k = 0;
  bool   all_accepted   = true;

  /// The ratios r = K / K_closed at both tips for a/W = 1/20 and 1/40.
  std::array<std::array<Complex, 2>, 2>
  ratios(const std::string                             &name,
         const Material                                &below,
         const Material                                &above,
         const Load                                    &load,
         const double                                   L,
         std::array<std::vector<EnergyReleaseRate>, 2> *keep = nullptr)
  {
    std::array<std::array<Complex, 2>, 2> r;
    const double                          sizes[2] = {0.05, 0.025};
    for (unsigned int k = 0; k < 2; ++k)
      {
        bool       accepted = false;
        const auto release =
          run(scene(sizes[k], below, above, load, L), name, accepted);
        all_accepted = all_accepted && accepted;
        if (!accepted)
          return r;
        for (unsigned int t = 0; t < 2; ++t)
          {
            const EnergyReleaseRate &g = release[t];
            const Complex            K(g.K_I, g.K_II);
            const Complex            exact =
              closed_form(sizes[k], load, g.oscillation_index, L);
            r[k][t] = K / exact;
            worst_g_from_k =
              std::max(worst_g_from_k, std::abs(g.G_from_K - g.G) / g.G);
            measured << std::setprecision(8) << name << " a = " << sizes[k]
                     << " tip " << t + 1 << ": K_I = " << g.K_I
                     << ", K_II = " << g.K_II << " (closed form "
                     << exact.real() << ", " << exact.imag()
                     << "), phase angle " << g.K_phase_angle << ", eps "
                     << g.oscillation_index << ", G " << g.G << ", G from K "
                     << g.G_from_K << std::endl;
          }
        if (keep != nullptr)
          (*keep)[k] = release;
      }
    return r;
  }

  /// The checks of a case: |r - 1| at 1/40 and of the extrapolation, and
  /// arg r where the closed form has a phase.
  void
  verdicts(const std::string                           &name,
           const std::array<std::array<Complex, 2>, 2> &r,
           const bool                                   phase)
  {
    bool raw = true, extrapolated = true, angle = true;
    for (unsigned int t = 0; t < 2; ++t)
      {
        const Complex e = (4. * r[1][t] - r[0][t]) / 3.;
        raw             = raw && std::abs(r[1][t] - 1.) <= 0.01;
        extrapolated    = extrapolated && std::abs(std::abs(e) - 1) <= 2e-3 &&
                       std::abs(e - 1.) <= (phase ? 5e-3 : 2e-3);
        angle = angle && std::abs(std::arg(r[1][t])) * 180 / M_PI <= 0.5 &&
                std::abs(std::arg(e)) * 180 / M_PI <= 0.2;
        measured << name << " tip " << t + 1 << ": r(1/20) = " << r[0][t]
                 << ", r(1/40) = " << r[1][t] << ", extrapolated " << e
                 << std::endl;
      }
    check(name + ": K within 1 % at a/W = 1/40", raw);
    check(name + ": extrapolated K within 2e-3", extrapolated);
    if (phase)
      check(name + ": phase within 0.5 degrees (extrapolated 0.2)", angle);
  }
} // namespace


int
main()
{
  const Material one{1, 0.3}, stiff{10, 0.2};
  {
    const auto r = ratios("mode I", one, one, {0, 1e-3, 0}, 0);
    verdicts("mode I", r, false);
  }
  {
    // K_II / K_closed: the closed form of (s, t) has K_I = s sqrt(pi a)
    // < 0, which the closed crack does not have; compare K_II alone.
    std::array<std::vector<EnergyReleaseRate>, 2> runs;
    ratios("closed, shear", one, one, {0, -5e-3, 1e-3}, 0, &runs);
    std::array<std::array<Complex, 2>, 2> r;
    bool                                  closed   = all_accepted;
    const double                          sizes[2] = {0.05, 0.025};
    for (unsigned int k = 0; k < 2 && all_accepted; ++k)
      for (unsigned int t = 0; t < 2; ++t)
        {
          const EnergyReleaseRate &g = runs[k][t];
          r[k][t] = Complex(g.K_II / (1e-3 * std::sqrt(M_PI * sizes[k])), 0);
          closed  = closed && std::abs(g.K_I) <= 1e-3 * g.K_II;
        }
    verdicts("closed, shear: K_II", r, false);
    check("closed, shear: |K_I| <= 1e-3 K_II", closed);
  }
  {
    const double beta = M_PI / 3, sigma = 1e-3;
    const Load   load{sigma * std::pow(std::cos(beta), 2),
                    sigma * std::pow(std::sin(beta), 2),
                    sigma * std::sin(beta) * std::cos(beta)};
    const auto   r = ratios("inclined 60", one, one, load, 0);
    verdicts("inclined 60", r, true);
  }
  {
    std::array<std::vector<EnergyReleaseRate>, 2> runs;
    const Load                                    load{0, 1e-3, 5e-4};
    const auto r = ratios("bimaterial", one, stiff, load, 0.1, &runs);
    verdicts("bimaterial", r, true);
    bool       accepted = false;
    const auto other =
      run(scene(0.025, one, stiff, load, 0.01), "bimaterial L", accepted);
    bool shift = accepted && all_accepted;
    for (unsigned int t = 0; t < 2 && shift; ++t)
      {
        const EnergyReleaseRate &g1 = runs[1][t], &g2 = other[t];
        const double             expected =
          g1.oscillation_index * std::log(0.1) * 180 / M_PI;
        shift =
          shift &&
          std::abs(g2.K_phase_angle - g1.K_phase_angle - expected) <= 1e-9 &&
          std::abs(g2.K_magnitude - g1.K_magnitude) <= 1e-12 * g1.K_magnitude &&
          std::abs(std::abs(g1.oscillation_index) - 0.0721) < 1e-4 &&
          g1.oscillation_index * runs[1][1 - t].oscillation_index < 0;
        measured << "bimaterial L = 0.01 tip " << t + 1 << ": phase angle "
                 << g2.K_phase_angle << " against " << g1.K_phase_angle
                 << " at L = 0.1" << std::endl;
      }
    check("bimaterial: L = 0.01 moves the phase angle by eps ln(0.1), "
          "|K| kept, eps = -+0.0721",
          shift);
  }
  check("every run accepted", all_accepted);
  check("G from K equals G within 2e-3 at every tip",
        all_accepted && worst_g_from_k <= 2e-3);
  measured << "largest |G_from_K - G| / G: " << worst_g_from_k << std::endl;
  {
    bool       accepted = false;
    const auto g =
      run(scene(0.05, one, stiff, {0, 1e-3, 0}, 0, 5), "no length", accepted);
    check("between two materials without a reference length: |K| and eps, "
          "K_I NaN, the note names the entry",
          accepted && std::isnan(g[0].K_I) && std::isnan(g[0].K_phase_angle) &&
            std::isfinite(g[0].K_magnitude) && g[0].oscillation_index != 0 &&
            g[0].K_note.find("Fracture/Reference length") != std::string::npos);
  }
  {
    bool              accepted = false;
    const std::string ortho =
      "  subsection Omega+\n   set Law = orthotropic\n"
      "   set E_1 = 3\n   set E_2 = 1\n   set E_3 = 1.2\n"
      "   set nu_12 = 0.25\n   set nu_13 = 0.3\n   set nu_23 = 0.35\n"
      "   set G_12 = 0.5\n  end\n";
    const auto g = run(scene(0.05, one, one, {0, 1e-3, 0}, 0, 5, ortho),
                       "orthotropic",
                       accepted);
    check("an orthotropic layer: K not computed, the note says so",
          accepted && std::isnan(g[0].K_I) && std::isnan(g[0].K_magnitude) &&
            g[0].K_note.find("anisotropic") != std::string::npos);
  }
}
