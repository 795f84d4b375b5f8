#include <deal.II/base/exceptions.h>
#include <deal.II/base/utilities.h>

#include <bilayer/gmsh_mesh.h>

#include <algorithm>
#include <cctype>
#include <cerrno>
#include <chrono>
#include <cmath>
#include <csignal>
#include <cstdlib>
#include <cstring>
#include <fcntl.h>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <set>
#include <sstream>
#include <sys/prctl.h>
#include <sys/wait.h>
#include <thread>
#include <unistd.h>

extern char **environ;

namespace bilayer
{
  using namespace dealii;

  namespace
  {
    std::string
    where(const std::string &file)
    {
      return "Geometry/Gmsh file '" + file + "'";
    }

    /// @p file opened for reading, refused (naming the entry) when it is
    /// missing, not a regular file or unreadable.
    std::ifstream
    open(const std::string &file)
    {
      namespace fs = std::filesystem;
      std::error_code error;
      AssertThrow(fs::is_regular_file(file, error),
                  ExcMessage(where(file) + (fs::exists(file, error) ?
                                              ": not a regular file" :
                                              ": no such file")));
      std::ifstream in(file);
      AssertThrow(in, ExcMessage(where(file) + ": " + std::strerror(errno)));
      return in;
    }

    /// Read the sections of a format-2 ASCII mesh.
    GmshMesh
    parse_msh(std::istream      &in,
              const std::string &file,
              const bool         names_only = false)
    {
      GmshMesh mesh;
      mesh.file = file;
      std::map<long, unsigned int>         node_index;
      std::vector<std::pair<long, double>> z_node;
      std::string                          line;
      bool                                 format_seen = false;
      const auto                           fail = [&](const std::string &what) {
        AssertThrow(false, ExcMessage(where(file) + ": " + what));
      };
      while (std::getline(in, line))
        {
          line = Utilities::trim(line);
          if (names_only && line == "$Nodes")
            break;
          if (line == "$MeshFormat")
            {
              double version = 0;
              int    binary  = 0;
              in >> version >> binary;
              if (!in || version < 2 || version >= 3 || binary != 0)
                fail("not a Gmsh mesh of format 2 (ASCII); write it with "
                     "'gmsh -2 -format msh2'");
              format_seen = true;
            }
          else if (line == "$PhysicalNames")
            {
              mesh.has_physical_names = true;
              unsigned int n          = 0;
              in >> n;
              for (unsigned int i = 0; i < n && in; ++i)
                {
                  int dim = 0, tag = 0;
                  in >> dim >> tag;
                  std::string rest;
                  std::getline(in, rest);
                  const auto        a = rest.find('"'), b = rest.rfind('"');
                  const std::string name = a != std::string::npos && b > a ?
                                             rest.substr(a + 1, b - a - 1) :
                                             Utilities::trim(rest);
                  auto             &names =
                    dim == 1 ? mesh.curve_names : mesh.surface_names;
                  if (dim == 1 || dim == 2)
                    {
                      for (const auto &[other, n] : names)
                        if (n == name && other != tag)
                          fail("two physical " +
                               std::string(dim == 1 ? "curves" : "surfaces") +
                               " (tags " + std::to_string(other) + " and " +
                               std::to_string(tag) + ") are named '" + name +
                               "': put all their entities into one group of "
                               "that name");
                      names[tag] = name;
                    }
                }
            }
          else if (line == "$Nodes")
            {
              unsigned int n = 0;
              in >> n;
              for (unsigned int i = 0; i < n && in; ++i)
                {
                  long   tag = 0;
                  double x = 0, y = 0, z = 0;
                  in >> tag >> x >> y >> z;
                  if (!in)
                    break;
                  if (!std::isfinite(x) || !std::isfinite(y) ||
                      !std::isfinite(z))
                    fail("node " + std::to_string(tag) + " is not finite");
                  node_index[tag] = mesh.nodes.size();
                  mesh.nodes.emplace_back(x, y);
                  z_node.emplace_back(tag, z);
                }
            }
          else if (line == "$Elements")
            {
              unsigned int n = 0;
              in >> n;
              for (unsigned int i = 0; i < n && in; ++i)
                {
                  long         tag  = 0;
                  unsigned int type = 0, n_tags = 0;
                  in >> tag >> type >> n_tags;
                  if (!in)
                    break;
                  // Physical and elementary tag, the partitions: a few.
                  if (n_tags > 1000)
                    fail("element " + std::to_string(tag) + " claims " +
                         std::to_string(n_tags) +
                         " tags (the file is corrupt: write it again with "
                         "gmsh -2 -format msh2)");
                  std::vector<int> tags(n_tags);
                  for (auto &t : tags)
                    in >> t;
                  static const std::map<unsigned int, unsigned int> n_nodes = {
                    {1, 2}, {2, 3}, {3, 4}, {15, 1}};
                  const auto it = n_nodes.find(type);
                  if (it == n_nodes.end())
                    fail("element " + std::to_string(tag) + " has Gmsh type " +
                         std::to_string(type) +
                         "; only first-order lines, triangles and "
                         "quadrilaterals are read (Mesh.ElementOrder = 1)");
                  GmshMesh::Element element;
                  element.type     = type;
                  element.physical = n_tags > 0 ? tags[0] : 0;
                  element.entity   = n_tags > 1 ? tags[1] : 0;
                  for (unsigned int k = 0; k < it->second; ++k)
                    {
                      long node = 0;
                      in >> node;
                      const auto found = node_index.find(node);
                      if (found == node_index.end())
                        fail("element " + std::to_string(tag) +
                             " refers to the missing node " +
                             std::to_string(node));
                      element.nodes.push_back(found->second);
                    }
                  if (type != 15)
                    mesh.elements.push_back(element);
                }
            }
          if (!in)
            fail("cannot read the section after '" + line + "'");
        }
      if (!format_seen)
        fail("not a Gmsh mesh (no $MeshFormat section)");
      // A 2d mesh lies in the plane z = 0 (up to round-off).
      double size = 0;
      for (const auto &p : mesh.nodes)
        size = std::max({size, std::abs(p[0]), std::abs(p[1])});
      for (const auto &[tag, z] : z_node)
        if (std::abs(z) > 1e-10 * std::max(size, 1e-300))
          {
            std::ostringstream value;
            value << z;
            fail("node " + std::to_string(tag) +
                 " lies off the plane z = 0 (z = " + value.str() +
                 "): bilayer reads plane meshes; put the geometry into z = 0");
          }
      return mesh;
    }
  } // namespace


