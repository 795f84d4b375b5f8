#ifndef bilayer_multiplier_space_h
#define bilayer_multiplier_space_h

#include <deal.II/fe/fe_q.h>
#include <deal.II/lac/block_vector.h>
#include <deal.II/lac/full_matrix.h>

#include <bilayer/core/layout.h>
#include <bilayer/geometry/interface_curve.h>
#include <bilayer/parameters/parameters.h>
#include <bilayer/physics/multiplier_set.h>

#include <cmath>
#include <memory>
#include <vector>

namespace bilayer
{
  /// The break points of the traces of an interface's two sides (below,
  /// above), values of the parameter s of its curve.
  using InterfaceTraces = std::array<std::vector<double>, 2>;

  /// Sorted union of two sorted break point lists, merging points closer
  /// than @p tol.
  std::vector<double>
  merge_breakpoints(const std::vector<double> &a,
                    const std::vector<double> &b,
                    const double               tol);

  /**
   * The multiplier spaces on Sigma (docs/problem.md §3, docs/multipliers.md):
   * for each multiplier block (Topology::coupling(): one across each
   * interface, 2N - 2 gluing the N layers along Sigma) on the block's curve
   * a mesh of Sigma, continuous
   * Lagrange elements of a degree of its own on it whose nodes are the
   * Gauss-Lobatto points of each segment, the lumped mass D (one weight per
   * node), and the admissible set of the multipliers (MultiplierSet). A vector
   * of multipliers is a BlockVector with one block per multiplier block and
   * entries Layout::entry(node, component).
   *
   * <h3>Meshes and degrees: the mortar choice</h3>
   * Each block b couples two subproblems (Layout::coupled(b)). Its
   * multiplier space is built on the trace of one of them, the "slave" of
   * b, with a degree that the slave's trace realises, so that the rows of
   * the coupling restricted to the slave's trace dofs form a square (up to
   * Gamma_D), invertible and local matrix: D for the lumped coupling, the
   * mass matrix of the multiplier basis against the trace basis for the
   * consistent one. The slaves' trace dofs of different blocks are
   * distinct, so the coupling B of all blocks restricted to them is block
   * diagonal with those blocks: B has full row rank (the multipliers are
   * unique) and the discrete inf-sup constant is that of each slave's trace
   * against its own multipliers, independent of the other side's mesh and
   * degree (uniformly stable, as in mortar methods).
   *  - mu_1 (u- against u+), degree p1: the points that both traces share
   *    (always the ends of Sigma) cut Sigma into macro segments; on each,
   *    the mesh is that of the trace with more segments there (Omega- on a
   *    tie), the slave of that macro segment. The finer side is the slave
   *    so that the non-penetration constraint is tested at the finer set of
   *    points; on nested traces (hanging nodes, adaptive refinement of each
   *    side, ratio 1:2) this is the union of the two traces and the gluing
   *    is conforming. A shared point pivots on either side's vertex, an
   *    interior node on its slave's node: distinct dofs. Contact/Multiplier
   *    mesh = coarser trace takes the side with fewer segments instead
   *    (fewer constraints, a better conditioned dual problem).
   *  - lambda- (u- against v-, one mesh): the trace of the Omega- mesh,
   *    degree min(p1, p2), slave v- (layer 2), whose trace of degree
   *    p2 >= min(p1, p2) is onto the multipliers' nodal values.
   *  - lambda+: likewise on Omega+, slave v+.
   *  - With N > 2 layers, the gluing of layer k to layer k - 1 on a side:
   *    the side's trace, degree min(p_(k-1), p_k), slave layer k. The rule:
   *    the slave of a gluing block is its upper layer, the one farther from
   *    the cracked layer 1, so every layer k >= 2 is the slave of exactly
   *    one block per side and the slaves' dofs stay distinct.
   * On matching meshes with p1 = p2 the three meshes are the common trace
   * and every degree is p1 (the spaces of the paper). A block whose
   * subproblems are not both present (no layer 2) has no nodes.
   *
   * <h3>Sets</h3>
   * mu_c nu at the nodes of mu_1 inside the crack (the normal component,
   * 0 <= mu_c <= p; the tangential one is fixed to 0 without friction and
   * lies in [-g, g] with the friction bound g, set_friction_bounds()),
   * -p <= . <= p elsewhere. At a corner of Sigma inside the
   * crack both components are contact components in [0, p], along the
   * normals of the two pieces that meet there (node_frame()). The crack tips
   * belong to Sigma \ gamma_c (glued); the mouth of an edge crack (an end of
   * Sigma off Gamma_D that a crack piece reaches) is a crack node. Nodes on
   * Gamma_D (the ends of Sigma on a clamped side) carry no multipliers
   * (bounds [0, 0]); without non-penetration neither do the crack nodes. A
   * component is "free" when it carries a multiplier (MultiplierSet::free()).
   */
  class MultiplierSpace
  {
  public:
    /// The mesh and degree of one block's multipliers.
    struct BlockChoice
    {
      std::vector<double> breakpoints;
      unsigned int        degree;
    };

