// The limits of friction on the crack faces (docs/problem.md §1, §3).
//
// Example 1 (parameter_files/partial_closure.prm: two layers, the crack
// (-0.5, 0.5), the faces open on the left and pressed together on the
// right) with a shear traction added, `Traction on top side = 0.5*c; -c*x`
// and `Traction on bottom side = -0.5*c; c*x`, so that the faces slide
// where they touch; Q1 on the prm's mesh (32 cells along Sigma for (b)),
// active-set solver, tolerance 1e-12.
// (a) Zero friction: Tresca with g = 0 and Coulomb with F = 0 are the
//     frictionless problem (the box of the tangential multiplier is {0}):
//     energy, multipliers and G at both tips agree with Friction = none to
//     1e-12 (relative to the largest of each), and the faces do slide (the
//     largest tangential jump on the crack is more than 1e-3 of the
//     displacement scale).
// (b) A bound that sticks the closed faces: with the Tresca bound g = 1e3
//     (some 1e4 times the tractions) on the crack nodes x >= x_c and 0
//     on the others, the faces stick where they touch and slide freely
//     where they are open. If the closed nodes are exactly those with
//     x >= x_c (x_c a vertex, found by iterating from the contact set of
//     the frictionless run), the solution is that of the same scene whose
//     crack is only the open part (-0.5, x_c), without friction: the
//     closed and stuck nodes carry the gluing constraint [u] = 0, the open
//     ones no tangential force. Asserted: the closed set settles, every
//     closed node sticks, the open ones slip freely, and energy and the
//     displacements of the four subproblems (same meshes) agree to 1e-10.
//     Coulomb with F = 1e4 (its bound F mu_c acts only where the faces are
//     pressed together) gives the same glued solution (1e-10).
// (c) The Griffith scene of friction_griffith.cc (one layer, E = 1, nu =
//     0.3, the crack (-0.05, 0.05), the uniform state sigma_yy = -sigma,
//     sigma_xy = tau prescribed on the boundary, sigma = tau = 1e-3) with
//     g = 1e3 tau (40 cells along Sigma refined once globally): every
//     crack node sticks and the solution is the uncracked
//     linear field, whose energy is
//       Pi = |Omega| / 2 (sigma:eps) = 2 ((1 - nu^2) sigma^2 + 2 (1 + nu)
//       tau^2) / E
//     (plane strain, |Omega| = 4); the computed energy agrees to 1e-10.
// The measured numbers are written to measured.txt in the test's directory.

#include <bilayer/drivers/study.h>
#include <bilayer/interface/interface_diagnostics.h>
#include <bilayer/parameters/parameters.h>

#include <algorithm>
#include <cmath>
#include <fstream>
#include <iomanip>
#include <iostream>
#include <memory>
#include <sstream>
#include <string>
#include <vector>

#include "friction_scenes.h"
#include "verdict.h"

using namespace bilayer;

namespace
{
  const char *const measured = "measured.txt";

  void
  check(const std::string &what, const bool ok)
  {
    std::cout << what << ": " << yes(ok) << std::endl;
  }

  /// Example 1 with the shear traction, the crack (-0.5, @p end), the
  /// entries @p contact of the Contact subsection and @p cells along Sigma.
  std::unique_ptr<Study>
  example(const std::string &contact,
          const unsigned int cells,
          std::ostream      &sink,
          const double       end = 0.5)
  {
    std::ifstream      in(std::string(SOURCE_DIR) +
                     "/../parameter_files/partial_closure.prm");
    std::ostringstream text;
    text << std::setprecision(17) << in.rdbuf()
         << "subsection Geometry\n set Crack interval on Sigma = -0.5, " << end
         << "\nend\n"
         << "subsection Mesh\n set Cells along Sigma = " << cells << "\nend\n"
         << friction_scenes::shear_loads("0.5", "1e-3*mu1")
         << "subsection Contact\n"
         << contact << "end\n"
         << "subsection Solver\n set Method = active set\n"
         << " set Tolerance = 1e-12\nend\n"
         << "subsection Output\n set Output directory = results\n"
         << " set Write VTU = false\n set Write interface CSV = false\n"
         << " set Terminal output = checks\nend\n";
    auto study =
      std::make_unique<Study>(scene_from_string(text.str(), "friction_limits"),
                              sink);
    study->run();
    return study;
  }

  std::vector<InterfaceNode>
  nodes_of(const Study &s)
  {
    return interface_nodes(s.interface(), s.solutions(), s.multipliers());
  }

