// Subproblems without a clamped side (docs/floating.md): a free bimetal
// strip, a free film on a free substrate, a film held only through its
// substrate. The expectations come from the mathematics only:
// - a free bimetal strip (layer 1 below, layer 2 above, thicknesses h1, h2,
//   L / h = 40) heated uniformly bends with Timoshenko's curvature
//     kappa = 6 (a2 - a1) dT (1 + m)^2 /
//             (h (3 (1 + m)^2 + (1 + m n) (m^2 + 1 / (m n)))),
//   m = h1 / h2, n = E1 / E2, in plane stress (E and the thermal strain
//   a dT), and in plane strain with E / (1 - nu^2) and (1 + nu) a dT: away
//   from the ends the exact state of a long strip has eps_xx = e0 + kappa y
//   and sigma_yy = sigma_xy = 0, so the curvature is exact there; u_y is
//   quadratic in x and its second difference at mid-span is the curvature
//   (within 1 % asked);
// - its energy lies between that of the infinite strip's state over
//   L - 4 h and over L (the free ends relax within about h of them), and
//   it does not depend on where the strip lies (the anchors and the
//   normalisation change with it): translated by (100, -37) the energy and
//   the curvature agree to 1e-7 (measured 8e-9 and 1.5e-8: the KKT
//   tolerance and the round-off of coordinates near 100);
// - the free strip is normalised: the integrals of w and of (x - c) x w
//   over all subproblems (c the centroid) vanish to 1e-10 of those of |w|
//   and |x - c| |w|;
// - the steady state of a debond in a cooled film on a free substrate
//   (tests/film_steady_state.cc, now with nothing clamped): G within 1 % of
//   the energy per unit length of the bonded strip, and of the rigid-
//   substrate value (1 - nu_f^2) sigma_f^2 h / (2 E_f) at E_s / E_f = 1000;
// - a cooled film with an edge debond held only through the substrate's
//   bottom (E_s / E_f = 10): far ahead of the tip the clamped bottom keeps
//   eps_xx = 0 through the thickness, so G tends to G_ss whatever E_s
//   (within 1 %), and the film with its far end clamped as well (30 film
//   thicknesses from the tip) releases the same G within 1 %;
//   and, on one mesh (global refinement, cells of h/4), G within 1 % of the
//   fourth-order difference of the energy in the debond length (G = -dPi/da);
// - an unbalanced traction on a free specimen is refused in one line
//   naming the resultant.

#include <deal.II/base/exceptions.h>
#include <deal.II/base/quadrature_lib.h>
#include <deal.II/fe/fe_values.h>

#include <bilayer/drivers/study.h>
#include <bilayer/parameters/parameters.h>

#include <cmath>
#include <fstream>
#include <iostream>
#include <sstream>
#include <string>

#include "verdict.h"

using namespace dealii;
using namespace bilayer;

namespace
{
  constexpr double E1 = 200, nu1 = 0.3, a1 = 12e-6;
  constexpr double E2 = 70, nu2 = 0.33, a2 = 23e-6;
  constexpr double h1 = 0.5, h2 = 0.5, L = 40, dT = 100;

  std::string
  output_section()
  {
    return "subsection Output\n set Output directory = results\n"
           " set Write VTU = false\n set Write interface CSV = false\n"
           " set Terminal output = checks\nend\n";
  }

  std::string
  bimetal(const bool stress, const double x0, const double y0)
  {
    const std::string  state = stress ? "plane stress" : "plane strain";
    std::ostringstream s;
    s.precision(17);
    s << "subsection Geometry\n set Lower left corner = " << x0 << ", "
      << y0 - h1 << "\n set Upper right corner = " << x0 + L << ", " << y0 + h2
      << "\n set Height of Sigma = " << y0
      << "\n set Crack interval on Sigma = " << x0 << ", " << x0
      << "\n set Clamped sides =\nend\n"
      << "subsection Mesh\n set Cells along Sigma = 160\n"
      << " set Polynomial degree of layer 1 = 2\n"
      << " set Number of cycles = 1\nend\n"
      << "subsection Materials\n set Number of layers = 1\n"
      << " subsection Layer 1\n  set Plane state = " << state
      << "\n  set Young's modulus = " << E1
      << "\n  set Poisson's ratio = " << nu1
      << "\n  set Thermal expansion = " << a1
      << "\n  subsection Omega+\n   set Young's modulus = " << E2
      << "\n   set Poisson's ratio = " << nu2
      << "\n   set Thermal expansion = " << a2 << "\n  end\n end\nend\n"
      << "subsection Loads\n set Temperature change = " << dT << "\nend\n"
      << "subsection Solver\n set Method = active set\n"
      << " set Tolerance = 1e-11\nend\n"
      << output_section();
    return s.str();
  }

