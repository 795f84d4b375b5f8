#include <deal.II/base/exceptions.h>
#include <deal.II/base/mpi.h>
#include <deal.II/base/multithread_info.h>
#include <deal.II/base/parameter_handler.h>
#include <deal.II/base/utilities.h>

#include <bilayer/build_info.h>
#include <bilayer/distribution.h>
#include <bilayer/output.h>
#include <bilayer/output_directory.h>
#include <bilayer/parameters.h>
#include <bilayer/resources.h>
#include <bilayer/study.h>

#include <algorithm>
#include <csignal>
#include <cstdlib>
#include <filesystem>
#include <iostream>
#include <memory>
#include <new>
#include <sstream>
#include <string>
#include <vector>

namespace
{
  const char *usage_line =
    "usage: bilayer PARAMETER_FILE.prm [--set Section/Entry=value ...]; "
    "bilayer --help";

  void
  print_usage(std::ostream &out)
  {
    out << "Usage: bilayer PARAMETER_FILE.prm [--set Section/Entry=value ...] "
           "[--allow-gmsh-commands]\n"
           "       bilayer --print-parameters   print every entry with its "
           "default and documentation\n"
           "       bilayer PARAMETER_FILE.prm --print-parameters [--set ...]\n"
           "                                    print every entry as the run "
           "would use it\n"
           "                                    (includes and --set applied), "
           "run nothing\n"
           "       bilayer --version            print the version, the git "
           "commit, deal.II's\n"
           "                                    version and the BLAS in use\n"
           "       bilayer --help               print this message\n\n"
           "--set overrides an entry of the file, e.g.\n"
           "  --set \"Solver/Uzawa step theta=70\" --set "
           "\"Materials/Layer 1/Young's modulus=210\"\n"
           "--allow-gmsh-commands lets a Gmsh scene (Geometry/Gmsh file, "
           ".geo) run programs\n"
           "  and write files (SystemCall, Printf > file, Save, ...): only "
           "for files you\n"
           "  trust; without it such scenes are refused (docs/geometry.md)\n"
           "\n"
           "Computes the equilibrium of a two-layer elastic structure with a "
           "through\ncrack whose faces must not penetrate each other "
           "(domain decomposition\nand Uzawa iteration). Results go to the "
           "directory Output/Output directory.\n";
  }

  /// What the command line asks for.
  struct CommandLine
  {
    enum class Action
    {
      run,
      help,
      print_parameters,
      version
    } action = Action::run;
    std::string              parameter_file;
    std::vector<std::string> overrides;
    bool                     allow_gmsh_commands = false;
  };

  /// An environment variable of the MPI launcher as a number, or -1.
  int
  launcher_number(const std::vector<const char *> &names)
  {
    for (const char *name : names)
      if (const char *value = std::getenv(name))
        return std::atoi(value);
    return -1;
  }

  /// This process's rank as the MPI launcher set it (0 without one).
  int
  launch_rank()
  {
    return std::max(0,
                    launcher_number({"OMPI_COMM_WORLD_RANK",
                                     "PMIX_RANK",
                                     "PMI_RANK",
                                     "MV2_COMM_WORLD_RANK"}));
  }

