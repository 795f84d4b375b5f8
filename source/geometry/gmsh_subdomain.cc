// Gmsh scenes: the subdomain meshes built from the cells of the physical
// surfaces, with their boundary ids and manifolds.

#include <deal.II/grid/grid_tools.h>
#include <deal.II/grid/manifold_lib.h>

#include <bilayer/geometry/geometry.h>

#include <algorithm>
#include <cmath>
#include <map>
#include <sstream>

namespace bilayer
{
  using namespace dealii;

  namespace
  {

    /// The cells of one physical surface with vertices of their own.
    struct SurfaceCells
    {
      std::vector<Point<2>>    vertices;
      std::vector<CellData<2>> cells;
      /// The Gmsh node of each vertex.
      std::vector<unsigned int> node_of;
      bool                      triangles = false, quads = false;
    };


    /// The cells of the physical surface @p tag, their vertices numbered in
    /// the order they first appear, each with the material id of its ply
    /// group in @p ply_cells (by sorted Gmsh nodes; 0 where in none).
    SurfaceCells
    surface_cells(
      const GmshMesh                                                &g,
      const int                                                      tag,
      const std::map<std::vector<unsigned int>, types::material_id> &ply_cells)
    {
      SurfaceCells                         surface;
      std::map<unsigned int, unsigned int> vertex_of;
      auto                                &node_of  = surface.node_of;
      auto                                &vertices = surface.vertices;
      for (const auto &e : g.elements)
        if ((e.type == 2 || e.type == 3) && e.physical == tag)
          {
            CellData<2> cell(e.nodes.size());
            // Gmsh's quadrilateral runs around the cell, deal.II's is
            // lexicographic.
            const std::vector<unsigned int> order =
              e.type == 3 ? std::vector<unsigned int>{0, 1, 3, 2} :
                            std::vector<unsigned int>{0, 1, 2};
            for (unsigned int k = 0; k < e.nodes.size(); ++k)
              {
                const auto [it, added] =
                  vertex_of.emplace(e.nodes[order[k]], vertices.size());
                if (added)
                  {
                    vertices.push_back(g.nodes[e.nodes[order[k]]]);
                    node_of.push_back(e.nodes[order[k]]);
                  }
                cell.vertices[k] = it->second;
              }
            // The ply group of the cell (0: none).
            if (!ply_cells.empty())
              {
                std::vector<unsigned int> key = e.nodes;
                std::sort(key.begin(), key.end());
                const auto ply   = ply_cells.find(key);
                cell.material_id = ply != ply_cells.end() ? ply->second : 0;
              }
            surface.triangles = surface.triangles || e.type == 2;
            surface.quads     = surface.quads || e.type == 3;
            surface.cells.push_back(cell);
          }
      return surface;
    }


    /// Refuse a surface with both kinds of cells, or with a kind that
    /// Mesh/Refinement or Mesh/Element shape excludes.
    void
    check_cell_kind(const SurfaceCells   &surface,
                    const MeshParameters &mesh,
                    const std::string    &name,
                    const std::string    &where)
    {
      const bool triangles = surface.triangles, quads = surface.quads;
      AssertThrow(!(triangles && quads),
                  ExcMessage(where + ": '" + name +
                             "' mixes triangles and quadrilaterals; use one "
                             "kind (Recombine Surface for quadrilaterals)"));
      AssertThrow(quads || mesh.refinement == Refinement::global,
                  ExcMessage("Mesh/Refinement = adaptive needs "
                             "quadrilaterals, but " +
                             where +
                             " has triangles (Recombine Surface in the .geo; "
                             "deal.II 9.4 refines triangle meshes only "
                             "globally)"));
      AssertThrow((mesh.shape == ElementShape::triangle) == triangles,
                  ExcMessage(
                    "Mesh/Element shape = " +
                    std::string(triangles ? "quadrilaterals" : "triangles") +
                    ", but " + where + " has " +
                    (triangles ? "triangles" : "quadrilaterals")));
    }


    /// Refuse degenerate cells and turn inverted ones around, so that all
    /// cells are positive.
    void
    orient_cells(SurfaceCells      &surface,
                 const std::string &name,
                 const std::string &where)
    {
      const auto &vertices = surface.vertices;
      // Degenerate cells are broken meshes; inverted ones are only
      // oriented the other way: each is turned around on its own (vertices 1
      // and 2 swapped: a triangle's order reversed, a quadrilateral's
      // lexicographic order mirrored), so that all cells are positive.
      for (auto &cell : surface.cells)
        {
          const unsigned int              n = cell.vertices.size();
          const std::vector<unsigned int> around =
            n == 3 ? std::vector<unsigned int>{0, 1, 2} :
                     std::vector<unsigned int>{0, 1, 3, 2};
          double area = 0, diameter = 0;
          for (unsigned int i = 0; i < n; ++i)
            {
              const Point<2> &a = vertices[cell.vertices[around[i]]];
              const Point<2> &b = vertices[cell.vertices[around[(i + 1) % n]]];
              area += a[0] * b[1] - a[1] * b[0];
              diameter = std::max(diameter, a.distance(b));
            }
          AssertThrow(!degenerate_cell(std::abs(area) / 2, diameter),
                      ExcMessage(where + ": '" + name +
                                 "' has a degenerate cell at " +
                                 point_text(vertices[cell.vertices[0]])));
          if (area < 0)
            std::swap(cell.vertices[1], cell.vertices[2]);
        }
    }


