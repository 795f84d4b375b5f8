// The multiplier spaces of every discretisation are unique and uniformly
// stable (MultiplierSpace, docs/multipliers.md).
//
// Uniqueness and stability: for degrees 1/1, 2/1, 1/2, 2/2 and 3/1 (layer 1
// / layer 2) and cell ratios 1:1, 2:3, 3:4, 1:2 and 2:1 along Sigma
// (Omega- : Omega+) on quadrilaterals, for triangles and for hanging nodes
// next to Sigma, the smallest eigenvalue of the dual operator S on the free
// multipliers (Lanczos, estimate_dual_spectrum) is positive, and
// lambda_min / h, which a uniformly inf-sup stable choice bounds below
// (lambda_min >= c beta^2 h), does not fall by more than a factor 2 when
// the meshes are halved, nor below a tenth of the matching Q1 value.
// A redundant constraint makes lambda_min vanish; a near-redundant one
// (the union of non-matching traces) makes lambda_min / h collapse under
// refinement.
//
// Solver independence: on mixed degrees, non-matching traces, triangles
// and hanging nodes the active set, the accelerated method and Uzawa
// (theta = auto) stopped at a KKT residual of 1e-10 give the same energy to
// 1e-8 and the same contact pressure, gluing tractions and layer-gluing
// tractions to 1e-8 of each group's largest value: the multipliers are a
// property of the discretisation, not of the solver.

#include <bilayer/drivers/study.h>
#include <bilayer/parameters/parameters.h>

#include <algorithm>
#include <cmath>
#include <iostream>
#include <sstream>

#include "reference.h"

using namespace dealii;
using namespace bilayer;

namespace
{
  std::ostringstream quiet;

  const std::string example1 =
    "subsection Loads\n set Constants = c = 1e-3*mu1\n"
    " subsection Layer 1\n"
    "  set Traction on bottom side = 0; c*x\n"
    "  set Traction on top side = 0; -c*x\n end\nend\n";

  const std::string output =
    "subsection Output\n set Output directory = results\n"
    " set Write VTU = false\n set Write interface CSV = false\n"
    " set Terminal output = checks\nend\n";

  struct Discretisation
  {
    std::string  name;
    unsigned int p1, p2, minus, plus;
    bool         triangles = false;
    /// Adaptive cycles before the one measured (hanging nodes).
    unsigned int adaptive = 0;
  };

  std::string
  mesh_section(const Discretisation &d, const unsigned int scale)
  {
    std::ostringstream s;
    s << "subsection Mesh\n set Cells along Sigma = " << d.minus * scale
      << "\n set Cells along Sigma on the plus side = " << d.plus * scale
      << "\n set Polynomial degree of layer 1 = " << d.p1
      << "\n set Polynomial degree of layer 2 = " << d.p2
      << "\n set Element shape = "
      << (d.triangles ? "triangles" : "quadrilaterals") << "\n";
    if (d.adaptive > 0)
      s << " set Refinement = adaptive\n set Number of cycles = "
        << d.adaptive + 1 << "\n set Refinement fraction = 0.2\n";
    s << "end\n";
    return s.str();
  }

  /// Runs all cycles of the scene; the study of the last one.
  std::unique_ptr<Study>
  solve(const Discretisation &d,
        const unsigned int    scale,
        const std::string    &solver)
  {
    auto study =
      std::make_unique<Study>(scene_from_string(mesh_section(d, scale) +
                                                  example1 + solver + output,
                                                d.name),
                              quiet);
    for (unsigned int cycle = 0; cycle <= d.adaptive; ++cycle)
      study->run_cycle(cycle);
    return study;
  }

  /// lambda_min / h of the last cycle.
  double
  scaled_lambda_min(const Discretisation &d, const unsigned int scale)
  {
    const auto study =
      solve(d,
            scale,
            "subsection Solver\n set Method = active set\n"
            " set Tolerance = 1e-10\n set Dual spectrum steps = 2000\nend\n");
    const DualSpectrum &s = study->records().back().spectrum;
    return s.lambda_min / s.h;
  }

