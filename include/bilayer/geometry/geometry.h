#ifndef bilayer_geometry_h
#define bilayer_geometry_h

#include <deal.II/grid/tria.h>
#include <deal.II/lac/vector.h>

#include <bilayer/core/boundary_ids.h>
#include <bilayer/geometry/interface_curve.h>
#include <bilayer/gmsh/gmsh_mesh.h>
#include <bilayer/parameters/parameters.h>

#include <array>
#include <cmath>
#include <map>
#include <memory>
#include <vector>

namespace bilayer
{
  /**
   * The cells across one subdomain of the rectangle's structured mesh of
   * refinement cycle 2^@p log2_factor: Mesh/Cells across times the factor,
   * or the number of the same aspect as @p cells_along (along Sigma, the
   * factor included) over @p width for the subdomain's @p height (rounded,
   * at least 1). In double precision, so that the memory estimate of a
   * cycle far too large for the mesh gets the same count.
   */
  inline double
  structured_cells_across(const MeshParameters &mesh,
                          const double          cells_along,
                          const double          height,
                          const double          width,
                          const unsigned int    log2_factor)
  {
    return mesh.cells_across > 0 ?
             std::ldexp(double(mesh.cells_across), int(log2_factor)) :
             std::max(1., std::round(cells_along * height / width));
  }

  /**
   * The heights of the vertex rows of a structured mesh between @p y0 and
   * @p y1 that fit the @p ply_heights inside: each ply's band gets
   * max(1, round(n0 t / H)) 2^cycle rows of equal height, t its thickness,
   * H = y1 - y0, n0 the rows of cycle 0 (@p rows0), so that the meshes of
   * the cycles are nested. Empty where no ply height lies inside, or every
   * one lies on a row of the uniform mesh of @p rows rows (then the uniform
   * mesh fits, bit for bit).
   */
  std::vector<double>
  ply_rows(const std::vector<double> &ply_heights,
           const double               y0,
           const double               y1,
           const unsigned int         rows,
           const unsigned int         rows0,
           const unsigned int         cycle);

  /**
   * Whether a cell with the signed area @p area (counter-clockwise
   * positive) and the longest edge @p diameter is inverted or degenerate:
   * the rule of every mesh bilayer reads (mesh files, Gmsh scenes).
   */
  inline bool
  degenerate_cell(const double area, const double diameter)
  {
    return !(area > 1e-10 * diameter * diameter);
  }

  /// A point of a mesh whose cells must be no larger than @p size.
  struct PointResolution
  {
    dealii::Point<2> point;
    double           size = 0;
  };

  /// Size data of one subdomain mesh (the columns of the paper's Table 1).
  struct MeshStatistics
  {
    unsigned int vertices = 0;
    unsigned int cells    = 0;
    /// Shortest and longest cell edge [length].
    double h_min = 0;
    double h_max = 0;
  };

  /**
   * The regions: the two subdomains Omega- = (x_min, x_max) x (y_min,
   * y_Sigma) and Omega+ = (x_min, x_max) x (y_Sigma, y_max), or the bands of
   * the rectangle between its interfaces (Geometry/Interfaces above Sigma),
   * each with its own serial Triangulation: structured (GridGenerator, the
   * same number of cells along the interfaces on all regions, so the traces
   * match) or read from Gmsh files (GridIn). The interfaces are curves
   * (Sigma first). The crack end points must be mesh vertices (checked).
   */
  class Geometry
  {
  public:
    /// The rectangle or Gmsh scene @p geometry, meshed by @p mesh; the
    /// structured meshes fit a row of vertices to each of @p ply_heights
    /// inside Omega (MaterialParameters::ply_heights); the cells of the
    /// Gmsh physical surfaces @p ply_groups (MaterialParameters::
    /// all_ply_groups()) carry the material id of their group.
    Geometry(const GeometryParameters       &geometry,
             const MeshParameters           &mesh,
             const std::vector<double>      &ply_heights = {},
             const std::vector<std::string> &ply_groups  = {});

    /// Build both meshes of refinement cycle @p cycle (cells along Sigma
    /// times 2^cycle).
    void
    create_meshes(const unsigned int cycle);

    /**
     * Refine both meshes from cell indicators (one per active cell of each
     * subdomain, in the order of active_cell_iterators()), marking by
     * Mesh/Marking with one threshold over the cells of both subdomains.
     * Each subdomain keeps its own hanging nodes; the traces on Sigma stop
     * matching where only one side is refined.
     *
     * The marking depends only on the ratios of the indicators: they are
     * divided by a power of two of their largest (exactly) and ranked in
     * single precision, so that indicators equal up to round-off (cells of
     * symmetric meshes) tie and refine together, and indicators scaled by a
     * power of two mark exactly the same cells.
     *
     * Besides, every active cell that has one of the points of @p resolve
     * as a vertex and is larger (cell_size()) than that point's size is
     * refined: the cells at a crack tip are refined until the support of
     * its velocity field theta holds them (fracture.h).
     */
    void
    refine(const std::vector<dealii::Vector<double>> &indicators,
           const std::vector<PointResolution>        &resolve = {});

    unsigned int
    n_regions() const
    {
      return triangulations.size();
    }

    const dealii::Triangulation<2> &
    triangulation(const unsigned int region) const;
    const dealii::Triangulation<2> &
    triangulation(const Subdomain subdomain) const
    {
      return triangulation(static_cast<unsigned int>(subdomain));
    }

    MeshStatistics
    statistics(const unsigned int region) const;
    MeshStatistics
    statistics(const Subdomain subdomain) const
    {
      return statistics(static_cast<unsigned int>(subdomain));
    }

