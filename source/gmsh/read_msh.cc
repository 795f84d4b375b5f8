// Reading a mesh of Gmsh's format 2 (ASCII): its sections $MeshFormat,
// $PhysicalNames, $Nodes and $Elements, and the check that it is plane.

#include <deal.II/base/exceptions.h>
#include <deal.II/base/utilities.h>

#include <bilayer/gmsh/gmsh_file_entry.h>
#include <bilayer/gmsh/read_msh.h>

#include <algorithm>
#include <cmath>
#include <map>
#include <sstream>
#include <utility>

namespace bilayer
{
  using namespace dealii;

  namespace
  {
    /// Throw the message @p what about the mesh of @p file.
    void
    fail(const std::string &file, const std::string &what)
    {
      AssertThrow(false, ExcMessage(where(file) + ": " + what));
    }

    /// Read the body of $MeshFormat: a version 2.x, ASCII.
    void
    read_mesh_format(std::istream &in, const std::string &file)
    {
      double version = 0;
      int    binary  = 0;
      in >> version >> binary;
      if (!in || version < 2 || version >= 3 || binary != 0)
        fail(file,
             "not a Gmsh mesh of format 2 (ASCII); write it with "
             "'gmsh -2 -format msh2'");
    }

    /// Read the body of $PhysicalNames: the names of the curve and surface
    /// groups, each name given to one group only.
    void
    read_physical_names(std::istream      &in,
                        const std::string &file,
                        GmshMesh          &mesh)
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
          auto &names = dim == 1 ? mesh.curve_names : mesh.surface_names;
          if (dim == 1 || dim == 2)
            {
              for (const auto &[other, n] : names)
                if (n == name && other != tag)
                  fail(file,
                       "two physical " +
                         std::string(dim == 1 ? "curves" : "surfaces") +
                         " (tags " + std::to_string(other) + " and " +
                         std::to_string(tag) + ") are named '" + name +
                         "': put all their entities into one group of "
                         "that name");
              names[tag] = name;
            }
        }
    }

    /// Read the body of $Nodes: the points (x, y) of @p mesh, the index of
    /// each node tag in @p node_index and its z coordinate in @p z_node.
    void
    read_nodes(std::istream                         &in,
               const std::string                    &file,
               GmshMesh                             &mesh,
               std::map<long, unsigned int>         &node_index,
               std::vector<std::pair<long, double>> &z_node)
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
          if (!std::isfinite(x) || !std::isfinite(y) || !std::isfinite(z))
            fail(file, "node " + std::to_string(tag) + " is not finite");
          node_index[tag] = mesh.nodes.size();
          mesh.nodes.emplace_back(x, y);
          z_node.emplace_back(tag, z);
        }
    }

    /// Read the body of $Elements: the lines, triangles and quadrilaterals
    /// of @p mesh with their tags and node indices (points are skipped).
    void
    read_elements(std::istream                       &in,
                  const std::string                  &file,
                  GmshMesh                           &mesh,
                  const std::map<long, unsigned int> &node_index)
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
            fail(file,
                 "element " + std::to_string(tag) + " claims " +
                   std::to_string(n_tags) +
                   " tags (the file is corrupt: write it again with "
                   "gmsh -2 -format msh2)");
          std::vector<int> tags(n_tags);
          for (auto &t : tags)
            in >> t;
          static const std::map<unsigned int, unsigned int> n_nodes = {{1, 2},
                                                                       {2, 3},
                                                                       {3, 4},
                                                                       {15, 1}};
          const auto it = n_nodes.find(type);
          if (it == n_nodes.end())
            fail(file,
                 "element " + std::to_string(tag) + " has Gmsh type " +
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
                fail(file,
                     "element " + std::to_string(tag) +
                       " refers to the missing node " + std::to_string(node));
              element.nodes.push_back(found->second);
            }
          if (type != 15)
            mesh.elements.push_back(element);
        }
    }

    /// Refuse a node of @p z_node off the plane z = 0 (relative to the size
    /// of the mesh).
    void
    check_plane(const std::string                          &file,
                const GmshMesh                             &mesh,
                const std::vector<std::pair<long, double>> &z_node)
    {
      // A 2d mesh lies in the plane z = 0 (up to round-off).
      double size = 0;
      for (const auto &p : mesh.nodes)
        size = std::max({size, std::abs(p[0]), std::abs(p[1])});
      for (const auto &[tag, z] : z_node)
        if (std::abs(z) > 1e-10 * std::max(size, 1e-300))
          {
            std::ostringstream value;
            value << z;
            fail(
              file,
              "node " + std::to_string(tag) +
                " lies off the plane z = 0 (z = " + value.str() +
                "): bilayer reads plane meshes; put the geometry into z = 0");
          }
    }
  } // namespace


  GmshMesh
  parse_msh(std::istream &in, const std::string &file, const bool names_only)
  {
    GmshMesh mesh;
    mesh.file = file;
    std::map<long, unsigned int>         node_index;
    std::vector<std::pair<long, double>> z_node;
    std::string                          line;
    bool                                 format_seen = false;
    while (std::getline(in, line))
      {
        line = Utilities::trim(line);
        if (names_only && line == "$Nodes")
          break;
        if (line == "$MeshFormat")
          {
            read_mesh_format(in, file);
            format_seen = true;
          }
        else if (line == "$PhysicalNames")
          read_physical_names(in, file, mesh);
        else if (line == "$Nodes")
          read_nodes(in, file, mesh, node_index, z_node);
        else if (line == "$Elements")
          read_elements(in, file, mesh, node_index);
        if (!in)
          fail(file, "cannot read the section after '" + line + "'");
      }
    if (!format_seen)
      fail(file, "not a Gmsh mesh (no $MeshFormat section)");
    check_plane(file, mesh, z_node);
    return mesh;
  }
} // namespace bilayer
