// Running the gmsh command: its temporary directory, its command line and
// environment, the child process and its group, the time limit, the stop
// signals, and the problem its log and exit status report.

#include <deal.II/base/exceptions.h>
#include <deal.II/base/utilities.h>

#include <bilayer/gmsh/gmsh_file_entry.h>
#include <bilayer/gmsh/gmsh_process.h>

#include <cerrno>
#include <chrono>
#include <csignal>
#include <cstdlib>
#include <cstring>
#include <fcntl.h>
#include <fstream>
#include <iostream>
#include <sstream>
#include <sys/prctl.h>
#include <sys/wait.h>
#include <thread>
#include <unistd.h>
#include <vector>

extern char **environ;

namespace bilayer
{
  using namespace dealii;

  namespace
  {
    /// The signal that stopped bilayer while gmsh ran, or 0.
    volatile std::sig_atomic_t stop_signal = 0;

    extern "C" void
    remember_stop(int signal)
    {
      stop_signal = signal;
    }

    /// The signals that stop gmsh and end bilayer.
    const int stops[3] = {SIGINT, SIGTERM, SIGHUP};

    /// Whether this process reports (the first of an MPI job).
    bool
    first_process()
    {
      for (const char *name : {"OMPI_COMM_WORLD_RANK",
                               "PMIX_RANK",
                               "PMI_RANK",
                               "MV2_COMM_WORLD_RANK"})
        if (const char *value = std::getenv(name))
          return std::atoi(value) == 0;
      return true;
    }

    /// Write bilayer's script @p post into @p directory as bilayer.geo.
    std::filesystem::path
    write_script(const std::string        &file,
                 const std::string        &post,
                 const TemporaryDirectory &directory)
    {
      namespace fs          = std::filesystem;
      const fs::path script = directory.path / "bilayer.geo";
      {
        std::ofstream out(script);
        out << post;
        AssertThrow(out,
                    ExcMessage(where(file) + ": cannot write '" +
                               script.string() + "'"));
      }
      return script;
    }

    /// The command line of gmsh: the scene @p file (absolute), then
    /// @p script, the mesh sizes scaled by @p options.size_factor.
    std::vector<std::string>
    gmsh_arguments(const std::string           &file,
                   const std::filesystem::path &script,
                   const GmshOptions           &options)
    {
      namespace fs = std::filesystem;
      std::error_code    error;
      const std::string  scene = fs::absolute(file, error).string();
      std::ostringstream factor;
      factor.precision(17);
      factor << options.size_factor;
      std::vector<std::string> arguments = {"gmsh",
                                            "-parse_and_exit",
                                            "-nopopup",
                                            "-clscale",
                                            factor.str(),
                                            scene,
                                            script.string()};
      return arguments;
    }

    /// The environment of gmsh: bilayer's, with HOME (gmsh's option and
    /// session files) in @p directory.
    std::vector<std::string>
    gmsh_environment(const TemporaryDirectory &directory)
    {
      std::vector<std::string> environment;
      for (char **e = environ; *e != nullptr; ++e)
        if (std::strncmp(*e, "HOME=", 5) != 0)
          environment.emplace_back(*e);
      environment.push_back("HOME=" + directory.path.string());
      return environment;
    }

    /// Pointers to @p strings followed by a null pointer, as execvpe()
    /// takes its arguments and environment.
    std::vector<char *>
    null_terminated(std::vector<std::string> &strings)
    {
      std::vector<char *> pointers;
      for (auto &s : strings)
        pointers.push_back(s.data());
      pointers.push_back(nullptr);
      return pointers;
    }

    /// Remember the stop signals from now on (signals the caller ignores
    /// stay ignored); their actions before go into @p previous.
    void remember_stops(struct sigaction (&previous)[3])
    {
      // Stop signals are remembered while gmsh runs.
      stop_signal = 0;
      struct sigaction remember;
      std::memset(&remember, 0, sizeof(remember));
      remember.sa_handler = remember_stop;
      sigemptyset(&remember.sa_mask);
      // (Signals the caller ignores stay ignored.)
      for (unsigned int k = 0; k < 3; ++k)
        {
          sigaction(stops[k], nullptr, &previous[k]);
          if (previous[k].sa_handler != SIG_IGN)
            sigaction(stops[k], &remember, nullptr);
        }
    }

