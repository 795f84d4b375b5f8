#include <deal.II/base/exceptions.h>
#include <deal.II/base/parameter_handler.h>

#include <bilayer/app/check_geometry.h>
#include <bilayer/geometry/geometry.h>
#include <bilayer/gmsh/gmsh_mesh.h>
#include <bilayer/parameters/parameter_overrides.h>
#include <bilayer/parameters/parameters.h>

#include <iomanip>
#include <map>
#include <sstream>

namespace bilayer
{
  using namespace dealii;

  namespace
  {
    /// A point as "(x, y)", six significant digits.
    std::string
    at(const Point<2> &p)
    {
      std::ostringstream s;
      s << std::setprecision(6) << "(" << p[0] + 0.0 << ", " << p[1] + 0.0
        << ")";
      return s.str();
    }


    /// The Mesh section with the --set assignments @p overrides applied.
    MeshParameters
    mesh_parameters(const std::vector<std::string> &overrides)
    {
      ParameterHandler prm;
      MeshParameters::declare_parameters(prm);
      apply_overrides(prm, overrides);
      MeshParameters mesh;
      mesh.parse_parameters(prm);
      return mesh;
    }


    /// The physical groups of @p g with their elements; whether its cells
    /// are triangles.
    bool
    print_groups(const GmshMesh &g, std::ostream &out)
    {
      std::map<std::pair<unsigned int, int>, unsigned int> elements;
      bool                                                 triangles = false;
      for (const auto &e : g.elements)
        {
          const bool cell = e.type == 2 || e.type == 3;
          ++elements[{cell ? 2u : 1u, e.physical}];
          triangles = triangles || e.type == 2;
        }
      out << "physical groups (dim tag name: elements):\n";
      for (const unsigned int dim : {1u, 2u})
        for (const auto &[tag, name] :
             dim == 1 ? g.curve_names : g.surface_names)
          out << "  " << dim << " " << tag << " \"" << name
              << "\": " << elements[{dim, tag}] << "\n";
      return triangles;
    }


    /// The names of the boundary parts of @p parts with a face at the
    /// point @p p of the meshes of @p geometry, quoted ("'left'").
    std::string
    parts_at(const Geometry      &geometry,
             const Point<2>      &p,
             const BoundaryParts &parts)
    {
      std::string names;
      for (const unsigned int r : Layout::indices(geometry.n_regions()))
        for (const auto &face :
             geometry.triangulation(r).active_face_iterators())
          if (face->at_boundary() && !on_sigma(face) &&
              face->boundary_id() < parts.size())
            for (const unsigned int v : face->vertex_indices())
              if (face->vertex(v).distance(p) <= 1e-10 * face->diameter())
                {
                  const std::string name =
                    "'" + parts.names[face->boundary_id()] + "'";
                  if (names.find(name) == std::string::npos)
                    names += (names.empty() ? "" : ", ") + name;
                }
      return names.empty() ? "(none: traction free)" : names;
    }


    /// Interface @p i (Sigma: 0) with its crack pieces.
    void
    print_interface(const Geometry      &geometry,
                    const BoundaryParts &parts,
                    const unsigned int   i,
                    std::ostream        &out)
    {
      const InterfaceCurve &curve = geometry.interface_curves()[i];
      const std::string     name =
        i == 0 ?
              std::string("Sigma") :
              "interface " + std::to_string(i + 1) + " ('" +
            gmsh_interface_name(i, false) + "', between '" +
            gmsh_region_name(geometry.interface_regions()[i][0]) + "' and '" +
            gmsh_region_name(geometry.interface_regions()[i][1]) + "')";
      out << name << " (with the crack): " << curve.description() << ", from "
          << at(curve.point(curve.s_begin())) << " to "
          << at(curve.point(curve.s_end())) << "\n";
      const auto &cracks = curve.crack().pieces();
      out << (i == 0 ? "crack" : "crack of interface " + std::to_string(i + 1))
          << ": " << cracks.size()
          << (cracks.size() == 1 ? " piece" : " pieces") << "\n";
      for (const auto &piece : cracks)
        {
          out << "  piece " << at(curve.point(piece.start)) << " -- "
              << at(curve.point(piece.end)) << ": length "
              << std::setprecision(6) << piece.end - piece.start;
          // An edge crack: its mouth on the outer boundary (no tip there),
          // its one tip at the other end.
          const bool mouth_at_start = curve.crack().mouth(piece.start);
          if (mouth_at_start || curve.crack().mouth(piece.end))
            {
              const Point<2> mouth =
                curve.point(mouth_at_start ? piece.start : piece.end);
              out << "; edge crack: its mouth " << at(mouth)
                  << " lies on the boundary part(s) "
                  << parts_at(geometry, mouth, parts)
                  << " (no tip there; a run must not clamp them), its tip "
                  << at(curve.point(mouth_at_start ? piece.end : piece.start));
            }
          out << "\n";
        }
    }


