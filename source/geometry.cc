#include <deal.II/grid/grid_generator.h>
#include <deal.II/grid/grid_in.h>

#include <bilayer/geometry.h>

#include <cerrno>
#include <cmath>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <set>
#include <sstream>

namespace bilayer
{
  using namespace dealii;

  Geometry::Geometry(const GeometryParameters &geometry,
                     const MeshParameters     &mesh)
    : geometry(geometry)
    , mesh(mesh)
  {
    // The rectangle's Sigma: the horizontal segment, s = x, nu = (0, 1);
    // its ends lie on Gamma_D where the left or right side is clamped.
    curve = InterfaceCurve::segment({geometry.x_min, geometry.sigma_height},
                                    {geometry.x_max, geometry.sigma_height});
    curve.set_crack(geometry.crack());
    curve.set_ends_on_gamma_d(
      {{geometry.clamped[static_cast<unsigned int>(Side::left)],
        geometry.clamped[static_cast<unsigned int>(Side::right)]}});
  }


  void
  Geometry::create_meshes(const unsigned int cycle)
  {
    if (!mesh.mesh_files.empty())
      {
        const unsigned int n     = mesh.mesh_files.size();
        const unsigned int entry = std::min(cycle, n - 1);
        for (const Subdomain s : {Subdomain::minus, Subdomain::plus})
          {
            auto &tria = triangulations[static_cast<unsigned int>(s)];
            tria.clear();
            read_subdomain(s, mesh.mesh_files[entry], tria);
            if (cycle > entry)
              tria.refine_global(cycle - entry);
          }
      }
    else
      {
        const unsigned int factor = 1u << cycle;
        const double       width  = geometry.x_max - geometry.x_min;
        for (const Subdomain s : {Subdomain::minus, Subdomain::plus})
          {
            const unsigned int n_x =
              (s == Subdomain::plus && mesh.cells_along_sigma_plus > 0 ?
                 mesh.cells_along_sigma_plus :
                 mesh.cells_along_sigma) *
              factor;
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

    check_crack_vertices();
  }


  void
  Geometry::refine(const std::array<Vector<float>, 2> &indicators)
  {
    // One threshold over the cells of both subdomains.
    std::vector<float> all;
    for (const auto &v : indicators)
      all.insert(all.end(), v.begin(), v.end());
    std::sort(all.begin(), all.end(), std::greater<float>());
    float threshold = all.empty() ? 0.f : all.front();
    if (mesh.marking == Marking::fixed_number)
      {
        const std::size_t n = std::max<std::size_t>(
          1, std::lround(mesh.refinement_fraction * all.size()));
        threshold = all[std::min(n, all.size()) - 1];
      }
    else
      {
        double total = 0, sum = 0;
        for (const float e : all)
          total += double(e) * e;
        for (const float e : all)
          {
            threshold = e;
            sum += double(e) * e;
            if (sum >= mesh.refinement_fraction * total)
              break;
          }
      }
    for (const Subdomain s : {Subdomain::minus, Subdomain::plus})
      {
        auto        &tria = triangulations[static_cast<unsigned int>(s)];
        const auto  &eta  = indicators[static_cast<unsigned int>(s)];
        unsigned int i    = 0;
        for (const auto &cell : tria.active_cell_iterators())
          if (eta[i++] >= threshold && threshold > 0)
            cell->set_refine_flag();
        tria.execute_coarsening_and_refinement();
      }
    check_crack_vertices();
  }


  void
  Geometry::check_crack_vertices() const
  {
    // The crack end points must be mesh vertices: no face on Sigma may
    // straddle one.
    for (const Subdomain s : {Subdomain::minus, Subdomain::plus})
      for (const auto &cell : triangulation(s).active_cell_iterators())
        for (const auto &face : cell->face_iterators())
          if (face->at_boundary() &&
              (face->boundary_id() == BoundaryIds::glued ||
               face->boundary_id() == BoundaryIds::crack))
            for (const double c : {geometry.crack_start, geometry.crack_end})
              {
                const double x0 =
                  std::min(face->vertex(0)[0], face->vertex(1)[0]);
                const double x1 =
                  std::max(face->vertex(0)[0], face->vertex(1)[0]);
                const double tol = 1e-8 * (x1 - x0);
                if (geometry.has_crack() && x0 + tol < c && c < x1 - tol)
                  {
                    std::ostringstream msg;
                    if (mesh.mesh_files.empty())
                      {
                        const bool plus = s == Subdomain::plus &&
                                          mesh.cells_along_sigma_plus > 0;
                        msg
                          << "Mesh/Cells along Sigma"
                          << (plus ?
                                " on the plus side = " +
                                  std::to_string(mesh.cells_along_sigma_plus) :
                                " = " + std::to_string(mesh.cells_along_sigma))
                          << " does not make the crack end point x = " << c
                          << " a mesh vertex";
                        const auto valid = valid_cells_along_sigma(5);
                        if (valid.empty())
                          msg << "; no number of cells up to 100000 does: "
                                 "move the crack end points";
                        else
                          {
                            msg << "; numbers of cells that do:";
                            for (const unsigned int n : valid)
                              msg << " " << n;
                          }
                      }
                    else
                      msg << "Mesh/Mesh files: the crack end point x = " << c
                          << " is not a vertex of the mesh of Omega"
                          << (s == Subdomain::minus ? "-" : "+");
                    AssertThrow(false, ExcMessage(msg.str()));
                  }
              }
  }


  std::vector<unsigned int>
  Geometry::valid_cells_along_sigma(const unsigned int how_many) const
  {
    std::vector<unsigned int> valid;
    const double              width = geometry.x_max - geometry.x_min;
    for (unsigned int n = 1; n <= 100000 && valid.size() < how_many; ++n)
      {
        bool ok = true;
        for (const double c : {geometry.crack_start, geometry.crack_end})
          {
            const double k = (c - geometry.x_min) / width * n;
            ok = ok && std::abs(k - std::round(k)) < 1e-8 * std::max(1., k);
          }
        if (ok)
          valid.push_back(n);
      }
    return valid;
  }


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
    assign_boundary_ids(tria);
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
        double area = 0;
        for (unsigned int i = 0; i < n; ++i)
          {
            const Point<2> &a = cell->vertex(order[i]);
            const Point<2> &b = cell->vertex(order[(i + 1) % n]);
            AssertThrow(std::isfinite(a[0]) && std::isfinite(a[1]),
                        ExcMessage("Mesh/Mesh files: '" + file +
                                   "' has a vertex that is not finite"));
            area += a[0] * b[1] - a[1] * b[0];
          }
        AssertThrow(area / 2 > 1e-12 * size * size,
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
    assign_boundary_ids(tria);
  }


  void
  Geometry::assign_boundary_ids(Triangulation<2> &tria) const
  {
    const CrackSet crack = geometry.crack();
    const double   tol   = 1e-10 * std::max(geometry.x_max - geometry.x_min,
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
                face->set_boundary_id(crack.contains(c[0]) ?
                                        BoundaryIds::crack :
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
