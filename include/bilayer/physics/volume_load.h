#ifndef bilayer_volume_load_h
#define bilayer_volume_load_h

#include <deal.II/base/point.h>
#include <deal.II/base/symmetric_tensor.h>
#include <deal.II/base/tensor.h>

namespace bilayer
{
  /**
   * The volume terms of a layer's load: a body force f [stress / length]
   * and an eigenstrain eps* (thermal, misfit, swelling strains), entering
   * the right-hand side of the cell system as
   *
   *   l_vol(z) = int f . z + sigma(eps*) : eps(z) dx,
   *
   * so that the stress of a displacement w is sigma(eps(w) - eps*). The
   * shipped scenes carry none (tractions and prescribed displacements
   * only); ElasticSubproblem::setup() takes one where a scene has it.
   */
  class VolumeLoad
  {
  public:
    virtual ~VolumeLoad() = default;

    /// The body force at @p p.
    virtual dealii::Tensor<1, 2>
    body_force(const dealii::Point<2> &p) const = 0;

    /// The eigenstrain at @p p.
    virtual dealii::SymmetricTensor<2, 2>
    eigenstrain(const dealii::Point<2> &p) const = 0;
  };
} // namespace bilayer

#endif