    /// Cells, the interfaces, their crack pieces and the boundary parts of
    /// the meshes of cycle 0.
    void
    print_meshes(const Geometry      &geometry,
                 const BoundaryParts &parts,
                 const bool           triangles,
                 std::ostream        &out)
    {
      const char *kind = triangles ? " triangles" : " quadrilaterals";
      out << "cells:";
      for (const unsigned int r : Layout::indices(geometry.n_regions()))
        out << (r > 0 ? ", " : " ") << gmsh_region_name(r) << " "
            << geometry.triangulation(r).n_active_cells() << kind;
      out << "\n";
      for (const unsigned int i :
           Layout::indices(geometry.interface_curves().size()))
        print_interface(geometry, parts, i, out);
      // Edges of each boundary part (in all region meshes).
      std::map<types::boundary_id, unsigned int> edges;
      for (const unsigned int r : Layout::indices(geometry.n_regions()))
        for (const auto &face :
             geometry.triangulation(r).active_face_iterators())
          if (face->at_boundary())
            ++edges[face->boundary_id()];
      out << "boundary parts (name: edges):\n";
      for (unsigned int i = 0; i < parts.size(); ++i)
        out << "  \"" << parts.names[i] << "\": " << edges[i] << "\n";
      out << "  unnamed (traction free): " << edges[BoundaryIds::free] << "\n";
    }
  } // namespace


  void
  check_geometry(const std::string              &file,
                 const std::vector<std::string> &overrides,
                 const bool                      allow_gmsh_commands,
                 std::ostream                   &out)
  {
    MeshParameters mesh = mesh_parameters(overrides);
    GmshOptions    options;
    options.allow_commands = allow_gmsh_commands;
    options.time_limit     = mesh.gmsh_time_limit;
    options.size_factor    = mesh.gmsh_size_factor;

    GeometryParameters geometry;
    geometry.gmsh_file = file;
    geometry.parts =
      BoundaryParts::of_gmsh(file, gmsh_group_names(file, options));
    // Every part clamped but those at the mouth of an edge crack (named
    // in the report: a run must leave them free).
    geometry.clamped.assign(geometry.parts.size(), true);
    geometry.free_parts_at_crack_mouths = true;
    geometry.allow_gmsh_commands        = allow_gmsh_commands;

    // The groups as Gmsh writes them, and the kind of cells the scene has
    // (which Mesh/Element shape a run must state).
    std::ostringstream report;
    const GmshMesh     g         = read_gmsh(file, options);
    const bool         triangles = print_groups(g, report);
    mesh.shape =
      triangles ? ElementShape::triangle : ElementShape::quadrilateral;
    // The physical surfaces other than the regions: plies that a scene
    // may name in Materials/Layer k/Ply groups (checked as such).
    std::vector<std::string> plies;
    for (const auto &[tag, name] : g.surface_names)
      if (gmsh_region_number(name) == 0)
        plies.push_back(name);
    if (!plies.empty())
      {
        report << "ply groups (for Materials/Layer k/Ply groups):";
        for (const std::string &name : plies)
          report << " '" << name << "'";
        report << "\n";
      }
    Geometry meshes(geometry, mesh, {}, plies);
    meshes.create_meshes(0);
    print_meshes(meshes, geometry.parts, triangles, report);
    out << report.str() << "PASS" << std::endl;
  }
} // namespace bilayer