    /// Give the stop signals their actions @p previous again.
    void
    restore_stops(const struct sigaction (&previous)[3])
    {
      for (unsigned int k = 0; k < 3; ++k)
        sigaction(stops[k], &previous[k], nullptr);
    }

    /// In the child of @p parent: a process group of its own that dies
    /// with @p parent, the stop signals at their defaults, stdin /dev/null,
    /// stdout and stderr into @p log, working directory @p dir; then gmsh
    /// (exit status 126 when this fails, 127 when gmsh cannot be started).
    [[noreturn]] void
    exec_gmsh(const pid_t          parent,
              std::vector<char *> &argv,
              std::vector<char *> &envp,
              const std::string   &dir,
              const std::string   &log)
    {
      setpgid(0, 0);
      prctl(PR_SET_PDEATHSIG, SIGKILL);
      if (getppid() != parent)
        _exit(127);
      for (const int s : stops)
        signal(s, SIG_DFL);
      const int in  = ::open("/dev/null", O_RDONLY);
      const int out = ::open(log.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0600);
      if (in < 0 || out < 0 || chdir(dir.c_str()) != 0)
        _exit(126);
      dup2(in, 0);
      dup2(out, 1);
      dup2(out, 2);
      execvpe("gmsh", argv.data(), envp.data());
      _exit(127);
    }

    /// Start gmsh (exec_gmsh()) as a child in a process group of its own;
    /// when it cannot be started, the stop signals get their actions
    /// @p previous again and the message names @p file.
    pid_t
    start_gmsh(const std::string   &file,
               std::vector<char *> &argv,
               std::vector<char *> &envp,
               const std::string   &dir,
               const std::string   &log,
               const struct sigaction (&previous)[3])
    {
      const pid_t parent = getpid();
      const pid_t child  = fork();
      if (child == 0)
        exec_gmsh(parent, argv, envp, dir, log);
      if (child < 0)
        {
          restore_stops(previous);
          AssertThrow(false,
                      ExcMessage(where(file) + ": cannot start gmsh: " +
                                 std::strerror(errno)));
        }
      setpgid(child, child);
      return child;
    }

    /// Wait for gmsh, the process @p child, until it ends (its wait status
    /// into @p status), a stop signal comes or @p options.time_limit
    /// passes (it is killed then), reporting every 30 s after the first
    /// 10 s that it is still @p doing @p file. Whether the time limit
    /// stopped it.
    bool
    wait_for_gmsh(const pid_t        child,
                  const std::string &file,
                  const GmshOptions &options,
                  const std::string &doing,
                  int               &status)
    {
      using clock            = std::chrono::steady_clock;
      const auto start       = clock::now();
      auto       next_report = std::chrono::seconds(10);
      bool       timed_out   = false;
      for (;;)
        {
          const pid_t done = waitpid(child, &status, WNOHANG);
          if (done == child || (done < 0 && errno != EINTR))
            break;
          const auto elapsed = clock::now() - start;
          if (stop_signal != 0 ||
              elapsed > std::chrono::duration<double>(options.time_limit))
            {
              timed_out = stop_signal == 0;
              kill(-child, SIGKILL);
              kill(child, SIGKILL);
              while (waitpid(child, &status, 0) < 0 && errno == EINTR)
                ;
              break;
            }
          if (elapsed >= next_report)
            {
              if (first_process())
                std::cout << "bilayer: gmsh is still " << doing << " '" << file
                          << "' ("
                          << std::chrono::duration_cast<std::chrono::seconds>(
                               elapsed)
                               .count()
                          << " s of Mesh/Gmsh time limit = "
                          << options.time_limit << " s)" << std::endl;
              next_report += std::chrono::seconds(30);
            }
          std::this_thread::sleep_for(std::chrono::milliseconds(20));
        }
      return timed_out;
    }