    /**
     * The mortar choice of the class documentation for the blocks of
     * @p topology, the traces' break points @p trace_breakpoints (of each
     * interface: below, above; points closer than @p tol are shared) and
     * the degrees of the layers' elements (@p degrees, one per layer slot).
     */
    static PerBlock<BlockChoice>
    choose(const Topology                     &topology,
           const std::vector<InterfaceTraces> &trace_breakpoints,
           const std::vector<unsigned int>    &degrees,
           const MultiplierMesh                rule,
           const double                        tol);

    /**
     * Build the meshes of the blocks of @p topology from the break points
     * of the two traces of each interface (sorted coordinates along it) and
     * the degrees of the layers' elements, by choose(); the crack pieces
     * and the ends on Gamma_D come from the interfaces' @p curves;
     * @p active[b] says whether both subproblems of block b exist.
     */
    void
    reinit(const Topology                     &topology,
           const std::vector<InterfaceCurve>  &curves,
           const ContactParameters            &contact,
           const std::vector<InterfaceTraces> &trace_breakpoints,
           const std::vector<unsigned int>    &degrees,
           const PerBlock<bool>               &active);

    const Topology &
    topology() const
    {
      return topology_;
    }

    /// The number of multiplier blocks (0 before reinit()).
    unsigned int
    n_blocks() const
    {
      return meshes.size();
    }

    /// Degree of the multipliers of block @p b.
    unsigned int
    degree(const unsigned int b = Layout::across_sigma) const
    {
      return meshes[b].degree;
    }

    /// Zero multipliers of the right sizes.
    void
    initialize(dealii::BlockVector<double> &multipliers) const
    {
      set_.initialize(multipliers);
    }

    /// The admissible set of the multipliers.
    const MultiplierSet &
    set() const
    {
      return set_;
    }

    /// Project onto the multiplier set.
    void
    project(dealii::BlockVector<double> &multipliers) const
    {
      set_.project(multipliers);
    }

    /// Zero the components that carry no multiplier (bounds [0, 0]).
    void
    restrict_to_free(dealii::BlockVector<double> &x) const;

    /// Whether component @p i (global index) carries a multiplier.
    bool
    free(const unsigned int i) const
    {
      return set_.free(i);
    }

    /// Multiplier components that are not fixed to zero.
    unsigned int
    n_free() const;


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

    /// Largest violation of the discrete constraints by the jumps g at the
    /// multipliers mu (MultiplierSet::violation(): |g| of a gluing
    /// component, max(g, 0) of a contact component, |g| of a friction
    /// component that sticks).
    double
    discrete_violation(const dealii::BlockVector<double> &g,
                       const dealii::BlockVector<double> &mu) const;
    /**
     * Set the friction bound of the tangential component of each crack node
     * a of mu_1 (not a corner) to min(@p bounds[a], p): a component with a
     * bound > 0 is a friction component, one with bound 0 carries no
     * multiplier. @p bounds has one entry per node of mu_1 (those off the
     * crack are not read). The multipliers of changed components are not
     * touched: project them.
     */
    void
    set_friction_bounds(const std::vector<double> &bounds,
                        const unsigned int         b = Layout::across_sigma);
    /// The friction bound g of the tangential component of node @p a of
    /// mu_1 (0 where no friction acts: off the crack, at corners, where the
    /// bound is 0).
    double
    friction_bound(const unsigned int a,
                   const unsigned int b = Layout::across_sigma) const
    {
      return set_.friction_bound(b, Layout::entry(a, Layout::tangential));
    }
    /// Whether node @p a of mu_1 has a tangential component that friction
    /// may act on (a crack node that is not a corner).
    bool
    friction_node(const unsigned int a,
                  const unsigned int b = Layout::across_sigma) const
    {
      return crack_nodes[b][a] && !corner_nodes[b][a];
    }

