#ifndef bilayer_interface_h
#define bilayer_interface_h

#include <deal.II/base/tensor.h>
#include <deal.II/lac/block_vector.h>
#include <deal.II/lac/sparse_matrix.h>
#include <deal.II/lac/sparsity_pattern.h>

#include <bilayer/interface_diagnostics.h>
#include <bilayer/layout.h>
#include <bilayer/multiplier_space.h>
#include <bilayer/parameters.h>
#include <bilayer/subproblem.h>
#include <bilayer/trace_coupling.h>

#include <ostream>
#include <vector>

namespace bilayer
{
  /**
   * The interface Sigma as the outer solvers see it: the multiplier spaces
   * (MultiplierSpace: meshes, bounds, projection, the D inner product), the
   * coupling to the subproblems' traces (TraceCoupling) and the two
   * operators of the dual problem that need both, apply() and jumps().
   * The residuals of a solution are in interface_diagnostics.h.
   *
   * <h3>Discrete problem and update</h3>
   * The multiplier terms of the four subproblems (paper.md §4, step 2) are
   *   u-: -C^T (mu_1 + mu-),  u+: C^T (mu_1 - mu+),  v-: C^T mu-,
   *   v+: C^T mu+.
   * The jumps are g_1 = D^{-1} (C u- - C u+), g- = D^{-1} (C u- - C v-),
   * g+ = D^{-1} (C u+ - C v+) ("weighted": the gradient of the Lagrangian in
   * the D-metric, so that the Uzawa step mu <- P(mu + theta g) is a
   * projected gradient step of the dual problem; the projection onto the
   * box is the nodal clamp in that metric) or the traces evaluated at the
   * nodes ("nodal", the paper's pointwise reading). With lumped coupling
   * both are the nodal jumps and the discrete constraints are nodal:
   * [u].nu >= 0 at crack nodes, u- = u+ at the other nodes, u = v at all
   * nodes. Components that carry no multiplier have zero jump.
   */
  class Interface
  {
  public:
    Interface(const GeometryParameters &geometry,
              const ContactParameters  &contact);

    /// Index of subproblem (layer, subdomain) in Solutions: Layout::index().
    static constexpr unsigned int
    index(const Layer layer, const Subdomain subdomain)
    {
      return Layout::index(layer, subdomain);
    }

    /// Build the multiplier spaces and all operators for the given
    /// subproblems (indexed by Layout::index()); without layer 2 its entries
    /// are null, and the gluing blocks have no nodes. The multipliers take
    /// the degree of layer 1.
    void
    setup(const PerSubproblem<const ElasticSubproblem *> &subproblems);

    const MultiplierSpace &
    space() const
    {
      return space_;
    }

    const TraceCoupling &
    coupling() const
    {
      return coupling_;
    }

    const GeometryParameters &
    geometry_parameters() const
    {
      return geometry;
    }

    const ContactParameters &
    contact_parameters() const
    {
      return contact;
    }

    /// The multiplier terms of the four subproblems' loads.
    void
    apply(const dealii::BlockVector<double> &multipliers,
          Solutions                         &loads) const
    {
      coupling_.apply_transpose(multipliers, loads);
    }

    /// The jumps g (weighted or nodal, zero where no multiplier acts).
    void
    jumps(const Solutions &w, dealii::BlockVector<double> &g) const;

    /// The traction that the multipliers @p mu apply to subproblem @p s at
    /// the point x of Sigma (the density of its multiplier load).
    dealii::Tensor<1, 2>
    multiplier_traction(const dealii::BlockVector<double> &mu,
                        const unsigned int                 s,
                        const double                       x) const;

    /**
     * The Gram matrix G = B B^T of the signed coupling B (the map from the
     * four subproblems' dofs to the multiplier space whose transpose is
     * -apply(); B w = D g for weighted jumps), restricted to the components
     * i with mask(i) != 0: TraceCoupling::gram(). Scales the FETI-type
     * preconditioners of the dual problem.
     */
    void
    coupling_gram(const dealii::BlockVector<double> &mask,
                  dealii::SparsityPattern           &pattern,
                  dealii::SparseMatrix<double>      &gram) const
    {
      coupling_.gram(mask, pattern, gram);
    }

