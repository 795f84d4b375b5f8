#ifndef bilayer_similarity_breaker_h
#define bilayer_similarity_breaker_h

#include <deal.II/fe/fe_values.h>
#include <deal.II/grid/grid_generator.h>
#include <deal.II/grid/grid_tools.h>
#include <deal.II/grid/reference_cell.h>
#include <deal.II/grid/tria.h>

namespace bilayer
{
  /**
   * Single-threaded, deal.II 9.4's FEValues reuses the mapping data of
   * the previous cell when the next one is a translation of it; with more
   * threads it recomputes them. The two differ in the last bits, which
   * would make results depend on the number of threads. Reinitialising
   * on a cell that is no translation of any mesh cell (a distorted
   * reference cell of a mesh of its own) before each cell makes every
   * run recompute, so that the assembled matrices and every cell integral
   * (the energy release rate) are the same bits for any number of threads.
   */
  class SimilarityBreaker
  {
  public:
    explicit SimilarityBreaker(const dealii::ReferenceCell cell_type)
    {
      dealii::GridGenerator::reference_cell(tria, cell_type);
      dealii::GridTools::transform(
        [](const dealii::Point<2> &p) {
          return dealii::Point<2>(p[0] + 0.37 * p[0] * p[1] + 0.11 * p[1],
                                  1.3 * p[1] + 0.07 * p[0]);
        },
        tria);
    }

    void
    apply(dealii::FEValues<2> &fe_values) const
    {
      fe_values.reinit(tria.begin_active());
    }

  private:
    dealii::Triangulation<2> tria;
  };
} // namespace bilayer

#endif
