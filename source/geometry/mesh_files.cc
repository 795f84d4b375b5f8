// Mesh/Mesh files: the meshes of the two subdomains read from files, and
// the checks of their cells and boundaries.

#include <deal.II/grid/grid_in.h>
#include <deal.II/grid/grid_tools.h>

#include <bilayer/geometry/geometry.h>

#include <algorithm>
#include <cerrno>
#include <cmath>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <sstream>

namespace bilayer
{
  using namespace dealii;

  void
  Geometry::read_subdomain(const Subdomain    subdomain,
                           const std::string &pattern,
                           Triangulation<2>  &tria) const
  {
    std::string file = pattern;
    const auto  at   = file.find("{side}");
    AssertThrow(at != std::string::npos,
                ExcMessage("Mesh/Mesh files: '" + pattern +
                           "' must contain {side} (minus or plus)"));
    file.replace(at, 6, subdomain == Subdomain::minus ? "minus" : "plus");
    std::error_code error;
    const auto      status = std::filesystem::status(file, error);
    AssertThrow(std::filesystem::is_regular_file(status),
                ExcMessage("Mesh/Mesh files: cannot open '" + file + "': " +
                           (std::filesystem::exists(status) ?
                              "not a regular file" :
                              "no such file")));
    std::ifstream in(file);
    AssertThrow(in,
                ExcMessage("Mesh/Mesh files: cannot open '" + file +
                           "': " + std::strerror(errno)));
    GridIn<2> grid_in;
    grid_in.attach_triangulation(tria);
    try
      {
        grid_in.read_msh(in);
      }
    catch (const ExceptionBase &e)
      {
        AssertThrow(false,
                    ExcMessage("Mesh/Mesh files: cannot read '" + file +
                               "' as a Gmsh mesh: " + one_line_message(e)));
      }
    catch (const std::exception &e)
      {
        AssertThrow(false,
                    ExcMessage("Mesh/Mesh files: cannot read '" + file +
                               "' as a Gmsh mesh: " + e.what()));
      }
    AssertThrow(!in.bad(),
                ExcMessage("Mesh/Mesh files: reading '" + file +
                           "' failed: " + std::strerror(errno)));
    check_cells(tria, subdomain, file);

    // The mesh must fill its subdomain.
    const double y0 =
      subdomain == Subdomain::minus ? geometry.y_min : geometry.sigma_height;
    const double y1 =
      subdomain == Subdomain::minus ? geometry.sigma_height : geometry.y_max;
    double area = 0;
    for (const auto &cell : tria.active_cell_iterators())
      area += cell->measure();
    const double expected = (geometry.x_max - geometry.x_min) * (y1 - y0);
    Point<2>     lower(std::numeric_limits<double>::max(),
                   std::numeric_limits<double>::max());
    Point<2>     upper = -lower;
    for (const auto &v : tria.get_vertices())
      for (unsigned int d = 0; d < 2; ++d)
        {
          lower[d] = std::min(lower[d], v[d]);
          upper[d] = std::max(upper[d], v[d]);
        }
    const double       tol = 1e-8 * expected;
    std::ostringstream region;
    region << "(" << geometry.x_min << ", " << geometry.x_max << ") x (" << y0
           << ", " << y1 << ")";
    AssertThrow(std::abs(area - expected) < tol &&
                  lower.distance(Point<2>(geometry.x_min, y0)) < 1e-8 &&
                  upper.distance(Point<2>(geometry.x_max, y1)) < 1e-8,
                ExcMessage("Mesh/Mesh files: '" + file + "' does not fill " +
                           region.str() + " (Geometry)"));
    assign_boundary_ids(tria, static_cast<unsigned int>(subdomain));
  }


  void
  Geometry::check_cells(const Triangulation<2> &tria,
                        const Subdomain         subdomain,
                        const std::string      &file) const
  {
    const double y0 =
      subdomain == Subdomain::minus ? geometry.y_min : geometry.sigma_height;
    const double y1 =
      subdomain == Subdomain::minus ? geometry.sigma_height : geometry.y_max;
    const double size = std::max(geometry.x_max - geometry.x_min, y1 - y0);
    const auto   at   = [](const Point<2> &p) {
      std::ostringstream s;
      s << "(" << p[0] << ", " << p[1] << ")";
      return s.str();
    };
    AssertThrow(tria.n_active_cells() > 0,
                ExcMessage("Mesh/Mesh files: '" + file + "' has no cells"));
    for (const auto &cell : tria.active_cell_iterators())
      {
        // Signed area (shoelace) over the vertices in the order of the
        // cell's boundary: inverted or degenerate cells are broken meshes.
        const unsigned int              n = cell->n_vertices();
        const std::vector<unsigned int> order =
          n == 3 ? std::vector<unsigned int>{0, 1, 2} :
                   std::vector<unsigned int>{0, 1, 3, 2};
        double area = 0, diameter = 0;
        for (unsigned int i = 0; i < n; ++i)
          {
            const Point<2> &a = cell->vertex(order[i]);
            const Point<2> &b = cell->vertex(order[(i + 1) % n]);
            AssertThrow(std::isfinite(a[0]) && std::isfinite(a[1]),
                        ExcMessage("Mesh/Mesh files: '" + file +
                                   "' has a vertex that is not finite"));
            area += a[0] * b[1] - a[1] * b[0];
            diameter = std::max(diameter, a.distance(b));
          }
        AssertThrow(!degenerate_cell(area / 2, diameter),
                    ExcMessage("Mesh/Mesh files: '" + file +
                               "' has an inverted or degenerate cell at " +
                               at(cell->center())));
        // Boundary faces may lie only on the subdomain's four sides: any
        // other is a slit or a hole.
        for (const auto &face : cell->face_iterators())
          if (face->at_boundary())
            {
              const double tol = 1e-8 * size;
              const auto   on  = [&](const unsigned int d, const double v) {
                return std::abs(face->vertex(0)[d] - v) < tol &&
                       std::abs(face->vertex(1)[d] - v) < tol;
              };
              AssertThrow(on(0, geometry.x_min) || on(0, geometry.x_max) ||
                            on(1, y0) || on(1, y1),
                          ExcMessage("Mesh/Mesh files: '" + file +
                                     "' has a boundary face inside its "
                                     "subdomain at " +
                                     at(face->center()) +
                                     " (a slit, a hole or cells that do not "
                                     "share their faces)"));
            }
      }
  }
} // namespace bilayer
