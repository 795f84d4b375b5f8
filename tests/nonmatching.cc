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
// The same patch test with hanging nodes next to Sigma: two rounds of
// refinement of cells along parts of Sigma, different on the two sides,
// leave hanging nodes whose constraints have masters on Sigma and graded,
// non-matching traces (Q1 lumped and consistent, Q2 consistent).
//
// Example 1 on non-matching meshes (16 and 24 cells along Sigma) lies
// within the discretisation error of the matching ones: its energy differs
// from that of 32 + 32 cells by at most twice the difference of 16 + 16.
// With the cells along parts of Sigma of the 16-cell meshes refined once
// (hanging nodes next to Sigma, different parts on the two sides) the
// spaces lie between those of 16 and 32 cells, and so does the energy.
//
// Adaptive refinement refines each subdomain on its own (hanging nodes,
// non-matching traces): the spaces and the conforming constraint sets are
// nested, so the energy must not increase from cycle to cycle, and the
// gluing stays conforming (the integral (12) vanishes to round-off).

#include <deal.II/dofs/dof_tools.h>

#include <bilayer/drivers/study.h>
#include <bilayer/parameters/parameters.h>

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

  // Largest deviation of the nodal values of all four subproblems from the
  // linear field (ex x, ey y), relative to its largest value.
  double
  linear_field_error(const Study &study, const double ex, const double ey)
  {
    double error = 0, size = 0;
    for (const Layer layer : {Layer::first, Layer::second})
      for (const Subdomain sd : {Subdomain::minus, Subdomain::plus})
        {
          const auto           &sub = study.subproblem(layer, sd);
          const auto           &w = study.solutions()[Layout::index(layer, sd)];
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
              const double exact =
                component[i] == 0 ? ex * support[i][0] : ey * support[i][1];
              error = std::max(error, std::abs(w(i) - exact));
              size  = std::max(size, std::abs(exact));
            }
        }
    return error / size;
  }

  // Hanging-node constraints of layer 1 on subdomain @p sd with a master
  // dof on Sigma (y = 0).
  unsigned int
  hanging_on_sigma(const Study &study, const Subdomain sd)
  {
    const auto               &sub = study.subproblem(Layer::first, sd);
    AffineConstraints<double> hanging;
    DoFTools::make_hanging_node_constraints(sub.dof_handler(), hanging);
    std::vector<Point<2>> support(sub.n_dofs());
    DoFTools::map_dofs_to_support_points(sub.mapping(),
                                         sub.dof_handler(),
                                         support);
    unsigned int n = 0;
    for (const auto &line : hanging.get_lines())
      for (const auto &entry : line.entries)
        if (std::abs(support[entry.first][1]) < 1e-12)
          {
            ++n;
            break;
          }
    return n;
  }

  // Indicators that mark the cells touching Sigma whose centres lie in
  // (a, b) on Omega- and in (c, d) on Omega+.
  std::vector<Vector<float>>
  along_sigma(const Study &study, const std::array<double, 4> &x)
  {
    std::vector<Vector<float>> marks(2);
    for (const Subdomain sd : {Subdomain::minus, Subdomain::plus})
      {
        const unsigned int s = static_cast<unsigned int>(sd);
        const auto &dof      = study.subproblem(Layer::first, sd).dof_handler();
        marks[s].reinit(dof.get_triangulation().n_active_cells());
        unsigned int i = 0;
        for (const auto &cell : dof.active_cell_iterators())
          {
            bool touches = false;
            for (const unsigned int v : cell->vertex_indices())
              touches = touches || std::abs(cell->vertex(v)[1]) < 1e-12;
            const double xc = cell->center()[0];
            marks[s][i++]   = touches && xc > x[2 * s] && xc < x[2 * s + 1];
          }
      }
    return marks;
  }
} // namespace

int
main()
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

  for (const std::string coupling : {"lumped", "consistent"})
    {
      Study              study(scene_from_string(
                    "subsection Mesh\n set Cells along Sigma = 8\n"
                                 " set Cells along Sigma on the plus side = 12\nend\n" +
                      loads +
                      "subsection Contact\n set Multiplier coupling = " +
                      coupling + "\nend\n" + solver,
                    "patch"),
                  quiet);
      const CycleRecord &r     = study.run_cycle(0);
      const double       error = linear_field_error(study, 1e-4, -2e-4);
      std::cout << "patch test, " << coupling
                << " coupling, 8 | 12 cells: accepted: " << yes(r.accepted())
                << ", linear field reproduced to 1e-9: " << yes(error <= 1e-9)
                << ", crack closed (mu_c > 0): "
                << yes(r.report.min_contact_multiplier > 0) << std::endl;
    }

  for (const auto &[degree, coupling] : {std::make_pair(1, "lumped"),
                                         std::make_pair(1, "consistent"),
                                         std::make_pair(2, "consistent")})
    {
      const std::string d = std::to_string(degree);
      Study             study(scene_from_string(
                    "subsection Mesh\n set Cells along Sigma = 8\n"
                                " set Cells along Sigma on the plus side = 12\n"
                                " set Refinement = adaptive\n set Number of cycles = 3\n"
                                " set Polynomial degree of layer 1 = " +
                      d + "\n set Polynomial degree of layer 2 = " + d +
                      "\nend\n" + loads +
                      "subsection Contact\n set Multiplier coupling = " +
                      coupling + "\nend\n" + solver,
                    "patch-hanging"),
                  quiet);
      bool              accepted = study.run_cycle(0).accepted();
      study.set_indicators(along_sigma(study, {-1, 0.25, -0.3, 1}));
      accepted = accepted && study.run_cycle(1).accepted();
      study.set_indicators(along_sigma(study, {-0.6, -0.1, 0.1, 0.7}));
      const CycleRecord &r = study.run_cycle(2);
      accepted             = accepted && r.accepted();
      const double error   = linear_field_error(study, 1e-4, -2e-4);
      if (getenv("BILAYER_TEST_DIAGNOSTICS"))
        std::cerr << "Q" << degree << " " << coupling << ": hanging on Sigma "
                  << hanging_on_sigma(study, Subdomain::minus) << " | "
                  << hanging_on_sigma(study, Subdomain::plus) << ", error "
                  << error << std::endl;
      std::cout << "patch test, Q" << degree << ", " << coupling
                << " coupling, hanging nodes next to Sigma on both sides: "
                << yes(hanging_on_sigma(study, Subdomain::minus) > 0 &&
                       hanging_on_sigma(study, Subdomain::plus) > 0)
                << ", accepted: " << yes(accepted)
                << ", linear field reproduced to 1e-9: " << yes(error <= 1e-9)
                << std::endl;
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

  Study hanging(
    scene_from_string("subsection Mesh\n set Cells along Sigma = 16\n"
                      " set Refinement = adaptive\n set Number of cycles = 2\n"
                      "end\n" +
                        example1 + solver,
                      "hanging"),
    quiet);
  hanging.run_cycle(0);
  hanging.set_indicators(along_sigma(hanging, {-1, 0, -0.25, 1}));
  const double eh = hanging.run_cycle(1).energy;
  if (getenv("BILAYER_TEST_DIAGNOSTICS"))
    std::cerr << "hanging: " << eh << std::endl;
  std::cout << "Example 1, 16 cells refined along parts of Sigma (hanging "
               "nodes next to Sigma): energy between those of 16 and 32 "
               "cells: "
            << yes(e32 <= eh && eh <= e16) << std::endl;

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
