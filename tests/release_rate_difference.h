#ifndef bilayer_tests_release_rate_difference_h
#define bilayer_tests_release_rate_difference_h

// The energy release rate G against the fourth-order central difference of
// the program's own energy in the crack length (docs/fracture.md, "Body
// forces and eigenstrains" and the verification of section 5), shared by
// tests/volume_load_release_rate.cc, tests/thermal_release_rate.cc and
// tests/law_release_rate.cc and tests/friction_release_rate.cc.
//
// The rectangle (-1, 1)^2, Sigma y = 0, the crack (-0.5, 0.5); its tip at
// x_t = 0.5 grows towards +x; Fracture/Support radius R = 0.3 (the outer
// boundary is 0.5 away). Q2, uniform cells of h = 1/32 (64 along Sigma, 32
// across each subdomain), written as Mesh/Mesh files. Pi(t) is the energy of
// the scene whose mesh nodes are moved by x -> x + t psi(|x - x_t|) e_x
// (psi the cut-off of docs/fracture.md §1 with this R, written here; with
// Tresca friction J = Pi + int g |[u].tau| in place of Pi) and
// whose crack ends at x_t + t: one mesh moved smoothly, the tip carried by
// t along Sigma, nothing within 0.2 of the outer boundary or of the other
// tip moved, the loads fixed in space. G of the unmoved mesh is compared
// with FD4 = -(8 (Pi(d) - Pi(-d)) - (Pi(2d) - Pi(-2d))) / 12d, d = R / 50,
// and FD2 = -(Pi(2d) - Pi(-2d)) / 4d: |FD4 - G| <= 3 |FD4 - FD2| + (h/R)^2
// G / 4 (the nodal motion is the vertex interpolant of theta), and 1e-3
// relative. The numbers go to measured.txt in the test's directory (not
// compared).

#include <deal.II/grid/grid_generator.h>
#include <deal.II/grid/grid_out.h>
#include <deal.II/grid/grid_tools.h>
#include <deal.II/grid/tria.h>

#include <bilayer/drivers/study.h>
#include <bilayer/parameters/parameters.h>

#include <cmath>
#include <fstream>
#include <iomanip>
#include <iostream>
#include <sstream>
#include <string>

#include "verdict.h"

namespace release_rate_difference
{
  constexpr double       x_tip = 0.5, R = 0.3;
  constexpr unsigned int cells    = 64; // along Sigma; h = 2 / cells
  constexpr double       h        = 2. / cells;
  constexpr const char  *measured = "measured.txt";

  /// Empties measured.txt; each comparison appends its line.
  inline void
  start_measured()
  {
    std::ofstream(measured, std::ios::trunc) << "";
  }

  /// The cut-off psi of docs/fracture.md §1.
  inline double
  psi(const double r)
  {
    if (r <= R / 2)
      return 1;
    if (r >= R)
      return 0;
    const double t = (r - R / 2) / (R / 2);
    return 1 - (10 * t * t * t - 15 * t * t * t * t + 6 * t * t * t * t * t);
  }

  /// The meshes of Omega- and Omega+ with the nodes moved by t psi e_x,
  /// written to NAME_minus.msh and NAME_plus.msh.
  inline void
  write_meshes(const std::string &name, const double t)
  {
    using dealii::Point;
    for (const bool plus : {false, true})
      {
        dealii::Triangulation<2> tria;
        dealii::GridGenerator::subdivided_hyper_rectangle(
          tria,
          {cells, cells / 2},
          Point<2>(-1, plus ? 0 : -1),
          Point<2>(1, plus ? 1 : 0));
        dealii::GridTools::transform(
          [t](const Point<2> &p) {
            return Point<2>(p[0] + t * psi(p.distance(Point<2>(x_tip, 0))),
                            p[1]);
          },
          tria);
        std::ofstream out(name + (plus ? "_plus.msh" : "_minus.msh"));
        out.precision(17);
        dealii::GridOut().write_msh(tria, out);
      }
  }

