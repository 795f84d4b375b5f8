#ifndef bilayer_trace_coupling_h
#define bilayer_trace_coupling_h

#include <deal.II/grid/tria.h>
#include <deal.II/lac/block_vector.h>
#include <deal.II/lac/sparse_matrix.h>
#include <deal.II/lac/sparsity_pattern.h>
#include <deal.II/lac/vector.h>

#include <bilayer/core/layout.h>
#include <bilayer/geometry/interface_curve.h>
#include <bilayer/interface/multiplier_space.h>
#include <bilayer/subproblem/subproblem.h>

#include <tuple>
#include <vector>

namespace bilayer
{
  /// The subproblem solutions (or loads), indexed by Topology::index().
  using Solutions = PerSubproblem<dealii::Vector<double>>;

  /**
   * The coupling of the multiplier spaces to the traces of the subproblems
   * on the interfaces.
   *
   * For each block b and each of its two subproblems s (Topology::coupling())
   * the matrix C_s, (C_s)_{2a+c, j} = int_Sigma phi_a psi_j^c ds (phi_a the
   * multiplier basis of block b), maps the dofs of s to the multiplier space
   * of b. Lumped coupling: phi_a is the dual (biorthogonal) basis psi_a of
   * MultiplierSpace; where the trace of s lies in the multiplier space
   * (MultiplierSpace::nodal: the slave of b, matching and nested traces)
   * this is exactly C_s = D E_s with E_s the evaluation at the nodes, else a
   * Gauss rule on the common refinement of the multiplier mesh and the
   * trace of s (the mortar projection). Consistent coupling: the Lagrange
   * basis, Gauss rule on the common refinement (standard mortar). On the
   * slave of b (the subproblem whose trace carries b's mesh, see
   * MultiplierSpace) C_s is D times the identity on its trace dofs (lumped,
   * same degree) or a local mass matrix. Rows follow MultiplierSpace::row
   * (the mortar modification at the ends on Gamma_D). The
   * trace of s at a point of Sigma is found by locating the point among the
   * Sigma faces of s's mesh, so nothing assumes that the Omega- and Omega+
   * traces match: non-matching meshes only change the break points of the
   * common refinement. D = diag(int_Sigma phi_a ds) is the lumped multiplier
   * mass of MultiplierSpace.
   *
   * It also evaluates the traces of every subproblem at the nodes of the
   * block across each interface that it touches and at the Gauss points of
   * the common refinement of the interface's two traces, where every trace
   * is a polynomial, which the diagnostics use. Sigma is interface 0, and
   * every such function without an interface argument is Sigma's.
   */
  class TraceCoupling
  {
  public:
    /// Take the subproblems @p subs of @p topology (null where absent),
    /// find the faces of each region's mesh on each interface and return
    /// the break points of the two traces of each interface (values of the
    /// parameter s of its curve in @p curves, which must outlive this
    /// object's use), from which the multiplier spaces are built.
    const std::vector<InterfaceTraces> &
    locate_traces(const Topology                                 &topology,
                  const PerSubproblem<const ElasticSubproblem *> &subs,
                  const std::vector<InterfaceCurve>              &curves);

    /// Build every matrix for the multiplier spaces @p space (after
    /// locate_traces()).
    void
    reinit(const MultiplierSpace   &space,
           const MultiplierCoupling coupling,
           const double             tolerance);

    /// The number of subproblems (2 per layer slot).
    unsigned int
    n_subproblems() const
    {
      return subproblems.size();
    }

    /// Whether subproblem @p s exists (layer 2 may be absent).
    bool
    present(const unsigned int s) const
    {
      return subproblems[s] != nullptr;
    }

    /// Whether both subproblems of multiplier block @p b exist.
    bool
    active(const unsigned int b) const
    {
      const Coupling c = topology.coupling(b);
      return present(c.first) && present(c.second);
    }

    /// loads[s] = sum over the blocks b coupling s of -+ C_s^T mu_b (minus
    /// for the first subproblem of b, plus for the second).
    void
    apply_transpose(const dealii::BlockVector<double> &mu,
                    Solutions                         &loads) const;

    /// Block b of the result is C_first w_first - C_second w_second
    /// (@p weighted) or E_first w_first - E_second w_second.
    void
    differences(const Solutions             &w,
                const bool                   weighted,
                dealii::BlockVector<double> &result) const;

    /// The traces of layer 1's two crack faces of interface @p i, the
    /// region below into @p minus and the one above into @p plus, at the
    /// nodes of the block across it (trace_at_nodes()): the one place that
    /// reads them.
    void
    crack_face_traces(const Solutions        &w,
                      dealii::Vector<double> &minus,
                      dealii::Vector<double> &plus,
                      const unsigned int      i = 0) const
    {
      const Coupling c = topology.coupling(i);
      trace_at_nodes(c.first, w[c.first], minus, i);
      trace_at_nodes(c.second, w[c.second], plus, i);
    }