  /// Read the command line; mistakes throw a one-line message.
  CommandLine
  parse_command_line(const int argc, char **argv)
  {
    using dealii::ExcMessage;
    CommandLine command;
    for (int i = 1; i < argc; ++i)
      {
        const std::string arg = argv[i];
        if (arg == "--help" || arg == "-h")
          command.action = CommandLine::Action::help;
        else if (arg == "--print-parameters")
          command.action = CommandLine::Action::print_parameters;
        else if (arg == "--version")
          command.action = CommandLine::Action::version;
        else if (arg == "--set")
          {
            AssertThrow(i + 1 < argc,
                        ExcMessage("--set needs a value "
                                   "'Section/Entry=value' after it (" +
                                   std::string(usage_line) + ")"));
            command.overrides.emplace_back(argv[++i]);
          }
        else if (arg.rfind("--set=", 0) == 0)
          command.overrides.emplace_back(arg.substr(6));
        else if (arg == "--allow-gmsh-commands")
          command.allow_gmsh_commands = true;
        else if (arg.size() > 1 && arg[0] == '-')
          {
            AssertThrow(false,
                        ExcMessage("unknown option '" + arg + "' (" +
                                   usage_line + ")"));
          }
        else
          {
            AssertThrow(command.parameter_file.empty(),
                        ExcMessage("more than one parameter file given ('" +
                                   command.parameter_file + "', '" + arg +
                                   "'): run them one at a time (" + usage_line +
                                   ")"));
            command.parameter_file = arg;
          }
      }
    AssertThrow(command.action != CommandLine::Action::version ||
                  (command.parameter_file.empty() && command.overrides.empty()),
                ExcMessage("--version takes no parameter file or --set"));
    AssertThrow(command.action != CommandLine::Action::print_parameters ||
                  !command.parameter_file.empty() || command.overrides.empty(),
                ExcMessage("--print-parameters with --set needs the parameter "
                           "file the settings apply to (" +
                           std::string(usage_line) + ")"));


    AssertThrow(command.action != CommandLine::Action::run ||
                  !command.parameter_file.empty(),
                ExcMessage(std::string("no parameter file given (") +
                           usage_line + ")"));
    return command;
  }
} // namespace

namespace
{
  /**
   * A process started without mpirun is a job of one process (an MPI
   * singleton). Open MPI's singleton start-up probes the network transports
   * and prepares a run-time server for processes it might spawn: 0.45 s of
   * the 1 s a small run takes on the development machine. One process
   * needs neither, so without a launcher (no OMPI_COMM_WORLD_SIZE, PMI or
   * PMIx rank in the environment) Open MPI is told to start isolated, with
   * the self transport only (0.07 s). Settings the user made win; other MPI
   * implementations ignore these variables.
   */
  void
  start_mpi_alone_quickly()
  {
    for (const char *launched : {"OMPI_COMM_WORLD_SIZE",
                                 "PMIX_RANK",
                                 "PMI_RANK",
                                 "PMI_SIZE",
                                 "MPI_LOCALNRANKS"})
      if (std::getenv(launched) != nullptr)
        return;
    for (const auto &[name, value] :
         std::vector<std::pair<const char *, const char *>>{
           {"OMPI_MCA_ess_singleton_isolated", "1"},
           {"OMPI_MCA_pml", "ob1"},
           {"OMPI_MCA_btl", "self"},
           {"OMPI_MCA_osc", "^ucx"},
           {"OMPI_MCA_mtl", "^ofi"},
           {"OMPI_MCA_btl_base_warn_component_unused", "0"}})
      setenv(name, value, 0);
  }
} // namespace


