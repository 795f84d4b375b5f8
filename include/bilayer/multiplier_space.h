#ifndef bilayer_multiplier_space_h
#define bilayer_multiplier_space_h

#include <deal.II/fe/fe_q.h>
#include <deal.II/lac/block_vector.h>

#include <bilayer/layout.h>
#include <bilayer/parameters.h>

#include <cmath>
#include <memory>
#include <vector>

namespace bilayer
{
  /// Sorted union of two sorted break point lists, merging points closer
  /// than @p tol.
  std::vector<double>
  merge_breakpoints(const std::vector<double> &a,
                    const std::vector<double> &b,
                    const double               tol);

  /**
   * The multiplier spaces on Sigma (paper.md §3): for each of the three
   * blocks (Layout::blocks) a mesh of Sigma, continuous Lagrange elements on
   * it whose nodes are the Gauss-Lobatto points of each segment, the lumped
   * mass D (one weight per node), and the multiplier set as bounds per
   * component. A vector of multipliers is a BlockVector with one block per
   * multiplier block and entries Layout::entry(node, component).
   *
   * <h3>Meshes</h3>
   *  - mu_1 (layer 1 across Sigma) on the union of the break points of the
   *    two traces (Omega- and Omega+ faces on Sigma);
   *  - lambda- on the trace of the Omega- mesh, lambda+ on that of the
   *    Omega+ mesh.
   * u- and v- share the Omega- mesh, so the nodal constraints u- = v- at its
   * trace nodes make the two traces equal, with no redundant constraint;
   * likewise on Omega+. Across Sigma the union mesh is the coarsest one on
   * which both traces are piecewise polynomials: equal values at its nodes
   * make the traces equal, and the map from the two traces to the jumps at
   * its nodes is onto. On matching meshes the three meshes coincide with the
   * common trace. A block whose subproblems are not both present (no layer
   * 2) has no nodes.
   *
   * <h3>Sets</h3>
   * mu_c nu at the nodes of mu_1 inside the crack (only the normal
   * component, 0 <= mu_c <= p; the tangential one is fixed to 0: no
   * friction), -p <= . <= p elsewhere. The crack tips belong to
   * Sigma \ gamma_c (glued). Nodes on Gamma_D (the ends of Sigma on a
   * clamped side) carry no multipliers (bounds [0, 0]); without
   * non-penetration neither do the crack nodes. A component is "free" when
   * its lower bound is below its upper bound.
   */
  class MultiplierSpace
  {
  public:
    /**
     * Build the meshes from the break points of the Omega- and Omega+ traces
     * on Sigma (sorted coordinates along Sigma), for multipliers of degree
     * @p degree; @p active[b] says whether both subproblems of block b exist.
     */
    void
    reinit(const GeometryParameters                 &geometry,
           const ContactParameters                  &contact,
           const std::array<std::vector<double>, 2> &trace_breakpoints,
           const unsigned int                        degree,
           const PerBlock<bool>                     &active);

    unsigned int
    degree() const
    {
      return degree_;
    }

    /// Zero multipliers of the right sizes.
    void
    initialize(dealii::BlockVector<double> &multipliers) const
    {
      multipliers.reinit(lower);
    }

    /// Clamp onto the multiplier sets.
    void
    project(dealii::BlockVector<double> &multipliers) const;

    /// Zero the components that carry no multiplier (bounds [0, 0]).
    void
    restrict_to_free(dealii::BlockVector<double> &x) const;

    /// Whether component @p i (global index) carries a multiplier.
    bool
    free(const unsigned int i) const
    {
      return lower(i) < upper(i);
    }

    /// Multiplier components that are not fixed to zero.
    unsigned int
    n_free() const;

    const dealii::BlockVector<double> &
    lower_bounds() const
    {
      return lower;
    }
    const dealii::BlockVector<double> &
    upper_bounds() const
    {
      return upper;
    }

    /// sum_i D_i x_i y_i over all blocks.
    double
    weighted_dot(const dealii::BlockVector<double> &x,
                 const dealii::BlockVector<double> &y) const;

