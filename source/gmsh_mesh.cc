#include <deal.II/base/exceptions.h>
#include <deal.II/base/utilities.h>

#include <bilayer/gmsh_mesh.h>

#include <cctype>
#include <cerrno>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <unistd.h>

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

    /// Quote a path for the shell.
    std::string
    quoted(const std::string &path)
    {
      std::string q = "'";
      for (const char c : path)
        q += c == '\'' ? std::string("'\\''") : std::string(1, c);
      return q + "'";
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
    parse_msh(std::istream &in, const std::string &file)
    {
      GmshMesh mesh;
      mesh.file = file;
      std::map<long, unsigned int> node_index;
      std::string                  line;
      bool                         format_seen = false;
      const auto                   fail        = [&](const std::string &what) {
        AssertThrow(false, ExcMessage(where(file) + ": " + what));
      };
      while (std::getline(in, line))
        {
          line = Utilities::trim(line);
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
              unsigned int n = 0;
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
                  (dim == 1 ? mesh.curve_names : mesh.surface_names)[tag] =
                    name;
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
                  if (!std::isfinite(x) || !std::isfinite(y))
                    fail("node " + std::to_string(tag) + " is not finite");
                  node_index[tag] = mesh.nodes.size();
                  mesh.nodes.emplace_back(x, y);
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


  GmshMesh
  read_gmsh(const std::string &file, const double size_factor)
  {
    namespace fs = std::filesystem;
    std::error_code   error;
    std::ifstream     in        = open(file);
    const std::string extension = fs::path(file).extension().string();
    AssertThrow(extension == ".geo" || extension == ".msh",
                ExcMessage(where(file) +
                           ": must be a .geo or a .msh file (Gmsh)"));
    if (extension == ".msh")
      return parse_msh(in, file);

    // Mesh the geometry with the gmsh command in a directory of our own.
    std::string pattern =
      (fs::temp_directory_path(error) / "bilayer-gmsh-XXXXXX").string();
    std::vector<char> buffer(pattern.begin(), pattern.end());
    buffer.push_back('\0');
    AssertThrow(mkdtemp(buffer.data()) != nullptr,
                ExcMessage(where(file) +
                           ": cannot create a temporary directory: " +
                           std::strerror(errno)));
    const fs::path     directory(buffer.data());
    const std::string  msh = (directory / "mesh.msh").string();
    const std::string  log = (directory / "gmsh.log").string();
    std::ostringstream command;
    command.precision(17);
    command << "gmsh -2 -format msh2 -clscale " << size_factor << " -o "
            << quoted(msh) << " " << quoted(file) << " > " << quoted(log)
            << " 2>&1";
    const int   status = std::system(command.str().c_str());
    GmshMesh    mesh;
    std::string problem;
    if (status != 0 || !fs::is_regular_file(msh, error))
      {
        // The first error line of gmsh's log.
        std::ifstream in(log);
        std::string   line;
        while (std::getline(in, line))
          if (line.find("Error") != std::string::npos)
            {
              problem = Utilities::trim(line);
              break;
            }
        if (problem.empty())
          problem =
            WIFEXITED(status) && WEXITSTATUS(status) == 127 ?
              "the gmsh command is missing (Debian: apt-get install "
              "gmsh)" :
              "gmsh failed (exit status " + std::to_string(status) + ")";
      }
    else
      try
        {
          std::ifstream in(msh);
          mesh      = parse_msh(in, file);
          mesh.file = file;
        }
      catch (const ExceptionBase &e)
        {
          problem = e.what();
        }
    fs::remove_all(directory, error);
    AssertThrow(problem.empty(),
                ExcMessage(where(file) + ": meshing failed: " + problem));
    return mesh;
  }


  std::vector<std::string>
  gmsh_boundary_names(const std::string &file)
  {
    std::ifstream              in = open(file);
    std::map<int, std::string> names;
    if (std::filesystem::path(file).extension() == ".msh")
      names = parse_msh(in, file).curve_names;
    else
      {
        // Physical Curve("name", tag) = {...}; or Physical Line("name").
        std::stringstream text;
        text << in.rdbuf();
        const std::string c     = text.str();
        int               order = 1 << 20;
        const auto        blank = [&](std::size_t i) {
          while (i < c.size() && std::isspace(static_cast<unsigned char>(c[i])))
            ++i;
          return i;
        };
        for (std::size_t at = c.find("Physical"); at != std::string::npos;
             at             = c.find("Physical", at + 8))
          {
                        std::size_t i = blank(at + 8);
                        if (c.compare(i, 5, "Curve") == 0)
              i += 5;
            else if (c.compare(i, 4, "Line") == 0)
              i += 4;
            else
              continue;
            i = blank(i);
                        if (i >= c.size() || c[i] != '(')
              continue;
            i = blank(i + 1);
                        if (i >= c.size() || c[i] != '"')
              continue;
            const std::size_t close = c.find('"', i + 1);
                        if (close == std::string::npos)
              continue;
            const std::string name = c.substr(i + 1, close - i - 1);
                        i                      = blank(close + 1);
                        int tag                = order++;
                        if (i < c.size() && c[i] == ',')
              {
                            i             = blank(i + 1);
                            std::size_t j = i;
                            while (j < c.size() && j < i + 9 &&
                       std::isdigit(static_cast<unsigned char>(c[j])))
                  ++j;
                if (j > i)
                  tag = std::stoi(c.substr(i, j - i));
              }
                        names[tag] = name;
          }
      }
    std::vector<std::string> result;
    for (const auto &[tag, name] : names)
      if (name != "Sigma" && name != "crack" &&
          std::find(result.begin(), result.end(), name) == result.end())
        result.push_back(name);
    return result;
  }
} // namespace bilayer
