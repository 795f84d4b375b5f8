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
#include <cerrno>
#include <climits>
#include <cstdlib>
#include <cstring>
#include <fcntl.h>
#include <filesystem>
#include <iostream>
#include <memory>
#include <new>
#include <sstream>
#include <string>
#include <sys/stat.h>
#include <unistd.h>
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

  /**
   * A standard stream the program was started without (`>&-`, `2>&-`) is
   * opened on /dev/null: the descriptor would otherwise go to the first
   * file the program opens (a mesh, the lock file), and progress lines into
   * it. The run then goes on without that output.
   */
  void
  open_closed_standard_streams()
  {
    for (int fd = 0; fd <= 2; ++fd)
      if (::fcntl(fd, F_GETFD) < 0 && errno == EBADF)
        {
          const int opened = ::open("/dev/null", fd == 0 ? O_RDONLY : O_WRONLY);
          if (opened >= 0 && opened != fd)
            {
              ::dup2(opened, fd);
              ::close(opened);
            }
        }
  }

  /**
   * The standard output of a run: written to descriptor 1 as std::cout
   * would, but a write that fails (a closed pipe, `| head -1`; a full disk)
   * ends the output instead of setting the stream's error state, which
   * deal.II's writers (the tables) turn into an exception. The run goes on
   * and commits; its exit status says how it ended.
   */
  class TolerantOutput : public std::streambuf
  {
  public:
    TolerantOutput()
      : original(std::cout.rdbuf())
    {
      setp(buffer, buffer + sizeof(buffer));
      std::cout.rdbuf(this);
    }
    ~TolerantOutput() override
    {
      sync();
      std::cout.rdbuf(original);
    }

  protected:
    // Line-buffered, as the standard output on a terminal.
    int_type
    overflow(const int_type c) override
    {
      write_out();
      if (!traits_type::eq_int_type(c, traits_type::eof()))
        {
          *pptr() = traits_type::to_char_type(c);
          pbump(1);
          if (traits_type::to_char_type(c) == '\n')
            write_out();
        }
      return traits_type::not_eof(c);
    }
    std::streamsize
    xsputn(const char *text, const std::streamsize n) override
    {
      for (std::streamsize i = 0; i < n; ++i)
        {
          if (pptr() == epptr())
            write_out();
          *pptr() = text[i];
          pbump(1);
          if (text[i] == '\n')
            write_out();
        }
      return n;
    }
    int
    sync() override
    {
      write_out();
      return 0;
    }

  private:
    void
    write_out()
    {
      const char *from = pbase();
      std::size_t left = pptr() - pbase();
      while (left > 0 && !broken)
        {
          const ssize_t n = ::write(1, from, left);
          if (n < 0 && errno == EINTR)
            continue;
          if (n <= 0)
            broken = true; // (the rest is dropped)
          else
            from += n, left -= n;
        }
      setp(buffer, buffer + sizeof(buffer));
    }

    std::streambuf *original;
    char            buffer[4096];
    bool            broken = false;
  };

  /**
   * The thread counts of the environment that bilayer's libraries read
   * while the program is loaded, before main(): deal.II's
   * DEAL_II_NUM_THREADS (garbage or 0 end in std::terminate there, a
   * negative count is taken modulo 2^32), OMP_NUM_THREADS (libgomp warns
   * and falls back), the BLAS's own (ignored when garbage). Each must be a
   * whole number from 1 to 1024 (OMP_NUM_THREADS: a comma-separated list
   * of them; empty counts as unset except for deal.II).
   */
  const char *const      thread_variables[] = {"DEAL_II_NUM_THREADS",
                                               "OMP_NUM_THREADS",
                                               "OPENBLAS_NUM_THREADS",
                                               "GOTO_NUM_THREADS",
                                               "MKL_NUM_THREADS"};
  constexpr unsigned int n_thread_variables = 5;
  /// Per thread variable: its value if it was invalid (and hidden).
  const char *invalid_thread_count[n_thread_variables] = {};

  /// Whether the text from @p begin to @p end is a whole number from 1 to
  /// 1024 (plain C: called before the libraries are initialised).
  bool
  is_thread_count(const char *begin, const char *end)
  {
    if (end - begin < 1 || end - begin > 4)
      return false;
    int n = 0;
    for (const char *c = begin; c != end; ++c)
      if (*c < '0' || *c > '9')
        return false;
      else
        n = 10 * n + (*c - '0');
    return n >= 1 && n <= 1024;
  }

  bool
  is_valid_thread_variable(const unsigned int variable, const char *value)
  {
    if (*value == 0)
      return variable != 0; // (empty: unset, except for deal.II)
    for (const char *from = value;;)
      {
        const char *end = from;
        while (*end != 0 && !(variable == 1 && *end == ','))
          ++end;
        if (!is_thread_count(from, end))
          return false;
        if (*end == 0)
          return true;
        from = end + 1; // OpenMP: one count per nesting level, "4,2"
      }
  }

  /**
   * Runs before every shared library's initialisation (the executable's
   * preinit array): an invalid thread count is remembered and hidden from
   * the libraries (the first letter of its name replaced by '_'), so that
   * main() refuses it with one line instead of deal.II's std::terminate or
   * libgomp's warning.
   */
  void
  hide_invalid_thread_counts(int, char **, char **environment)
  {
    for (char **e = environment; e != nullptr && *e != nullptr; ++e)
      for (unsigned int v = 0; v < n_thread_variables; ++v)
        {
          const char *name = thread_variables[v];
          char       *c    = *e;
          while (*name != 0 && *c == *name)
            ++c, ++name;
          if (*name == 0 && *c == '=' && !is_valid_thread_variable(v, c + 1))
            {
              invalid_thread_count[v] = c + 1;
              (*e)[0]                 = '_';
            }
        }
  }

  __attribute__((section(".preinit_array"), used)) void (
      *const hide_invalid_thread_counts_early)(int, char **, char **) =
    &hide_invalid_thread_counts;

  /**
   * The environment that bilayer and its libraries read, checked before
   * MPI_Init (where Open MPI ends a bad TMPDIR or working directory with a
   * page of text); mistakes throw a one-line message.
   */
  void
  check_environment()
  {
    using dealii::ExcMessage;
    {
      std::vector<char> cwd(PATH_MAX + 1);
      if (::getcwd(cwd.data(), cwd.size()) == nullptr)
        {
          const int why = errno;
          AssertThrow(why != ENAMETOOLONG && why != ERANGE,
                      ExcMessage("the working directory is longer than "
                                 "PATH_MAX = " +
                                 std::to_string(PATH_MAX) +
                                 " characters, where MPI cannot start: run "
                                 "bilayer from a shorter path"));
          AssertThrow(why != ENOENT,
                      ExcMessage("the working directory has been removed: "
                                 "run bilayer from an existing directory"));
          AssertThrow(false,
                      ExcMessage(std::string("cannot read the working "
                                             "directory: ") +
                                 std::strerror(why)));
        }
    }
    // (BILAYER_BLAS_THREADS is checked where it is used.)
    for (unsigned int v = 0; v < n_thread_variables; ++v)
      {
        const char *value = invalid_thread_count[v];
        if (value == nullptr)
          {
            // (Set after loading, e.g. by a debugger: checked here.)
            value = std::getenv(thread_variables[v]);
            if (value == nullptr || is_valid_thread_variable(v, value))
              continue;
          }
        AssertThrow(false,
                    ExcMessage(
                      std::string(thread_variables[v]) +
                      " must be a whole number from 1 to 1024" +
                      (v == 1 ? " (or a comma-separated list of them)" : "") +
                      ", got '" + value + "'; set it so or unset it"));
      }
    // Open MPI keeps its session files under TMPDIR (and creates a missing
    // one, outside what the run was asked to write).
    for (const char *name : {"TMPDIR"})
      if (const char *set = std::getenv(name); set != nullptr && *set != 0)
        {
          struct stat status;
          const int   missing      = ::stat(set, &status) == 0 ? 0 : errno;
          const bool  is_directory = missing == 0 && S_ISDIR(status.st_mode);
          AssertThrow(
            is_directory && ::access(set, W_OK | X_OK) == 0,
            ExcMessage(std::string(name) + " = '" + set + "' " +
                       (is_directory ? "is a directory this user cannot write" :
                        missing == ENOENT ? "does not exist" :
                                            "is not a directory") +
                       " (MPI keeps its session files there): set " + name +
                       " to an existing, writable directory or "
                       "unset it"));
        }
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
  open_closed_standard_streams();
  TolerantOutput standard_output;
  bilayer::prepare_stop_signals();
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
      check_environment();
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
  // error report and MPI_Abort: a stopped run removes what it staged and
  // its lock, says so in one line and ends by its signal instead.
  bilayer::watch_stop_signals(reporter);
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
            std::ostringstream entries;
            prm.print_parameters(entries, ParameterHandler::ShortPRM);
            used << bilayer::applicable_entries(entries.str(), scene);
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
      // (On every process: the check is collective; the first verifies.)
      study.set_directory_check([&output]() {
        if (output)
          output->verify();
      });
      bool         passed = false;
      std::string  failure;
      unsigned int failed_cycle = 0;
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
