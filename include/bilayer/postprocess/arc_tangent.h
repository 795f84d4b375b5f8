#ifndef bilayer_arc_tangent_h
#define bilayer_arc_tangent_h

#include <deal.II/base/point.h>
#include <deal.II/base/tensor.h>

#include <bilayer/geometry/interface_curve.h>

/**
 * @file
 * The tangent of an arc of Sigma, shared by crack_tips.cc (the shape of
 * Sigma at a crack tip) and theta_field.cc (the tangent field T of theta
 * across a smooth junction). Only these two files include it.
 */
namespace bilayer
{
  namespace fracture
  {
    /// The unit tangent of the arc @p piece at its point @p p, in the
    /// direction of increasing s.
    inline dealii::Tensor<1, 2>
    arc_tangent(const InterfaceCurve::Piece &piece, const dealii::Point<2> &p)
    {
      const dealii::Tensor<1, 2> r =
        (p - piece.centre) / (p - piece.centre).norm();
      const double sign = piece.sweep >= 0 ? 1. : -1.;
      return sign * dealii::Tensor<1, 2>({-r[1], r[0]});
    }
  } // namespace fracture
} // namespace bilayer

#endif