  /// Largest difference of the multiplier groups (contact pressure,
  /// gluing across Sigma, layer gluing) relative to each group's largest
  /// value.
  std::array<double, 3>
  multiplier_differences(const Study &a, const Study &b)
  {
    const MultiplierSpace     &space = a.interface().space();
    const BlockVector<double> &x = a.multipliers(), &y = b.multipliers();
    std::array<double, 3>      size{}, diff{};
    const auto                 add =
      [&](const unsigned int group, const double u, const double v) {
        size[group] = std::max(size[group], std::abs(u));
        diff[group] = std::max(diff[group], std::abs(u - v));
      };
    for (unsigned int n = 0; n < space.n_nodes(); ++n)
      {
        add(0, space.contact_multiplier(x, n), space.contact_multiplier(y, n));
        for (unsigned int c = 0; c < Layout::n_components; ++c)
          add(1,
              space.gluing_multiplier(x, n, c),
              space.gluing_multiplier(y, n, c));
      }
    for (const unsigned int b : {Layout::glue_minus, Layout::glue_plus})
      for (unsigned int i = 0; i < x.block(b).size(); ++i)
        add(2, x.block(b)(i), y.block(b)(i));
    for (unsigned int g = 0; g < 3; ++g)
      diff[g] = size[g] > 0 ? diff[g] / size[g] : diff[g];
    return diff;
  }
} // namespace


int
main()
{
  // Uniqueness and stability.
  std::vector<Discretisation>                              matrix;
  const std::vector<std::pair<unsigned int, unsigned int>> degrees = {
    {1, 1}, {2, 1}, {1, 2}, {2, 2}, {3, 1}};
  const std::vector<std::pair<unsigned int, unsigned int>> ratios = {
    {4, 4}, {8, 12}, {12, 16}, {4, 8}, {8, 4}};
  for (const auto &[p1, p2] : degrees)
    for (const auto &[m, p] : ratios)
      matrix.push_back({"Q" + std::to_string(p1) + "/Q" + std::to_string(p2) +
                          " " + std::to_string(m) + ":" + std::to_string(p),
                        p1,
                        p2,
                        m,
                        p});
  matrix.push_back({"P2/P1 triangles 8:12", 2, 1, 8, 12, true});
  matrix.push_back({"P1/P1 triangles 12:16", 1, 1, 12, 16, true});
  matrix.push_back({"Q1/Q1 hanging nodes 4:4", 1, 1, 4, 4, false, 2});
  matrix.push_back({"Q2/Q1 hanging nodes 4:8", 2, 1, 4, 8, false, 2});

  const double reference = scaled_lambda_min(matrix[0], 2);
  for (const Discretisation &d : matrix)
    {
      const double coarse = scaled_lambda_min(d, 1);
      const double fine   = scaled_lambda_min(d, 2);
      std::cout << d.name << ": lambda_min > 0: "
                << (coarse > 0 && fine > 0 ? "yes" : "NO")
                << ", bounded under refinement (fine >= coarse / 2): "
                << (fine >= 0.5 * coarse ? "yes" : "NO")
                << ", >= matching Q1 / 10: "
                << (fine >= 0.1 * reference ? "yes" : "NO") << std::endl;
    }

  // Solver independence.
  const std::vector<Discretisation> scenes = {
    {"Q2/Q1 8:8", 2, 1, 8, 8},
    {"Q3/Q1 8:8", 3, 1, 8, 8},
    {"Q1/Q1 8:12", 1, 1, 8, 12},
    {"Q1/Q2 12:16", 1, 2, 12, 16},
    {"Q2/Q1 16:8", 2, 1, 16, 8},
    {"P2/P1 triangles 8:12", 2, 1, 8, 12, true},
    {"Q1/Q1 hanging nodes 8:8", 1, 1, 8, 8, false, 2}};
  const std::string kkt = " set Stopping rule = kkt\n set Tolerance = 1e-10\n"
                          " set Maximum iterations = 500000\n";
  for (const Discretisation &d : scenes)
    {
      const auto active =
        solve(d,
              1,
              "subsection Solver\n set Method = active set\n" + kkt + "end\n");
      bool   converged = active->records().back().result.converged;
      double energy = 0, multipliers = 0;
      for (const std::string method : {"accelerated", "uzawa"})
        {
          const auto other =
            solve(d,
                  1,
                  "subsection Solver\n set Method = " + method +
                    "\n set Uzawa step theta = auto\n" + kkt + "end\n");
          converged = converged && other->records().back().result.converged;
          const double e0 = active->records().back().energy,
                       e1 = other->records().back().energy;
          energy          = std::max(energy, std::abs(e0 - e1) / std::abs(e0));
          for (const double m : multiplier_differences(*active, *other))
            multipliers = std::max(multipliers, m);
        }
      std::cout << d.name << ": all converged: " << (converged ? "yes" : "NO")
                << ", energies agree to 1e-8: "
                << (energy <= 1e-8 ? "yes" : "NO")
                << ", multipliers agree to 1e-8: "
                << (multipliers <= 1e-8 ? "yes" : "NO") << std::endl;
    }
}
