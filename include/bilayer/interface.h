#ifndef bilayer_interface_h
#define bilayer_interface_h

#include <deal.II/fe/fe_q.h>
#include <deal.II/lac/block_vector.h>
#include <deal.II/lac/sparse_matrix.h>
#include <deal.II/lac/sparsity_pattern.h>
#include <deal.II/lac/vector.h>

#include <bilayer/parameters.h>
#include <bilayer/subproblem.h>

#include <algorithm>
#include <array>
#include <memory>
#include <ostream>
#include <vector>

namespace bilayer
{
  using namespace dealii;

  /// The four subproblem solutions, indexed by Interface::index().
  using Solutions = std::array<Vector<double>, 4>;

  /**
   * The relative residual of the KKT conditions of the discrete dual
   * problem at multipliers mu with jumps g (stationarity of the primal
   * variables holds exactly: the subproblems are solved directly). All
   * three parts are scale invariant:
   *  - primal: largest violation of the discrete constraints (|g| where a
   *    jump must vanish, max(g, 0) = penetration at crack nodes) divided by
   *    the displacement scale;
   *  - dual: largest max(-mu_c, 0) divided by max |mu|;
   *  - complementarity: largest |mu_c g| at crack nodes divided by
   *    max |mu| times the displacement scale.
   * A multiplier held at a bound by a jump pushing it outward (at +-p, or
   * mu_c = 0 with an open gap) is optimal for the bounded problem of
   * paper.md §3, so its jump counts as no violation and no
   * complementarity: the residual measures the solution of the problem
   * with the bound p. Whether p is active is checked separately (the
   * constraints are then violated, estimate (12)).
   */
  struct KKTResidual
  {
    double primal = 0, dual = 0, complementarity = 0;

    double
    value() const
    {
      return std::max(primal, std::max(dual, complementarity));
    }
  };

  /**
   * Residuals of a computed solution (paper.md §3 and the KKT conditions of
   * the discrete problem), all evaluated by the Interface.
   */
  struct InterfaceReport
  {
    /// The integral (12) of paper.md, Gauss quadrature on Sigma [length^2].
    double constraint_violation = 0;
    /// (12) divided by the integral of |u-|_1 + |u+|_1 + |v-|_1 + |v+|_1.
    double relative_constraint_violation = 0;
    /// Largest (u- - u+).nu on gamma_c at the Gauss points and nodes [length].
    double max_penetration = 0;
    /// Largest |trace| of the four subproblems on Sigma [length].
    double displacement_scale = 0;
    /// Largest violation of the discrete constraints (jumps that must vanish,
    /// positive penetration at crack nodes) divided by displacement_scale.
    double relative_discrete_violation = 0;
    /// Smallest contact multiplier mu_c (0 without crack nodes) [stress].
    double min_contact_multiplier = 0;
    /// sum m mu_c |jump| / (sum m mu_c * displacement_scale) [-].
    double complementarity = 0;
    /// Largest |multiplier| / p [-].
    double max_multiplier_over_bound = 0;
    /// The relative KKT residual [-].
    KKTResidual kkt;
  };