  /// Timoshenko's curvature, and the energy per unit length of the long
  /// strip's state (1/2 min over (e0, k) of int E (e0 + k y - m)^2 dy).
  void
  strip(const bool stress, double &kappa, double &energy)
  {
    const double Ea = stress ? E1 : E1 / (1 - nu1 * nu1),
                 Eb = stress ? E2 : E2 / (1 - nu2 * nu2);
    const double ma = (stress ? 1 : 1 + nu1) * a1 * dT,
                 mb = (stress ? 1 : 1 + nu2) * a2 * dT;
    const double m = h1 / h2, n = Ea / Eb, h = h1 + h2;
    kappa = 6 * (mb - ma) * (1 + m) * (1 + m) /
            (h * (3 * (1 + m) * (1 + m) + (1 + m * n) * (m * m + 1 / (m * n))));
    // y from -h1 to h2.
    const double A = Ea * h1 + Eb * h2, B = Eb * h2 * h2 / 2 - Ea * h1 * h1 / 2,
                 D   = Ea * h1 * h1 * h1 / 3 + Eb * h2 * h2 * h2 / 3;
    const double f0  = Ea * ma * h1 + Eb * mb * h2,
                 f1  = Eb * mb * h2 * h2 / 2 - Ea * ma * h1 * h1 / 2,
                 c   = Ea * ma * ma * h1 + Eb * mb * mb * h2;
    const double det = A * D - B * B;
    const double e0 = (D * f0 - B * f1) / det, k = (A * f1 - B * f0) / det;
    energy = (c - f0 * e0 - f1 * k) / 2;
  }

  struct BimetalRun
  {
    bool   accepted  = false;
    double curvature = 0, energy = 0;
    /// |int w dx| / int |w| dx and |int (x - c) x w dx| / int |x - c| |w| dx
    /// over all subproblems (c the centroid): the mean translation and
    /// rotation the normalisation leaves.
    double translation = 1, rotation = 1;
  };

  /// The mean translation and rotation of the solution of @p study,
  /// relative (BimetalRun).
  void
  mean_rigid_motion(const Study &study, BimetalRun &r)
  {
    const auto subproblems = study.state().subproblem_views();
    double     m0 = 0, mx = 0, my = 0;
    for (const ElasticSubproblem *sub : subproblems)
      if (sub != nullptr)
        {
          FEValues<2> values(sub->mapping(),
                             sub->fe(),
                             QGauss<2>(sub->fe().degree + 1),
                             update_quadrature_points | update_JxW_values);
          for (const auto &cell : sub->dof_handler().active_cell_iterators())
            {
              values.reinit(cell);
              for (const unsigned int q : values.quadrature_point_indices())
                {
                  m0 += values.JxW(q);
                  mx += values.quadrature_point(q)[0] * values.JxW(q);
                  my += values.quadrature_point(q)[1] * values.JxW(q);
                }
            }
        }
    const Point<2> c(mx / m0, my / m0);
    Tensor<1, 2>   mean;
    double         size = 0, turn = 0, turn_size = 0;
    for (unsigned int s = 0; s < subproblems.size(); ++s)
      if (subproblems[s] != nullptr)
        {
          const ElasticSubproblem    &sub = *subproblems[s];
          FEValues<2>                 values(sub.mapping(),
                             sub.fe(),
                             QGauss<2>(sub.fe().degree + 1),
                             update_values | update_quadrature_points |
                               update_JxW_values);
          std::vector<Vector<double>> w(values.n_quadrature_points,
                                        Vector<double>(2));
          for (const auto &cell : sub.dof_handler().active_cell_iterators())
            {
              values.reinit(cell);
              values.get_function_values(study.solutions()[s], w);
              for (const unsigned int q : values.quadrature_point_indices())
                {
                  const Tensor<1, 2> d  = values.quadrature_point(q) - c;
                  const double       dx = values.JxW(q);
                  const Tensor<1, 2> u({w[q](0), w[q](1)});
                  mean += u * dx;
                  size += u.norm() * dx;
                  turn += (d[0] * u[1] - d[1] * u[0]) * dx;
                  turn_size += d.norm() * u.norm() * dx;
                }
            }
        }
    r.translation = mean.norm() / size;
    r.rotation    = std::abs(turn) / turn_size;
  }