    /// Sigma as a curve: parametrisation, normals, crack pieces and the
    /// ends on Gamma_D (set by create_meshes()).
    const InterfaceCurve &
    interface_curve() const
    {
      return curves[0];
    }

    /// The named physical surfaces of a Gmsh scene inside its regions that
    /// no Materials/Layer k/Ply groups entry names (read, not used: their
    /// cells take their region's law).
    const std::vector<std::string> &
    unread_surfaces() const
    {
      return unlisted_surfaces;
    }

    /// Every interface (Sigma first) as a curve.
    const std::vector<InterfaceCurve> &
    interface_curves() const
    {
      return curves;
    }

    /// The two regions each interface joins, the lower number first (side
    /// 0 and side 1 of its curve): the rectangle's bands a chain from the
    /// bottom, a Gmsh scene's the regions whose cells share the
    /// interface's edges (known once the meshes are built).
    const std::vector<std::array<unsigned int, 2>> &
    interface_regions() const
    {
      return between;
    }

    /**
     * Replace the crack gamma_c by @p crack on the present meshes (the one
     * source of the crack: the multiplier spaces, the coupling, the
     * estimator and the tips follow the interface curve's CrackSet). Its
     * pieces must be ordered, disjoint, on Sigma (reaching an end of Sigma
     * only where it is not on Gamma_D: an edge crack, leaving some of Sigma
     * glued; InterfaceCurve::crack_refusal()) and end at vertices of both
     * meshes on Sigma; else nothing changes and the error names the piece or
     * the end point. The crack of interface @p i (Sigma: 0); with
     * @p whole_allowed it may cover all of the interface (a cohesive zone).
     */
    void
    set_crack(const CrackSet    &crack,
              const unsigned int i             = 0,
              const bool         whole_allowed = false);

    /// The parameters s of the vertices of interface @p i (Sigma: 0) that
    /// both meshes have, increasing: where a crack tip may stand
    /// (Fracture/Crack growth).
    std::vector<double>
    sigma_vertex_parameters(const unsigned int i = 0) const;

    /// P of Table 1: vertices on Sigma.
    unsigned int
    n_sigma_vertices() const;

    /// M of Table 1: vertices on the outer boundary of Omega.
    unsigned int
    n_outer_vertices() const;

    /// The first @p how_many numbers of cells along Sigma whose structured
    /// meshes have every crack end point as a vertex.
    std::vector<unsigned int>
    valid_cells_along_sigma(const unsigned int how_many) const;

  private:
    void
    check_crack_vertices() const;
    /// The crack end points of interface @p i are vertices of the meshes
    /// of its two regions.
    void
    check_crack_vertices(const unsigned int i) const;

    /// Refuse a mesh read from a file whose cells are inverted or
    /// degenerate, or whose boundary has faces inside the subdomain (slits,
    /// holes, overlapping or unconnected cells).
    void
    check_cells(const dealii::Triangulation<2> &tria,
                const Subdomain                 subdomain,
                const std::string              &file) const;

    /// The structured mesh of @p region: @p cells_along cells along
    /// Sigma, @p cells_across across (refinement cycle @p cycle), its rows
    /// fitted to the ply heights.
    void
    make_subdomain(const unsigned int        region,
                   const unsigned int        cells_along,
                   const unsigned int        cells_across,
                   const unsigned int        cycle,
                   dealii::Triangulation<2> &tria) const;

    void
    read_subdomain(const Subdomain           subdomain,
                   const std::string        &pattern,
                   dealii::Triangulation<2> &tria) const;

    /// Mesh/Fit crack tips: move the vertex columns of a structured mesh
    /// with @p n_x cells along Sigma onto the crack end points.
    void
    fit_crack_tips(const unsigned int        n_x,
                   dealii::Triangulation<2> &tria) const;

    /// Side ids on the outer boundary, interface ids on the interfaces of
    /// @p region, from the face centres.
    void
    assign_boundary_ids(dealii::Triangulation<2> &tria,
                        const unsigned int        region) const;

    /// Read the Gmsh scene (once), check it and build Sigma's curve.
    void
    load_gmsh();

    /// Take the cells of the ply groups out of @p g, keeping their
    /// material ids by nodes; refuse a ply cell that is no cell of Omega- or
    /// Omega+.
    void
    take_ply_groups(GmshMesh &g, const std::string &where);


    /// The mesh of @p region from the Gmsh scene: cells of its physical
    /// surface (gmsh_region_name()), boundary ids from the physical curves,
    /// polar manifolds on the circular arcs.
    void
    make_gmsh_subdomain(const unsigned int        region,
                        dealii::Triangulation<2> &tria) const;

    const GeometryParameters       geometry;
    const MeshParameters           mesh;
    const std::vector<double>      ply_heights;
    const std::vector<std::string> ply_groups;
    /// The named physical surfaces of the Gmsh scene inside the regions
    /// that no Ply groups entry names (their cells take their region's
    /// law).
    std::vector<std::string> unlisted_surfaces;
    /// The material id (ply group k: k + 1) of the Gmsh cells in a ply
    /// group, by their sorted Gmsh nodes.
    std::map<std::vector<unsigned int>, dealii::types::material_id> ply_cells;
    /// One mesh per region, one curve per interface.
    std::vector<dealii::Triangulation<2>>    triangulations;
    std::vector<InterfaceCurve>              curves;
    std::vector<std::array<unsigned int, 2>> between;
    /// The Gmsh scene (null for the rectangle and mesh files).
    std::shared_ptr<const GmshMesh> gmsh;
    /// Centres of the circular Gmsh curves, by entity tag.
    std::map<int, dealii::Point<2>> arc_centres;
  };
} // namespace bilayer

#endif