  /**
   * The interface Sigma: multiplier spaces, interface quadrature and the
   * operators between multipliers and subproblems.
   *
   * <h3>Multipliers</h3>
   * Three vector-valued multipliers (paper.md §3) are stored as the three
   * blocks of a BlockVector, each with entries 2 a + c (node a of its own
   * multiplier mesh on Sigma, component c), continuous Lagrange elements of
   * the degree of layer 1 whose nodes are the Gauss-Lobatto points of each
   * segment:
   *  - block 0, layer 1 across Sigma, on the union of the break points of
   *    the two traces (Omega- and Omega+ faces on Sigma): mu_c nu at nodes
   *    inside the open crack (only the normal component, 0 <= mu_c <= p;
   *    the tangential component is fixed to 0: no friction), mu_g at the
   *    other nodes (-p <= . <= p). The crack tips belong to
   *    Sigma \ gamma_c: they are glued.
   *  - block 1, lambda-, gluing u- to v- on the trace of the Omega- mesh;
   *    block 2, lambda+, gluing u+ to v+ on the trace of the Omega+ mesh
   *    (-p <= . <= p).
   * Why these meshes: u- and v- share the Omega- mesh, so the nodal
   * constraints u- = v- at its trace nodes make the two traces equal, with
   * no redundant constraint; likewise on Omega+. Across Sigma the union
   * mesh is the coarsest one on which both traces are piecewise
   * polynomials: equal values at its nodes make the traces equal (the
   * gluing is conforming, and the contact constraint holds at every node
   * of either side), and the map from the two traces to the jumps at its
   * nodes is onto (no redundant constraint: each node belongs to a trace
   * whose values there are free). On matching meshes the three meshes
   * coincide with the common trace.
   * Nodes on Gamma_D (the ends of Sigma on a clamped side) carry no
   * multipliers (bounds [0, 0]): the Dirichlet condition already enforces
   * the constraints there. Without non-penetration the crack nodes carry no
   * layer-1 multiplier either (the linear problem of Fig. 3).
   *
   * <h3>Coupling</h3>
   * For each block b and each of its two subproblems s the matrix C_s,
   * (C_s)_{2a+c, j} = int_Sigma phi_a psi_j^c ds (phi_a the multiplier
   * basis of block b), maps the dofs of s to the multiplier space of b. The
   * quadrature is either the Gauss-Lobatto rule of the multiplier segments
   * (lumped: C_s = D E_s with E_s the evaluation at the nodes, node-to-node
   * coupling) or a Gauss rule on the common refinement of the multiplier
   * mesh and the trace of s (consistent, mortar coupling). The trace of s at
   * a point of Sigma is found by locating the point among the Sigma faces
   * of s's mesh, so nothing assumes that the Omega- and Omega+ traces match:
   * non-matching meshes only change the breakpoints of the common
   * refinement. D = diag(int_Sigma phi_a ds) is the lumped multiplier mass.
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

    /// Index of subproblem (layer, subdomain) in Solutions: u-, u+, v-, v+.
    static unsigned int
    index(const Layer layer, const Subdomain subdomain)
    {
      return 2 * static_cast<unsigned int>(layer) +
             static_cast<unsigned int>(subdomain);
    }

    /// Build the multiplier mesh and all operators for the given
    /// subproblems (indexed as in index()); without layer 2 its entries are
    /// null, and the blocks of mu- and mu+ have no nodes.
    void
    setup(const std::array<const ElasticSubproblem *, 4> &subproblems);

    /// Zero multipliers of the right sizes.
    void
    initialize(BlockVector<double> &multipliers) const;

    /// The multiplier terms of the four subproblems' loads.
    void
    apply(const BlockVector<double> &multipliers, Solutions &loads) const;

    /// The jumps g (weighted or nodal, zero where no multiplier acts).
    void
    jumps(const Solutions &w, BlockVector<double> &g) const;

    /// Zero the components that carry no multiplier (bounds [0, 0]).
    void
    restrict_to_free(BlockVector<double> &x) const;

    /// Clamp onto the multiplier sets.
    void
    project(BlockVector<double> &multipliers) const;

    /// sum_i D_i x_i y_i over all blocks.
    double
    weighted_dot(const BlockVector<double> &x,
                 const BlockVector<double> &y) const;

    /// sqrt(sum_i D_i x_i^2) over all blocks.
    double
    weighted_norm(const BlockVector<double> &x) const;

    /// Largest violation of the discrete constraints by the jumps g.
    double
    discrete_violation(const BlockVector<double> &g) const;

    /// The traction that the multipliers @p mu apply to subproblem @p s at
    /// the point x of Sigma (the density of its multiplier load).
    Tensor<1, 2>
    multiplier_traction(const BlockVector<double> &mu,
                        const unsigned int         s,
                        const double               x) const;

    /// A segment [a, b] of the multiplier mesh of mu_1 on the crack with the
    /// value int_a^b mu_c [u].nu ds (Simpson's rule on the nodal values).
    struct ContactSegment
    {
      double a, b, complementarity;
    };

    /**
     * The complementarity density of the contact pair per segment of the
     * mu_1 mesh that touches the crack. The discrete constraints hold at
     * the nodes, so mu_c [u].nu vanishes at every node; between nodes it
     * does not where the contact zone ends inside a segment (mu_c > 0 at
     * one end, an open gap at the other): the term marks the end of the
     * contact zone for refinement.
     */
    std::vector<ContactSegment>
    contact_residual(const Solutions &w, const BlockVector<double> &mu) const;

    /// The relative KKT residual of multipliers @p mu with solutions @p w
    /// and their jumps @p g.
    KKTResidual
    kkt_residual(const Solutions           &w,
                 const BlockVector<double> &g,
                 const BlockVector<double> &mu) const;

    /// x_i <- D_i x_i, or x_i / D_i with @p inverse.
    void
    scale_by_weights(BlockVector<double> &x, const bool inverse = false) const;

    /// Lower and upper bounds of the multipliers (equal where a component
    /// carries no multiplier).
    const BlockVector<double> &
    lower_bounds() const
    {
      return lower;
    }
    const BlockVector<double> &
    upper_bounds() const
    {
      return upper;
    }

    /**
     * The Gram matrix G = B B^T of the signed coupling B (the map from the
     * four subproblems' dofs to the multiplier space whose transpose is
     * -apply(); B w = D g for weighted jumps), restricted to the components
     * i with mask(i) != 0: the other rows and columns are those of the
     * identity. Global index of component i of block b: b * block size + i.
     * Scales the FETI-type preconditioners of the dual problem.
     */
    void
    coupling_gram(const BlockVector<double> &mask,
                  SparsityPattern           &pattern,
                  SparseMatrix<double>      &gram) const;

    /// Largest |trace value| at the nodes of the four subproblems.
    double
    displacement_scale(const Solutions &w) const;

    /// The normal opening [u].nu = (u+ - u-).nu of layer 1 at every node.
    std::vector<double>
    normal_opening(const Solutions &w) const;

