// The energy release rate with the laws of issue 32 against the
// fourth-order central difference of the program's own energy in the crack
// length (docs/fracture.md, "Interface cracks" and the verification of
// section 5): materials that differ across Sigma, and an orthotropic layer
// at 30 degrees. (A body force alone: tests/volume_load_release_rate.cc,
// case (a), by the same method.)
//
// The method of tests/volume_load_release_rate.cc: the rectangle (-1, 1)^2,
// Sigma y = 0, the crack (-0.5, 0.5); its tip at x_t = 0.5 grows towards
// +x; Fracture/Support radius R = 0.3. Q2 on uniform cells of h = 1/32,
// written as Mesh/Mesh files; Pi(t) is the energy of the scene whose mesh
// nodes move by x -> x + t psi(|x - x_t|) e_x (psi the cut-off of
// docs/fracture.md §1 with this R) and whose crack ends at x_t + t. Each
// subdomain keeps its material under the motion (the nodes move along
// Sigma, not across it). G of the unmoved mesh against FD4 = -(8 (Pi(d) -
// Pi(-d)) - (Pi(2d) - Pi(-2d))) / 12d, d = R/50, within 1e-3 relative and
// within 3 |FD4 - FD2| + (h/R)^2 G / 4 (FD2 = -(Pi(2d) - Pi(-2d)) / 4d;
// the nodal motion is the vertex interpolant of theta).
//
// (a) Per-side materials, two layers, clamped left and right: layer 1
//     isotropic E = 200, nu = 0.28 on Omega- and E = 70, nu = 0.35 on
//     Omega+ (an interface crack between dissimilar materials); layer 2
//     isotropic E = 112, nu = 0.32 on Omega- and orthotropic (E_1 = 140,
//     E_2 = 10, E_3 = 12, nu_12 = 0.3, nu_13 = 0.28, nu_23 = 0.45,
//     G_12 = 5) at 60 degrees on Omega+; all plane strain. Tractions on
//     layer 1: top (0.05, 0.1), bottom (0, -0.1): the crack opens, in mixed
//     mode.
// (b) One orthotropic layer at 30 degrees, plane stress (the constants of
//     (a)'s orthotropic side), clamped left and right, tractions top
//     (0, 0.1) and bottom (0, -0.1): the material axes turned against the
//     crack give a mixed-mode opening.
// The numbers go to measured.txt in the test's directory.

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

using namespace dealii;
using namespace bilayer;

namespace
{
  constexpr double       x_tip = 0.5, R = 0.3;
  constexpr unsigned int cells    = 64; // along Sigma; h = 2 / cells
  constexpr double       h        = 2. / cells;
  const char *const      measured = "measured.txt";

  /// The cut-off psi of docs/fracture.md §1.
  double
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
  void
  write_meshes(const std::string &name, const double t)
  {
    for (const bool plus : {false, true})
      {
        Triangulation<2> tria;
        GridGenerator::subdivided_hyper_rectangle(tria,
                                                  {cells, cells / 2},
                                                  Point<2>(-1, plus ? 0 : -1),
                                                  Point<2>(1, plus ? 1 : 0));
        GridTools::transform(
          [t](const Point<2> &p) {
            return Point<2>(p[0] + t * psi(p.distance(Point<2>(x_tip, 0))),
                            p[1]);
          },
          tria);
        std::ofstream out(name + (plus ? "_plus.msh" : "_minus.msh"));
        out.precision(17);
        GridOut().write_msh(tria, out);
      }
  }

  struct Result
  {
    bool   accepted = false;
    double energy   = 0;
    double G        = 0;
  };

  Result
  run(const std::string &scene, const double t)
  {
    const std::string name = "moved";
    write_meshes(name, t);
    std::ostringstream s;
    s.precision(17);
    s << scene << "subsection Geometry\n set Crack interval on Sigma = -0.5, "
      << x_tip + t << "\n set Clamped sides = left, right\nend\n"
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
    Study  study(scene_from_string(s.str(), "law_release_rate"), sink);
    Result r;
    r.accepted = study.run();
    r.energy   = study.records().back().energy;
    // The tip at x_t + t is the second in the order of s.
    r.G = study.records().back().release.at(1).G;
    return r;
  }

  void
  compare(const std::string &name, const std::string &scene)
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
    std::cout << name
              << ": every run accepted, G > 0: " << yes(accepted && base.G > 0)
              << std::endl;
    std::cout << name
              << ": G within 3 |FD4 - FD2| + (h/R)^2 G / 4 of the difference "
                 "of the energy: "
              << yes(std::abs(fd4 - base.G) <= tolerance) << std::endl;
    std::cout << name << ": G within 1e-3 of the difference: "
              << yes(std::abs(fd4 - base.G) <= 1e-3 * base.G) << std::endl;
  }

  const std::string orthotropic_constants =
    "set E_1 = 140\n set E_2 = 10\n set E_3 = 12\n set nu_12 = 0.3\n"
    " set nu_13 = 0.28\n set nu_23 = 0.45\n set G_12 = 5\n";
} // namespace


int
main()
{
  std::ofstream(measured, std::ios::trunc) << "";
  compare("materials per side, two layers",
          "subsection Materials\n subsection Layer 1\n"
          "  subsection Omega-\n   set Young's modulus = 200\n"
          "   set Poisson's ratio = 0.28\n  end\n"
          "  subsection Omega+\n   set Young's modulus = 70\n"
          "   set Poisson's ratio = 0.35\n  end\n end\n"
          " subsection Layer 2\n"
          "  subsection Omega-\n   set Young's modulus = 112\n"
          "   set Poisson's ratio = 0.32\n  end\n"
          "  subsection Omega+\n   set Law = orthotropic\n " +
            orthotropic_constants +
            "   set Orientation angle = 60\n  end\n end\nend\n"
            "subsection Loads\n subsection Layer 1\n"
            "  set Traction on top side = 0.05; 0.1\n"
            "  set Traction on bottom side = 0; -0.1\n end\nend\n");
  compare("orthotropic layer at 30 degrees, plane stress",
          "subsection Materials\n set Number of layers = 1\n"
          " subsection Layer 1\n  set Law = orthotropic\n"
          "  set Plane state = plane stress\n " +
            orthotropic_constants +
            "  set Orientation angle = 30\n end\nend\n"
            "subsection Loads\n subsection Layer 1\n"
            "  set Traction on top side = 0; 0.1\n"
            "  set Traction on bottom side = 0; -0.1\n end\nend\n");
}
