// Non-matching traces on Sigma.
//
// Patch test: with Cells along Sigma = 8 on Omega- and 12 on Omega+ (the
// traces do not match), both layers under the uniform strain
// eps = diag(ex, ey), ey < 0 (compression across Sigma: the crack stays
// closed, mu_c = -sigma_yy > 0), with the linear displacement prescribed on
// Gamma_D and the matching tractions on the top and bottom: the exact
// solution u = v = (ex x, ey y) lies in every discrete space and the
// multiplier loads of the constant interface tractions are integrated
// exactly, so it must be reproduced to round-off (lumped and consistent
// coupling).
//
// Example 1 on non-matching meshes (16 and 24 cells along Sigma) lies
// within the discretisation error of the matching ones: its energy differs
// from that of 32 + 32 cells by at most twice the difference of 16 + 16.
//
// Adaptive refinement refines each subdomain on its own (hanging nodes,
// non-matching traces): the spaces and the conforming constraint sets are
// nested, so the energy must not increase from cycle to cycle, and the
// gluing stays conforming (the integral (12) vanishes to round-off).

#include <deal.II/dofs/dof_tools.h>

#include <bilayer/parameters.h>
#include <bilayer/study.h>

#include <cmath>
#include <iostream>
#include <sstream>

#include "reference.h"

using namespace dealii;
using namespace bilayer;

namespace
{
  std::ostringstream quiet;

  const std::string solver =
    "subsection Solver\n set Method = active set\n set Tolerance = 1e-12\n"
    "end\n"
    "subsection Output\n set Output directory = results\n"
    " set Write VTU = false\n set Write interface CSV = false\n"
    " set Terminal output = checks\nend\n";

  const std::string example1 =
    "subsection Loads\n set Constants = c = 1e-3*mu1\n"
    " subsection Layer 1\n"
    "  set Traction on bottom side = 0; c*x\n"
    "  set Traction on top side = 0; -c*x\n end\nend\n";

  double
  energy(const std::string &mesh)
  {
    Study study(scene_from_string("subsection Mesh\n" + mesh + "end\n" +
                                    example1 + solver,
                                  "energy"),
                quiet);
    return study.run_cycle(0).energy;
  }
} // namespace

int
main()
{
  for (const std::string coupling : {"lumped", "consistent"})
    {
      std::string loads =
        "subsection Loads\n set Constants = ex = 1e-4; ey = -2e-4\n";
      for (const std::string layer : {"1", "2"})
        {
          const std::string s =
            "(lambda" + layer + "*(ex+ey)+2*mu" + layer + "*ey)"; // sigma_yy
          loads += " subsection Layer " + layer +
                   "\n  set Prescribed displacement = ex*x; ey*y\n"
                   "  set Traction on bottom side = 0; -" +
                   s + "\n  set Traction on top side = 0; " + s + "\n end\n";
        }
      loads += "end\n";
      Study              study(scene_from_string(
                    "subsection Mesh\n set Cells along Sigma = 8\n"
                                 " set Cells along Sigma on the plus side = 12\nend\n" +
                      loads +
                      "subsection Contact\n set Multiplier coupling = " +
                      coupling + "\nend\n" + solver,
                    "patch"),
                  quiet);
      const CycleRecord &r     = study.run_cycle(0);
      double             error = 0, size = 0;
      for (const Layer layer : {Layer::first, Layer::second})
        for (const Subdomain sd : {Subdomain::minus, Subdomain::plus})
          {
            const auto &sub = study.subproblem(layer, sd);
            const auto &w   = study.solutions()[Interface::index(layer, sd)];
            std::vector<Point<2>> support(sub.n_dofs());
            DoFTools::map_dofs_to_support_points(sub.mapping(),
                                                 sub.dof_handler(),
                                                 support);
            // Component of each dof from the cell-wise numbering.
            std::vector<unsigned int>            component(sub.n_dofs());
            std::vector<types::global_dof_index> local(
              sub.fe().n_dofs_per_cell());
            for (const auto &cell : sub.dof_handler().active_cell_iterators())
              {
                cell->get_dof_indices(local);
                for (unsigned int k = 0; k < local.size(); ++k)
                  component[local[k]] =
                    sub.fe().system_to_component_index(k).first;
              }
            for (unsigned int i = 0; i < sub.n_dofs(); ++i)
              {
                const double exact = component[i] == 0 ? 1e-4 * support[i][0] :
                                                         -2e-4 * support[i][1];
                error              = std::max(error, std::abs(w(i) - exact));
                size               = std::max(size, std::abs(exact));
              }
          }
      std::cout << "patch test, " << coupling
                << " coupling, 8 | 12 cells: accepted: " << yes(r.accepted())
                << ", linear field reproduced to 1e-9: "
                << yes(error <= 1e-9 * size) << ", crack closed (mu_c > 0): "
                << yes(r.report.min_contact_multiplier > 0) << std::endl;
    }

  const double e16   = energy(" set Cells along Sigma = 16\n");
  const double e32   = energy(" set Cells along Sigma = 32\n");
  const double e1624 = energy(" set Cells along Sigma = 16\n"
                              " set Cells along Sigma on the plus side = 24\n");
  if (getenv("BILAYER_TEST_DIAGNOSTICS"))
    std::cerr << "energies 16: " << e16 << ", 16|24: " << e1624
              << ", 32: " << e32 << std::endl;
  std::cout << "Example 1, 16 | 24 cells: within the discretisation error: "
            << yes(std::abs(e1624 - e32) <= 2 * std::abs(e16 - e32))
            << std::endl;

  Study adaptive(
    scene_from_string("subsection Mesh\n set Cells along Sigma = 8\n"
                      " set Refinement = adaptive\n set Number of cycles = 4\n"
                      "end\n" +
                        example1 + solver,
                      "adaptive"),
    quiet);
  bool   decreasing = true, conforming = true, accepted = true;
  double previous = 0;
  for (unsigned int cycle = 0; cycle < 4; ++cycle)
    {
      const CycleRecord &r = adaptive.run_cycle(cycle);
      accepted             = accepted && r.accepted();
      if (cycle > 0)
        decreasing = decreasing && r.energy <= previous * (1 - 1e-12);
      previous   = r.energy;
      conforming = conforming && r.report.relative_constraint_violation < 1e-9;
    }
  std::cout << "Example 1, 4 adaptive cycles: accepted: " << yes(accepted)
            << ", energy decreases: " << yes(decreasing)
            << ", gluing conforming: " << yes(conforming) << std::endl;
}