    InterfaceReport
    assess(const Solutions &w, const BlockVector<double> &multipliers) const;

    /// One row per multiplier node: x, jumps, gaps, multipliers, traces.
    void
    write_csv(std::ostream              &out,
              const Solutions           &w,
              const BlockVector<double> &multipliers) const;

    /// Nodes of block 0 (the layer-1 multiplier).
    unsigned int
    n_nodes() const
    {
      return meshes[0].node_x.size();
    }

    /// Multiplier components that are not fixed to zero.
    unsigned int
    n_multipliers() const;

    /// Position x of node a of the layer-1 multiplier (block 0).
    double
    node_position(const unsigned int a) const
    {
      return meshes[0].node_x[a];
    }

    /// Whether node a of block 0 lies strictly inside the crack.
    bool
    node_on_crack(const unsigned int a) const
    {
      return on_crack[a];
    }

    /**
     * The multipliers as functions on Sigma, kept to warm-start the next
     * mesh: the break points, degree and nodal values of each block.
     */
    struct MultiplierFunctions
    {
      unsigned int                       degree = 0;
      std::array<std::vector<double>, 3> breakpoints;
      BlockVector<double>                values;
    };

    /// The multipliers @p mu with the current multiplier meshes.
    MultiplierFunctions
    functions(const BlockVector<double> &mu) const;

    /// Interpolate @p old at the current multiplier nodes (same degree:
    /// exact on nested refinements of the multiplier meshes), then project
    /// onto the multiplier sets.
    void
    interpolate(const MultiplierFunctions &old, BlockVector<double> &mu) const;

    /// Whether subproblem @p s exists (layer 2 may be absent).
    bool
    present(const unsigned int s) const
    {
      return subproblems[s] != nullptr;
    }

    /// Whether both subproblems of multiplier block @p b exist.
    bool
    active(const unsigned int b) const;

  private:
    /// A face of one subdomain mesh on Sigma.
    struct SigmaFace
    {
      double                                 x0, x1;
      Triangulation<2>::active_cell_iterator cell;
      /// Unit-cell coordinates of the face ends at x0 and x1.
      Point<2> unit0, unit1;
    };

    /// A matrix with its own sparsity pattern.
    struct PointMatrix
    {
      SparsityPattern      pattern;
      SparseMatrix<double> matrix;
    };

    /// Sorted Sigma faces of a mesh.
    static std::vector<SigmaFace>
    sigma_faces(const Triangulation<2> &tria, const double sigma_height);

    /**
     * The matrix with rows 2 r + c whose product with the dofs of
     * subproblem s gives sum_k weight_k * (component c of the trace at x_k),
     * for the entries (r, x_k, weight_k) of @p points.
     */
    void
    build_point_matrix(
      const unsigned int                                           s,
      const std::vector<std::tuple<unsigned int, double, double>> &points,
      const unsigned int                                           n_rows,
      PointMatrix &result) const;

    /// Segment of the multiplier mesh of block @p b containing x, and the
    /// shape values there.
    unsigned int
    multiplier_shape_values(const unsigned int   b,
                            const double         x,
                            std::vector<double> &values) const;

    /// The global multiplier node of local shape function i of segment e.
    unsigned int
    multiplier_node(const unsigned int e, const unsigned int i) const
    {
      return i == 0 ? e * degree :
             i == 1 ? (e + 1) * degree :
                      e * degree + i - 1;
    }

    /// g = a - b, scaled by D^{-1} for the weighted sampling, masked.
    void
    difference(const Vector<double> &a,
               const Vector<double> &b,
               const unsigned int    block,
               BlockVector<double>  &g) const;

    const GeometryParameters geometry;
    const ContactParameters  contact;

    std::array<const ElasticSubproblem *, 4> subproblems;
    std::array<std::vector<SigmaFace>, 2>    faces;

    /// A multiplier mesh on Sigma: break points, nodes, D per node.
    struct MultiplierMesh
    {
      std::vector<double> breakpoints, node_x, node_weight;
    };

    unsigned int             degree = 1;
    std::unique_ptr<FE_Q<1>> fe_multiplier;
    /// Per block: mu_1 on the union of the two traces, mu- on the trace of
    /// the Omega- mesh, mu+ on that of the Omega+ mesh.
    std::array<MultiplierMesh, 3> meshes;
    /// Per node of block 0.
    std::vector<bool>   on_crack;
    BlockVector<double> lower, upper;

    /// C and E (evaluation at the nodes) of the two subproblems that each
    /// block couples (first, second: u- and u+, u- and v-, u+ and v+).
    std::array<std::array<PointMatrix, 2>, 3> coupling, evaluation;
    /// Traces of the four subproblems at the nodes of block 0.
    std::array<PointMatrix, 4> node_traces;
    /// Traces at the Gauss points of the common refinement (diagnostics).
    std::array<PointMatrix, 4> gauss_traces;
    std::vector<double>        gauss_x, gauss_weight;
  };
} // namespace bilayer

#endif