    /**
     * The cohesive zone of block @p b (docs/cohesive.md): per node, the
     * compliance c >= 0 of its springs (the inverse of the secant stiffness
     * of the traction-separation law), +infinity where the node is fully
     * damaged, NaN where it is not in the zone. The zone's nodes (crack
     * nodes that are not corners) take both components as springs
     * (MultiplierSet::set_cohesive(), the normal one in tension only);
     * the fully damaged ones and those outside take the kinds that the
     * crack gives them (contact, friction). The multipliers are not
     * touched.
     */
    void
    set_cohesive_compliance(const std::vector<double> &compliance,
                            const unsigned int         b);

    /// Whether node @p a of block @p b may carry a cohesive spring: a crack
    /// node of a block across an interface, not a corner, with a normal
    /// component that carries a multiplier in the crack's set.
    bool
    cohesive_node(const unsigned int a, const unsigned int b) const;

    /// g <- g - c phi(mu): the jumps less those the springs hold at mu
    /// (MultiplierSet::cohesive_term()); the residual of the cohesive law.
    void
    add_cohesive_jumps(const dealii::BlockVector<double> &mu,
                       dealii::BlockVector<double>       &g) const;

    /// Fx <- Fx + D c'(mu) x: the springs' part of the Hessian of the
    /// dual function at mu (MultiplierSet::cohesive_slope()).
    void
    add_cohesive_operator(const dealii::BlockVector<double> &mu,
                          const dealii::BlockVector<double> &x,
                          dealii::BlockVector<double>       &Fx) const;

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

    /**
     * The unit normal of node @p a of block @p b, the normal of the frame
     * (tangent, normal) in which the node's multiplier components are
     * taken: int_Sigma phi_a nu_h ds over the chords of the block's mesh
     * (nu_h the chord normals, pointing into Omega+), normalised. On a
     * straight piece it is the piece's normal; at a corner, or on an arc,
     * the mean of the two neighbouring chords' normals weighted by the
     * integrals of phi_a, so that a uniform pressure on the discrete
     * (chordal) trace is transmitted exactly.
     */
    const dealii::Tensor<1, 2> &
    node_normal(const unsigned int a,
                const unsigned int b = Layout::across_sigma) const
    {
      return meshes[b].normal[a];
    }

    /**
     * The frame of node @p a of block @p b: the two vectors along which the
     * node's multiplier components (Layout::tangential, Layout::normal) act
     * and along which the jumps of its constraints are measured. At every
     * node but a corner of Sigma inside the crack it is (tangent_of(n), n)
     * with n = node_normal(a, b). At a crack corner of mu_1 (corner()) it is
     * (nu_before, nu_after), the normals of the two pieces of Sigma that
     * meet there, and both components are contact components: two
     * non-penetration constraints [u].nu_before >= 0, [u].nu_after >= 0 and
     * the multiplier a nu_before + b nu_after in the cone a, b in [0, p].
     */
    const std::array<dealii::Tensor<1, 2>, 2> &
    node_frame(const unsigned int a,
               const unsigned int b = Layout::across_sigma) const
    {
      return meshes[b].frame[a];
    }

    /// Whether node @p a of mu_1 is a corner of Sigma inside the crack
    /// (two contact components, see node_frame()).
    bool
    corner(const unsigned int a,
           const unsigned int b = Layout::across_sigma) const
    {
      return corner_nodes[b][a];
    }

    /// The lumped mass D of node @p a of block @p b (with the masses of the
    /// end nodes merged into it, see row()).
    double
    node_weight(const unsigned int a, const unsigned int b) const
    {
      return meshes[b].node_weight[a];
    }

    /// int_Sigma phi_a ds of the basis function of node @p a of block @p b
    /// alone.
    double
    node_mass(const unsigned int a, const unsigned int b) const
    {
      return meshes[b].node_mass[a];
    }

    /**
     * Whether the trace of the @p j-th subproblem that block @p b couples
     * (Layout::coupled(b): 0 first, 1 second) lies in the multiplier space
     * of b: its break points are among b's and its degree is at most b's.
     * Then the dual basis integrates it exactly at the nodes, and the lumped
     * coupling of that side is D times the evaluation at the nodes;
     * otherwise it is integrated with the dual basis on the common
     * refinement.
     */
    bool
    nodal(const unsigned int b, const unsigned int j) const
    {
      return meshes[b].nodal[j];
    }

