// Objectivity of the laws and loads (issue 32): a scene rotated by an angle
// phi, with every material orientation and every load rotated by the same
// phi, has the same energy and the same G at every tip.
//
// The scene (tests/objectivity.geo, meshed once into tests/objectivity.msh:
// unstructured triangles): the rectangle (-2, 2) x (-1, 1), Sigma y = 0,
// two cracks (-1.4, -0.6) and (0.3, 1.2), four tips; left and right
// clamped. The test reads the .msh and writes it with every node x
// replaced by Q x (Q the rotation by phi; the elements and groups as they
// are), so the meshes at every phi are congruent, not remeshed. Two layers,
// Q2, one cycle, the active set to KKT 1e-12:
// - layer 1 orthotropic, plane strain (E_1 = 140, E_2 = 10, E_3 = 12,
//   nu_12 = 0.3, nu_13 = 0.28, nu_23 = 0.45, G_12 = 5), Orientation angle
//   25 + phi; a traction on top and bottom and an eigenstrain;
// - layer 2 per side (plane strain): Omega- orthotropic (E_1 = 60, E_2 =
//   20, E_3 = 25, nu_12 = 0.2, nu_13 = 0.25, nu_23 = 0.3, G_12 = 9) at
//   -40 + phi, Omega+ anisotropic with a full stiffness C (C16, C26 != 0)
//   given in the x-y frame, rotated here (C'_ijkl = Q_ia Q_jb Q_kc Q_ld
//   C_abcd, in the test's own code); a body force.
// Loads of the unrotated scene, with (xb, yb) the body's coordinates:
// traction on top (0.03 + 0.01 xb, 0.1), on bottom (-0.02, -0.1 + 0.02 xb)
// (layer 1); eigenstrain (5e-4 (1 + 0.3 xb), -2e-4, 1e-4 yb) (layer 1);
// body force (0.01 yb, 0.05 + 0.02 xb) (layer 2). The rotated scene
// carries t'(x) = Q t(Q^T x), f'(x) = Q f(Q^T x), eps*'(x) = Q eps*(Q^T x)
// Q^T, with xb = cos(phi) x + sin(phi) y, yb = -sin(phi) x + cos(phi) y in
// the expressions. The loads are polynomials of degree <= 1: their
// gradients (fourth-order differences whose step is 1e-3 of the bounding
// box, which turns with the scene) are exact.
// Asserted at phi = 30, 137 and -71 degrees against phi = 0: every run
// accepted with four tips, each at Q times the tip of phi = 0 (1e-12), and
// G > 0 at each; the energy and G at every tip equal to 1e-8 relative.
// The numbers go to measured.txt in the test's directory.

#include <deal.II/base/tensor.h>

#include <bilayer/drivers/study.h>
#include <bilayer/parameters/parameters.h>

#include <array>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <iomanip>
#include <iostream>
#include <sstream>
#include <string>
#include <vector>

#include "verdict.h"

using namespace dealii;
using namespace bilayer;

namespace
{
  const char *const measured = "measured.txt";

  /// The rotation by @p phi degrees.
  Tensor<2, 2>
  rotation(const double phi)
  {
    const double r = phi * M_PI / 180, c = std::cos(r), s = std::sin(r);
    Tensor<2, 2> Q;
    Q[0][0] = c;
    Q[0][1] = -s;
    Q[1][0] = s;
    Q[1][1] = c;
    return Q;
  }