  int
  GmshMesh::physical_tag(const unsigned int dim, const std::string &name) const
  {
    for (const auto &[tag, n] : dim == 1 ? curve_names : surface_names)
      if (n == name)
        return tag;
    return -1;
  }


  namespace
  {
    /// A token of Gmsh's script language.
    struct Token
    {
      enum class Kind
      {
        name,
        string,
        number,
        symbol
      } kind;
      std::string  text;
      unsigned int line;
      std::size_t  offset;
    };

    /// The tokens of a .geo file: comments (// and /* */) dropped, strings
    /// one token each, ">>" one symbol.
    std::vector<Token>
    tokenize(const std::string &c)
    {
      std::vector<Token> tokens;
      unsigned int       line = 1;
      for (std::size_t i = 0; i < c.size();)
        {
          const char ch = c[i];
          if (ch == '\n')
            {
              ++line;
              ++i;
            }
          else if (std::isspace(static_cast<unsigned char>(ch)))
            ++i;
          else if (c.compare(i, 2, "//") == 0)
            {
              while (i < c.size() && c[i] != '\n')
                ++i;
            }
          else if (c.compare(i, 2, "/*") == 0)
            {
              i += 2;
              while (i < c.size() && c.compare(i, 2, "*/") != 0)
                line += c[i++] == '\n';
              i = std::min(c.size(), i + 2);
            }
          else if (ch == '"')
            {
              const unsigned int first = line;
              const std::size_t  start = i;
              std::string        text;
              // Gmsh's strings have no escapes: the next " ends them.
              for (++i; i < c.size() && c[i] != '"'; ++i)
                {
                  text += c[i];
                  line += c[i] == '\n';
                }
              ++i;
              tokens.push_back({Token::Kind::string, text, first, start});
            }
          else if (std::isalpha(static_cast<unsigned char>(ch)) || ch == '_')
            {
              const std::size_t start = i;
              while (
                i < c.size() &&
                (std::isalnum(static_cast<unsigned char>(c[i])) || c[i] == '_'))
                ++i;
              tokens.push_back(
                {Token::Kind::name, c.substr(start, i - start), line, start});
            }
          else if (std::isdigit(static_cast<unsigned char>(ch)))
            {
              const std::size_t start = i;
              while (i < c.size() &&
                     (std::isalnum(static_cast<unsigned char>(c[i])) ||
                      c[i] == '.' ||
                      ((c[i] == '+' || c[i] == '-') &&
                       (c[i - 1] == 'e' || c[i - 1] == 'E'))))
                ++i;
              tokens.push_back(
                {Token::Kind::number, c.substr(start, i - start), line, start});
            }
          else
            {
              const std::size_t n = c.compare(i, 2, ">>") == 0 ? 2 : 1;
              tokens.push_back({Token::Kind::symbol, c.substr(i, n), line, i});
              i += n;
            }
        }
      return tokens;
    }