    /// @name The multiplier space (MultiplierSpace)
    /// @{
    void
    initialize(dealii::BlockVector<double> &multipliers) const
    {
      space_.initialize(multipliers);
    }
    void
    project(dealii::BlockVector<double> &multipliers) const
    {
      space_.project(multipliers);
    }
    void
    restrict_to_free(dealii::BlockVector<double> &x) const
    {
      space_.restrict_to_free(x);
    }
    double
    weighted_dot(const dealii::BlockVector<double> &x,
                 const dealii::BlockVector<double> &y) const
    {
      return space_.weighted_dot(x, y);
    }
    /// sqrt(sum_i D_i x_i^2) over all blocks.
    double
    weighted_norm(const dealii::BlockVector<double> &x) const
    {
      return std::sqrt(space_.weighted_dot(x, x));
    }
    double
    discrete_violation(const dealii::BlockVector<double> &g) const
    {
      return space_.discrete_violation(g);
    }
    void
    scale_by_weights(dealii::BlockVector<double> &x,
                     const bool                   inverse = false) const
    {
      space_.scale_by_weights(x, inverse);
    }
    const dealii::BlockVector<double> &
    lower_bounds() const
    {
      return space_.lower_bounds();
    }
    const dealii::BlockVector<double> &
    upper_bounds() const
    {
      return space_.upper_bounds();
    }
    /// Nodes of mu_1.
    unsigned int
    n_nodes() const
    {
      return space_.n_nodes(Layout::across_sigma);
    }
    unsigned int
    n_multipliers() const
    {
      return space_.n_free();
    }
    /// Position x of node a of mu_1.
    double
    node_position(const unsigned int a) const
    {
      return space_.node_position(a, Layout::across_sigma);
    }
    /// Whether node a of mu_1 lies strictly inside the crack.
    bool
    node_on_crack(const unsigned int a) const
    {
      return space_.on_crack(a);
    }
    using MultiplierFunctions = MultiplierSpace::Functions;
    MultiplierFunctions
    functions(const dealii::BlockVector<double> &mu) const
    {
      return space_.functions(mu);
    }
    void
    interpolate(const MultiplierFunctions   &old,
                dealii::BlockVector<double> &mu) const
    {
      space_.interpolate(old, mu);
    }
    /// @}

    /// @name Residuals of a solution (interface_diagnostics.h)
    /// @{
    double
    displacement_scale(const Solutions &w) const
    {
      return bilayer::displacement_scale(*this, w);
    }
    KKTResidual
    kkt_residual(const Solutions                   &w,
                 const dealii::BlockVector<double> &g,
                 const dealii::BlockVector<double> &mu) const
    {
      return bilayer::kkt_residual(*this, w, g, mu);
    }
    std::vector<double>
    normal_opening(const Solutions &w) const
    {
      return bilayer::normal_opening(*this, w);
    }
    InterfaceReport
    assess(const Solutions &w, const dealii::BlockVector<double> &mu) const
    {
      return bilayer::assess(*this, w, mu);
    }
    std::vector<ContactSegment>
    contact_residual(const Solutions                   &w,
                     const dealii::BlockVector<double> &mu) const
    {
      return bilayer::contact_residual(*this, w, mu);
    }
    void
    write_csv(std::ostream                      &out,
              const Solutions                   &w,
              const dealii::BlockVector<double> &mu) const
    {
      write_interface_csv(out, *this, w, mu);
    }
    /// @}

    /// Whether subproblem @p s exists (layer 2 may be absent).
    bool
    present(const unsigned int s) const
    {
      return coupling_.present(s);
    }

    /// Whether both subproblems of multiplier block @p b exist.
    bool
    active(const unsigned int b) const
    {
      return coupling_.active(b);
    }

  private:
    const GeometryParameters geometry;
    const ContactParameters  contact;
    MultiplierSpace          space_;
    TraceCoupling            coupling_;
  };
} // namespace bilayer

#endif