    /// Remove @p directory and end bilayer by the stop signal that came
    /// while gmsh ran (the message, naming @p file, when it does not end).
    void
    end_by_stop_signal(const std::string        &file,
                       const TemporaryDirectory &directory)
    {
      const int       s = stop_signal;
      std::error_code error;
      std::filesystem::remove_all(directory.path, error);
      raise(s);
      AssertThrow(false,
                  ExcMessage(where(file) + ": interrupted by signal " +
                             std::to_string(s) + " while gmsh ran"));
    }

    /// What went wrong in gmsh's run with the wait status @p status: a
    /// missing command, a signal, the first error line of its log @p log or
    /// its exit status; "" when nothing did.
    std::string
    gmsh_problem(const std::string &log, const int status)
    {
      std::string problem;
      {
        // The first error line of gmsh's log.
        std::ifstream in(log);
        std::string   line;
        while (std::getline(in, line))
          if (line.rfind("Error", 0) == 0)
            {
              problem = Utilities::trim(line);
              break;
            }
      }
      if (WIFEXITED(status) && WEXITSTATUS(status) == 127)
        problem = "the gmsh command is missing (Debian: apt-get install "
                  "gmsh), or it cannot be started";
      else if (WIFSIGNALED(status))
        problem = "gmsh was killed by signal " +
                  std::to_string(WTERMSIG(status)) +
                  (problem.empty() ? "" : " after '" + problem + "'");
      else if (problem.empty() && WEXITSTATUS(status) != 0)
        problem = "gmsh failed (exit status " +
                  std::to_string(WEXITSTATUS(status)) + ")";
      return problem;
    }
  } // namespace


  TemporaryDirectory::TemporaryDirectory(const std::string &file)
  {
    namespace fs = std::filesystem;
    std::error_code error;
    std::string     pattern =
      (fs::temp_directory_path(error) / "bilayer-gmsh-XXXXXX").string();
    std::vector<char> buffer(pattern.begin(), pattern.end());
    buffer.push_back('\0');
    AssertThrow(mkdtemp(buffer.data()) != nullptr,
                ExcMessage(where(file) +
                           ": cannot create a temporary directory: " +
                           std::strerror(errno) + " (set TMPDIR)"));
    path = fs::path(buffer.data());
    AssertThrow(path.string().find_first_of("\"\\") == std::string::npos,
                ExcMessage(where(file) + ": the temporary directory '" +
                           path.string() +
                           "' has a quote or backslash in its name: set "
                           "TMPDIR to another directory"));
  }


  TemporaryDirectory::~TemporaryDirectory()
  {
    std::error_code error;
    std::filesystem::remove_all(path, error);
  }


  void
  run_gmsh(const std::string        &file,
           const std::string        &post,
           const TemporaryDirectory &directory,
           const GmshOptions        &options,
           const std::string        &doing)
  {
    const std::filesystem::path script = write_script(file, post, directory);
    std::vector<std::string> arguments = gmsh_arguments(file, script, options);
    std::vector<char *>      argv      = null_terminated(arguments);
    std::vector<std::string> environment = gmsh_environment(directory);
    std::vector<char *>      envp        = null_terminated(environment);
    const std::string        dir         = directory.path.string();
    const std::string        log = (directory.path / "gmsh.log").string();

    struct sigaction previous[3];
    remember_stops(previous);
    const pid_t child     = start_gmsh(file, argv, envp, dir, log, previous);
    int         status    = 0;
    const bool  timed_out = wait_for_gmsh(child, file, options, doing, status);
    // Whatever gmsh started in its group goes with it.
    kill(-child, SIGKILL);
    restore_stops(previous);
    if (stop_signal != 0)
      end_by_stop_signal(file, directory);
    AssertThrow(!timed_out,
                ExcMessage(where(file) + ": gmsh was stopped after " +
                           Utilities::to_string(options.time_limit) +
                           " s (Mesh/Gmsh time limit): raise the limit for "
                           "a large mesh, or look for an endless loop in "
                           "the scene"));

    const std::string problem = gmsh_problem(log, status);
    AssertThrow(problem.empty(),
                ExcMessage(
                  where(file) + ": " +
                  (doing == "meshing" ? "meshing failed: " : "gmsh failed: ") +
                  problem));
  }
} // namespace bilayer