    /// The index of the token after the parenthesis that closes the one at
    /// @p open (or the end).
    std::size_t
    after_parentheses(const std::vector<Token> &t, std::size_t open)
    {
      int depth = 0;
      for (std::size_t i = open; i < t.size(); ++i)
        if (t[i].kind == Token::Kind::symbol)
          {
            depth += t[i].text == "(" ? 1 : t[i].text == ")" ? -1 : 0;
            if (depth == 0)
              return i + 1;
          }
      return t.size();
    }

    bool
    is(const std::vector<Token> &t, const std::size_t i, const char *text)
    {
      return i < t.size() && t[i].kind != Token::Kind::string &&
             t[i].text == text;
    }

    /// Why the option @p category.@p name may not be set by a scene, or "".
    std::string
    writing_option(const std::string &category, const std::string &name)
    {
      if (category == "Solver")
        return "Solver options start external solver programs";
      if (category == "Print")
        return "Print options control writing pictures";
      if (category == "General" &&
          (name.find("FileName") != std::string::npos ||
           name.rfind("Save", 0) == 0 || name.rfind("RecentFile", 0) == 0 ||
           name.rfind("Watch", 0) == 0 || name == "TextEditor" ||
           name == "WebBrowser" || name.rfind("Executable", 0) == 0))
        return "this option makes gmsh write or run files";
      return "";
    }

    struct Scan
    {
      const std::string                 &top;
      std::vector<std::filesystem::path> stack;
      std::vector<std::string>           findings;

      void
      file(const std::filesystem::path &path, const std::string &from)
      {
        namespace fs = std::filesystem;
        std::error_code error;
        const fs::path  canonical = fs::weakly_canonical(path, error);
        if (std::find(stack.begin(), stack.end(), canonical) != stack.end())
          {
            findings.push_back(from + ": includes '" + path.string() +
                               "' again inside itself (an endless Include)");
            return;
          }
        std::ifstream in(path);
        if (!fs::is_regular_file(path, error) || !in)
          {
            findings.push_back(from + ": cannot read the included file '" +
                               path.string() + "'");
            return;
          }
        std::stringstream text;
        text << in.rdbuf();
        stack.push_back(canonical);
        statements(path, text.str());
        stack.pop_back();
      }

