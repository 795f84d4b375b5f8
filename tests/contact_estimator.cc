// The complementarity term of the estimator (contact_residual() of
// interface_diagnostics.h).
//
// Example 1 on 32 cells along Sigma, solved to a KKT residual of 1e-12: the
// discrete constraints hold at the nodes, so mu_c [u].nu vanishes at every
// node of the crack. On a segment of the mu_1 mesh in contact at both ends
// (gap 0) or open at both ends (mu_c = 0) the linear interpolants' product
// vanishes too; only a segment with contact at one end and an open gap at
// the other carries a non-zero term, and there it is positive. Example 1
// has one contact zone, starting inside the crack and reaching its right
// tip, so exactly one such segment exists. Without non-penetration there is
// no term at all.
//
// For multipliers of degree 1, 3 and 4 the term of each segment is the
// exact integral of the product of the two interpolants: compared with
// Lagrange interpolation through the segment's nodes (found by position)
// and a 12-point Gauss rule. (Degree 2 uses Simpson's rule on the nodal
// values, an approximation of that integral.)

#include <deal.II/base/quadrature_lib.h>

#include <bilayer/drivers/study.h>
#include <bilayer/parameters/parameters.h>

#include <cmath>
#include <iostream>
#include <sstream>

#include "reference.h"

using namespace dealii;
using namespace bilayer;

int
main()
{
  std::ostringstream quiet;
  const std::string  scene =
    "subsection Mesh\n set Cells along Sigma = 32\nend\n" +
    std::string(example1_loads) +
    "subsection Solver\n set Method = active set\n set Tolerance = 1e-12\n"
    "end\n"
    "subsection Output\n set Output directory = results\n"
    " set Write VTU = false\n set Write interface CSV = false\n"
    " set Terminal output = checks\nend\n";
  for (const std::string contact : {"true", "false"})
    {
      Study study(
        scene_from_string(scene +
                            "subsection Contact\n set Non-penetration "
                            "on the crack = " +
                            contact + "\nend\n",
                          "contact-estimator"),
        quiet);
      const CycleRecord &r        = study.run_cycle(0);
      const auto         segments = contact_residual(study.interface(),
                                             study.solutions(),
                                             study.multipliers());
      if (contact == "false")
        {
          std::cout << "without non-penetration: no complementarity term: "
                    << yes(segments.empty()) << std::endl;
          continue;
        }
      double largest = 0;
      for (const auto &c : segments)
        largest = std::max(largest, std::abs(c.complementarity));
      unsigned int n_large = 0;
      double       at = 0, value = 0;
      for (const auto &c : segments)
        if (std::abs(c.complementarity) > 1e-6 * largest)
          {
            ++n_large;
            at    = 0.5 * (c.a + c.b);
            value = c.complementarity;
          }
      if (getenv("BILAYER_TEST_DIAGNOSTICS"))
        std::cerr << "segments " << segments.size() << ", largest " << largest
                  << " at " << at << std::endl;
      std::cout << "accepted: " << yes(r.accepted())
                << ", segments on the crack: " << segments.size()
                << ", non-zero (> 1e-6 of the largest) on exactly one: "
                << yes(n_large == 1) << ", positive there: " << yes(value > 0)
                << ", inside the crack, right of its centre: "
                << yes(at > 0 && at < 0.5) << std::endl;
    }

  for (const unsigned int degree : {1u, 3u, 4u})
    {
      const std::string d = std::to_string(degree);
      Study             study(
        scene_from_string(
          "subsection Mesh\n set Cells along Sigma = 8\n"
                      " set Polynomial degree of layer 1 = " +
            d + "\n set Polynomial degree of layer 2 = " + d + "\nend\n" +
            std::string(example1_loads) +
            "subsection Solver\n set Method = active set\n"
                        " set Tolerance = 1e-12\nend\n"
                        "subsection Output\n set Output directory = results\n"
                        " set Write VTU = false\n set Write interface CSV = false\n"
                        " set Terminal output = checks\nend\n",
          "contact-estimator-degree"),
        quiet);
      study.run_cycle(0);
      const Interface &sigma = study.interface();
      const auto       segments =
        contact_residual(sigma, study.solutions(), study.multipliers());
      const std::vector<double> open = normal_opening(sigma, study.solutions());
      const QGauss<1>           gauss(12);
      double                    largest = 0, error = 0;
      unsigned int              wrong_nodes = 0;
      for (const auto &c : segments)
        {
          std::vector<unsigned int> nodes;
          for (unsigned int a = 0; a < sigma.space().n_nodes(); ++a)
            if (sigma.space().node_position(a) >= c.a - 1e-12 &&
                sigma.space().node_position(a) <= c.b + 1e-12)
              nodes.push_back(a);
          wrong_nodes += nodes.size() != degree + 1;
          double exact = 0;
          for (unsigned int q = 0; q < gauss.size(); ++q)
            {
              const double x  = c.a + gauss.point(q)[0] * (c.b - c.a);
              double       mu = 0, gap = 0;
              for (const unsigned int i : nodes)
                {
                  double l = 1;
                  for (const unsigned int j : nodes)
                    if (j != i)
                      l *= (x - sigma.space().node_position(j)) /
                           (sigma.space().node_position(i) -
                            sigma.space().node_position(j));
                  mu +=
                    l *
                    sigma.space().contact_multiplier(study.multipliers(), i);
                  gap += l * open[i];
                }
              exact += gauss.weight(q) * (c.b - c.a) * mu * gap;
            }
          largest = std::max(largest, std::abs(exact));
          error   = std::max(error, std::abs(exact - c.complementarity));
        }
      std::cout << "degree " << degree
                << ": each segment's term is the integral of the product of "
                   "the interpolants to 1e-10 of the largest: "
                << yes(wrong_nodes == 0 && largest > 0 &&
                       error <= 1e-10 * largest)
                << std::endl;
    }
}
