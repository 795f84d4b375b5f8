#ifndef bilayer_plies_h
#define bilayer_plies_h

#include <deal.II/grid/tria.h>
#include <deal.II/grid/tria_accessor.h>

#include <bilayer/physics/elastic_law.h>
#include <bilayer/physics/volume_load.h>

#include <memory>
#include <vector>

/**
 * @file
 * The plies of a subproblem: the cell groups of its region, each with its
 * own law and volume load. A ply is either a band y_j < y < y_(j+1) of the
 * plane between the ply heights (MaterialParameters::ply_heights; the
 * meshes fit a row of vertices to each height, so a cell lies in one ply,
 * the one of its centre), or a Gmsh physical surface named by Ply groups
 * (the cells carry it as their material id, which refinement keeps). One
 * ply (no heights, no groups) is the whole region, and every value is that
 * of its one law or load, bit for bit.
 */
namespace bilayer
{
  /// The ply of the height @p y among the sorted @p heights: the number of
  /// heights below @p y.
  unsigned int
  ply_of(const std::vector<double> &heights, const double y);


  /**
   * How a layer's region is cut into plies: by heights (horizontal bands)
   * or by the cells' material ids (Gmsh ply groups). Neither: one ply.
   */
  struct PlyDivision
  {
    /// The ply heights, increasing (bands; empty with groups).
    std::vector<double> heights;
    /**
     * The ply of each material id (Geometry::ply_material_id(): 0 the
     * cells in no ply group, k the k-th ply group of the scene); empty
     * with heights. A layer's plies are its own groups in its order and
     * one more, last: the cells in none of them.
     */
    std::vector<unsigned int> by_material_id;

    /// The ply of @p cell.
    unsigned int
    ply(const dealii::CellAccessor<2, 2> &cell) const
    {
      if (by_material_id.empty())
        return ply_of(heights, cell.center()[1]);
      const auto id = cell.material_id();
      return id < by_material_id.size() ? by_material_id[id] :
                                          by_material_id[0];
    }
  };


  /// The elastic laws of a subproblem, by ply.
  class PlyLaws
  {
  public:
    /// The laws of @p materials (one per ply: from the bottom between
    /// heights, one fewer; by group, the cells in none last) of the plies
    /// @p division.
    PlyLaws(const std::vector<LayerMaterial> &materials,
            const PlyDivision                &division);

    unsigned int
    size() const
    {
      return laws.size();
    }

    /// The law of ply @p j.
    const ElasticLaw &
    law(const unsigned int j) const
    {
      return *laws[j];
    }

    /// The ply of @p cell.
    unsigned int
    ply(const dealii::CellAccessor<2, 2> &cell) const
    {
      return laws.size() == 1 ? 0 : division.ply(cell);
    }

    /// The law of @p cell.
    const ElasticLaw &
    law(const dealii::CellAccessor<2, 2> &cell) const
    {
      return *laws[ply(cell)];
    }

    /**
     * The ply of the cell with a face on the boundary part @p id of
     * @p tria nearest to @p point (the face whose centre is nearest; the
     * first such face without a point: a horizontal line of the rectangle
     * lies inside one ply); 0 with one ply or where no face has @p id.
     */
    unsigned int
    ply_on_boundary(const dealii::Triangulation<2>  &tria,
                    const dealii::types::boundary_id id,
                    const dealii::Point<2>          *point = nullptr) const;

    /// Whether plies @p i and @p j differ in their law or their thermal
    /// expansion (a material boundary between them).
    bool
    differ(const unsigned int i, const unsigned int j) const;

    /// Whether all plies have the same energy-norm scale.
    bool
    uniform_energy_norm_scale() const;

  private:
    std::vector<std::unique_ptr<const ElasticLaw>> laws;
    std::vector<LayerMaterial>                     materials;
    PlyDivision                                    division;
  };


  /**
   * The faces of the active cells of @p tria between plies of @p laws that
   * differ (PlyLaws::differ()), each once, as the segments between their
   * vertices: the material boundaries inside a region.
   */
  std::vector<std::array<dealii::Point<2>, 2>>
  material_boundaries(const dealii::Triangulation<2> &tria,
                      const PlyLaws                  &laws);


  /**
   * The volume loads of the plies of a subproblem as one VolumeLoad: each
   * value in a cell (in()) is that of the load of the cell's ply; with
   * heights also each value at a point, that of the point's ply (a point on
   * a ply height belongs to the ply below; the cells' quadrature points lie
   * inside their ply). A ply without a load (null) has none. The gradients
   * are the ply's own, so a jump between plies is never differentiated.
   */
  class PlyVolumeLoad : public VolumeLoad
  {
  public:
    PlyVolumeLoad(std::vector<std::unique_ptr<VolumeLoad>> loads,
                  const PlyDivision                       &division);

    CellLoad
    in(const dealii::CellAccessor<2, 2> &cell) const override;

    dealii::Tensor<1, 2>
    body_force(const dealii::Point<2> &p) const override;

    dealii::SymmetricTensor<2, 2>
    eigenstrain(const dealii::Point<2> &p) const override;

    double
    eigenstress_zz(const dealii::Point<2> &p) const override;

    bool
    has_body_force() const override;

    bool
    has_eigenstrain() const override;

    double
    length_scale() const override;

    dealii::Tensor<2, 2>
    body_force_gradient(const dealii::Point<2> &p) const override;

    std::array<dealii::SymmetricTensor<2, 2>, 2>
    eigenstrain_gradient(const dealii::Point<2> &p) const override;

  private:
    /// The load at @p p, null where its ply has none (plies by heights
    /// alone: a point does not know its ply group).
    const VolumeLoad *
    at(const dealii::Point<2> &p) const;

    std::vector<std::unique_ptr<VolumeLoad>> loads;
    PlyDivision                              division;
  };
} // namespace bilayer

#endif