      void
      statements(const std::filesystem::path &path, const std::string &c)
      {
        const std::vector<Token> t     = tokenize(c);
        const auto               where = [&](const std::size_t i) {
          std::string text = c.substr(t[i].offset, 60);
          text = text.substr(0, text.find_first_of(";\n"));
          return path.string() + ":" + std::to_string(t[i].line) + ": '" +
                 Utilities::trim(text) + "'";
        };
        for (std::size_t i = 0; i < t.size(); ++i)
          {
            // (A name after '.' is an option's or a plugin's.)
            if (t[i].kind != Token::Kind::name || (i > 0 && is(t, i - 1, ".")))
              continue;
            const std::string                              &k = t[i].text;
            static const std::map<std::string, std::string> commands = {
              {"SystemCall", "runs a shell command"},
              {"NonBlockingSystemCall", "runs a shell command"},
              {"System", "runs a shell command"},
              {"OnelabRun", "runs a ONELAB client program"},
              {"Save", "writes a file"},
              {"Print", "writes a picture file"},
              {"SendToServer", "sends data to a ONELAB server"},
              {"CreateDir", "creates a directory"},
              {"RemoveDir", "removes a directory"},
              {"CreateFile", "creates a file"},
              {"DeleteFile", "deletes a file"},
              {"RenameFile", "renames a file"},
              {"ShapeFromFile", "loads a CAD file"},
              {"MergeWithBoundingBox", "loads another file"},
              {"ExternalProcess",
               "runs an external program (a mesh size field)"},
              {"Solver", "Solver options start external solver programs"}};
            const auto command = commands.find(k);
            if (command != commands.end())
              findings.push_back(where(i) + " " + command->second);
            else if (k == "Delete" && i + 1 < t.size() &&
                     (t[i + 1].text == "File" || t[i + 1].text == "Dir" ||
                      t[i + 1].text == "Directory"))
              findings.push_back(where(i) + " deletes a file");
            else if ((k == "Printf" || k == "Sprintf") && is(t, i + 1, "("))
              {
                const std::size_t j = after_parentheses(t, i + 1);
                if (is(t, j, ">") || is(t, j, ">>"))
                  findings.push_back(where(i) + " writes a file");
              }
            else if (k == "Plugin" && is(t, i + 1, "("))
              {
                const std::size_t j = after_parentheses(t, i + 1);
                if (is(t, j, ".") && is(t, j + 1, "Run"))
                  findings.push_back(where(i) +
                                     " runs a plugin (plugins may write "
                                     "files)");
              }
            else if (k == "Include" || k == "Merge")
              {
                if (i + 2 < t.size() && t[i + 1].kind == Token::Kind::string &&
                    is(t, i + 2, ";"))
                  {
                    std::filesystem::path included(t[i + 1].text);
                    if (included.is_relative())
                      included = path.parent_path() / included;
                    if (k == "Include" || included.extension() == ".geo")
                      file(included, where(i));
                    else
                      findings.push_back(where(i) + " loads another file");
                  }
                else
                  findings.push_back(where(i) +
                                     " has a computed path, which cannot "
                                     "be checked; write the file name as a "
                                     "literal string");
              }
            else if ((k == "General" || k == "Print" || k == "Solver") &&
                     is(t, i + 1, ".") && i + 2 < t.size())
              {
                const std::string why = writing_option(k, t[i + 2].text);
                if (!why.empty())
                  findings.push_back(where(i) + ": " + why);
              }
          }
      }
    };
  } // namespace


  void
  scan_geo(const std::string &file, const bool allow_commands)
  {
    open(file);
    if (allow_commands)
      return;
    Scan scan{file, {}, {}};
    scan.file(file, file);
    AssertThrow(
      scan.findings.empty(),
      ExcMessage(where(file) + ": " + scan.findings.front() +
                 (scan.findings.size() > 1 ?
                    " (and " + std::to_string(scan.findings.size() - 1) +
                      " more such statements)" :
                    std::string()) +
                 "; a scene file may not run programs, write, rename or delete "
                 "files or load files bilayer cannot check: remove it, or run "
                 "bilayer with --allow-gmsh-commands if you trust the file "
                 "(docs/geometry.md)"));
  }


  namespace
  {
    /// The signal that stopped bilayer while gmsh ran, or 0.
    volatile std::sig_atomic_t stop_signal = 0;

    extern "C" void
    remember_stop(int signal)
    {
      stop_signal = signal;
    }

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

    /// A directory of our own, removed with everything in it at the end.
    class TemporaryDirectory
    {
    public:
      explicit TemporaryDirectory(const std::string &file)
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
      ~TemporaryDirectory()
      {
        std::error_code error;
        std::filesystem::remove_all(path, error);
      }
      std::filesystem::path path;
    };

