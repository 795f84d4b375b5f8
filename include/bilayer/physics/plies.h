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
 * own law and volume load. A ply is a band y_j < y < y_(j+1) of the plane
 * between the ply heights (MaterialParameters::ply_heights); the meshes fit
 * a row of vertices to each height, so a cell lies in one ply, the one of
 * its centre. One ply (no heights) is the whole region, and every value is
 * that of its one law or load, bit for bit.
 */
namespace bilayer
{
  /// The ply of the height @p y among the sorted @p heights: the number of
  /// heights below @p y.
  unsigned int
  ply_of(const std::vector<double> &heights, const double y);


  /// The elastic laws of a subproblem, by ply.
  class PlyLaws
  {
  public:
    /// The laws of @p materials (one per ply, from the bottom) between the
    /// ply @p heights (one fewer).
    PlyLaws(const std::vector<LayerMaterial> &materials,
            const std::vector<double>        &heights);

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

    /// The ply of @p cell (of its centre).
    unsigned int
    ply(const dealii::CellAccessor<2, 2> &cell) const
    {
      return laws.size() == 1 ? 0 : ply_of(heights, cell.center()[1]);
    }

    /// The law of @p cell.
    const ElasticLaw &
    law(const dealii::CellAccessor<2, 2> &cell) const
    {
      return *laws[ply(cell)];
    }

    /**
     * The ply of the cells with a face on the boundary part @p id of
     * @p tria (Sigma: a horizontal line of the rectangle, inside one ply;
     * that of the first such cell); 0 with one ply.
     */
    unsigned int
    ply_on_boundary(const dealii::Triangulation<2>  &tria,
                    const dealii::types::boundary_id id) const;

    /// Whether all plies have the same energy-norm scale.
    bool
    uniform_energy_norm_scale() const;

  private:
    std::vector<std::unique_ptr<const ElasticLaw>> laws;
    std::vector<double>                            heights;
  };


  /**
   * The volume loads of the plies of a subproblem as one VolumeLoad: each
   * value at a point is that of the load of the point's ply (a point on a
   * ply height belongs to the ply below; the cells' quadrature points lie
   * inside their ply). A ply without a load (null) has none. The gradients
   * are the ply's own, so a jump between plies is never differentiated.
   */
  class PlyVolumeLoad : public VolumeLoad
  {
  public:
    PlyVolumeLoad(std::vector<std::unique_ptr<VolumeLoad>> loads,
                  const std::vector<double>               &heights);

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
    /// The load at @p p, null where its ply has none.
    const VolumeLoad *
    at(const dealii::Point<2> &p) const
    {
      return loads[ply_of(heights, p[1])].get();
    }

    std::vector<std::unique_ptr<VolumeLoad>> loads;
    std::vector<double>                      heights;
  };
} // namespace bilayer

#endif
