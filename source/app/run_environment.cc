#include <deal.II/base/exceptions.h>

#include <bilayer/app/run_environment.h>

#include <algorithm>
#include <cerrno>
#include <climits>
#include <cstdlib>
#include <cstring>
#include <fcntl.h>
#include <iostream>
#include <string>
#include <sys/stat.h>
#include <unistd.h>
#include <utility>
#include <vector>

namespace bilayer
{
  namespace
  {
    /// An environment variable of the MPI launcher as a number, or -1.
    int
    launcher_number(const std::vector<const char *> &names)
    {
      for (const char *name : names)
        if (const char *value = std::getenv(name))
          return std::atoi(value);
      return -1;
    }

    /// The thread counts of the environment that are checked.
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
  } // namespace


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


  TolerantOutput::TolerantOutput()
    : original(std::cout.rdbuf())
  {
    setp(buffer, buffer + sizeof(buffer));
    std::cout.rdbuf(this);
  }


  TolerantOutput::~TolerantOutput()
  {
    sync();
    std::cout.rdbuf(original);
  }


  // Line-buffered, as the standard output on a terminal.
  TolerantOutput::int_type
  TolerantOutput::overflow(const int_type c)
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
  TolerantOutput::xsputn(const char *text, const std::streamsize n)
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
  TolerantOutput::sync()
  {
    write_out();
    return 0;
  }


  void
  TolerantOutput::write_out()
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
} // namespace bilayer
