// Geometry: the two meshes of a cycle (created or refined), the crack on
// them, and their sizes. The meshes themselves come from
// structured_mesh.cc (the rectangle), mesh_files.cc and gmsh_scene.cc.

#include <deal.II/grid/grid_tools.h>

#include <bilayer/geometry/geometry.h>

#include <algorithm>
#include <cmath>
#include <iomanip>
#include <set>
#include <sstream>

namespace bilayer
{
  using namespace dealii;


  Geometry::Geometry(const GeometryParameters       &geometry,
                     const MeshParameters           &mesh,
                     const std::vector<double>      &ply_heights,
                     const std::vector<std::string> &ply_groups)
    : geometry(geometry)
    , mesh(mesh)
    , ply_heights(ply_heights)
    , ply_groups(ply_groups)
    , triangulations(geometry.n_regions())
    , curves(geometry.n_interfaces())
    , between(Topology::chain(triangulations.size()))
  {
    // The rectangle's interfaces: horizontal segments, s = x, nu = (0, 1);
    // their ends lie on Gamma_D where the left or right side is clamped (a
    // side spans all regions, so an end is clamped on both or neither).
    for (const unsigned int i : Layout::indices(curves.size()))
      {
        // A Gmsh scene's interfaces come from its file (load_gmsh(); Sigma
        // holds the rectangle's segment until then, as before the scene
        // had further interfaces).
        if (i > 0 && !geometry.gmsh_file.empty())
          break;
        InterfaceCurve &curve  = curves[i];
        const double    height = geometry.interface_height(i);
        curve = InterfaceCurve::segment({geometry.x_min, height},
                                        {geometry.x_max, height});
        curve.set_crack(geometry.crack(i));
        const std::array<bool, 2> ends = {
          {geometry.clamped[static_cast<unsigned int>(Side::left)],
           geometry.clamped[static_cast<unsigned int>(Side::right)]}};
        curve.set_clamped_ends({{ends, ends}});
        // An edge crack reaches a side that is not clamped (checked with
        // the entries' names when the parameters are read).
        const std::string refusal = curve.crack_refusal(curve.crack());
        AssertThrow(refusal.empty(),
                    ExcMessage((i == 0 ? std::string("Geometry/Crack interval "
                                                     "on Sigma: ") :
                                         "Geometry/Interfaces above Sigma: "
                                         "interface " +
                                           std::to_string(i + 1) + ": ") +
                               refusal));
      }
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
        for (const unsigned int r : Layout::indices(triangulations.size()))
          {
            auto &tria = triangulations[r];
            tria.clear();
            make_gmsh_subdomain(r, tria);
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
        for (const unsigned int r : Layout::indices(triangulations.size()))
          {
            const unsigned int n_x = (r > 0 && mesh.cells_along_sigma_plus > 0 ?
                                        mesh.cells_along_sigma_plus :
                                        mesh.cells_along_sigma) *
                                     factor;
            const auto         y      = geometry.region_heights(r);
            const double       height = y[1] - y[0];
            const unsigned int n_y    = static_cast<unsigned int>(
              structured_cells_across(mesh, n_x, height, width, cycle));
            auto &tria = triangulations[r];
            tria.clear();
            make_subdomain(r, n_x, n_y, cycle, tria);
          }
      }

    check_crack_vertices();
  }