    /**
     * The node whose multiplier the basis function of node @p a of block
     * @p b carries: a itself, except at an end of Sigma on Gamma_D (no
     * multiplier) of a block with a side that is not nodal(), whose basis
     * function joins that of the other vertex of its segment, so that the
     * multipliers still contain the constants and constant tractions are
     * transmitted exactly (the mortar modification at the ends).
     */
    unsigned int
    row(const unsigned int a, const unsigned int b) const
    {
      return meshes[b].row[a];
    }

    /// Segment of the mesh of block @p b containing @p x and the values
    /// there of the dual basis of its shape functions (biorthogonal:
    /// int psi_i phi_k = delta_ik int phi_i on each segment).
    unsigned int
    dual_shape_values(const unsigned int   b,
                      const double         x,
                      std::vector<double> &values) const;

    /// Break points of the mesh of block @p b.
    const std::vector<double> &
    breakpoints(const unsigned int b) const
    {
      return meshes[b].breakpoints;
    }

    /// Whether node @p a of mu_1 lies on the crack: strictly inside a
    /// piece, or at the mouth of an edge crack (CrackSet::contains()).
    bool
    on_crack(const unsigned int a,
             const unsigned int b = Layout::across_sigma) const
    {
      return crack_nodes[b][a];
    }

    /**
     * The contact multiplier mu_c at node @p a of mu_1 (0 off the crack):
     * the normal component. At a crack corner, the component along
     * node_normal() of the multiplier vector a nu_before + b nu_after (the
     * compressive force the corner transmits; >= 0 with a, b >= 0).
     */
    double
    contact_multiplier(const dealii::BlockVector<double> &mu,
                       const unsigned int                 a,
                       const unsigned int b = Layout::across_sigma) const
    {
      if (!crack_nodes[b][a])
        return 0.;
      const auto &m = mu.block(b);
      if (!corner_nodes[b][a])
        return m(Layout::entry(a, Layout::normal));
      const auto &f = node_frame(a, b);
      return (m(Layout::entry(a, 0)) * f[0] + m(Layout::entry(a, 1)) * f[1]) *
             node_normal(a, b);
    }

    /**
     * The components of mu_1 at node @p a that are contact components: the
     * normal one at a crack node, both at a crack corner, none elsewhere.
     */
    std::vector<unsigned int>
    contact_components(const unsigned int a,
                       const unsigned int b = Layout::across_sigma) const
    {
      if (!crack_nodes[b][a])
        return {};
      if (corner_nodes[b][a])
        return {Layout::tangential, Layout::normal};
      return {Layout::normal};
    }

    /// Component @p c of the gluing multiplier mu_g at node @p a of mu_1
    /// (0 on the crack).
    double
    gluing_multiplier(const dealii::BlockVector<double> &mu,
                      const unsigned int                 a,
                      const unsigned int                 c,
                      const unsigned int b = Layout::across_sigma) const
    {
      return crack_nodes[b][a] ? 0. : mu.block(b)(Layout::entry(a, c));
    }

    /// Segment of the mesh of block @p b containing the coordinate @p x, and
    /// the values of its shape functions there.
    unsigned int
    shape_values(const unsigned int   b,
                 const double         x,
                 std::vector<double> &values) const;

    /// As shape_values(), with the derivatives d/ds of the shape functions
    /// (s the coordinate along Sigma) in @p derivatives.
    unsigned int
    shape_values(const unsigned int   b,
                 const double         x,
                 std::vector<double> &values,
                 std::vector<double> &derivatives) const;

    /// The node of local shape function i of segment e of a mesh with
    /// elements of degree @p degree (vertices first, as FE_Q<1> numbers
    /// them).
    static unsigned int
    node_of(const unsigned int degree,
            const unsigned int e,
            const unsigned int i)
    {
      return i == 0 ? e * degree :
             i == 1 ? (e + 1) * degree :
                      e * degree + i - 1;
    }

    /// The node of block @p b's mesh of local shape function i of segment e.
    unsigned int
    node(const unsigned int e,
         const unsigned int i,
         const unsigned int b = Layout::across_sigma) const
    {
      return node_of(degree(b), e, i);
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
      PerBlock<unsigned int>        degree;
      PerBlock<std::vector<double>> breakpoints;
      dealii::BlockVector<double>   values;
    };

