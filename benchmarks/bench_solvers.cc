// Outer solvers on one scene and its mesh sequence: for every mesh and every
// solver, the outer and conjugate-gradient iterations, the subdomain solves
// (and the Dirichlet solves of a preconditioner), the wall time split into
// the set-up of the subproblems (assembly, factorisation), the solver's own
// set-up (spectrum estimate, preconditioner factorisations) and its
// iterations, the final relative KKT residual, and the difference from the
// paper's Uzawa solution (theta = 65, run to the same KKT tolerance):
// relative in the energy norm of the four subproblems and on the normal
// crack opening (largest nodal difference over the largest opening).
//
// Usage: bench_solvers SCENE.prm CYCLES TOLERANCE OUTPUT.csv
// Appends one CSV row per mesh and solver (the header when the file is new)
// and prints the rows as they come. A benchmark: it times and prints.

#include <deal.II/base/parameter_handler.h>

#include <bilayer/drivers/study.h>
#include <bilayer/parameters/parameters.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <iomanip>
#include <iostream>
#include <sstream>

using namespace dealii;
using namespace bilayer;

namespace
{
  struct Solver
  {
    std::string              name;
    std::vector<std::string> settings;
  };

  const std::vector<Solver> solvers = {
    {"uzawa-65", {"Solver/Method=uzawa", "Solver/Uzawa step theta=65"}},
    {"uzawa-auto", {"Solver/Method=uzawa", "Solver/Uzawa step theta=auto"}},
    {"accelerated",
     {"Solver/Method=accelerated", "Solver/Uzawa step theta=auto"}},
    {"active-set-dirichlet",
     {"Solver/Method=active set",
      "Solver/Active set/Preconditioner=dirichlet"}},
    {"active-set-lumped",
     {"Solver/Method=active set", "Solver/Active set/Preconditioner=lumped"}},
    {"active-set-none",
     {"Solver/Method=active set", "Solver/Active set/Preconditioner=none"}}};

  std::unique_ptr<Study>
  run(const std::string              &file,
      const std::vector<std::string> &settings,
      const std::string              &tolerance,
      const std::string              &directory,
      const unsigned int              cycle,
      std::ostream                   &sink)
  {
    std::vector<std::string> overrides = settings;
    for (const std::string s : {"Solver/Stopping rule=kkt",
                                "Output/Write VTU=false",
                                "Output/Write interface CSV=false",
                                "Output/Terminal output=checks",
                                "Output/Progress interval=0"})
      overrides.push_back(s);
    overrides.push_back("Solver/Tolerance=" + tolerance);
    overrides.push_back("Output/Output directory=" + directory);
    ParameterHandler prm;
    const Scene      scene = read_scene(prm, file, overrides);
    AssertThrow(cycle < scene.mesh.n_cycles,
                ExcMessage("CYCLES exceeds Mesh/Number of cycles of " + file));
    auto study = std::make_unique<Study>(scene, sink);
    study->run_cycle(cycle);
    return study;
  }
} // namespace

int
main(int argc, char **argv)
{
  if (argc != 5)
    {
      std::cerr << "Usage: bench_solvers SCENE.prm CYCLES TOLERANCE OUTPUT.csv"
                << std::endl;
      return 1;
    }
  try
    {
      const std::string  file      = argv[1];
      const unsigned int cycles    = std::stoi(argv[2]);
      const std::string  tolerance = argv[3];
      const std::string  csv       = argv[4];
      const std::string  scene     = std::filesystem::path(file).stem();
      const std::string  directory =
        (std::filesystem::path(csv).parent_path() / ("runs-" + scene)).string();

      const bool    fresh = !std::filesystem::exists(csv);
      std::ofstream out(csv, std::ios::app);
      if (fresh)
        out << "scene,cycle,P,dofs,multipliers,solver,iterations,"
               "linear_iterations,subdomain_solves,preconditioner_solves,"
               "assembly_factorisation_seconds,solver_setup_seconds,"
               "iteration_seconds,kkt_residual,energy_norm_difference,"
               "opening_difference,converged\n";

      for (unsigned int cycle = 0; cycle < cycles; ++cycle)
        {
          std::ostringstream     sink;
          std::unique_ptr<Study> reference;
          for (const auto &solver : solvers)
            {
              auto study =
                run(file, solver.settings, tolerance, directory, cycle, sink);
              const CycleRecord &r = study->records().back();
              if (!reference)
                reference = std::move(study);
              const Study &s = study ? *study : *reference;

              // Differences from the reference solution.
              double d2 = 0, n2 = 0;
              for (unsigned int i = 0; i < 4; ++i)
                {
                  const auto    &sub = s.subproblem(static_cast<Layer>(i / 2),
                                                 static_cast<Subdomain>(i % 2));
                  Vector<double> d   = s.solutions()[i];
                  d -= reference->solutions()[i];
                  d2 += sub.energy_norm_squared(d);
                  n2 += sub.energy_norm_squared(reference->solutions()[i]);
                }
              const auto open = normal_opening(s.interface(), s.solutions());
              const auto open_ref =
                normal_opening(reference->interface(), reference->solutions());
              double od = 0, on = 0;
              for (unsigned int a = 0; a < open.size(); ++a)
                if (s.interface().space().on_crack(a))
                  {
                    od = std::max(od, std::abs(open[a] - open_ref[a]));
                    on = std::max(on, std::abs(open_ref[a]));
                  }

              std::ostringstream row;
              row << std::setprecision(6) << scene << ',' << cycle << ',' << r.P
                  << ',' << r.dofs << ',' << r.multipliers << ',' << solver.name
                  << ',' << r.result.iterations << ','
                  << r.result.linear_iterations << ','
                  << r.result.subdomain_solves << ','
                  << r.result.preconditioner_solves << ','
                  << r.assembly_seconds + r.factorisation_seconds << ','
                  << r.result.setup_seconds << ',' << r.result.iteration_seconds
                  << ',' << r.report.kkt.value() << ','
                  << (n2 > 0 ? std::sqrt(d2 / n2) : 0.) << ','
                  << (on > 0 ? od / on : 0.) << ','
                  << (r.result.converged && r.accepted() ? 1 : 0) << '\n';
              out << row.str() << std::flush;
              std::cout << row.str() << std::flush;
            }
        }
    }
  catch (const ExceptionBase &e)
    {
      std::cerr << "bench_solvers: error: " << one_line_message(e) << std::endl;
      return 1;
    }
  return 0;
}