  BimetalRun
  run_bimetal(const bool stress, const double x0, const double y0)
  {
    std::ostringstream sink;
    Study study(scene_from_string(bimetal(stress, x0, y0), "bimetal"), sink);
    BimetalRun r;
    r.accepted       = study.run();
    const Model &m   = study.state();
    const double d   = L / 8;
    const auto   u_y = [&](const double x) {
      const Point<2> p(x0 + x, y0 + h2 / 2);
      return m.point_displacement(p, m.point_subproblem(p))[1];
    };
    r.curvature = (u_y(L / 2 + d) - 2 * u_y(L / 2) + u_y(L / 2 - d)) / (d * d);
    r.energy    = study.records().back().energy;
    mean_rigid_motion(study, r);
    return r;
  }

  std::string
  film(const std::string &clamped,
       const double       E_s,
       const double       crack_start,
       const double       crack_end,
       const double       width,
       const bool         adaptive = true)
  {
    std::ostringstream s;
    s.precision(17);
    s << "subsection Geometry\n set Lower left corner = 0, -2"
      << "\n set Upper right corner = " << width
      << ", 1\n set Height of Sigma = 0\n set Crack interval on Sigma = "
      << crack_start << ", " << crack_end
      << "\n set Clamped sides = " << clamped << "\nend\n"
      << "subsection Mesh\n set Cells along Sigma = " << 4 * width
      << "\n set Polynomial degree of layer 1 = 2\n"
      << (adaptive ? " set Refinement = adaptive\n set Number of cycles = 5\n" :
                     " set Refinement = global\n set Number of cycles = 1\n")
      << "end\n"
      << "subsection Materials\n set Number of layers = 1\n"
      << " subsection Layer 1\n  set Young's modulus = " << E_s
      << "\n  set Poisson's ratio = 0.28\n  set Thermal expansion = 0\n"
      << "  subsection Omega+\n   set Young's modulus = 70\n"
      << "   set Poisson's ratio = 0.35\n   set Thermal expansion = 23e-6\n"
      << "  end\n end\nend\n"
      << "subsection Loads\n set Temperature change = -200\nend\n"
      << "subsection Contact\n set Non-penetration on the crack = true\nend\n"
      << "subsection Solver\n set Method = active set\nend\n"
      << "subsection Fracture\n set Energy release rate = true\nend\n"
      << output_section();
    return s.str();
  }

  /// G at the tips of a run (empty where it is not accepted), and its
  /// energy in @p energy (NaN where not accepted).
  std::vector<double>
  release(const std::string &scene, double *energy = nullptr)
  {
    std::ostringstream  sink;
    Study               study(scene_from_string(scene, "film"), sink);
    std::vector<double> G;
    if (energy != nullptr)
      *energy = std::nan("");
    if (!study.run())
      return G;
    for (const auto &r : study.records().back().release)
      G.push_back(r.G);
    if (energy != nullptr)
      *energy = study.records().back().energy;
    return G;
  }
} // namespace