  /// tests/objectivity.msh with its nodes rotated by @p phi, written to
  /// a file of the test's directory; its absolute path.
  std::string
  rotated_mesh(const double phi)
  {
    const Tensor<2, 2> Q = rotation(phi);
    std::ifstream      in(std::string(SOURCE_DIR) + "/objectivity.msh");
    const std::string  name =
      "objectivity_" + std::to_string(static_cast<int>(phi)) + ".msh";
    std::ofstream out(name);
    out << std::setprecision(17);
    std::string  line;
    bool         nodes = false;
    unsigned int count = 0;
    while (std::getline(in, line))
      {
        if (line == "$Nodes")
          {
            nodes = true;
            out << line << "\n";
            std::getline(in, line);
            count = std::stoul(line);
            out << line << "\n";
            for (unsigned int i = 0; i < count; ++i)
              {
                std::getline(in, line);
                std::istringstream n(line);
                unsigned int       id;
                Tensor<1, 2>       x;
                double             z;
                n >> id >> x[0] >> x[1] >> z;
                const Tensor<1, 2> y = Q * x;
                out << id << " " << y[0] << " " << y[1] << " " << z << "\n";
              }
            continue;
          }
        out << line << "\n";
      }
    AssertThrow(nodes && count > 0, ExcMessage("no nodes in objectivity.msh"));
    return std::filesystem::absolute(name).string();
  }

  /// The anisotropic stiffness (C11, C12, C16, C22, C26, C66) rotated by Q.
  std::array<double, 6>
  rotate_stiffness(const std::array<double, 6> &c, const Tensor<2, 2> &Q)
  {
    const double D[3][3] = {{c[0], c[1], c[2]},
                            {c[1], c[3], c[4]},
                            {c[2], c[4], c[5]}};
    const auto   v       = [](const unsigned int i, const unsigned int j) {
      return i == j ? i : 2u;
    };
    const auto C = [&](const unsigned int a,
                       const unsigned int b,
                       const unsigned int k,
                       const unsigned int l) {
      double sum = 0;
      for (unsigned int p = 0; p < 2; ++p)
        for (unsigned int q = 0; q < 2; ++q)
          for (unsigned int r = 0; r < 2; ++r)
            for (unsigned int t = 0; t < 2; ++t)
              sum +=
                Q[a][p] * Q[b][q] * Q[k][r] * Q[l][t] * D[v(p, q)][v(r, t)];
      return sum;
    };
    return {{C(0, 0, 0, 0),
             C(0, 0, 1, 1),
             C(0, 0, 0, 1),
             C(1, 1, 1, 1),
             C(1, 1, 0, 1),
             C(0, 1, 0, 1)}};
  }

  struct Result
  {
    bool                      accepted = false;
    double                    energy   = 0;
    std::vector<Tensor<1, 2>> tips;
    std::vector<double>       G;
  };

