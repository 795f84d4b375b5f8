#include <bilayer/subproblem/cell_extents.h>

namespace bilayer
{
  void
  CellExtents::reinit(const dealii::DoFHandler<2> &dofs)
  {
    cells.clear();
    centers.clear();
    diameters.clear();
    const unsigned int n = dofs.get_triangulation().n_active_cells();
    cells.reserve(n);
    centers.reserve(n);
    diameters.reserve(n);
    for (const auto &cell : dofs.active_cell_iterators())
      {
        cells.push_back(cell);
        centers.push_back(cell->center());
        diameters.push_back(cell->diameter());
      }
  }
} // namespace bilayer
