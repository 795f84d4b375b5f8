#include <deal.II/grid/grid_generator.h>

#include <bilayer/geometry.h>

#include <cmath>
#include <set>
#include <sstream>

namespace bilayer
{
  Geometry::Geometry(const GeometryParameters &geometry,
                     const MeshParameters     &mesh)
    : geometry(geometry)
    , mesh(mesh)
  {}


  void
  Geometry::create_meshes(const unsigned int cycle)
  {
    const unsigned int factor = 1u << cycle;
    const double       width  = geometry.x_max - geometry.x_min;
    const unsigned int n_x    = mesh.cells_along_sigma * factor;

    // The crack end points must be vertices of the uniform grid along Sigma.
    const double dx = width / n_x;
    for (const double c : {geometry.crack_start, geometry.crack_end})
      {
        const double j = (c - geometry.x_min) / dx;
        if (std::abs(j - std::round(j)) > 1e-8 * std::max(1.0, j))
          {
            std::ostringstream msg;
            msg << "Mesh/Cells along Sigma = " << mesh.cells_along_sigma
                << " does not make the crack end point x = " << c
                << " a mesh vertex: choose a number of cells for which the "
                << "spacing " << width << "/n divides " << c - geometry.x_min;
            AssertThrow(false, ExcMessage(msg.str()));
          }
      }

    for (const Subdomain s : {Subdomain::minus, Subdomain::plus})
      {
        const double       height = s == Subdomain::minus ?
                                      geometry.sigma_height - geometry.y_min :
                                      geometry.y_max - geometry.sigma_height;
        const unsigned int n_y =
          mesh.cells_across > 0 ?
            mesh.cells_across * factor :
            std::max<unsigned int>(1, std::lround(n_x * height / width));
        auto &tria = triangulations[static_cast<unsigned int>(s)];
        tria.clear();
        make_subdomain(s, n_x, n_y, tria);
      }
  }


  void
  Geometry::make_subdomain(const Subdomain    subdomain,
                           const unsigned int n_x,
                           const unsigned int n_y,
                           Triangulation<2>  &tria) const
  {
    const Point<2> p1(geometry.x_min,
                      subdomain == Subdomain::minus ? geometry.y_min :
                                                      geometry.sigma_height);
    const Point<2> p2(geometry.x_max,
                      subdomain == Subdomain::minus ? geometry.sigma_height :
                                                      geometry.y_max);
    if (mesh.shape == ElementShape::quadrilateral)
      GridGenerator::subdivided_hyper_rectangle(tria, {n_x, n_y}, p1, p2);
    else
      GridGenerator::subdivided_hyper_rectangle_with_simplices(tria,
                                                               {n_x, n_y},
                                                               p1,
                                                               p2);

    const double tol = 1e-10 * std::max(geometry.x_max - geometry.x_min,
                                        geometry.y_max - geometry.y_min);
    for (const auto &cell : tria.active_cell_iterators())
      for (const auto &face : cell->face_iterators())
        if (face->at_boundary())
          {
            const Point<2> c = face->center();
            if (std::abs(c[0] - geometry.x_min) < tol)
              face->set_boundary_id(BoundaryIds::left);
            else if (std::abs(c[0] - geometry.x_max) < tol)
              face->set_boundary_id(BoundaryIds::right);
            else if (std::abs(c[1] - geometry.y_min) < tol)
              face->set_boundary_id(BoundaryIds::bottom);
            else if (std::abs(c[1] - geometry.y_max) < tol)
              face->set_boundary_id(BoundaryIds::top);
            else
              {
                Assert(std::abs(c[1] - geometry.sigma_height) < tol,
                       ExcInternalError());
                const bool on_crack = geometry.has_crack() &&
                                      c[0] > geometry.crack_start &&
                                      c[0] < geometry.crack_end;
                face->set_boundary_id(on_crack ? BoundaryIds::crack :
                                                 BoundaryIds::glued);
              }
          }
  }


  const Triangulation<2> &
  Geometry::triangulation(const Subdomain subdomain) const
  {
    return triangulations[static_cast<unsigned int>(subdomain)];
  }


  MeshStatistics
  Geometry::statistics(const Subdomain subdomain) const
  {
    const auto    &tria = triangulation(subdomain);
    MeshStatistics stats;
    stats.vertices = tria.n_used_vertices();
    stats.cells    = tria.n_active_cells();
    stats.h_min    = std::numeric_limits<double>::max();
    stats.h_max    = 0;
    for (const auto &cell : tria.active_cell_iterators())
      for (const auto &face : cell->face_iterators())
        {
          stats.h_min = std::min(stats.h_min, face->diameter());
          stats.h_max = std::max(stats.h_max, face->diameter());
        }
    return stats;
  }


  namespace
  {
    /// Distinct vertices of the boundary faces whose id passes @p select.
    template <typename Predicate>
    std::set<std::pair<long long, long long>>
    boundary_vertices(const Triangulation<2> &tria,
                      const double            scale,
                      const Predicate        &select)
    {
      std::set<std::pair<long long, long long>> keys;
      for (const auto &cell : tria.active_cell_iterators())
        for (const auto &face : cell->face_iterators())
          if (face->at_boundary() && select(face->boundary_id()))
            for (const unsigned int v : face->vertex_indices())
              keys.emplace(std::llround(face->vertex(v)[0] * scale),
                           std::llround(face->vertex(v)[1] * scale));
      return keys;
    }
  } // namespace


  unsigned int
  Geometry::n_sigma_vertices() const
  {
    const double scale =
      1e9 / std::max(geometry.x_max - geometry.x_min, 1e-300);
    return boundary_vertices(triangulation(Subdomain::minus),
                             scale,
                             [](const types::boundary_id id) {
                               return id == BoundaryIds::glued ||
                                      id == BoundaryIds::crack;
                             })
      .size();
  }


  unsigned int
  Geometry::n_outer_vertices() const
  {
    const double scale =
      1e9 / std::max(geometry.x_max - geometry.x_min, 1e-300);
    const auto outer = [](const types::boundary_id id) {
      return id <= BoundaryIds::top;
    };
    auto keys =
      boundary_vertices(triangulation(Subdomain::minus), scale, outer);
    const auto plus =
      boundary_vertices(triangulation(Subdomain::plus), scale, outer);
    keys.insert(plus.begin(), plus.end());
    return keys.size();
  }
} // namespace bilayer