    /// The multipliers @p mu with the current meshes.
    Functions
    functions(const dealii::BlockVector<double> &mu) const;

    /// Interpolate @p old at the current nodes (exact where the new mesh and
    /// degree refine the old ones), then project onto the multiplier sets.
    void
    interpolate(const Functions &old, dealii::BlockVector<double> &mu) const;

  private:
    /// A mesh on Sigma: break points, nodes, D per node, the degree and
    /// element of its multipliers.
    struct Mesh
    {
      std::vector<double> breakpoints, node_x, node_weight, node_mass;
      /// Unit normal of each node (weighted nodal normal).
      std::vector<dealii::Tensor<1, 2>> normal;
      /// The frame of each node (node_frame()).
      std::vector<std::array<dealii::Tensor<1, 2>, 2>> frame;
      std::vector<unsigned int>                        row;
      std::array<bool, 2>                              nodal  = {{true, true}};
      unsigned int                                     degree = 1;
      std::shared_ptr<dealii::FE_Q<1>>                 fe;
      /// psi_i = sum_k dual(i, k) phi_k on every segment.
      dealii::FullMatrix<double> dual;
    };

    /// The nodes of block @p b's mesh with their lumped masses D, weighted
    /// nodal normals and frames, each node its own row.
    void
    place_nodes(const unsigned int b, const InterfaceCurve &curve);

    /// Which of the traces that block @p b couples lie in its multiplier
    /// space (nodal()).
    void
    find_nodal_sides(const unsigned int                  b,
                     const std::vector<InterfaceTraces> &traces,
                     const std::vector<unsigned int>    &degrees,
                     const double                        tol);

    /// The multiplier set of all blocks and the crack and corner nodes of
    /// the blocks across the interfaces (docs/problem.md §3).
    void
    build_set(const std::vector<InterfaceCurve> &curves,
              const ContactParameters           &contact);

    /// The mortar modification at the ends on Gamma_D (row()).
    void
    join_end_rows(const std::vector<InterfaceCurve> &curves);

    /**
     * The ends of the blocks at a point where several interfaces end (a
     * cross-point, where three regions or more meet, or a point of the
     * outer boundary shared by interfaces) whose constraint the others
     * there already imply: the copies of a point that the blocks at it tie
     * together (or to Gamma_D) form a graph, and a block whose two
     * subproblems the blocks before it or Gamma_D already connect has its
     * end removed, as an end on Gamma_D is (the equations of a cycle are
     * linearly dependent: a singular Schur complement). The kept blocks
     * form a spanning forest of the graph. The blocks nodal on both sides
     * (nodal()) come first, in block order, then the mortar blocks: a
     * nodal block's removed end is implied exactly (no jump there), a
     * mortar block's end basis function joins its neighbour's
     * (join_end_rows()), its jump there a discretisation error like its
     * jumps between the nodes.
     */
    void
    drop_cross_point_ends(const std::vector<InterfaceCurve> &curves);

  public:
    /// Whether node @p a of block @p b is an end removed at a point where
    /// several interfaces end (drop_cross_point_ends()).
    bool
    cross_point_end(const unsigned int a, const unsigned int b) const
    {
      return (a == 0 && dropped_ends[b][0]) ||
             (a + 1 == meshes[b].node_x.size() && dropped_ends[b][1]);
    }

  private:
    /// Whether node @p a of block @p b carries no multiplier: an end on
    /// Gamma_D or one dropped at a cross-point.
    bool
    end_removed(const unsigned int    a,
                const unsigned int    b,
                const InterfaceCurve &curve) const;

    Topology       topology_;
    PerBlock<Mesh> meshes;
    /// Per node of each block (none on a gluing block's crack).
    PerBlock<std::vector<bool>> crack_nodes, corner_nodes;
    /// Per block: its first and last node dropped at a cross-point.
    PerBlock<std::array<bool, 2>> dropped_ends;
    /// The bound p of the multiplier sets (Contact/Multiplier bound p).
    double        multiplier_bound = 0;
    MultiplierSet set_;
    /// The set as build_set() made it (the crack's kinds that a cohesive
    /// node takes back once fully damaged).
    MultiplierSet crack_set;
  };
} // namespace bilayer

#endif