  /// max |x - y| / max |x| over the four subproblems' solutions.
  double
  solution_difference(const Study &x, const Study &y)
  {
    double diff = 0, size = 0;
    for (unsigned int s = 0; s < x.solutions().size(); ++s)
      {
        const auto &u = x.solutions()[s], &v = y.solutions()[s];
        if (u.size() != v.size())
          return 1;
        for (unsigned int i = 0; i < u.size(); ++i)
          {
            diff = std::max(diff, std::abs(u[i] - v[i]));
            size = std::max(size, std::abs(u[i]));
          }
      }
    return diff / size;
  }

  /// (a) Zero friction against none.
  void
  zero_friction()
  {
    std::ostringstream sink;
    const auto         none = example(" set Friction = none\n", 16, sink);
    const auto         g0 =
      example(" set Friction = tresca\n set Friction bound = 0\n", 16, sink);
    const auto F0 =
      example(" set Friction = coulomb\n set Friction coefficient = 0\n",
              16,
              sink);
    const CycleRecord &r = none->records().back();
    check("zero friction: the three runs accepted, two tips",
          r.accepted() && g0->records().back().accepted() &&
            F0->records().back().accepted() && r.release.size() == 2);
    if (r.release.size() != 2)
      return;

    double slip = 0;
    for (const InterfaceNode &n : nodes_of(*none))
      if (n.on_crack)
        slip = std::max(slip, std::abs(n.jump_tangential));
    slip /= r.report.displacement_scale;
    check("zero friction: the faces slide (largest tangential jump > 1e-3 of "
          "the displacement scale)",
          slip > 1e-3);

    double G_max = 0;
    for (const auto &t : r.release)
      G_max = std::max(G_max, std::abs(t.G));
    const auto &mu = none->multipliers();
    for (const auto &[name, study] :
         {std::make_pair("Tresca g = 0", g0.get()),
          std::make_pair("Coulomb F = 0", F0.get())})
      {
        const CycleRecord &q = study->records().back();
        const double dE  = std::abs(q.energy - r.energy) / std::abs(r.energy);
        double       dmu = 0;
        const auto  &nu  = study->multipliers();
        if (nu.size() != mu.size())
          dmu = 1;
        else
          for (unsigned int i = 0; i < mu.size(); ++i)
            dmu = std::max(dmu, std::abs(nu[i] - mu[i]));
        dmu /= mu.linfty_norm();
        double dG = q.release.size() == 2 ? 0 : 1;
        for (unsigned int t = 0; t < q.release.size() && t < 2; ++t)
          dG = std::max(dG, std::abs(q.release[t].G - r.release[t].G) / G_max);
        std::ofstream(measured, std::ios::app)
          << std::setprecision(6) << name << " against none: |dPi|/|Pi| " << dE
          << ", max|dmu|/max|mu| " << dmu << ", max|dG|/max|G| " << dG
          << " (G = " << r.release[0].G << ", " << r.release[1].G
          << "; largest slip/displacement scale " << slip << ")" << std::endl;
        check(std::string(name) +
                ": energy, multipliers and G those without friction (1e-12)",
              dE <= 1e-12 && dmu <= 1e-12 && dG <= 1e-12);
      }
  }

  /// The crack nodes by x.
  std::vector<InterfaceNode>
  crack_nodes(const Study &s)
  {
    std::vector<InterfaceNode> crack;
    for (const InterfaceNode &n : nodes_of(s))
      if (n.on_crack)
        crack.push_back(n);
    std::sort(crack.begin(), crack.end(), [](const auto &p, const auto &q) {
      return p.point[0] < q.point[0];
    });
    return crack;
  }

  /// Whether the crack nodes are open below some x_c and closed from x_c
  /// on; x_c (the first closed node) in @p x_c.
  bool
  open_then_closed(const std::vector<InterfaceNode> &crack, double &x_c)
  {
    bool closed = false, ok = true;
    x_c = 0.5;
    for (const InterfaceNode &n : crack)
      if (n.state == ContactState::closed)
        {
          if (!closed)
            x_c = n.point[0];
          closed = true;
        }
      else
        ok = ok && !closed;
    return ok && closed;
  }

