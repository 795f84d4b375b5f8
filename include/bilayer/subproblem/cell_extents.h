#ifndef bilayer_cell_extents_h
#define bilayer_cell_extents_h

#include <deal.II/base/point.h>
#include <deal.II/dofs/dof_handler.h>

#include <vector>

namespace bilayer
{
  /**
   * The centre and the diameter of every active cell of a mesh, in the
   * order of its active cells, computed once per mesh. The questions asked
   * at every crack tip of every state (which cells the support of theta
   * reaches, which cells have the tip as a vertex) read these arrays
   * instead of the cells' vertices: a growth curve asks them at every step
   * on the same mesh.
   */
  class CellExtents
  {
  public:
    /// The active cells of @p dofs (after distribute_dofs()).
    void
    reinit(const dealii::DoFHandler<2> &dofs);

    unsigned int
    size() const
    {
      return cells.size();
    }

    const dealii::DoFHandler<2>::active_cell_iterator &
    cell(const unsigned int i) const
    {
      return cells[i];
    }

    /// cell(i)->center().
    const dealii::Point<2> &
    center(const unsigned int i) const
    {
      return centers[i];
    }

    /// cell(i)->diameter().
    double
    diameter(const unsigned int i) const
    {
      return diameters[i];
    }

  private:
    std::vector<dealii::DoFHandler<2>::active_cell_iterator> cells;
    std::vector<dealii::Point<2>>                            centers;
    std::vector<double>                                      diameters;
  };
} // namespace bilayer

#endif