    /// A polar manifold on @p tria around the centre of each circular curve
    /// of @p arc_centres: the manifold id of each curve's entity.
    std::map<int, types::manifold_id>
    set_arc_manifolds(const std::map<int, Point<2>> &arc_centres,
                      Triangulation<2>              &tria)
    {
      std::map<int, types::manifold_id> manifold_of;
      for (const auto &[entity, centre] : arc_centres)
        {
          const types::manifold_id id = 1 + manifold_of.size();
          manifold_of[entity]         = id;
          tria.set_manifold(id, PolarManifold<2>(centre));
        }
      return manifold_of;
    }


    /// Boundary ids and manifold ids of the boundary faces of @p tria from
    /// the line elements on them (vertex i of @p tria is Gmsh node
    /// @p node_of[i]); whether a face lies on a clamped part.
    bool
    assign_line_ids(const GmshMesh                          &g,
                    const std::vector<std::string>          &part_names,
                    const std::vector<bool>                 &clamped,
                    const std::vector<unsigned int>         &node_of,
                    const std::map<int, types::manifold_id> &manifold_of,
                    Triangulation<2>                        &tria)
    {
      std::map<GmshEdge, const GmshMesh::Element *> lines;
      for (const auto &e : g.elements)
        if (e.type == 1)
          lines[gmsh_edge(e.nodes[0], e.nodes[1])] = &e;
      // The interface of each interface curve's physical tag.
      std::map<int, unsigned int> interface_of;
      for (const auto &[tag, name] : g.curve_names)
        if (const unsigned int k = gmsh_interface_number(name); k > 0)
          interface_of[tag] = k - 1;
      bool clamped_part = false;
      for (const auto &cell : tria.active_cell_iterators())
        for (const auto &face : cell->face_iterators())
          if (face->at_boundary())
            {
              const auto found =
                lines.find(gmsh_edge(node_of[face->vertex_index(0)],
                                     node_of[face->vertex_index(1)]));
              if (found == lines.end())
                {
                  face->set_boundary_id(BoundaryIds::free);
                  continue;
                }
              const GmshMesh::Element &line = *found->second;
              if (const auto i = interface_of.find(line.physical);
                  i != interface_of.end())
                face->set_boundary_id(BoundaryIds::interface(i->second));
              else if (g.curve_names.count(line.physical) > 0)
                {
                  const auto        &names = part_names;
                  const unsigned int part =
                    std::find(names.begin(),
                              names.end(),
                              g.curve_names.at(line.physical)) -
                    names.begin();
                  face->set_boundary_id(part);
                  clamped_part = clamped_part || clamped[part];
                }
              else
                face->set_boundary_id(BoundaryIds::free);
              if (manifold_of.count(line.entity) > 0)
                face->set_manifold_id(manifold_of.at(line.entity));
            }
      return clamped_part;
    }
  } // namespace


  void
  Geometry::make_gmsh_subdomain(const unsigned int region,
                                Triangulation<2>  &tria) const
  {
    const GmshMesh   &g     = *gmsh;
    const std::string where = "Geometry/Gmsh file '" + geometry.gmsh_file + "'";
    const std::string name  = gmsh_region_name(region);
    const int         tag   = g.physical_tag(2, name);
    SurfaceCells      surface = surface_cells(g, tag, ply_cells);
    check_cell_kind(surface, mesh, name, where);
    orient_cells(surface, name, where);
    if (surface.quads)
      GridTools::consistently_order_cells(surface.cells);
    try
      {
        tria.create_triangulation(surface.vertices,
                                  surface.cells,
                                  SubCellData());
      }
    catch (const ExceptionBase &e)
      {
        AssertThrow(false,
                    ExcMessage(
                      where + ": the cells of '" + name +
                      "' do not form a valid mesh: " + one_line_message(e)));
      }

    // Boundary ids and manifolds from the line elements.
    const std::map<int, types::manifold_id> manifold_of =
      set_arc_manifolds(arc_centres, tria);
    // (A region without a clamped part floats: docs/floating.md.)
    assign_line_ids(g,
                    geometry.parts.names,
                    geometry.clamped,
                    surface.node_of,
                    manifold_of,
                    tria);
  }
} // namespace bilayer
