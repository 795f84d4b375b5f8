#include <deal.II/base/exceptions.h>
#include <deal.II/base/parameter_handler.h>
#include <deal.II/base/utilities.h>

#include <bilayer/output.h>
#include <bilayer/parameters.h>
#include <bilayer/study.h>

#include <filesystem>
#include <iostream>
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
  try
    {
      const bool help = argc >= 2 && (std::string(argv[1]) == "--help" ||
                                      std::string(argv[1]) == "-h");
      if (argc < 2 || help || argc % 2 != 0)
        {
          print_usage(help ? std::cout : std::cerr);
          return help ? 0 : 1;
        }
      std::vector<std::string> overrides;
      for (int i = 2; i + 1 < argc; i += 2)
        {
          if (std::string(argv[i]) != "--set")
            {
              print_usage(std::cerr);
              return 1;
            }
          overrides.emplace_back(argv[i + 1]);
        }
      ParameterHandler prm;
      if (std::string(argv[1]) == "--print-parameters")
        {
          bilayer::Scene::declare_parameters(prm);
          prm.print_parameters(std::cout, ParameterHandler::PRM);
          return 0;
        }

      bilayer::Scene scene = bilayer::read_scene(prm, argv[1], overrides);
      // Results appear in the output directory only when the run is over:
      // a refused or failed run leaves an existing one as it was.
      bilayer::StagedDirectory output(scene.output.directory);
      scene.output.directory = output.staging();
      prm.print_parameters(scene.output.directory + "/used_parameters.prm",
                           ParameterHandler::ShortPRM);

      bilayer::Study    study(scene, std::cout);
      const bool        passed = study.run();
      const std::string where  = output.commit(passed);
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
      return 1;
    }
  catch (const std::exception &e)
    {
      std::cerr << "bilayer: error: " << e.what() << std::endl;
      return 1;
    }
}