    /// Whether subproblem @p s has a trace on interface @p i (its region
    /// lies on one side of it).
    bool
    touches(const unsigned int s, const unsigned int i) const
    {
      return present(s) && topology.joins(i, topology.region(s));
    }

    /// The trace of subproblem @p s at the nodes of the block across
    /// interface @p i: entries Layout::entry(a, c).
    void
    trace_at_nodes(const unsigned int            s,
                   const dealii::Vector<double> &w,
                   dealii::Vector<double>       &trace,
                   const unsigned int            i = 0) const;

    /// The trace of subproblem @p s at the Gauss points of interface @p i.
    void
    trace_at_gauss_points(const unsigned int            s,
                          const dealii::Vector<double> &w,
                          dealii::Vector<double>       &trace,
                          const unsigned int            i = 0) const;

    /// Gauss points of the common refinement of the two traces of
    /// interface @p i (coordinates along it, weights).
    const std::vector<double> &
    gauss_points(const unsigned int i = 0) const
    {
      return gauss[i].x;
    }
    const std::vector<double> &
    gauss_weights(const unsigned int i = 0) const
    {
      return gauss[i].weight;
    }

    /**
     * The Gram matrix G = B B^T of the signed coupling B (+C on the first,
     * -C on the second subproblem of each block), restricted to the
     * components i with mask(i) != 0: the other rows and columns are those
     * of the identity. Global index of component i of block b: the sizes of
     * the blocks before b plus i.
     */
    void
    gram(const dealii::BlockVector<double> &mask,
         dealii::SparsityPattern           &pattern,
         dealii::SparseMatrix<double>      &gram) const;

  private:
    /// A face of one subdomain mesh on Sigma.
    struct SigmaFace
    {
      double                                         x0, x1;
      dealii::Triangulation<2>::active_cell_iterator cell;
      /// Unit-cell coordinates of the face ends at x0 and x1.
      dealii::Point<2> unit0, unit1;
    };

    /// A matrix with its own sparsity pattern.
    struct PointMatrix
    {
      dealii::SparsityPattern      pattern;
      dealii::SparseMatrix<double> matrix;
    };

    /// The Gauss points of interface @p i (@p rule on each segment of the
    /// common refinement of its two traces) and the traces there.
    void
    build_gauss_traces(const unsigned int           i,
                       const dealii::Quadrature<1> &rule,
                       const double                 tol);

    /// Sorted faces of a mesh on interface @p i (by the parameter s of
    /// @p curve).
    static std::vector<SigmaFace>
    sigma_faces(const dealii::Triangulation<2> &tria,
                const InterfaceCurve           &curve,
                const unsigned int              i);

    /**
     * The matrix with rows 2 r + c whose product with the dofs of
     * subproblem s gives sum_k weight_k * (component c of the trace at x_k),
     * for the entries (r, x_k, weight_k) of @p points; component c is the
     * trace's component along @p frames[r][c] (multiplier rows: their
     * node's frame, MultiplierSpace::node_frame; the traces at the nodes
     * and at the Gauss points: (tangent, normal) of the node's normal and
     * of the curve's, the tangent being the normal turned by -90 degrees).
     */
    void
    build_point_matrix(
      const unsigned int                                           s,
      const unsigned int                                           i,
      const std::vector<std::tuple<unsigned int, double, double>> &points,
      const std::vector<std::array<dealii::Tensor<1, 2>, 2>>      &frames,
      PointMatrix &result) const;

    Topology                                 topology;
    PerSubproblem<const ElasticSubproblem *> subproblems;
    const std::vector<InterfaceCurve>       *curves = nullptr;
    /// The faces of each interface's two sides.
    std::vector<std::array<std::vector<SigmaFace>, 2>> faces;
    /// The break points of each interface's two traces (the ends of faces).
    std::vector<InterfaceTraces> traces;

    /// C and E (evaluation at the nodes) of the two subproblems that each
    /// block couples (Topology::coupling(b): first, second).
    PerBlock<std::array<PointMatrix, 2>> coupling, evaluation;
    /// Per interface: the traces of the subproblems at the nodes of the
    /// block across it.
    std::vector<PerSubproblem<PointMatrix>> node_traces;
    /// Per interface: the traces at the Gauss points of the common
    /// refinement, and those points.
    std::vector<PerSubproblem<PointMatrix>> gauss_traces;
    struct GaussRule
    {
      std::vector<double> x, weight;
    };
    std::vector<GaussRule> gauss;
  };
} // namespace bilayer

#endif