  /// (b) A huge bound on the closed part: the glued solution there.
  void
  stuck_faces()
  {
    const unsigned int cells = 32;
    const double       g     = 1e3;
    std::ostringstream sink;
    double             x_c       = 0;
    bool               structure = open_then_closed(
      crack_nodes(*example(" set Friction = none\n", cells, sink)), x_c);
    std::unique_ptr<Study> tresca;
    unsigned int           iterations = 0;
    for (bool settled = false; structure && !settled && iterations < 10;
         ++iterations)
      {
        std::ostringstream contact;
        contact << std::setprecision(17)
                << " set Friction = tresca\n set Friction bound = x > "
                << x_c - 0.25 / cells << " ? " << g << " : 0\n";
        tresca       = example(contact.str(), cells, sink);
        double x_new = 0;
        structure    = open_then_closed(crack_nodes(*tresca), x_new);
        settled      = std::abs(x_new - x_c) < 1e-12;
        x_c          = x_new;
      }
    check("huge bound: the crack open below a vertex x_c, closed above; the "
          "closed set settles",
          structure && tresca && tresca->records().back().accepted());
    if (!structure || !tresca)
      return;

    bool         states = true;
    unsigned int closed = 0;
    for (const InterfaceNode &n : crack_nodes(*tresca))
      if (n.state == ContactState::closed)
        {
          ++closed;
          states = states && n.friction_state == FrictionState::stick;
        }
      else
        states = states && n.friction_state == FrictionState::free &&
                 n.friction_bound == 0;
    check("huge bound: the closed nodes stick, the open ones slide freely",
          states);

    const auto glued = example(" set Friction = none\n", cells, sink, x_c);
    const auto coulomb =
      example(" set Friction = coulomb\n set Friction coefficient = 1e4\n",
              cells,
              sink);
    const double E = glued->records().back().energy;
    const double dE =
      std::abs(tresca->records().back().energy - E) / std::abs(E);
    const double du = solution_difference(*glued, *tresca);
    const double dEc =
      std::abs(coulomb->records().back().energy - E) / std::abs(E);
    const double duc = solution_difference(*glued, *coulomb);
    std::ofstream(measured, std::ios::app)
      << std::setprecision(6) << "huge bound: x_c = " << x_c << " after "
      << iterations << " Tresca runs, " << closed
      << " closed crack nodes; against the crack (-0.5, x_c): |dPi|/|Pi| " << dE
      << ", max|dw|/max|w| " << du << "; Coulomb F = 1e4: |dPi|/|Pi| " << dEc
      << ", max|dw|/max|w| " << duc << ", "
      << coulomb->records().back().friction_iterations
      << " fixed-point iterations" << std::endl;
    check("huge bound: the glued crack (-0.5, x_c) accepted",
          glued->records().back().accepted());
    check("huge bound: energy and displacements those of the crack "
          "(-0.5, x_c) (1e-10)",
          dE <= 1e-10 && du <= 1e-10);
    check("Coulomb F = 1e4: accepted, energy and displacements those of the "
          "crack (-0.5, x_c) (1e-10)",
          coulomb->records().back().accepted() && dEc <= 1e-10 && duc <= 1e-10);
  }

  /// (c) The Griffith crack stuck by a huge bound: the uncracked field.
  void
  stuck_griffith()
  {
    const double       E = 1, nu = 0.3, a = 0.05, sigma = 1e-3, tau = 1e-3;
    std::ostringstream s;
    s << friction_scenes::uniform_state_griffith(a, E, nu, sigma, tau)
      << "subsection Mesh\n set Cells along Sigma = 40\n"
      << " set Fit crack tips = true\n"
      << " set Polynomial degree of layer 1 = 2\n"
      << " set Number of cycles = 2\nend\n"
      << "subsection Contact\n set Non-penetration on the crack = true\n"
      << " set Friction = tresca\n set Friction bound = " << 1e3 * tau
      << "\nend\n"
      << "subsection Solver\n set Method = active set\n"
      << " set Tolerance = 1e-12\nend\n"
      << "subsection Output\n set Output directory = results\n"
      << " set Write VTU = false\n set Write interface CSV = false\n"
      << " set Terminal output = checks\nend\n";
    std::ostringstream sink;
    Study      study(scene_from_string(s.str(), "friction_limits"), sink);
    const bool accepted  = study.run();
    const CycleRecord &r = study.records().back();
    const double       exact =
      2 * ((1 - nu * nu) * sigma * sigma + 2 * (1 + nu) * tau * tau) / E;
    const double dE   = std::abs(r.energy - exact) / exact;
    const double slip = r.report.max_slip / r.report.displacement_scale;
    std::ofstream(measured, std::ios::app)
      << std::setprecision(6) << "Griffith, g = 1e3 tau: |Pi - Pi_exact|/Pi "
      << dE << " (Pi_exact = " << exact << "), max slip/displacement scale "
      << slip << ", stick " << r.report.stick_nodes << ", slip "
      << r.report.slip_nodes << std::endl;
    check("Griffith, g = 1e3 tau: accepted, every crack node sticks",
          accepted && r.report.stick_nodes > 0 && r.report.slip_nodes == 0);
    check("Griffith, g = 1e3 tau: the energy of the uncracked linear field "
          "(1e-10)",
          dE <= 1e-10);
  }
} // namespace


int
main()
{
  std::ofstream(measured, std::ios::trunc) << "";
  zero_friction();
  stuck_faces();
  stuck_griffith();
}
