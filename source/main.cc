#include <deal.II/base/exceptions.h>
#include <deal.II/base/mpi.h>
#include <deal.II/base/parameter_handler.h>
#include <deal.II/base/utilities.h>

#include <bilayer/distribution.h>
#include <bilayer/output.h>
#include <bilayer/parameters.h>
#include <bilayer/study.h>

#include <filesystem>
#include <iostream>
#include <memory>
#include <sstream>
#include <string>
#include <vector>

namespace
{
  void
  print_usage(std::ostream &out)
  {
    out << "Usage: bilayer PARAMETER_FILE.prm [--set Section/Entry=value ...]\n"
           "       bilayer --print-parameters   print every entry with its "
           "default and documentation\n"
           "       bilayer --help               print this message\n\n"
           "--set overrides an entry of the file, e.g.\n"
           "  --set \"Solver/Uzawa step theta=70\" --set "
           "\"Materials/Layer 1/Young's modulus=210\"\n\n"
           "Computes the equilibrium of a two-layer elastic structure with a "
           "through\ncrack whose faces must not penetrate each other "
           "(domain decomposition\nand Uzawa iteration). Results go to the "
           "directory Output/Output directory.\n";
  }

} // namespace

int
main(int argc, char **argv)
{
  using namespace dealii;
  dealii::deal_II_exceptions::disable_abort_on_exception();
  dealii::deal_II_exceptions::suppress_stacktrace_in_exceptions();
  // Under mpirun the processes share the subproblems (bilayer::
  // Distribution); without it this is a job of one process. Threads: the
  // cores of the node divided among its processes.
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv);
  const bilayer::Distribution     &processes = bilayer::Distribution::world();
  // Refusals of the input happen on every process alike: one reports.
  const auto refuse = [&](const std::string &message) {
    if (processes.is_root())
      std::cerr << "bilayer: error: " << message << std::endl;
    return 1;
  };

  bilayer::Scene   scene;
  ParameterHandler prm;
  try
    {
      const bool help = argc >= 2 && (std::string(argv[1]) == "--help" ||
                                      std::string(argv[1]) == "-h");
      if (argc < 2 || help || argc % 2 != 0)
        {
          if (processes.is_root())
            print_usage(help ? std::cout : std::cerr);
          return help ? 0 : 1;
        }
      std::vector<std::string> overrides;
      for (int i = 2; i + 1 < argc; i += 2)
        {
          if (std::string(argv[i]) != "--set")
            {
              if (processes.is_root())
                print_usage(std::cerr);
              return 1;
            }
          overrides.emplace_back(argv[i + 1]);
        }
      if (std::string(argv[1]) == "--print-parameters")
        {
          bilayer::Scene::declare_parameters(prm);
          if (processes.is_root())
            prm.print_parameters(std::cout, ParameterHandler::PRM);
          return 0;
        }
      scene = bilayer::read_scene(prm, argv[1], overrides);
    }
  catch (const ExceptionBase &e)
    {
      return refuse(bilayer::one_line_message(e));
    }
  catch (const std::exception &e)
    {
      return refuse(e.what());
    }

  try
    {
      // Results appear in the output directory only when the run is over:
      // a refused or failed run leaves an existing one as it was. The first
      // process prepares it and tells the others whether it could.
      std::unique_ptr<bilayer::StagedDirectory> output;
      bool                                      ready = true;
      std::string                               problem;
      if (processes.is_root())
        try
          {
            output = std::make_unique<bilayer::StagedDirectory>(
              scene.output.directory);
            prm.print_parameters(output->staging() + "/used_parameters.prm",
                                 ParameterHandler::ShortPRM);
            problem = output->staging();
          }
        catch (const ExceptionBase &e)
          {
            ready   = false;
            problem = bilayer::one_line_message(e);
          }
      // On success the message is the staging directory.
      processes.broadcast(ready, problem);
      if (!ready)
        return refuse(problem);
      scene.output.directory = problem;

      bilayer::Study study(scene, std::cout, processes);
      const bool     passed = study.run();
      if (!processes.is_root())
        return passed ? 0 : 2;
      const std::string where = output->commit(passed);
      if (!passed)
        {
          const auto &last = study.records().back();
          std::cerr << "bilayer: cycle " << last.cycle
                    << " did not pass its checks: " << last.failure()
                    << " (its results are in " << where << ")" << std::endl;
          return 2;
        }
      return 0;
    }
  catch (const ExceptionBase &e)
    {
      std::cerr << "bilayer: error: " << bilayer::one_line_message(e)
                << std::endl;
    }
  catch (const std::exception &e)
    {
      std::cerr << "bilayer: error: " << e.what() << std::endl;
    }
  // An error on one process would leave the others waiting.
  if (processes.parallel())
    MPI_Abort(processes.communicator(), 1);
  return 1;
}