    /**
     * Run gmsh on the scene @p file followed by bilayer's script @p post in
     * @p directory (working directory and HOME, stdin /dev/null, its output
     * into gmsh.log), as a child in a process group of its own that dies
     * with bilayer, within @p options.time_limit seconds. SIGINT, SIGTERM
     * and SIGHUP while it runs stop it, remove the directory and end
     * bilayer by the signal.
     */
    void
    run_gmsh(const std::string        &file,
             const std::string        &post,
             const TemporaryDirectory &directory,
             const GmshOptions        &options,
             const std::string        &doing)
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
      std::vector<char *>      argv;
      for (auto &a : arguments)
        argv.push_back(a.data());
      argv.push_back(nullptr);
      // The environment with HOME (gmsh's option and session files) in the
      // directory.
      std::vector<std::string> environment;
      for (char **e = environ; *e != nullptr; ++e)
        if (std::strncmp(*e, "HOME=", 5) != 0)
          environment.emplace_back(*e);
      environment.push_back("HOME=" + directory.path.string());
      std::vector<char *> envp;
      for (auto &e : environment)
        envp.push_back(e.data());
      envp.push_back(nullptr);
      const std::string dir = directory.path.string();
      const std::string log = (directory.path / "gmsh.log").string();

      // Stop signals are remembered while gmsh runs.
      stop_signal = 0;
      struct sigaction remember, previous[3];
      std::memset(&remember, 0, sizeof(remember));
      remember.sa_handler = remember_stop;
      sigemptyset(&remember.sa_mask);
      const int stops[3] = {SIGINT, SIGTERM, SIGHUP};
      // (Signals the caller ignores stay ignored.)
      for (unsigned int k = 0; k < 3; ++k)
        {
          sigaction(stops[k], nullptr, &previous[k]);
          if (previous[k].sa_handler != SIG_IGN)
            sigaction(stops[k], &remember, nullptr);
        }
      const auto restore = [&]() {
        for (unsigned int k = 0; k < 3; ++k)
          sigaction(stops[k], &previous[k], nullptr);
      };

      const pid_t parent = getpid();
      const pid_t child  = fork();
      if (child == 0)
        {
          setpgid(0, 0);
          prctl(PR_SET_PDEATHSIG, SIGKILL);
          if (getppid() != parent)
            _exit(127);
          for (const int s : stops)
            signal(s, SIG_DFL);
          const int in = ::open("/dev/null", O_RDONLY);
          const int out =
            ::open(log.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0600);
          if (in < 0 || out < 0 || chdir(dir.c_str()) != 0)
            _exit(126);
          dup2(in, 0);
          dup2(out, 1);
          dup2(out, 2);
          execvpe("gmsh", argv.data(), envp.data());
          _exit(127);
        }
      if (child < 0)
        {
          restore();
          AssertThrow(false,
                      ExcMessage(where(file) + ": cannot start gmsh: " +
                                 std::strerror(errno)));
        }
      setpgid(child, child);

      using clock            = std::chrono::steady_clock;
      const auto start       = clock::now();
      auto       next_report = std::chrono::seconds(10);
      int        status      = 0;
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
      // Whatever gmsh started in its group goes with it.
      kill(-child, SIGKILL);
      restore();
      if (stop_signal != 0)
        {
          const int s = stop_signal;
          std::filesystem::remove_all(directory.path, error);
          raise(s);
          AssertThrow(false,
                      ExcMessage(where(file) + ": interrupted by signal " +
                                 std::to_string(s) + " while gmsh ran"));
        }
      AssertThrow(!timed_out,
                  ExcMessage(where(file) + ": gmsh was stopped after " +
                             Utilities::to_string(options.time_limit) +
                             " s (Mesh/Gmsh time limit): raise the limit for "
                             "a large mesh, or look for an endless loop in "
                             "the scene"));

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
      AssertThrow(problem.empty(),
                  ExcMessage(where(file) + ": " +
                             (doing == "meshing" ? "meshing failed: " :
                                                   "gmsh failed: ") +
                             problem));
    }

    /// Bilayer's settings after the scene's: meshes of format 2.2 ASCII.
    const char *const msh_settings =
      "Mesh.Binary = 0;\nMesh.MshFileVersion = 2.2;\nMesh.Format = 1;\n"
      "Mesh.SaveAll = 0;\nMesh.SaveParametric = 0;\n"
      "Mesh.SaveElementTagType = 1;\nMesh.PartitionSplitMeshFiles = 0;\n";

