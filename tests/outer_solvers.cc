// Every outer solver solves the same discrete problem as the paper's Uzawa
// iteration: the saddle point is unique, so run to a tight KKT tolerance
// their solutions, multipliers and energies agree up to the iteration error,
// and every one meets its own stopping test (relative KKT residual below
// Solver/Tolerance). The reference is the paper's Uzawa at theta = 65 run to
// the same KKT tolerance. The faster solvers must need fewer subdomain
// solves than the reference; the active-set method at most 15 Newton steps.
//
// The Dirichlet preconditioner rests on the Schur complement of each
// subproblem on Sigma: for a load that acts on Sigma only, the homogeneous
// solution w satisfies S (w on Sigma) = load, which is checked directly.
//
// Example 1 on 8 quadrilaterals along Sigma and on the paper's mesh1 (P1
// triangles).

#include <bilayer/drivers/study.h>
#include <bilayer/parameters/parameters.h>
#include <bilayer/solvers/subdomain_solves.h>
#include <bilayer/subproblem/interface_stiffness.h>

#include <cmath>
#include <iostream>
#include <random>
#include <sstream>

#include "reference.h"

using namespace dealii;
using namespace bilayer;

namespace
{
  const double tolerance = 1e-11;

  std::unique_ptr<Study>
  run(const std::string &mesh, const std::string &solver)
  {
    static std::ostringstream quiet;
    std::ostringstream        tol;
    tol << tolerance;
    auto study = std::make_unique<Study>(
      scene_from_string(
        "subsection Mesh\n" + mesh +
          "end\n"
          "subsection Loads\n set Constants = c = 1e-3*mu1\n"
          " subsection Layer 1\n"
          "  set Traction on bottom side = 0; c*x\n"
          "  set Traction on top side = 0; -c*x\n end\nend\n"
          "subsection Solver\n" +
          solver + " set Stopping rule = kkt\n set Tolerance = " + tol.str() +
          "\nend\n"
          "subsection Output\n set Output directory = results\n"
          " set Write VTU = false\n set Write interface CSV = false\n"
          " set Terminal output = checks\nend\n",
        "solver"),
      quiet);
    study->run_cycle(0);
    return study;
  }
} // namespace

int
main()
{
  const std::string meshes[] = {" set Cells along Sigma = 8\n",
                                " set Mesh files = " + std::string(SOURCE_DIR) +
                                  "/../meshes/table1_P12_M32_{side}.msh\n"};
  const std::pair<std::string, std::string> solvers[] = {
    {"uzawa, theta = auto", " set Uzawa step theta = auto\n"},
    {"accelerated",
     " set Method = accelerated\n set Uzawa step theta = auto\n"},
    {"active set, dirichlet",
     " set Method = active set\n subsection Active set\n"
     "  set Preconditioner = dirichlet\n end\n"},
    {"active set, lumped",
     " set Method = active set\n subsection Active set\n"
     "  set Preconditioner = lumped\n end\n"},
    {"active set, none",
     " set Method = active set\n subsection Active set\n"
     "  set Preconditioner = none\n end\n"}};

  for (const auto &mesh : meshes)
    {
      const std::string name =
        mesh.find("msh") != std::string::npos ? "mesh1" : "quads";
      const auto  reference = run(mesh, " set Uzawa step theta = 65\n");
      const auto &ref       = reference->records().back();
      std::cout << name
                << ", uzawa, theta = 65: accepted: " << yes(ref.accepted())
                << ", KKT residual <= tolerance: "
                << yes(ref.report.kkt.value() <= tolerance) << std::endl;
      double size = 0;
      for (unsigned int s = 0; s < 4; ++s)
        size = std::max(size, reference->solutions()[s].linfty_norm());

      for (const auto &[label, settings] : solvers)
        {
          const auto  study      = run(mesh, settings);
          const auto &record     = study->records().back();
          double      difference = 0;
          for (unsigned int s = 0; s < 4; ++s)
            {
              Vector<double> d = study->solutions()[s];
              d -= reference->solutions()[s];
              difference = std::max(difference, d.linfty_norm());
            }
          BlockVector<double> dmu = study->multipliers();
          dmu -= reference->multipliers();
          const bool active_set = label.find("active set") == 0;
          std::cout << name << ", " << label
                    << ": accepted: " << yes(record.accepted())
                    << ", KKT residual <= tolerance: "
                    << yes(record.report.kkt.value() <= tolerance)
                    << ", displacements agree to 1e-8: "
                    << yes(difference <= 1e-8 * size)
                    << ", multipliers agree to 1e-7: "
                    << yes(dmu.linfty_norm() <=
                           1e-7 * reference->multipliers().linfty_norm())
                    << ", energies agree to 1e-10: "
                    << yes(std::abs(record.energy - ref.energy) <=
                           1e-10 * std::abs(ref.energy));
          if (label != "uzawa, theta = auto")
            std::cout << ", fewer subdomain solves than the reference: "
                      << yes(record.result.subdomain_solves +
                               record.result.preconditioner_solves <
                             ref.result.subdomain_solves);
          if (active_set)
            std::cout << ", at most 15 Newton steps: "
                      << yes(record.result.iterations <= 15);
          std::cout << std::endl;

          if (label == "active set, dirichlet")
            {
              // S (w on Sigma) = load for w = K^-1 load, load on Sigma only.
              const Interface    &interface = study->interface();
              BlockVector<double> mu;
              interface.space().initialize(mu);
              std::mt19937                           random(7);
              std::uniform_real_distribution<double> uniform(-1., 1.);
              for (unsigned int i = 0; i < mu.size(); ++i)
                mu(i) = uniform(random);
              interface.space().restrict_to_free(mu);
              Solutions loads, w;
              interface.apply(mu, loads);
              Subproblems subproblems(Topology().n_subproblems());
              for (const unsigned int s :
                   Layout::indices(Topology().n_subproblems()))
                subproblems[s] = &study->subproblem(s);
              solve_homogeneous_subproblems(subproblems, interface, mu, w);
              double error = 0, norm = 0;
              for (const unsigned int s :
                   Layout::indices(Topology().n_subproblems()))
                {
                  Vector<double> reaction;
                  InterfaceStiffness(*subproblems[s], true)
                    .apply_schur_complement(w[s], reaction);
                  reaction -= loads[s];
                  error = std::max(error, reaction.linfty_norm());
                  norm  = std::max(norm, loads[s].linfty_norm());
                }
              std::cout << name
                        << ", Schur complement inverts the Sigma-load "
                           "solve to 1e-10: "
                        << yes(error <= 1e-10 * norm) << std::endl;
            }
        }
    }
}
