#ifndef bilayer_interface_h
#define bilayer_interface_h

#include <deal.II/base/tensor.h>
#include <deal.II/lac/block_vector.h>
#include <deal.II/lac/sparse_matrix.h>
#include <deal.II/lac/sparsity_pattern.h>

#include <bilayer/core/layout.h>
#include <bilayer/interface/multiplier_space.h>
#include <bilayer/interface/trace_coupling.h>
#include <bilayer/parameters/parameters.h>
#include <bilayer/subproblem/subproblem.h>

#include <vector>

namespace bilayer
{
  /**
   * The interface Sigma as the outer solvers see it: the multiplier spaces
   * (MultiplierSpace: meshes, bounds, projection, the D inner product), the
   * coupling to the subproblems' traces (TraceCoupling) and the two
   * operators of the dual problem that need both, apply() and jumps(), and
   * the traction of the multipliers on a subproblem. The residuals of a
   * solution and the CSV writer are in interface_diagnostics.h.
   *
   * <h3>Discrete problem and update</h3>
   * The multiplier terms of the subproblems (docs/problem.md §4, step 2)
   * are u-: -C^T (mu_1 + mu-),  u+: C^T (mu_1 - mu+),  v-: C^T mu-, v+: C^T
   * mu+. The jumps are g_1 = D^{-1} (C u- - C u+), g- = D^{-1} (C u- - C v-),
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
    explicit Interface(const ContactParameters &contact);

    /// Build the multiplier spaces and all operators for the given
    /// subproblems of @p topology (indexed by Topology::index()); without
    /// layer 2 its entries are null, and the gluing blocks have no nodes.
    /// The multipliers across the interfaces take the degree of layer 1;
    /// @p curves are the interfaces (Sigma first).
    void
    setup(const Topology                                 &topology,
          const PerSubproblem<const ElasticSubproblem *> &subproblems,
          const std::vector<InterfaceCurve>              &curves);

    const MultiplierSpace &
    space() const
    {
      return space_;
    }

    /// The springs of the cohesive zone of block @p b
    /// (MultiplierSpace::set_cohesive_compliance()).
    void
    set_cohesive_compliance(const std::vector<double> &compliance,
                            const unsigned int         b)
    {
      space_.set_cohesive_compliance(compliance, b);
    }

    /// The friction bounds of the crack nodes of mu_1 (one per node):
    /// MultiplierSpace::set_friction_bounds(). Coulomb friction's fixed
    /// point changes them between solves.
    void
    set_friction_bounds(const std::vector<double> &bounds,
                        const unsigned int         i = 0)
    {
      space_.set_friction_bounds(bounds, i);
    }

    const TraceCoupling &
    coupling() const
    {
      return coupling_;
    }

    /// Interface @p i (Sigma: 0) with its parametrisation, normals and
    /// crack pieces.
    const InterfaceCurve &
    curve(const unsigned int i = 0) const
    {
      return curves_[i];
    }

    unsigned int
    n_interfaces() const
    {
      return curves_.size();
    }

    const Topology &
    topology() const
    {
      return space_.topology();
    }

    const ContactParameters &
    contact_parameters() const
    {
      return contact;
    }

    /// The multiplier terms of the subproblems' loads.
    void
    apply(const dealii::BlockVector<double> &multipliers,
          Solutions                         &loads) const
    {
      coupling_.apply_transpose(multipliers, loads);
    }

    /// The jumps g (weighted or nodal, zero where no multiplier acts
    /// unless @p every_component: a cohesive zone's separations, the
    /// sliding of its frictionless crack faces included).
    void
    jumps(const Solutions             &w,
          dealii::BlockVector<double> &g,
          const bool                   every_component = false) const;

    /// The traction (Cartesian components) that the multipliers @p mu
    /// apply to subproblem @p s at the point of parameter @p x on
    /// interface @p i (the density of its multiplier load; the multipliers'
    /// components are in the frame (tangent, normal) of their nodes).
    dealii::Tensor<1, 2>
    multiplier_traction(const dealii::BlockVector<double> &mu,
                        const unsigned int                 s,
                        const double                       x,
                        const unsigned int                 i = 0) const;

    /**
     * The Gram matrix G = B B^T of the signed coupling B (the map from the
     * subproblems' dofs to the multiplier space whose transpose is
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

    /// The number of subproblems (2 per layer slot) and of multiplier
    /// blocks (2 per layer slot, less one).
    unsigned int
    n_subproblems() const
    {
      return coupling_.n_subproblems();
    }
    unsigned int
    n_blocks() const
    {
      return space_.n_blocks();
    }

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
    const ContactParameters     contact;
    std::vector<InterfaceCurve> curves_;
    MultiplierSpace             space_;
    TraceCoupling               coupling_;
  };
} // namespace bilayer

#endif
