#include <deal.II/grid/grid_generator.h>
#include <deal.II/grid/grid_in.h>
#include <deal.II/grid/grid_tools.h>
#include <deal.II/grid/manifold_lib.h>

#include <bilayer/geometry.h>

#include <algorithm>
#include <cerrno>
#include <cmath>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <optional>
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
    // its ends lie on Gamma_D where the left or right side is clamped (a
    // side spans both subdomains, so an end is clamped on both or neither).
    curve = InterfaceCurve::segment({geometry.x_min, geometry.sigma_height},
                                    {geometry.x_max, geometry.sigma_height});
    curve.set_crack(geometry.crack());
    const std::array<bool, 2> ends = {
      {geometry.clamped[static_cast<unsigned int>(Side::left)],
       geometry.clamped[static_cast<unsigned int>(Side::right)]}};
    curve.set_clamped_ends({{ends, ends}});
  }


  void
  Geometry::create_meshes(const unsigned int cycle)
  {
    if (!geometry.gmsh_file.empty())
      {
        // Meshed once by Gmsh, then refined by deal.II (the arcs stay on
        // their circles through the polar manifolds).
        if (!gmsh)
          load_gmsh();
        for (const Subdomain s : {Subdomain::minus, Subdomain::plus})
          {
            auto &tria = triangulations[static_cast<unsigned int>(s)];
            tria.clear();
            make_gmsh_subdomain(s, tria);
            if (cycle > 0)
              tria.refine_global(cycle);
          }
        return;
      }
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
  Geometry::refine(const std::array<Vector<double>, 2> &indicators,
                   const std::vector<PointResolution>  &resolve)
  {
    // The indicators divided by a power of two of the largest (exact), in
    // single precision: in (0, 1], ties as among the float indicators.
    double largest = 0;
    for (const auto &v : indicators)
      for (const double e : v)
        AssertThrow(std::isfinite(e),
                    ExcMessage("Mesh/Refinement = adaptive: an error "
                               "indicator is not finite, so no cells can be "
                               "marked"));
    for (const auto &v : indicators)
      if (v.size() > 0)
        largest = std::max(largest, v.linfty_norm());
    int exponent = 0;
    if (largest > 0)
      std::frexp(largest, &exponent);
    std::array<std::vector<float>, 2> relative;
    for (unsigned int k = 0; k < 2; ++k)
      for (const double e : indicators[k])
        relative[k].push_back(float(std::ldexp(e, -exponent)));

    // One threshold over the cells of both subdomains.
    std::vector<float> all;
    for (const auto &v : relative)
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
        const auto  &eta  = relative[static_cast<unsigned int>(s)];
        unsigned int i    = 0;
        for (const auto &cell : tria.active_cell_iterators())
          {
            if (eta[i++] >= threshold && threshold > 0)
              cell->set_refine_flag();
            for (const PointResolution &p : resolve)
              if (cell_size(cell) * (1 - 1e-9) > p.size)
                for (const unsigned int v : cell->vertex_indices())
                  if ((cell->vertex(v) - p.point).norm() <=
                      1e-8 * cell->diameter())
                    cell->set_refine_flag();
          }
        tria.execute_coarsening_and_refinement();
      }
    check_crack_vertices();
  }


  void
  Geometry::check_crack_vertices() const
  {
    // Gmsh scenes: the crack tips are vertices of the file's mesh.
    if (gmsh)
      return;
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
                        msg << " (or Mesh/Fit crack tips = true)";
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
    if (mesh.fit_crack_tips && geometry.has_crack())
      fit_crack_tips(n_x, tria);
    assign_boundary_ids(tria);
  }


  void
  Geometry::fit_crack_tips(const unsigned int n_x, Triangulation<2> &tria) const
  {
    // Knots of a piecewise linear map of x: the ends of Sigma stay, the
    // vertex column nearest to each crack end point inside Omega moves
    // onto it (neighbouring columns where two would share one).
    const double        width = geometry.x_max - geometry.x_min;
    const double        h     = width / n_x;
    std::vector<double> tips;
    for (const double c : {geometry.crack_start, geometry.crack_end})
      if (c > geometry.x_min + 1e-10 * width &&
          c < geometry.x_max - 1e-10 * width)
        tips.push_back(c);
    // Columns 1 ... n_x - 1 lie inside Sigma (0 and n_x are its ends): a
    // tip within half a cell of an end takes the column next to it, tips
    // within half a cell of each other take neighbouring columns.
    AssertThrow(n_x >= tips.size() + 1,
                ExcMessage("Mesh/Fit crack tips: Mesh/Cells along Sigma = " +
                           std::to_string(n_x) + " has " +
                           std::to_string(n_x > 0 ? n_x - 1 : 0) +
                           " vertices inside Sigma for " +
                           std::to_string(tips.size()) +
                           " crack end points; allowed: at least " +
                           std::to_string(tips.size() + 1)));
    std::vector<long> column(tips.size());
    for (unsigned int i = 0; i < tips.size(); ++i)
      column[i] = std::max(std::lround((tips[i] - geometry.x_min) / h),
                           i > 0 ? column[i - 1] + 1 : 1l);
    for (unsigned int i = tips.size(); i-- > 0;)
      column[i] =
        std::min(column[i],
                 i + 1 < tips.size() ? column[i + 1] - 1 : long(n_x) - 1);
    Assert(tips.empty() || (column[0] >= 1 && column.back() < long(n_x)),
           ExcInternalError());
    std::vector<double> from = {geometry.x_min}, to = {geometry.x_min};
    for (unsigned int i = 0; i < tips.size(); ++i)
      {
        from.push_back(geometry.x_min + column[i] * h);
        to.push_back(tips[i]);
      }
    from.push_back(geometry.x_max);
    to.push_back(geometry.x_max);
    GridTools::transform(
      [&](const Point<2> &p) {
        unsigned int k = 1;
        while (k + 1 < from.size() && p[0] > from[k])
          ++k;
        // Exact at the knots: the crack tips and the ends of Sigma.
        const double t = (p[0] - from[k - 1]) / (from[k] - from[k - 1]);
        return Point<2>(t >= 1 ? to[k] : to[k - 1] + t * (to[k] - to[k - 1]),
                        p[1]);
      },
      tria);
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
    const double scale = 1e9 / std::max(curve.length(), 1e-300);
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
    const double scale = 1e9 / std::max(curve.length(), 1e-300);
    const auto   outer = [](const types::boundary_id id) {
      return id != BoundaryIds::glued && id != BoundaryIds::crack;
    };
    auto keys =
      boundary_vertices(triangulation(Subdomain::minus), scale, outer);
    const auto plus =
      boundary_vertices(triangulation(Subdomain::plus), scale, outer);
    keys.insert(plus.begin(), plus.end());
    return keys.size();
  }
  namespace
  {
    /// The circle through the points @p p, if they are not collinear and
    /// all lie on one circle (relative tolerance 1e-8): (centre, radius).
    std::optional<std::pair<Point<2>, double>>
    fit_circle(const std::vector<Point<2>> &p)
    {
      if (p.size() < 3)
        return std::nullopt;
      // Three well separated points: the first, the farthest from it, the
      // farthest from the line through both.
      const Point<2> a = p[0];
      Point<2>       b = a;
      for (const auto &q : p)
        if (q.distance(a) > b.distance(a))
          b = q;
      const double ab  = a.distance(b);
      Point<2>     c   = a;
      double       off = 0;
      for (const auto &q : p)
        {
          const Tensor<1, 2> d = q - a, e = (b - a) / ab;
          const double       h = std::abs(d[0] * e[1] - d[1] * e[0]);
          if (h > off)
            {
              off = h;
              c   = q;
            }
        }
      if (off <= 1e-8 * ab)
        return std::nullopt;
      // Circumcentre of a, b, c.
      const double d  = 2 * (a[0] * (b[1] - c[1]) + b[0] * (c[1] - a[1]) +
                            c[0] * (a[1] - b[1]));
      const double a2 = a.norm_square(), b2 = b.norm_square(),
                   c2 = c.norm_square();
      const Point<2> centre(
        (a2 * (b[1] - c[1]) + b2 * (c[1] - a[1]) + c2 * (a[1] - b[1])) / d,
        (a2 * (c[0] - b[0]) + b2 * (a[0] - c[0]) + c2 * (b[0] - a[0])) / d);
      const double radius = centre.distance(a);
      for (const auto &q : p)
        if (std::abs(centre.distance(q) - radius) > 1e-8 * radius)
          return std::nullopt;
      return std::make_pair(centre, radius);
    }

    std::string
    at(const Point<2> &p)
    {
      std::ostringstream s;
      s << "(" << p[0] << ", " << p[1] << ")";
      return s.str();
    }

    using Edge = std::pair<unsigned int, unsigned int>;

    Edge
    edge(unsigned int a, unsigned int b)
    {
      return a < b ? Edge(a, b) : Edge(b, a);
    }

    /// The edges of the cells of one physical surface with the number of
    /// cells that use them.
    std::map<Edge, unsigned int>
    cell_edges(const GmshMesh &mesh, const int surface)
    {
      std::map<Edge, unsigned int> edges;
      for (const auto &e : mesh.elements)
        if ((e.type == 2 || e.type == 3) && e.physical == surface)
          for (unsigned int k = 0; k < e.nodes.size(); ++k)
            ++edges[edge(e.nodes[k], e.nodes[(k + 1) % e.nodes.size()])];
      return edges;
    }
  } // namespace


  void
  Geometry::load_gmsh()
  {
    const std::string file  = geometry.gmsh_file;
    const std::string where = "Geometry/Gmsh file '" + file + "'";
    GmshOptions       options;
    options.allow_commands = geometry.allow_gmsh_commands;
    options.time_limit     = this->mesh.gmsh_time_limit;
    options.size_factor    = this->mesh.gmsh_size_factor;
    const auto mesh_ptr = std::make_shared<GmshMesh>(read_gmsh(file, options));
    const GmshMesh &g   = *mesh_ptr;

    // The groups by name.
    std::array<int, 2> surface;
    for (const Subdomain s : {Subdomain::minus, Subdomain::plus})
      {
        const std::string name = s == Subdomain::minus ? "Omega-" : "Omega+";
        surface[static_cast<unsigned int>(s)] = g.physical_tag(2, name);
        AssertThrow(surface[static_cast<unsigned int>(s)] >= 0,
                    ExcMessage(where + ": no physical surface named '" + name +
                               "' (the subdomain " +
                               (s == Subdomain::minus ? "below" : "above") +
                               " Sigma)"));
      }
    const int sigma = g.physical_tag(1, "Sigma"),
              crack = g.physical_tag(1, "crack");
    AssertThrow(sigma >= 0 || crack >= 0,
                ExcMessage(where + ": no physical curve named 'Sigma' (the "
                                   "glued part of the interface) or 'crack'"));
    for (const auto &[tag, name] : g.curve_names)
      AssertThrow(name == "Sigma" || name == "crack" ||
                    std::find(geometry.parts.names.begin(),
                              geometry.parts.names.end(),
                              name) != geometry.parts.names.end(),
                  ExcMessage(where + ": the physical curve '" + name +
                             "' is not among the boundary parts read from "
                             "the file"));

    // Every cell in exactly one of Omega- and Omega+, every line element
    // of a physical curve in exactly one named group.
    const auto mid_point = [&](const GmshMesh::Element &e) {
      Point<2> centre;
      for (const unsigned int n : e.nodes)
        centre += g.nodes[n] / double(e.nodes.size());
      return at(centre);
    };
    const auto group = [&](const GmshMesh::Element &e) {
      const auto &names = e.type == 1 ? g.curve_names : g.surface_names;
      return names.count(e.physical) > 0 ?
               "'" + names.at(e.physical) + "'" :
               "number " + std::to_string(e.physical) + " (without a name)";
    };
    std::map<std::vector<unsigned int>, const GmshMesh::Element *> seen;
    for (const auto &e : g.elements)
      {
        const bool cell = e.type == 2 || e.type == 3;
        if (!cell && e.physical == 0)
          continue;
        const std::string entity =
          std::string(cell ? "Gmsh surface " : "Gmsh curve ") +
          std::to_string(e.entity);
        if (cell)
          {
            AssertThrow(
              e.physical != 0,
              ExcMessage(
                where + ": the cells of " + entity + " (e.g. at " +
                mid_point(e) +
                ") are in no physical surface: add the surface to "
                "Physical Surface(\"Omega-\") or (\"Omega+\"), or remove it"));
            AssertThrow(e.physical == surface[0] || e.physical == surface[1],
                        ExcMessage(where + ": the cells of " + entity +
                                   " (e.g. at " + mid_point(e) +
                                   ") are in the physical surface " + group(e) +
                                   "; bilayer reads only 'Omega-' and "
                                   "'Omega+': put the surface into one of "
                                   "them"));
          }
        else
          AssertThrow(g.curve_names.count(e.physical) > 0,
                      ExcMessage(where + ": the line elements of " + entity +
                                 " (e.g. at " + mid_point(e) +
                                 ") are in the physical curve " + group(e) +
                                 "; give the group a name (Physical "
                                 "Curve(\"NAME\")) or remove it"));
        std::vector<unsigned int> key = e.nodes;
        std::sort(key.begin(), key.end());
        key.push_back(cell ? 2 : 1);
        const auto [it, added] = seen.emplace(key, &e);
        AssertThrow(added,
                    ExcMessage(
                      where + ": the " + (cell ? "cell" : "edge") + " at " +
                      mid_point(e) + " (" + entity + ") is in two physical " +
                      (cell ? "surfaces" : "curves") + ", " +
                      group(*it->second) + " and " + group(e) +
                      (cell ? std::string() :
                              std::string("; a curve must be in one of "
                                          "'Sigma', 'crack' or one "
                                          "boundary part")) +
                      ": remove it from all but one"));
      }

    // Sigma and the crack are the edges the two surfaces share, and
    // nothing else is shared; every other edge of a surface belongs to one
    // cell or two.
    const auto minus = cell_edges(g, surface[0]),
               plus  = cell_edges(g, surface[1]);
    for (const auto &[name, edges] :
         {std::make_pair("Omega-", &minus), std::make_pair("Omega+", &plus)})
      {
        AssertThrow(!edges->empty(),
                    ExcMessage(where + ": the physical surface '" + name +
                               "' has no triangles or quadrilaterals"));
        for (const auto &[e, n] : *edges)
          AssertThrow(n <= 2,
                      ExcMessage(
                        where + ": more than two cells of '" + name +
                        "' share the edge at " +
                        at(0.5 * (g.nodes[e.first] + g.nodes[e.second])) +
                        " (overlapping cells)"));
      }
    std::map<Edge, const GmshMesh::Element *> on_sigma;
    for (const auto &e : g.elements)
      if (e.type == 1 && (e.physical == sigma || e.physical == crack))
        on_sigma[edge(e.nodes[0], e.nodes[1])] = &e;
    for (const auto &[e, element] : on_sigma)
      {
        const auto m = minus.find(e), p = plus.find(e);
        AssertThrow(m != minus.end() && p != plus.end() && m->second == 1 &&
                      p->second == 1,
                    ExcMessage(
                      where + ": the '" +
                      (element->physical == sigma ? "Sigma" : "crack") +
                      "' edge at " +
                      at(0.5 * (g.nodes[e.first] + g.nodes[e.second])) +
                      " is not a boundary edge of both Omega- and "
                      "Omega+: Sigma must separate the two "
                      "subdomains (curves shared by both surfaces)"));
      }
    for (const auto &[e, n] : minus)
      AssertThrow(plus.count(e) == 0 || on_sigma.count(e) == 1,
                  ExcMessage(where + ": Omega- and Omega+ share the edge at " +
                             at(0.5 * (g.nodes[e.first] + g.nodes[e.second])) +
                             ", which is in neither 'Sigma' nor 'crack'"));
    // The named boundary parts lie on the outer boundary: each edge is an
    // edge of one cell.
    for (const auto &e : g.elements)
      if (e.type == 1 && e.physical != sigma && e.physical != crack &&
          g.curve_names.count(e.physical) > 0)
        {
          const Edge         k = edge(e.nodes[0], e.nodes[1]);
          const auto         m = minus.find(k), p = plus.find(k);
          const unsigned int cells = (m == minus.end() ? 0 : m->second) +
                                     (p == plus.end() ? 0 : p->second);
          AssertThrow(cells == 1,
                      ExcMessage(
                        where + ": the '" + g.curve_names.at(e.physical) +
                        "' edge at " +
                        at(0.5 * (g.nodes[k.first] + g.nodes[k.second])) +
                        " (Gmsh curve " + std::to_string(e.entity) +
                        ") is an edge of " + std::to_string(cells) +
                        " cells, not of the outer boundary: a boundary "
                        "part must lie on the boundary of Omega- or "
                        "Omega+"));
        }
    // Non-conforming meshes: a boundary edge along another boundary edge
    // (a hanging node, or cells that do not share their nodes).
    std::vector<Edge> boundary;
    for (const auto *edges : {&minus, &plus})
      for (const auto &[e, n] : *edges)
        if (n == 1 && on_sigma.count(e) == 0)
          boundary.push_back(e);
    for (const auto &[e, n] : minus)
      if (n == 1 && on_sigma.count(e) == 1)
        boundary.push_back(e);
    double size = 0;
    for (const auto &e : boundary)
      size = std::max(size, g.nodes[e.first].distance(g.nodes[e.second]));
    for (const auto &e : boundary)
      {
        const Point<2> mid = 0.5 * (g.nodes[e.first] + g.nodes[e.second]);
        for (const auto &f : boundary)
          if (f != e)
            {
              const Point<2>     a = g.nodes[f.first], b = g.nodes[f.second];
              const Tensor<1, 2> t = b - a;
              const double       l = (mid - a) * t / t.norm_square();
              const double       d = (a + l * t).distance(mid);
              AssertThrow(!(l > 1e-8 && l < 1 - 1e-8 && d < 1e-8 * size),
                          ExcMessage(where + ": the boundary edge at " +
                                     at(mid) +
                                     " lies along another edge: the mesh is "
                                     "not conforming (a hanging node, or "
                                     "cells that do not share their nodes)"));
            }
      }

    // The circular curves (by their nodes), for the manifolds and Sigma.
    std::map<int, std::vector<Point<2>>> entity_nodes;
    for (const auto &e : g.elements)
      if (e.type == 1)
        for (const unsigned int n : e.nodes)
          entity_nodes[e.entity].push_back(g.nodes[n]);
    arc_centres.clear();
    std::map<int, double> arc_radii;
    for (const auto &[entity, points] : entity_nodes)
      if (const auto circle = fit_circle(points))
        {
          arc_centres[entity] = circle->first;
          arc_radii[entity]   = circle->second;
        }

    // Sigma as a chain: walk from one end through the Sigma and crack
    // edges.
    std::map<unsigned int, std::vector<const GmshMesh::Element *>> at_node;
    for (const auto &[e, element] : on_sigma)
      for (const unsigned int n : element->nodes)
        at_node[n].push_back(element);
    std::vector<unsigned int> ends;
    for (const auto &[n, elements] : at_node)
      {
        AssertThrow(elements.size() <= 2,
                    ExcMessage(where + ": Sigma and the crack branch at " +
                               at(g.nodes[n]) +
                               "; they must form one open curve"));
        if (elements.size() == 1)
          ends.push_back(n);
      }
    AssertThrow(ends.size() == 2,
                ExcMessage(where +
                           ": Sigma and the crack must form one open "
                           "curve from the outer boundary to the outer "
                           "boundary (found " +
                           std::to_string(ends.size()) + " ends)"));
    std::vector<const GmshMesh::Element *> chain;
    std::vector<unsigned int>              nodes = {ends[0]};
    for (const GmshMesh::Element *previous = nullptr;;)
      {
        const GmshMesh::Element *next = nullptr;
        for (const auto *e : at_node[nodes.back()])
          if (e != previous)
            next = e;
        if (next == nullptr)
          break;
        chain.push_back(next);
        nodes.push_back(next->nodes[0] == nodes.back() ? next->nodes[1] :
                                                         next->nodes[0]);
        previous = next;
      }
    AssertThrow(chain.size() == on_sigma.size(),
                ExcMessage(where + ": Sigma and the crack must form one "
                                   "connected curve"));

    // Pieces: a circular curve one arc, a straight curve one segment, any
    // other curve one segment per edge (the polygon of its nodes).
    std::vector<InterfaceCurve::Piece> pieces;
    for (unsigned int i = 0; i < chain.size();)
      {
        unsigned int j = i;
        while (j < chain.size() && chain[j]->entity == chain[i]->entity)
          ++j;
        const int             entity = chain[i]->entity;
        std::vector<Point<2>> points;
        for (unsigned int k = i; k <= j; ++k)
          points.push_back(g.nodes[nodes[k]]);
        bool straight = true;
        for (const auto &q : points)
          {
            const Tensor<1, 2> t = points.back() - points.front();
            const Tensor<1, 2> d = q - points.front();
            straight = straight && std::abs(d[0] * t[1] - d[1] * t[0]) <=
                                     1e-10 * t.norm_square();
          }
        InterfaceCurve::Piece piece;
        if (straight)
          {
            piece.a = points.front();
            piece.b = points.back();
            pieces.push_back(piece);
          }
        else if (arc_centres.count(entity) > 0)
          {
            piece.kind   = InterfaceCurve::Piece::Kind::arc;
            piece.a      = points.front();
            piece.b      = points.back();
            piece.centre = arc_centres[entity];
            piece.radius = arc_radii[entity];
            for (unsigned int k = 0; k + 1 < points.size(); ++k)
              {
                const Tensor<1, 2> u = points[k] - piece.centre,
                                   v = points[k + 1] - piece.centre;
                piece.sweep += std::atan2(u[0] * v[1] - u[1] * v[0], u * v);
              }
            pieces.push_back(piece);
          }
        else
          for (unsigned int k = 0; k + 1 < points.size(); ++k)
            {
              piece.a         = points[k];
              piece.b         = points[k + 1];
              piece.continues = k > 0;
              pieces.push_back(piece);
            }
        i = j;
      }
    curve = InterfaceCurve(pieces, 0.);

    // The crack pieces: runs of crack edges, inside Sigma.
    std::vector<CrackSet::Piece> cracks;
    for (unsigned int i = 0; i < chain.size(); ++i)
      if (chain[i]->physical == crack &&
          (i == 0 || chain[i - 1]->physical != crack))
        {
          unsigned int j = i;
          while (j < chain.size() && chain[j]->physical == crack)
            ++j;
          AssertThrow(i > 0 && j < chain.size(),
                      ExcMessage(where + ": the crack piece from " +
                                 at(g.nodes[nodes[i]]) + " to " +
                                 at(g.nodes[nodes[j]]) +
                                 " reaches an end of Sigma: a crack lies "
                                 "inside Sigma, its tips glued"));
          cracks.push_back({curve.parameter(g.nodes[nodes[i]]),
                            curve.parameter(g.nodes[nodes[j]])});
        }
    curve.set_crack(CrackSet(cracks, curve.tolerance()));

    // The clamped ends: the end node of a subdomain is clamped if it lies
    // on an edge of a clamped part that is an edge of that subdomain's
    // cells (its Dirichlet data fix that node alone). The gluing across
    // Sigma drops its multiplier at an end only where both sides are
    // clamped (InterfaceCurve::on_gamma_d).
    std::array<std::array<bool, 2>, 2> clamped_end = {
      {{{false, false}}, {{false, false}}}};
    for (const auto &e : g.elements)
      if (e.type == 1 && e.physical != sigma && e.physical != crack &&
          g.curve_names.count(e.physical) > 0 && e.nodes.size() == 2)
        {
          const auto &names = geometry.parts.names;
          const auto  part  = std::find(names.begin(),
                                      names.end(),
                                      g.curve_names.at(e.physical)) -
                            names.begin();
          if (geometry.clamped[part])
            for (unsigned int d = 0; d < 2; ++d)
              if ((d == 0 ? minus : plus).count(edge(e.nodes[0], e.nodes[1])) >
                  0)
                for (unsigned int k = 0; k < 2; ++k)
                  for (const unsigned int n : e.nodes)
                    clamped_end[d][k] =
                      clamped_end[d][k] ||
                      n == (k == 0 ? nodes.front() : nodes.back());
        }
    curve.set_clamped_ends(clamped_end);

    // Orientation: the normal points out of Omega-.
    {
      const auto    &first = *chain.front();
      const Point<2> mid =
        0.5 * (g.nodes[first.nodes[0]] + g.nodes[first.nodes[1]]);
      for (const auto &e : g.elements)
        if ((e.type == 2 || e.type == 3) && e.physical == surface[0] &&
            std::count(e.nodes.begin(), e.nodes.end(), first.nodes[0]) > 0 &&
            std::count(e.nodes.begin(), e.nodes.end(), first.nodes[1]) > 0)
          {
            Point<2> centre;
            for (const unsigned int n : e.nodes)
              centre += g.nodes[n] / double(e.nodes.size());
            if ((centre - mid) * curve.normal(curve.parameter(mid)) > 0)
              curve.reverse();
            break;
          }
    }
    gmsh = mesh_ptr;
  }


  void
  Geometry::make_gmsh_subdomain(const Subdomain   subdomain,
                                Triangulation<2> &tria) const
  {
    const GmshMesh   &g     = *gmsh;
    const std::string where = "Geometry/Gmsh file '" + geometry.gmsh_file + "'";
    const std::string name =
      subdomain == Subdomain::minus ? "Omega-" : "Omega+";
    const int                            tag = g.physical_tag(2, name);
    std::map<unsigned int, unsigned int> vertex_of;
    std::vector<unsigned int>            node_of;
    std::vector<Point<2>>                vertices;
    std::vector<CellData<2>>             cells;
    bool                                 triangles = false, quads = false;
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
          triangles = triangles || e.type == 2;
          quads     = quads || e.type == 3;
          cells.push_back(cell);
        }
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
    // Degenerate cells are broken meshes; inverted ones are only
    // oriented the other way: each is turned around on its own (vertices 1
    // and 2 swapped: a triangle's order reversed, a quadrilateral's
    // lexicographic order mirrored), so that all cells are positive.
    for (auto &cell : cells)
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
        AssertThrow(std::abs(area) / 2 > 1e-10 * diameter * diameter,
                    ExcMessage(where + ": '" + name +
                               "' has a degenerate cell at " +
                               at(vertices[cell.vertices[0]])));
        if (area < 0)
          std::swap(cell.vertices[1], cell.vertices[2]);
      }
    if (quads)
      GridTools::consistently_order_cells(cells);
    try
      {
        tria.create_triangulation(vertices, cells, SubCellData());
      }
    catch (const ExceptionBase &e)
      {
        AssertThrow(false,
                    ExcMessage(
                      where + ": the cells of '" + name +
                      "' do not form a valid mesh: " + one_line_message(e)));
      }

    // Boundary ids and manifolds from the line elements.
    std::map<Edge, const GmshMesh::Element *> lines;
    for (const auto &e : g.elements)
      if (e.type == 1)
        lines[edge(e.nodes[0], e.nodes[1])] = &e;
    const int sigma = g.physical_tag(1, "Sigma"),
              crack = g.physical_tag(1, "crack");
    std::map<int, types::manifold_id> manifold_of;
    for (const auto &[entity, centre] : arc_centres)
      {
        const types::manifold_id id = 1 + manifold_of.size();
        manifold_of[entity]         = id;
        tria.set_manifold(id, PolarManifold<2>(centre));
      }
    bool clamped_part = false;
    for (const auto &cell : tria.active_cell_iterators())
      for (const auto &face : cell->face_iterators())
        if (face->at_boundary())
          {
            const auto found = lines.find(edge(node_of[face->vertex_index(0)],
                                               node_of[face->vertex_index(1)]));
            if (found == lines.end())
              {
                face->set_boundary_id(BoundaryIds::free);
                continue;
              }
            const GmshMesh::Element &line = *found->second;
            if (line.physical == sigma)
              face->set_boundary_id(BoundaryIds::glued);
            else if (line.physical == crack)
              face->set_boundary_id(BoundaryIds::crack);
            else if (g.curve_names.count(line.physical) > 0)
              {
                const auto        &names = geometry.parts.names;
                const unsigned int part =
                  std::find(names.begin(),
                            names.end(),
                            g.curve_names.at(line.physical)) -
                  names.begin();
                face->set_boundary_id(part);
                clamped_part = clamped_part || geometry.clamped[part];
              }
            else
              face->set_boundary_id(BoundaryIds::free);
            if (manifold_of.count(line.entity) > 0)
              face->set_manifold_id(manifold_of.at(line.entity));
          }
    AssertThrow(clamped_part,
                ExcMessage(where + ": '" + name +
                           "' has no clamped part (Geometry/Clamped sides): "
                           "each subdomain must touch Gamma_D"));
  }

} // namespace bilayer
