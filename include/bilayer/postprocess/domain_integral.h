#ifndef bilayer_domain_integral_h
#define bilayer_domain_integral_h

#include <deal.II/base/point.h>
#include <deal.II/base/quadrature.h>
#include <deal.II/fe/fe_values.h>
#include <deal.II/grid/reference_cell.h>

#include <bilayer/postprocess/fracture.h>
#include <bilayer/subproblem/subproblem.h>

#include <functional>
#include <vector>

/**
 * @file
 * The quadrature of the domain integrals at the crack tips (G and the
 * interaction integral of K): cells that the support of theta reaches,
 * with their rule subdivided where they are large against the support.
 */
namespace bilayer
{
  /**
   * A Gauss rule with @p n points per direction on each of the m x m
   * (quadrilateral) or m^2 (triangle) congruent pieces of the reference
   * cell: cells much larger than the support of theta see its fall from
   * 1 to 0 with enough points.
   */
  dealii::Quadrature<2>
  subdivided_quadrature(const dealii::ReferenceCell &cell,
                        const unsigned int           n,
                        const unsigned int           m);

  /// The smallest R of the defined tips whose theta reaches the cell of
  /// @p center and @p diameter, or 0.
  double
  smallest_support_radius(const std::vector<CrackTip>   &tips,
                          const std::vector<ThetaField> &fields,
                          const dealii::Point<2>        &center,
                          const double                   diameter);

  /// The pieces per direction of the rule of a cell of @p diameter in a
  /// support of radius @p R: no piece larger than R / 8 (at least four
  /// across the fall of theta, R/2 < r < R), at most 32.
  unsigned int
  support_pieces(const double diameter, const double R);

  /**
   * Calls @p f for every cell of @p sub that the support of a defined tip
   * of @p tips reaches, with FEValues (@p flags) reinitialised on it with
   * the rule subdivided for the smallest such support (degree + 3 Gauss
   * points per direction on each piece), and the cell's centre and
   * diameter.
   */
  void
  for_each_support_cell(const ElasticSubproblem       &sub,
                        const std::vector<CrackTip>   &tips,
                        const std::vector<ThetaField> &fields,
                        const dealii::UpdateFlags      flags,
                        const std::function<void(
                          const dealii::FEValues<2> &,
                          const dealii::DoFHandler<2>::active_cell_iterator &,
                          const dealii::Point<2> &,
                          const double)>              &f);
} // namespace bilayer

#endif
