#ifndef bilayer_volume_load_h
#define bilayer_volume_load_h

#include <deal.II/base/point.h>
#include <deal.II/base/symmetric_tensor.h>
#include <deal.II/base/tensor.h>
#include <deal.II/grid/tria_accessor.h>

#include <array>
#include <memory>

namespace bilayer
{
  class VolumeLoad;

  /**
   * The load in one cell (VolumeLoad::in()): the load of the cell's ply
   * (null: none) under a load factor on its body force and one on its
   * eigenstrain. Each value is the load's own times its factor; with
   * factors 1 the load's value, bit for bit.
   */
  struct CellLoad
  {
    const VolumeLoad *load    = nullptr;
    double            factor  = 1;
    double            preload = 1;

    dealii::Tensor<1, 2>
    body_force(const dealii::Point<2> &p) const;

    dealii::SymmetricTensor<2, 2>
    eigenstrain(const dealii::Point<2> &p) const;

    double
    eigenstress_zz(const dealii::Point<2> &p) const;

    dealii::Tensor<2, 2>
    body_force_gradient(const dealii::Point<2> &p) const;

    std::array<dealii::SymmetricTensor<2, 2>, 2>
    eigenstrain_gradient(const dealii::Point<2> &p) const;
  };


  /**
   * The volume terms of a layer's load: a body force f [stress / length]
   * and an eigenstrain eps* (thermal, misfit, swelling strains; in-plane,
   * eps*_zz = 0), entering the right-hand side of the cell system as
   *
   *   l_vol(z) = int f . z + sigma(eps*) : eps(z) dx,
   *
   * so that the stress of a displacement w is sigma(eps(w) - eps*) and the
   * energy is the potential energy of the eigenstrained body,
   *
   *   Pi(w) = 1/2 int (eps(w) - eps*) : C (eps(w) - eps*) - int f . w - ...
   *
   * (docs/problem.md §1). A thermal load (ThermalVolumeLoad) enters as the
   * plane eigenstrain that the law gives its 3-D thermal strain, with the
   * sigma_zz of eigenstress_zz(). A layer without either passes no VolumeLoad
   * at all (ElasticSubproblem::setup() takes a null pointer).
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

    /**
     * The out-of-plane stress of the eigenstrain at @p p where the elastic
     * in-plane strain is zero: sigma_zz = Z : (eps(w) - eps*) + this (a
     * thermal strain in plane strain: -E_3 alpha_3 dT,
     * ElasticLaw::plane_eigenstrain()). 0 for an in-plane eigenstrain.
     */
    virtual double
    eigenstress_zz(const dealii::Point<2> &) const
    {
      return 0;
    }

    /// Whether the body force may be non-zero (false: it is zero
    /// everywhere, and the terms of f may be skipped).
    virtual bool
    has_body_force() const
    {
      return true;
    }

    /// Whether the eigenstrain may be non-zero (false: zero everywhere).
    virtual bool
    has_eigenstrain() const
    {
      return true;
    }

    /**
     * The length over which the fields vary, of the order of the size of
     * the domain: the step of the default gradients below is
     * gradient_step_fraction times it.
     */
    virtual double
    length_scale() const
    {
      return 1;
    }

    /// The step of the default gradients over length_scale().
    static constexpr double gradient_step_fraction = 1e-3;

    /**
     * grad f at @p p: entry (i, j) = d f_i / d x_j. The default: the
     * fourth-order central difference (f(p - 2h) - 8 f(p - h) + 8 f(p + h)
     * - f(p + 2h)) / 12h along each axis, h = gradient_step_fraction *
     * length_scale() (truncation h^4 f^(5) / 30, exact for polynomials of
     * degree 4; rounding about 1e-16 |f| / h).
     */
    virtual dealii::Tensor<2, 2>
    body_force_gradient(const dealii::Point<2> &p) const;

    /// d eps* / d x_j at @p p for j = 0, 1 (the default as above).
    virtual std::array<dealii::SymmetricTensor<2, 2>, 2>
    eigenstrain_gradient(const dealii::Point<2> &p) const;

    /**
     * The load at load factor 1 (ScaledVolumeLoad: the load it scales;
     * otherwise this load itself): the one that ElasticSubproblem::setup()
     * assembles as the unit proportional load and the preload.
     */
    virtual const VolumeLoad &
    unit_load() const
    {
      return *this;
    }

    /**
     * The load in @p cell: this load itself, except for the loads that
     * differ by the cell's ply (PlyVolumeLoad) and their scaled views
     * (ScaledVolumeLoad). The readers that loop over cells read the load
     * through it, so that a ply that a point alone does not identify (a
     * Gmsh ply group) gets its own load.
     */
    virtual CellLoad
    in(const dealii::CellAccessor<2, 2> &) const
    {
      return {this, 1, 1};
    }
  };


  /**
   * A VolumeLoad under a load factor lambda: the body force lambda f (a
   * proportional load) and the eigenstrain eps* of the load it holds
   * unscaled (a preload, as the thermal strain), or scaled by a factor of
   * its own (Loads/Load factor scales): every reader of the body
   * force (the energy release rate, the error estimator) sees lambda f,
   * while ElasticSubproblem::setup() assembles unit_load(). With lambda = 1
   * every value is that of the held load, bit for bit.
   */
  class ScaledVolumeLoad : public VolumeLoad
  {
  public:
    explicit ScaledVolumeLoad(std::unique_ptr<VolumeLoad> load)
      : load(std::move(load))
    {}

    /// Set lambda (any finite number; 1 after construction), and the
    /// factor @p preload of the eigenstrain (1: held; Loads/Load factor
    /// scales = thermal or all).
    void
    set_load_factor(const double lambda, const double preload = 1)
    {
      factor         = lambda;
      preload_factor = preload;
    }

    double
    load_factor() const
    {
      return factor;
    }

    dealii::Tensor<1, 2>
    body_force(const dealii::Point<2> &p) const override
    {
      return factor * load->body_force(p);
    }

    dealii::SymmetricTensor<2, 2>
    eigenstrain(const dealii::Point<2> &p) const override
    {
      return preload_factor == 1 ? load->eigenstrain(p) :
                                   preload_factor * load->eigenstrain(p);
    }

    double
    eigenstress_zz(const dealii::Point<2> &p) const override
    {
      return preload_factor * load->eigenstress_zz(p);
    }

    bool
    has_body_force() const override
    {
      return load->has_body_force();
    }

    bool
    has_eigenstrain() const override
    {
      return load->has_eigenstrain();
    }

    double
    length_scale() const override
    {
      return load->length_scale();
    }

    dealii::Tensor<2, 2>
    body_force_gradient(const dealii::Point<2> &p) const override
    {
      return factor * load->body_force_gradient(p);
    }

    std::array<dealii::SymmetricTensor<2, 2>, 2>
    eigenstrain_gradient(const dealii::Point<2> &p) const override
    {
      auto gradient = load->eigenstrain_gradient(p);
      if (preload_factor != 1)
        for (auto &g : gradient)
          g *= preload_factor;
      return gradient;
    }

    const VolumeLoad &
    unit_load() const override
    {
      return load->unit_load();
    }

    CellLoad
    in(const dealii::CellAccessor<2, 2> &cell) const override
    {
      CellLoad inner = load->in(cell);
      inner.factor *= factor;
      inner.preload *= preload_factor;
      return inner;
    }

  private:
    std::unique_ptr<VolumeLoad> load;
    double                      factor = 1, preload_factor = 1;
  };
} // namespace bilayer

#endif