    /// The mesh gmsh wrote to @p path, or a message that it wrote none.
    GmshMesh
    read_written(const std::string           &file,
                 const std::filesystem::path &path,
                 const bool                   names_only = false)
    {
      std::error_code error;
      AssertThrow(std::filesystem::is_regular_file(path, error),
                  ExcMessage(where(file) +
                             ": gmsh ended without error but wrote no mesh "
                             "(does the scene stop early, with Exit or "
                             "Abort?)"));
      std::ifstream in(path);
      GmshMesh      mesh = parse_msh(in, file, names_only);
      mesh.file          = file;
      return mesh;
    }
  } // namespace


  GmshMesh
  read_gmsh(const std::string &file, const GmshOptions &options)
  {
    namespace fs                = std::filesystem;
    std::ifstream     in        = open(file);
    const std::string extension = fs::path(file).extension().string();
    AssertThrow(extension == ".geo" || extension == ".msh",
                ExcMessage(where(file) +
                           ": must be a .geo or a .msh file (Gmsh)"));
    if (extension == ".msh")
      return parse_msh(in, file);

    // Mesh the geometry with gmsh in a directory of its own: the groups,
    // then every cell (Mesh.SaveAll: physical tag 0, elementary tags).
    scan_geo(file, options.allow_commands);
    const TemporaryDirectory directory(file);
    const fs::path           groups = directory.path / "groups.msh",
                   all              = directory.path / "all.msh";
    run_gmsh(file,
             std::string(msh_settings) +
               "Mesh.ElementOrder = 1;\nMesh 2;\nSetOrder 1;\nSave \"" +
               groups.string() + "\";\nMesh.SaveAll = 1;\nSave \"" +
               all.string() + "\";\n",
             directory,
             options,
             "meshing");
    GmshMesh       mesh = read_written(file, all);
    const GmshMesh with = read_written(file, groups);
    // A physical group is a set of entities: the groups of each cell and
    // line are those of its entity, one element per group as in a .msh
    // file of format 2, physical tag 0 for a cell in none.
    std::map<std::pair<unsigned int, int>, std::set<int>> physicals;
    for (const auto &e : with.elements)
      physicals[{e.type == 1 ? 1 : 2, e.entity}].insert(e.physical);
    std::vector<GmshMesh::Element> elements;
    for (const auto &e : mesh.elements)
      {
        const auto found = physicals.find({e.type == 1 ? 1 : 2, e.entity});
        if (found == physicals.end())
          {
            if (e.type != 1)
              elements.push_back(e);
            continue;
          }
        for (const int p : found->second)
          {
            elements.push_back(e);
            elements.back().physical = p;
          }
      }
    mesh.elements = std::move(elements);
    return mesh;
  }


  std::vector<std::string>
  gmsh_boundary_names(const std::string &file, const GmshOptions &options)
  {
    std::ifstream              in = open(file);
    std::map<int, std::string> names, surfaces;
    if (std::filesystem::path(file).extension() == ".msh")
      {
        const GmshMesh mesh = parse_msh(in, file);
        names               = mesh.curve_names;
        surfaces            = mesh.surface_names;
      }
    else if (std::filesystem::path(file).extension() != ".geo")
      return {};
    else
      {
        // The groups of the model gmsh builds (no mesh).
        scan_geo(file, options.allow_commands);
        const TemporaryDirectory directory(file);
        const auto               path = directory.path / "names.msh";
        run_gmsh(file,
                 std::string(msh_settings) + "Save \"" + path.string() +
                   "\";\n",
                 directory,
                 options,
                 "reading the groups of");
        const GmshMesh mesh = read_written(file, path, true);
        names               = mesh.curve_names;
        surfaces            = mesh.surface_names;
      }
    AssertThrow(!names.empty() || !surfaces.empty(),
                ExcMessage(
                  where(file) + ": no named physical groups" +
                  (std::filesystem::path(file).extension() == ".msh" ?
                     " (no $PhysicalNames section)" :
                     "") +
                  ": bilayer reads the specimen's parts by "
                  "name, Physical Surface(\"Omega-\"), (\"Omega+\"), "
                  "Physical Curve(\"Sigma\"), ... (docs/geometry.md)"));
    std::vector<std::string> result;
    for (const auto &[tag, name] : names)
      if (name != "Sigma" && name != "crack" &&
          std::find(result.begin(), result.end(), name) == result.end())
        result.push_back(name);
    return result;
  }
} // namespace bilayer
