#ifndef bilayer_boundary_ids_h
#define bilayer_boundary_ids_h

#include <deal.II/base/types.h>
#include <deal.II/grid/tria.h>

#include <cmath>
#include <set>

/**
 * @file
 * The boundary ids of the subdomain meshes and the small questions asked of
 * their faces and cells: the vocabulary that every layer may include
 * (meshes, subproblems, coupling, estimators, fracture).
 */
namespace bilayer
{
  /**
   * Boundary ids of the subdomain meshes. The outer boundary parts keep
   * their own ids (so that each can carry its own traction): the
   * rectangle's sides 0-3, a Gmsh scene's named curves 0, 1, ... in the
   * order of BoundaryParts, its unnamed boundary curves `free` (traction
   * free). Which parts form Gamma_D is GeometryParameters::clamped. Every
   * face on Sigma has the id `sigma`, glued or cracked: which part of Sigma
   * is the crack gamma_c is the interface curve's CrackSet alone, so that the
   * crack can change on a fixed mesh. The faces on interface i (Sigma: 0)
   * have the id interface(i).
   */
  namespace BoundaryIds
  {
    constexpr dealii::types::boundary_id left   = 0;
    constexpr dealii::types::boundary_id right  = 1;
    constexpr dealii::types::boundary_id bottom = 2;
    constexpr dealii::types::boundary_id top    = 3;
    /// Boundary part i of a Gmsh scene has id i (< free).
    constexpr dealii::types::boundary_id free  = 199;
    constexpr dealii::types::boundary_id sigma = 200;
    /// The most interfaces a scene may have (ids sigma ... 254).
    constexpr unsigned int max_interfaces = 55;

    constexpr dealii::types::boundary_id
    interface(const unsigned int i)
    {
      return sigma + i;
    }

    /// The interface of a face with the id @p id of an interface (the
    /// inverse of interface()).
    constexpr unsigned int
    interface_of(const dealii::types::boundary_id id)
    {
      return id - sigma;
    }

    /// The ids of the interfaces of a scene of @p n_regions regions (the
    /// faces of the subproblems' traces).
    /// The ids of every interface a scene may have.
    inline std::set<dealii::types::boundary_id>
    interfaces()
    {
      std::set<dealii::types::boundary_id> ids;
      for (unsigned int i = 0; i < max_interfaces; ++i)
        ids.insert(interface(i));
      return ids;
    }
  } // namespace BoundaryIds

  /// Whether the face @p face of a subdomain mesh lies on an interface
  /// (Sigma or another).
  template <typename FaceIterator>
  inline bool
  on_sigma(const FaceIterator &face)
  {
    return face->at_boundary() && face->boundary_id() >= BoundaryIds::sigma &&
           face->boundary_id() <
             BoundaryIds::interface(BoundaryIds::max_interfaces);
  }

  /// Whether the face @p face of a subdomain mesh lies on interface @p i.
  template <typename FaceIterator>
  inline bool
  on_interface(const FaceIterator &face, const unsigned int i)
  {
    return face->at_boundary() &&
           face->boundary_id() == BoundaryIds::interface(i);
  }

  /**
   * The size of a cell as the cells at a crack tip are measured: sqrt(area)
   * for a quadrilateral, sqrt(2 area) for a triangle (the side of the square
   * of two).
   */
  inline double
  cell_size(const dealii::Triangulation<2>::active_cell_iterator &cell)
  {
    return std::sqrt(cell->measure() * (cell->n_vertices() == 3 ? 2. : 1.));
  }
} // namespace bilayer

#endif