  struct Result
  {
    bool   accepted = false;
    double energy   = 0;
    double G        = 0;
  };

  /// The comparison of one test: TEST names its scenes (for
  /// scene_from_string); GEOMETRY, lines added to subsection Geometry after
  /// the crack interval (e.g. " set Clamped sides = left, right\n").
  struct Difference
  {
    std::string test;
    std::string geometry = "";

    /// The scene SCENE (its loads, materials, ...) with the nodes moved by
    /// t psi e_x and the crack ending at x_t + t.
    Result
    run(const std::string &scene, const double t) const
    {
      const std::string name = "moved";
      write_meshes(name, t);
      std::ostringstream s;
      s.precision(17);
      s << scene << "subsection Geometry\n set Crack interval on Sigma = -0.5, "
        << x_tip + t << "\n"
        << geometry << "end\n"
        << "subsection Mesh\n set Mesh files = " << name << "_{side}.msh\n"
        << " set Polynomial degree of layer 1 = 2\n"
        << " set Polynomial degree of layer 2 = 2\nend\n"
        << "subsection Solver\n set Method = active set\n"
        << " set Tolerance = 1e-12\nend\n"
        << "subsection Fracture\n set Support radius = " << R << "\nend\n"
        << "subsection Output\n set Output directory = results_fd\n"
        << " set Write VTU = false\n set Write interface CSV = false\n"
        << " set Terminal output = checks\nend\n";
      std::ostringstream sink;
      bilayer::Study     study(bilayer::scene_from_string(s.str(), test), sink);
      Result             r;
      r.accepted = study.run();
      // J = Pi + int g |[u].tau| ds, the functional whose derivative in
      // the crack length G is with Tresca friction (docs/fracture.md §6):
      // at a solution the friction integral is the dissipation sum D mu_t
      // jump_t (0 without friction).
      r.energy = study.records().back().energy +
                 study.records().back().report.friction_dissipation;
      // The tip at x_t + t is the second in the order of s.
      r.G = study.records().back().release.at(1).G;
      return r;
    }

    /// G of SCENE against FD4: the numbers to measured.txt, the three
    /// verdicts, headed NAME, to std::cout.
    void
    compare(const std::string &name, const std::string &scene) const
    {
      const double d        = R / 50;
      const Result base     = run(scene, 0);
      bool         accepted = base.accepted;
      const auto   energy   = [&](const double t) {
        const Result r = run(scene, t);
        accepted       = accepted && r.accepted;
        return r.energy;
      };
      const double p1 = energy(d), m1 = energy(-d), p2 = energy(2 * d),
                   m2  = energy(-2 * d);
      const double fd4 = -(8 * (p1 - m1) - (p2 - m2)) / (12 * d);
      const double fd2 = -(p2 - m2) / (4 * d);
      const double tolerance =
        3 * std::abs(fd4 - fd2) + (h / R) * (h / R) * std::abs(base.G) / 4;
      std::ofstream(measured, std::ios::app)
        << std::setprecision(10) << name << ": G = " << base.G
        << ", FD4 = " << fd4 << ", FD2 = " << fd2
        << ", |FD4 - G| / G = " << std::abs(fd4 - base.G) / base.G
        << ", tolerance / G = " << tolerance / base.G << std::endl;
      std::cout << name << ": every run accepted, G > 0: "
                << yes(accepted && base.G > 0) << std::endl;
      std::cout << name
                << ": G within 3 |FD4 - FD2| + (h/R)^2 G / 4 of the "
                   "difference of the energy: "
                << yes(std::abs(fd4 - base.G) <= tolerance) << std::endl;
      std::cout << name << ": G within 1e-3 of the difference: "
                << yes(std::abs(fd4 - base.G) <= 1e-3 * base.G) << std::endl;
    }
  };
} // namespace release_rate_difference

#endif