int
main(int argc, char **argv)
{
  using namespace dealii;
  dealii::deal_II_exceptions::disable_abort_on_exception();
  dealii::deal_II_exceptions::suppress_stacktrace_in_exceptions();
  // The input is read and checked before MPI_Init, which costs about a
  // second for a job of one process: refusals come at once. Under mpirun
  // every process reads it alike and the first one reports.
  const bool reporter = launch_rank() == 0;
  const auto refuse   = [&](const std::string &message) {
    if (reporter)
      std::cerr << "bilayer: error: " << message << std::endl;
    return 1;
  };

  bilayer::Scene   scene;
  ParameterHandler prm;
  try
    {
      const CommandLine command = parse_command_line(argc, argv);
      if (command.action == CommandLine::Action::help)
        {
          if (reporter)
            print_usage(std::cout);
          return 0;
        }
      if (command.action == CommandLine::Action::version)
        {
          if (reporter)
            std::cout << "bilayer " << bilayer::version() << " (git commit "
                      << bilayer::git_commit() << ")\ndeal.II "
                      << bilayer::deal_ii_version() << "\nBLAS "
                      << bilayer::blas_library() << std::endl;
          return 0;
        }
      if (command.action == CommandLine::Action::print_parameters &&
          command.parameter_file.empty())
        {
          bilayer::Scene::declare_parameters(prm);
          if (reporter)
            prm.print_parameters(std::cout, ParameterHandler::PRM);
          return 0;
        }
      scene = bilayer::read_scene(prm,
                                  command.parameter_file,
                                  command.overrides,
                                  command.allow_gmsh_commands);
      // Every entry as this run would use it (the file with its includes,
      // then the --set), as used_parameters.prm records it; nothing is run
      // or written.
      if (command.action == CommandLine::Action::print_parameters)
        {
          if (reporter)
            prm.print_parameters(std::cout, ParameterHandler::ShortPRM);
          return 0;
        }
    }
  catch (const ExceptionBase &e)
    {
      return refuse(bilayer::one_line_message(e));
    }
  catch (const std::bad_alloc &)
    {
      return refuse("out of memory while reading the parameters");
    }
  catch (const std::exception &e)
    {
      return refuse(e.what());
    }
  catch (...)
    {
      return refuse("the parameters could not be read (unknown error)");
    }

  // Under mpirun the processes share the subproblems (bilayer::
  // Distribution); without it this is a job of one process. Threads: the
  // cores of the node divided among its processes.
  start_mpi_alone_quickly();
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv);
  // PETSc, initialised with MPI, turns SIGHUP, SIGINT and SIGTERM into an
  // error report and MPI_Abort: a stopped run ends by its signal instead, as
  // any program does (the next run removes what it staged).
  for (const int stop : {SIGHUP, SIGINT, SIGTERM})
    std::signal(stop, SIG_DFL);
  const bilayer::Distribution &processes = bilayer::Distribution::world();
  // The four subproblems are factorised and solved as parallel tasks, each
  // calling the BLAS: a threaded BLAS gets this process's threads divided
  // among them (one each on a machine with fewer than eight cores), so that
  // the two kinds of threads do not compete for the cores (docs/
  // performance.md measures the choices; BILAYER_BLAS_THREADS overrides
  // the count, OPENBLAS_NUM_THREADS and its kin do not).
  unsigned int blas_threads = 1;
  try
    {
      blas_threads = bilayer::fit_blas_threads(MultithreadInfo::n_threads(),
                                               bilayer::Layout::n_subproblems);
    }
  catch (const ExceptionBase &e)
    {
      return refuse(bilayer::one_line_message(e));
    }

  // The memory each process sees may differ a little: the processes decide
  // together whether the scene fits.
  {
    std::string too_large;
    try
      {
        bilayer::check_scene_resources(scene, processes.n_processes());
      }
    catch (const ExceptionBase &e)
      {
        too_large = bilayer::one_line_message(e);
      }
    too_large = processes.first_error(too_large);
    if (!too_large.empty())
      return refuse(too_large);
  }

  std::unique_ptr<bilayer::StagedDirectory> output;
  try
    {
      // Results appear in the output directory only when the run is over:
      // a refused or failed run leaves an existing one as it was. The first
      // process prepares it and tells the others whether it could.
      bool        ready = true;
      std::string problem;
      if (processes.is_root())
        try
          {
            std::vector<std::string> inputs = scene.input_files;
            if (!scene.geometry.gmsh_file.empty())
              inputs.push_back(scene.geometry.gmsh_file);
            for (const auto &pattern : scene.mesh.mesh_files)
              for (const std::string side : {"minus", "plus"})
                {
                  std::string file = pattern;
                  const auto  at   = file.find("{side}");
                  if (at != std::string::npos)
                    file.replace(at, 6, side);
                  inputs.push_back(file);
                }
            output =
              std::make_unique<bilayer::StagedDirectory>(scene.output.directory,
                                                         inputs);
            // The files of all cycles must fit on the file system (known
            // in advance for structured meshes refined globally).
            double files = 0;
            for (unsigned int cycle = 0; cycle < scene.mesh.n_cycles; ++cycle)
              {
                const auto cells = bilayer::structured_cells(scene, cycle);
                files +=
                  bilayer::estimate_resources(scene, cells[0], cells[1]).output;
              }
            AssertThrow(files <= output->free_bytes(),
                        ExcMessage(
                          "Output/Output directory: the results of all "
                          "cycles need about " +
                          bilayer::format_bytes(files) + ", but " +
                          bilayer::format_bytes(output->free_bytes()) +
                          " are free on its file system: make room, choose "
                          "another directory or set Output/Write VTU = false"));
            // Every entry as used, after the versions that used them.
            std::ostringstream used;
            used << "# bilayer " << bilayer::version() << ", git commit "
                 << bilayer::git_commit() << ", deal.II "
                 << bilayer::deal_ii_version() << "\n# BLAS "
                 << bilayer::blas_library() << "\n";
            prm.print_parameters(used, ParameterHandler::ShortPRM);
            bilayer::write_atomically(output->staging() +
                                        "/used_parameters.prm",
                                      [&](std::ostream &out) {
                                        out << used.str();
                                      });
            problem = output->staging();
          }
        catch (const ExceptionBase &e)
          {
            output.reset();
            ready   = false;
            problem = bilayer::one_line_message(e);
          }
        catch (const std::exception &e)
          {
            output.reset();
            ready   = false;
            problem = std::string("Output/Output directory: ") + e.what();
          }
      // On success the message is the staging directory.
      processes.broadcast(ready, problem);
      if (!ready)
        return refuse(problem);
      // (As the user wrote it, for the last line of a successful run.)
      const std::string requested = scene.output.directory;
      scene.output.directory      = problem;

      if (processes.is_root() &&
          scene.output.terminal == bilayer::TerminalOutput::full)
        {
          const std::string variable = bilayer::blas_threads_variable();
          std::cout << "bilayer " << bilayer::version() << " (git commit "
                    << bilayer::git_commit() << "), deal.II "
                    << bilayer::deal_ii_version() << "; "
                    << processes.n_processes() << " process"
                    << (processes.n_processes() > 1 ? "es" : "") << " of "
                    << MultithreadInfo::n_threads() << " thread"
                    << (MultithreadInfo::n_threads() > 1 ? "s" : "")
                    << " (the subproblems' tasks), " << blas_threads
                    << " BLAS thread" << (blas_threads > 1 ? "s" : "")
                    << " per call"
                    << (variable.empty() ? "" : " (" + variable + ")")
                    << "; BLAS " << bilayer::blas_library() << std::endl;
        }
      bilayer::Study study(scene, std::cout, processes);
      bool           passed = false;
      std::string    failure;
      unsigned int   failed_cycle = 0;
      try
        {
          passed = study.run();
          if (!passed)
            {
              failed_cycle = study.records().back().cycle;
              failure      = study.records().back().failure();
            }
        }
      catch (const bilayer::RunFailure &e)
        {
          failed_cycle = e.cycle;
          failure      = e.what();
        }
      catch (const std::bad_alloc &)
        {
          failed_cycle = study.records().size();
          failure =
            "out of memory (an allocation failed): use fewer cells or cycles";
        }
      if (!processes.is_root())
        return passed ? 0 : 2;
      const std::string where = output->commit(passed);
      if (!passed)
        {
          std::cerr << "bilayer: cycle " << failed_cycle
                    << " FAILED: " << failure << " (its results are in "
                    << where << ")" << std::endl;
          return 2;
        }
      std::cout << "bilayer: results are in " << requested << std::endl;
      return 0;
    }
  catch (const bilayer::CollectiveError &e)
    {
      // Every process knows: the first reports, none aborts, and the
      // staging directory goes with `output`.
      return refuse(e.what());
    }
  catch (const ExceptionBase &e)
    {
      std::cerr << "bilayer: error: " << bilayer::one_line_message(e)
                << std::endl;
    }
  catch (const std::bad_alloc &)
    {
      std::cerr << "bilayer: error: out of memory (an allocation failed)"
                << std::endl;
    }
  catch (const std::exception &e)
    {
      std::cerr << "bilayer: error: " << e.what() << std::endl;
    }
  catch (...)
    {
      std::cerr << "bilayer: error: unknown error" << std::endl;
    }
  // An error on one process would leave the others waiting; the staging
  // directory goes first.
  output.reset();
  if (processes.parallel())
    MPI_Abort(processes.communicator(), 1);
  return 1;
}
