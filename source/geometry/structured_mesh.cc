// The rectangle's structured meshes: subdivided rectangles on each side of
// Sigma, the crack tips fitted to vertex columns, the boundary ids.

#include <deal.II/grid/grid_generator.h>
#include <deal.II/grid/grid_tools.h>

#include <bilayer/geometry/geometry.h>

#include <algorithm>
#include <cmath>
#include <sstream>

namespace bilayer
{
  using namespace dealii;

  void
  Geometry::make_subdomain(const unsigned int region,
                           const unsigned int n_x,
                           const unsigned int n_y,
                           const unsigned int cycle,
                           Triangulation<2>  &tria) const
  {
    const auto         y = geometry.region_heights(region);
    const Point<2>     p1(geometry.x_min, y[0]);
    const Point<2>     p2(geometry.x_max, y[1]);
    const unsigned int n_y0 = static_cast<unsigned int>(structured_cells_across(
      mesh, n_x >> cycle, p2[1] - p1[1], geometry.x_max - geometry.x_min, 0));
    const std::vector<double> rows =
      ply_rows(ply_heights, p1[1], p2[1], n_y, n_y0, cycle);
    const unsigned int n_rows = rows.empty() ? n_y : rows.size() - 1;
    if (mesh.shape == ElementShape::quadrilateral)
      GridGenerator::subdivided_hyper_rectangle(tria, {n_x, n_rows}, p1, p2);
    else
      GridGenerator::subdivided_hyper_rectangle_with_simplices(tria,
                                                               {n_x, n_rows},
                                                               p1,
                                                               p2);
    if (!rows.empty())
      {
        // Row i of the uniform mesh moves to the height rows[i] (the ends
        // stay where they are).
        const double step = (p2[1] - p1[1]) / n_rows;
        GridTools::transform(
          [&](const Point<2> &p) {
            const long i = std::lround((p[1] - p1[1]) / step);
            return Point<2>(p[0], rows[std::clamp<long>(i, 0, n_rows)]);
          },
          tria);
      }
    if (mesh.fit_crack_tips)
      fit_crack_tips(n_x, tria);
    assign_boundary_ids(tria, region);
  }


  std::vector<double>
  ply_rows(const std::vector<double> &ply_heights,
           const double               y0,
           const double               y1,
           const unsigned int         rows,
           const unsigned int         rows0,
           const unsigned int         cycle)
  {
    const double        H      = y1 - y0;
    const double        tol    = 1e-10 * H;
    std::vector<double> knots  = {y0};
    bool                fitted = true;
    for (const double y : ply_heights)
      if (y > y0 + tol && y < y1 - tol)
        {
          knots.push_back(y);
          const double row = (y - y0) / H * rows;
          fitted = fitted && std::abs(row - std::round(row)) * H / rows <= tol;
        }
    if (knots.size() == 1 || fitted)
      return {};
    knots.push_back(y1);
    std::vector<double> heights = {y0};
    for (unsigned int k = 1; k < knots.size(); ++k)
      {
        const double t = knots[k] - knots[k - 1];
        const long   n = std::max(1l, std::lround(rows0 * t / H)) << cycle;
        for (long i = 1; i < n; ++i)
          heights.push_back(knots[k - 1] + t * i / n);
        heights.push_back(knots[k]);
      }
    return heights;
  }


  void
  Geometry::fit_crack_tips(const unsigned int n_x, Triangulation<2> &tria) const
  {
    // Knots of a piecewise linear map of x: the ends of Sigma stay, the
    // vertex column nearest to each crack end point inside Omega moves
    // onto it (neighbouring columns where two would share one).
    // The crack end points of every interface: the regions share their
    // vertex columns.
    const double        width = geometry.x_max - geometry.x_min;
    const double        h     = width / n_x;
    std::vector<double> tips;
    for (const unsigned int i : Layout::indices(curves.size()))
      if (geometry.has_crack(i))
        for (const double c : geometry.crack_interval(i))
          if (c > geometry.x_min + 1e-10 * width &&
              c < geometry.x_max - 1e-10 * width &&
              std::find_if(tips.begin(), tips.end(), [&](const double t) {
                return std::abs(t - c) <= 1e-10 * width;
              }) == tips.end())
            tips.push_back(c);
    std::sort(tips.begin(), tips.end());
    if (tips.empty())
      return;
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
  Geometry::assign_boundary_ids(Triangulation<2>  &tria,
                                const unsigned int region) const
  {
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
                // The interface below the region or the one above it.
                const unsigned int i =
                  region > 0 &&
                      std::abs(c[1] - geometry.interface_height(region - 1)) <
                        tol ?
                    region - 1 :
                    region;
                Assert(std::abs(c[1] - geometry.interface_height(i)) < tol,
                       ExcInternalError());
                face->set_boundary_id(BoundaryIds::interface(i));
              }
          }
  }
} // namespace bilayer