int
main()
{
  // The numbers, for the docs (not compared).
  std::ofstream measured("measured.txt");
  measured.precision(14);
  // The free bimetal strip.
  for (const bool stress : {true, false})
    {
      const std::string name  = stress ? "plane stress" : "plane strain";
      double            kappa = 0, energy = 0;
      strip(stress, kappa, energy);
      const BimetalRun a = run_bimetal(stress, 0, 0);
      const BimetalRun b = run_bimetal(stress, 100, -37);
      measured << name << ": mean translation " << a.translation << " rotation "
               << a.rotation << "; kappa " << -a.curvature << " Timoshenko "
               << kappa << " translated " << -b.curvature << "; energy "
               << a.energy << " translated " << b.energy << " strip "
               << energy * L << std::endl;
      std::cout << name
                << ": free strip accepted: " << yes(a.accepted && b.accepted)
                << std::endl;
      std::cout << name << ": mid-span curvature within 1 % of Timoshenko's: "
                << yes(std::abs(-a.curvature / kappa - 1) < 0.01) << std::endl;
      std::cout << name
                << ": energy between the long strip's over L - 4 h and L: "
                << yes(a.energy <= energy * L &&
                       a.energy >= energy * (L - 4 * (h1 + h2)))
                << std::endl;
      std::cout << name
                << ": zero mean translation and rotation (1e-10 relative): "
                << yes(a.translation < 1e-10 && a.rotation < 1e-10 &&
                       b.translation < 1e-10 && b.rotation < 1e-10)
                << std::endl;
      std::cout << name
                << ": translated strip, same energy and curvature (1e-7): "
                << yes(std::abs(a.energy - b.energy) <=
                         1e-7 * std::abs(a.energy) &&
                       std::abs(a.curvature - b.curvature) <=
                         1e-7 * std::abs(a.curvature))
                << std::endl;
    }

  // A cooled film on a free substrate: the steady state.
  {
    const double Ef = 70, nuf = 0.35, af = 23e-6, dTf = -200, nus = 0.28;
    const double sigma = -Ef * af * dTf / (1 - nuf);
    const double G_ss  = (1 - nuf * nuf) * sigma * sigma / (2 * Ef);
    const double Es    = 1000 * Ef;
    // The bonded strip's energy per unit length (film h = 1 on H = 2).
    const double Eff = Ef / (1 - nuf * nuf), Ess = Es / (1 - nus * nus);
    const double m = (1 + nuf) * af * dTf, H = 2, h = 1;
    const double A = Ess * H + Eff * h, B = Eff * h * h / 2 - Ess * H * H / 2,
                 D  = Eff * h * h * h / 3 + Ess * H * H * H / 3;
    const double f0 = Eff * m * h, f1 = Eff * m * h * h / 2,
                 c   = Eff * m * m * h;
    const double det = A * D - B * B;
    const double g_beam =
      (c - f0 * (D * f0 - B * f1) / det - f1 * (A * f1 - B * f0) / det) / 2;
    const std::vector<double> G = release(film("", Es, 0, 10, 20));
    measured << "free film: G " << (G.empty() ? 0. : G[0]) << " strip "
             << g_beam << " G_ss " << G_ss << std::endl;
    std::cout << "free film on a free substrate accepted, one tip: "
              << yes(G.size() == 1) << std::endl;
    std::cout << "E_s/E_f = 1000: G within 1 % of the bonded strip's energy: "
              << yes(G.size() == 1 && std::abs(G[0] / g_beam - 1) < 0.01)
              << std::endl;
    std::cout << "E_s/E_f = 1000: G within 1 % of G_ss: "
              << yes(G.size() == 1 && std::abs(G[0] / G_ss - 1) < 0.01)
              << std::endl;
  }

  // A film held only through the substrate's bottom, an edge debond: far
  // ahead of the tip the clamped bottom keeps eps_xx = 0 through the
  // thickness (the state depends on y alone), so the bonded film holds
  // the rigid-substrate state and the steady state is G_ss whatever E_s.
  {
    const double              Ef = 70, nuf = 0.35, af = 23e-6, dTf = -200;
    const double              sigma = -Ef * af * dTf / (1 - nuf);
    const double              G_ss = (1 - nuf * nuf) * sigma * sigma / (2 * Ef);
    const std::vector<double> held = release(film("bottom", 700, 0, 10, 40));
    const std::vector<double> both =
      release(film("bottom, right", 700, 0, 10, 40));
    for (const double g : held)
      measured << "held through the substrate: G " << g << std::endl;
    for (const double g : both)
      measured << "film's end clamped as well: G " << g << std::endl;
    std::cout << "film held through the substrate accepted, one tip: "
              << yes(held.size() == 1 && both.size() == 1) << std::endl;
    std::cout << "G within 1 % of G_ss: "
              << yes(held.size() == 1 && std::abs(held[0] / G_ss - 1) < 0.01)
              << std::endl;
    // G against the fourth-order difference of the energy in the debond
    // length on one mesh (global refinement: the same cells for every a;
    // the cell 0.25 = delta, so every tip lies on a vertex).
    const double delta = 0.25;
    double       Pi[5], G_here = std::nan("");
    for (int k = -2; k <= 2; ++k)
      {
        const std::vector<double> g =
          release(film("bottom", 700, 0, 10 + k * delta, 40, false),
                  &Pi[k + 2]);
        if (k == 0 && g.size() == 1)
          G_here = g[0];
      }
    const double G_fd = -(Pi[0] - 8 * Pi[1] + 8 * Pi[3] - Pi[4]) / (12 * delta);
    measured << "held through the substrate, one mesh: G " << G_here
             << " fourth-order difference of the energy " << G_fd << std::endl;
    std::cout << "G within 1 % of the fourth-order difference of the energy: "
              << yes(std::abs(G_here / G_fd - 1) < 0.01) << std::endl;
    std::cout << "G within 1 % of the film clamped at its far end as well: "
              << yes(held.size() == 1 && both.size() == 1 &&
                     std::abs(held[0] / both[0] - 1) < 0.01)
              << std::endl;
  }

  // An unbalanced load on a free specimen.
  {
    std::string scene = bimetal(true, 0, 0);
    scene += "subsection Loads\n subsection Layer 1\n"
             "  set Traction on top side = 0; 1e-3\n end\nend\n";
    std::ostringstream sink;
    std::string        message;
    try
      {
        Study study(scene_from_string(scene, "unbalanced"), sink);
        study.run();
        message = sink.str();
      }
    catch (const ExceptionBase &e)
      {
        std::ostringstream what;
        e.print_info(what);
        message = what.str();
      }
    std::cout << "unbalanced free specimen refused naming the resultant: "
              << yes(message.find("resultant force") != std::string::npos)
              << std::endl;
  }
}