    /// sqrt(sum_i D_i x_i^2) over all blocks.
    double
    weighted_norm(const dealii::BlockVector<double> &x) const
    {
      return std::sqrt(weighted_dot(x, x));
    }

    /// x_i <- D_i x_i, or x_i / D_i with @p inverse.
    void
    scale_by_weights(dealii::BlockVector<double> &x,
                     const bool                   inverse = false) const;

    /// Largest violation of the discrete constraints by the jumps g: |g| of
    /// a free component, max(g, 0) of a contact component (lower bound 0).
    double
    discrete_violation(const dealii::BlockVector<double> &g) const;

    /// Nodes of block @p b.
    unsigned int
    n_nodes(const unsigned int b = Layout::across_sigma) const
    {
      return meshes[b].node_x.size();
    }

    /// Coordinate along Sigma of node @p a of block @p b.
    double
    node_position(const unsigned int a,
                  const unsigned int b = Layout::across_sigma) const
    {
      return meshes[b].node_x[a];
    }

    /// The lumped mass D of node @p a of block @p b.
    double
    node_weight(const unsigned int a, const unsigned int b) const
    {
      return meshes[b].node_weight[a];
    }

    /// Break points of the mesh of block @p b.
    const std::vector<double> &
    breakpoints(const unsigned int b) const
    {
      return meshes[b].breakpoints;
    }

    /// Whether node @p a of mu_1 lies strictly inside the crack.
    bool
    on_crack(const unsigned int a) const
    {
      return crack_nodes[a];
    }

    /// The contact multiplier mu_c at node @p a of mu_1 (0 off the crack).
    double
    contact_multiplier(const dealii::BlockVector<double> &mu,
                       const unsigned int                 a) const
    {
      return crack_nodes[a] ? mu.block(Layout::across_sigma)(
                                Layout::entry(a, Layout::normal)) :
                              0.;
    }

    /// Component @p c of the gluing multiplier mu_g at node @p a of mu_1
    /// (0 on the crack).
    double
    gluing_multiplier(const dealii::BlockVector<double> &mu,
                      const unsigned int                 a,
                      const unsigned int                 c) const
    {
      return crack_nodes[a] ?
               0. :
               mu.block(Layout::across_sigma)(Layout::entry(a, c));
    }

    /// Segment of the mesh of block @p b containing the coordinate @p x, and
    /// the values of its shape functions there.
    unsigned int
    shape_values(const unsigned int   b,
                 const double         x,
                 std::vector<double> &values) const;

    /// The node of block b's mesh of local shape function i of segment e
    /// (vertices first, as FE_Q<1> numbers them).
    unsigned int
    node(const unsigned int e, const unsigned int i) const
    {
      return i == 0 ? e * degree_ :
             i == 1 ? (e + 1) * degree_ :
                      e * degree_ + i - 1;
    }

    /// Component @p c of the multiplier function of block @p b at @p x
    /// (zero for a block without nodes).
    double
    value(const dealii::BlockVector<double> &mu,
          const unsigned int                 b,
          const double                       x,
          const unsigned int                 c) const;

    /**
     * The multipliers as functions on Sigma, kept to warm-start the next
     * mesh: the break points, degree and nodal values of each block.
     */
    struct Functions
    {
      unsigned int                  degree = 0;
      PerBlock<std::vector<double>> breakpoints;
      dealii::BlockVector<double>   values;
    };

    /// The multipliers @p mu with the current meshes.
    Functions
    functions(const dealii::BlockVector<double> &mu) const;

    /// Interpolate @p old at the current nodes (same degree: exact on nested
    /// refinements of the meshes), then project onto the multiplier sets.
    void
    interpolate(const Functions &old, dealii::BlockVector<double> &mu) const;

  private:
    /// A mesh on Sigma: break points, nodes, D per node.
    struct Mesh
    {
      std::vector<double> breakpoints, node_x, node_weight;
    };

    unsigned int                     degree_ = 1;
    std::unique_ptr<dealii::FE_Q<1>> fe;
    PerBlock<Mesh>                   meshes;
    /// Per node of mu_1.
    std::vector<bool>           crack_nodes;
    dealii::BlockVector<double> lower, upper;
  };
} // namespace bilayer

#endif
