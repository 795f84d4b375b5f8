// The Gmsh mesh of the entry Geometry/Gmsh file: a .msh file read directly
// (read_msh.cc), a .geo scene checked (scan_geo.cc) and meshed by gmsh
// (gmsh_process.cc), and the names of its boundary curves.

#include <deal.II/base/exceptions.h>
#include <deal.II/base/utilities.h>

#include <bilayer/gmsh/gmsh_file_entry.h>
#include <bilayer/gmsh/gmsh_mesh.h>
#include <bilayer/gmsh/gmsh_process.h>
#include <bilayer/gmsh/read_msh.h>

#include <algorithm>
#include <cerrno>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <set>

namespace bilayer
{
  using namespace dealii;

  std::string
  where(const std::string &file)
  {
    return "Geometry/Gmsh file '" + file + "'";
  }


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


  GmshGroupNames
  gmsh_group_names(const std::string &file, const GmshOptions &options)
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
    GmshGroupNames result;
    for (const auto &[tag, name] : names)
      result.interfaces =
        std::max(result.interfaces, gmsh_interface_number(name));
    for (const auto &[tag, name] : names)
      if (gmsh_interface_number(name) == 0 &&
          std::find(result.parts.begin(), result.parts.end(), name) ==
            result.parts.end())
        result.parts.push_back(name);
    for (const auto &[tag, name] : surfaces)
      result.surfaces.push_back(name);
    return result;
  }


  std::string
  gmsh_region_name(const unsigned int r)
  {
    return r == 0 ? "Omega-" :
           r == 1 ? "Omega+" :
                    "Region " + std::to_string(r + 1);
  }


  std::string
  gmsh_interface_name(const unsigned int i, const bool crack)
  {
    const std::string name = crack ? "crack" : "Sigma";
    return i == 0 ? name : name + " " + std::to_string(i + 1);
  }


  namespace
  {
    /// K where @p name is @p prefix, a blank and the decimal number K >= 1
    /// (no sign, no leading zero); else 0.
    unsigned int
    numbered(const std::string &name, const std::string &prefix)
    {
      if (name.size() <= prefix.size() + 1 ||
          name.compare(0, prefix.size() + 1, prefix + " ") != 0)
        return 0;
      const std::string digits = name.substr(prefix.size() + 1);
      if (digits.size() > 6 || digits[0] == '0' ||
          digits.find_first_not_of("0123456789") != std::string::npos)
        return 0;
      return std::stoul(digits);
    }
  } // namespace


  unsigned int
  gmsh_region_number(const std::string &name)
  {
    if (name == "Omega-")
      return 1;
    if (name == "Omega+")
      return 2;
    return numbered(name, "Region");
  }


  unsigned int
  gmsh_interface_number(const std::string &name)
  {
    if (name == "Sigma" || name == "crack")
      return 1;
    return std::max(numbered(name, "Sigma"), numbered(name, "crack"));
  }


  unsigned int
  gmsh_region_count(const std::vector<std::string> &surfaces)
  {
    unsigned int n = 2;
    while (std::find(surfaces.begin(), surfaces.end(), gmsh_region_name(n)) !=
           surfaces.end())
      ++n;
    return n;
  }


  std::string
  point_text(const Point<2> &p)
  {
    std::ostringstream s;
    s << "(" << p[0] << ", " << p[1] << ")";
    return s.str();
  }
} // namespace bilayer