  Result
  run(const double phi)
  {
    const double r = phi * M_PI / 180;
    // The body's coordinates and a vector or tensor of the body turned.
    const std::string xb = "(cs*x + sn*y)", yb = "(-sn*x + cs*y)";
    const auto        vec = [](const std::string &u, const std::string &v) {
      return "cs*(" + u + ") - sn*(" + v + "); sn*(" + u + ") + cs*(" + v + ")";
    };
    const std::string e11 = "5e-4*(1 + 0.3*" + xb + ")", e22 = "(-2e-4)",
                      e12 = "1e-4*" + yb;
    const std::string eigenstrain =
      "cs*cs*" + e11 + " - 2*cs*sn*" + e12 + " + sn*sn*" + e22 + "; sn*sn*" +
      e11 + " + 2*cs*sn*" + e12 + " + cs*cs*" + e22 + "; cs*sn*(" + e11 +
      " - " + e22 + ") + (cs*cs - sn*sn)*" + e12;
    const std::array<double, 6> C =
      rotate_stiffness({{80, 25, 6, 50, -4, 18}}, rotation(phi));

    std::ostringstream p;
    p << std::setprecision(17)
      << "subsection Geometry\n set Gmsh file = " << rotated_mesh(phi)
      << "\n set Clamped sides = left, right\nend\n"
      << "subsection Mesh\n set Polynomial degree of layer 1 = 2\n"
      << " set Polynomial degree of layer 2 = 2\n set Number of cycles = 1\n"
      << " set Element shape = triangles\n"
      << "end\nsubsection Materials\n subsection Layer 1\n"
      << "  set Law = orthotropic\n  set E_1 = 140\n  set E_2 = 10\n"
      << "  set E_3 = 12\n  set nu_12 = 0.3\n  set nu_13 = 0.28\n"
      << "  set nu_23 = 0.45\n  set G_12 = 5\n  set Orientation angle = "
      << 25 + phi << "\n end\n subsection Layer 2\n"
      << "  subsection Omega-\n   set Law = orthotropic\n   set E_1 = 60\n"
      << "   set E_2 = 20\n   set E_3 = 25\n   set nu_12 = 0.2\n"
      << "   set nu_13 = 0.25\n   set nu_23 = 0.3\n   set G_12 = 9\n"
      << "   set Orientation angle = " << -40 + phi << "\n  end\n"
      << "  subsection Omega+\n   set Law = anisotropic\n   set Stiffness = "
      << C[0] << ", " << C[1] << ", " << C[2] << ", " << C[3] << ", " << C[4]
      << ", " << C[5] << "\n  end\n end\nend\n"
      << "subsection Loads\n set Constants = cs = " << std::cos(r)
      << "; sn = " << std::sin(r) << "\n subsection Layer 1\n"
      << "  set Traction on top = " << vec("0.03 + 0.01*" + xb, "0.1") << "\n"
      << "  set Traction on bottom = " << vec("-0.02", "-0.1 + 0.02*" + xb)
      << "\n  set Eigenstrain = " << eigenstrain << "\n end\n"
      << " subsection Layer 2\n  set Body force = "
      << vec("0.01*" + yb, "0.05 + 0.02*" + xb) << "\n end\nend\n"
      << "subsection Solver\n set Method = active set\n"
      << " set Tolerance = 1e-12\nend\n"
      << "subsection Output\n set Output directory = results\n"
      << " set Write VTU = false\n set Write interface CSV = false\n"
      << " set Terminal output = checks\nend\n";
    std::ostringstream sink;
    Study              study(scene_from_string(p.str(), "objectivity"), sink);
    Result             res;
    res.accepted = study.run();
    res.energy   = study.records().back().energy;
    for (const auto &tip : study.records().back().release)
      {
        res.tips.push_back(tip.tip.point);
        res.G.push_back(tip.G);
      }
    return res;
  }
} // namespace


int
main()
{
  std::ofstream(measured, std::ios::trunc) << "";
  const Result base = run(0);
  bool         ok   = base.accepted && base.G.size() == 4;
  for (const double g : base.G)
    ok = ok && g > 0;
  std::cout << "phi = 0: accepted, four tips, G > 0 at each: " << yes(ok)
            << std::endl;
  {
    std::ofstream m(measured, std::ios::app);
    m << std::setprecision(12) << "phi = 0: energy " << base.energy << ", G";
    for (const double g : base.G)
      m << " " << g;
    m << std::endl;
  }
  for (const double phi : {30., 137., -71.})
    {
      const Result       r         = run(phi);
      const Tensor<2, 2> Q         = rotation(phi);
      bool               same_tips = r.accepted && r.G.size() == base.G.size();
      double largest = std::abs(r.energy - base.energy) / std::abs(base.energy),
             largest_G = 0;
      for (unsigned int k = 0; same_tips && k < r.G.size(); ++k)
        {
          same_tips =
            same_tips && (r.tips[k] - Q * base.tips[k]).norm() <= 1e-12;
          largest_G =
            std::max(largest_G, std::abs(r.G[k] - base.G[k]) / base.G[k]);
        }
      std::ofstream(measured, std::ios::app)
        << "phi = " << phi
        << ": |Pi - Pi_0| / |Pi_0| = " << std::setprecision(2) << largest
        << ", largest |G - G_0| / G_0 over the tips = " << largest_G
        << std::endl;
      const std::string name = "phi = " + std::to_string(static_cast<int>(phi));
      std::cout << name << ": accepted, the tips of phi = 0 rotated (1e-12): "
                << yes(same_tips) << std::endl
                << name << ": energy as at phi = 0 (1e-8 relative): "
                << yes(largest <= 1e-8) << std::endl
                << name << ": G at every tip as at phi = 0 (1e-8 relative): "
                << yes(same_tips && largest_G <= 1e-8) << std::endl;
    }
}