  void
  Geometry::refine(const std::vector<Vector<double>>  &indicators,
                   const std::vector<PointResolution> &resolve)
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
    std::vector<std::vector<float>> relative(indicators.size());
    for (const unsigned int k : Layout::indices(indicators.size()))
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
    for (const unsigned int r : Layout::indices(triangulations.size()))
      {
        auto        &tria = triangulations[r];
        const auto  &eta  = relative[r];
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


  namespace
  {
    /// The end points of the pieces of @p crack.
    std::vector<double>
    crack_end_points(const CrackSet &crack)
    {
      std::vector<double> ends;
      for (const auto &piece : crack.pieces())
        {
          ends.push_back(piece.start);
          ends.push_back(piece.end);
        }
      return ends;
    }
  } // namespace


  void
  Geometry::set_crack(const CrackSet    &crack,
                      const unsigned int i,
                      const bool         whole_allowed)
  {
    InterfaceCurve   &curve   = curves[i];
    const std::string refusal = curve.crack_refusal(crack, whole_allowed);
    AssertThrow(refusal.empty(), ExcMessage(refusal));
    const CrackSet previous = curve.crack();
    curve.set_crack(crack);
    try
      {
        check_crack_vertices();
      }
    catch (...)
      {
        curve.set_crack(previous);
        throw;
      }
  }


  void
  Geometry::check_crack_vertices() const
  {
    for (const unsigned int i : Layout::indices(curves.size()))
      check_crack_vertices(i);
  }


  void
  Geometry::check_crack_vertices(const unsigned int i) const
  {
    const InterfaceCurve     &curve = curves[i];
    const std::vector<double> ends  = crack_end_points(curve.crack());
    if (gmsh)
      {
        // Gmsh scenes: the crack end points are vertices of the meshes on
        // the interface (those of the file's crack group are by
        // construction).
        for (const unsigned int r : between[i])
          for (const double c : ends)
            {
              bool found = false;
              for (const auto &face : triangulation(r).active_face_iterators())
                if (on_interface(face, i))
                  for (const unsigned int v : face->vertex_indices())
                    found = found || std::abs(curve.parameter(face->vertex(v)) -
                                              c) <= curve.tolerance();
              std::ostringstream m;
              m << std::setprecision(10) << "the crack end point s = " << c
                << " is not a vertex of the mesh of '" << gmsh_region_name(r)
                << "' on '" << gmsh_interface_name(i, false) << "'";
              AssertThrow(found, ExcMessage(m.str()));
            }
        return;
      }
    // The crack end points must be mesh vertices: no face on Sigma may
    // straddle one.
    for (const unsigned int r : between[i])
      for (const auto &cell : triangulations[r].active_cell_iterators())
        for (const auto &face : cell->face_iterators())
          if (on_interface(face, i))
            for (const double c : ends)
              {
                const double x0 =
                  std::min(face->vertex(0)[0], face->vertex(1)[0]);
                const double x1 =
                  std::max(face->vertex(0)[0], face->vertex(1)[0]);
                const double tol = 1e-8 * (x1 - x0);
                if (x0 + tol < c && c < x1 - tol)
                  {
                    std::ostringstream msg;
                    if (mesh.mesh_files.empty())
                      {
                        const bool plus =
                          r > 0 && mesh.cells_along_sigma_plus > 0;
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
                          << (r == 0 ? "-" : "+");
                    AssertThrow(false, ExcMessage(msg.str()));
                  }
              }
  }


  std::vector<unsigned int>
  Geometry::valid_cells_along_sigma(const unsigned int how_many) const
  {
    std::vector<unsigned int> valid;
    const double              width = geometry.x_max - geometry.x_min;
    std::vector<double>       ends;
    for (const InterfaceCurve &curve : curves)
      for (const double c : crack_end_points(curve.crack()))
        ends.push_back(c);
    for (unsigned int n = 1; n <= 100000 && valid.size() < how_many; ++n)
      {
        bool ok = true;
        for (const double c : ends)
          {
            const double k = (c - geometry.x_min) / width * n;
            ok = ok && std::abs(k - std::round(k)) < 1e-8 * std::max(1., k);
          }
        if (ok)
          valid.push_back(n);
      }
    return valid;
  }


  const Triangulation<2> &
  Geometry::triangulation(const unsigned int region) const
  {
    return triangulations[region];
  }


  MeshStatistics
  Geometry::statistics(const unsigned int region) const
  {
    const auto    &tria = triangulation(region);
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
    const double scale = 1e9 / std::max(curves[0].length(), 1e-300);
    return boundary_vertices(triangulation(Subdomain::minus),
                             scale,
                             [](const types::boundary_id id) {
                               return id == BoundaryIds::sigma;
                             })
      .size();
  }


  unsigned int
  Geometry::n_outer_vertices() const
  {
    const double scale = 1e9 / std::max(curves[0].length(), 1e-300);
    const auto   outer = [](const types::boundary_id id) {
      return id < BoundaryIds::sigma ||
             id >= BoundaryIds::interface(BoundaryIds::max_interfaces);
    };
    std::set<std::pair<long long, long long>> keys;
    for (const auto &tria : triangulations)
      {
        const auto region = boundary_vertices(tria, scale, outer);
        keys.insert(region.begin(), region.end());
      }
    return keys.size();
  }


  std::vector<double>
  Geometry::sigma_vertex_parameters(const unsigned int i) const
  {
    // The parameters of the vertices on the interface of each mesh, sorted;
    // then those of both (within the curve's tolerance).
    const InterfaceCurve              &curve = curves[i];
    std::array<std::vector<double>, 2> on_sigma;
    for (const unsigned int side : {0u, 1u})
      {
        auto &list = on_sigma[side];
        for (const auto &cell :
             triangulations[between[i][side]].active_cell_iterators())
          for (const auto &face : cell->face_iterators())
            if (on_interface(face, i))
              for (const unsigned int v : face->vertex_indices())
                list.push_back(curve.parameter(face->vertex(v)));
        std::sort(list.begin(), list.end());
      }
    const double        tol = curve.tolerance();
    std::vector<double> both;
    unsigned int        j = 0;
    for (const double s : on_sigma[0])
      {
        while (j < on_sigma[1].size() && on_sigma[1][j] < s - tol)
          ++j;
        if (j < on_sigma[1].size() && std::abs(on_sigma[1][j] - s) <= tol &&
            (both.empty() || s > both.back() + tol))
          both.push_back(s);
      }
    return both;
  }
} // namespace bilayer
