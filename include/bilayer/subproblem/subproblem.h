#ifndef bilayer_subproblem_h
#define bilayer_subproblem_h

#include <deal.II/base/function.h>
#include <deal.II/dofs/dof_handler.h>
#include <deal.II/fe/fe_system.h>
#include <deal.II/fe/mapping.h>
#include <deal.II/lac/affine_constraints.h>
#include <deal.II/lac/sparse_matrix.h>
#include <deal.II/lac/sparsity_pattern.h>
#include <deal.II/lac/vector.h>

#include <bilayer/core/boundary_ids.h>
#include <bilayer/physics/elastic_law.h>
#include <bilayer/physics/plies.h>
#include <bilayer/physics/volume_load.h>
#include <bilayer/subproblem/cell_extents.h>
#include <bilayer/subproblem/cholesky.h>
#include <bilayer/subproblem/distributed_system.h>
#include <bilayer/subproblem/distribution.h>

#include <array>
#include <memory>
#include <string>

namespace bilayer
{
  /**
   * One of the four linear elasticity subproblems of docs/problem.md §2: one
   * layer (u or v) on one subdomain (Omega- or Omega+), sigma(w) = C eps(w)
   * with the layer's ElasticLaw.
   *
   * It owns its FESystem (two Lagrange components of the layer's degree, on
   * quadrilaterals or triangles as the mesh has), its DoFHandler and its
   * constraints (hanging nodes and the prescribed displacement on its part
   * of Gamma_D). setup() assembles and factorises the matrix once; solve()
   * then only costs a forward/back substitution:
   *
   *   a(w, z) = (F, z) + (c, z)   for all z,
   *
   * where F holds the tractions on Gamma_N and the volume terms (a
   * VolumeLoad, where given), and c is any extra load vector
   * given in the unconstrained dof numbering (the interface's multiplier
   * terms). The subproblem knows nothing of the coupling.
   *
   * In an MPI job (see Distribution) every process builds the dof numbering
   * and the constraints of every subproblem, but only the owners of a
   * subproblem assemble, factorise and solve it; share_trace() then sends
   * the values on Sigma to the other processes. A subproblem owned by a
   * group of processes (more than four in all) is assembled and factorised
   * by the group as a DistributedSystem (Trilinos, METIS, a parallel direct
   * solver @p shared_solver of Amesos); its vectors stay whole on every
   * process of the group.
   */
  class ElasticSubproblem
  {
  public:
    /// The subproblem of one material (one ply).
    ElasticSubproblem(const Layer                     layer,
                      const Subdomain                 subdomain,
                      const dealii::Triangulation<2> &triangulation,
                      const unsigned int              degree,
                      const LayerMaterial            &material,
                      const Distribution &distribution = Distribution::world())
      : ElasticSubproblem(layer,
                          subdomain,
                          triangulation,
                          degree,
                          std::vector<LayerMaterial>{material},
                          {},
                          distribution)
    {}

    /// The subproblem of the plies @p plies of @p materials (PlyLaws), on
    /// region @p subdomain of a scene of @p n_regions regions (Topology;
    /// Omega- and Omega+ of Sigma: 0 and 1 of 2).
    ElasticSubproblem(const Layer                       layer,
                      const Subdomain                   subdomain,
                      const dealii::Triangulation<2>   &triangulation,
                      const unsigned int                degree,
                      const std::vector<LayerMaterial> &materials,
                      const PlyDivision                &plies,
                      const Distribution &distribution = Distribution::world(),
                      const unsigned int  n_regions    = 2);

    /**
     * Distribute dofs, build constraints, assemble the stiffness matrix and
     * the load vector, factorise. @p traction[side] is used on the sides
     * that are not clamped; @p prescribed on the clamped ones; @p volume
     * (if not null) adds its volume terms to the load and the constant E*
     * of an eigenstrain to energy(); it is kept (volume_load(): the
     * stresses, G and the error estimator read it) and must outlive the
     * subproblem's solutions.
     */
    void
    setup(const std::vector<bool>                        &clamped,
          const dealii::Function<2>                      &prescribed,
          const std::vector<const dealii::Function<2> *> &traction,
          const std::string &shared_solver     = "Amesos_Mumps",
          const bool         condense_on_sigma = false,
          const VolumeLoad  *volume            = nullptr);

    /**
     * Whether setup() kept the Schur complement of the stiffness matrix on
     * the Sigma dofs (asked for with @p condense_on_sigma; not for a
     * subproblem shared by a group, nor where its dense factor would be
     * larger than the sparse one, nor where a constrained Sigma dof depends
     * on dofs off Sigma): then solve_on_sigma() and
     * apply_schur_complement() are available. Only on the owners.
     */
    bool
    condensed() const
    {
      return factorisation.schur_complement() != nullptr;
    }

    /// The number of Sigma dofs of the Schur complement (0 if not
    /// condensed()).
    unsigned int
    n_schur_dofs() const
    {
      return condensed() ? factorisation.schur_complement()->size() : 0;
    }

    /**
     * With condensed(): the values on the dofs of the Sigma faces of
     * solve() (or, with @p homogeneous, of solve_homogeneous()) for a load
     * @p coupling that is zero off the Sigma dofs, as the interface's
     * multiplier terms are. Two dense triangular solves with the factor of
     * the Schur complement S: the Sigma part of K^{-1} c is S^{-1} c. The
     * other entries of @p solution are those of the solution without
     * coupling (or zero): not the solution there.
     */
    /// solve_on_sigma() with @p homogeneous for the loads @p couplings at
    /// once (SchurComplementFactor::solve_many()).
    void
    solve_homogeneous_on_sigma(
      const std::vector<const dealii::Vector<double> *> &couplings,
      std::vector<dealii::Vector<double>>               &solutions) const;

    void
    solve_on_sigma(const dealii::Vector<double> &coupling,
                   dealii::Vector<double>       &solution,
                   const bool                    homogeneous) const;

    /**
     * With condensed(): y = S x on the unconstrained Sigma dofs (zero
     * elsewhere), S = K_SS - K_SI K_II^{-1} K_IS the Schur complement of
     * the stiffness matrix (the reaction on Sigma of the discrete-harmonic
     * extension of the Sigma values of @p x).
     */
    void
    apply_schur_complement(const dealii::Vector<double> &x,
                           dealii::Vector<double>       &y) const;

    /**
     * Whether the subproblem floats: no side of it is clamped, so its
     * stiffness has the rigid motions (two translations and a rotation) as
     * kernel. setup() then holds three anchor dofs at zero (both components
     * at one support point near the middle, one component at the support
     * point farthest from it), which makes the factorised matrix K~
     * non-singular: K~^{-1} b solves K w = b wherever the load b is in
     * equilibrium (R^T b = 0, R the rigid motions), since the anchors' three
     * reactions then balance each other and vanish. Where it is not, the
     * anchors carry the out-of-balance force and moment: the reactions that
     * FloatingParts (solvers/floating_parts.h) drives to zero by moving the
     * anchors (set_anchor_displacements()).
     */
    bool
    floating() const
    {
      return !anchors_.empty();
    }

    /// With floating(): the three anchor dofs.
    const std::vector<dealii::types::global_dof_index> &
    anchors() const
    {
      return anchors_;
    }

    /**
     * With floating(), on an owner: E_k, the rigid motion with a unit
     * displacement of anchor k and zero at the other two, interpolated at
     * the support points where the element space holds the rigid motions
     * (K E_k = 0 to round-off: Lagrange elements on straight cells,
     * isoparametric ones); otherwise the discrete-harmonic extension of
     * those anchor values (the solution without load).
     */
    const dealii::Vector<double> &
    anchor_mode(const unsigned int k) const
    {
      return anchor_modes[k];
    }

    /// With floating(): the support point of anchor @p k and the component
    /// (0: x, 1: y) it holds.
    std::pair<dealii::Point<2>, unsigned int>
    anchor_place(const unsigned int k) const
    {
      return anchor_places[k];
    }

    /// With floating(): the anchors' displacements alpha (zero after
    /// setup()). solve() and solve_on_sigma() (not the homogeneous solves)
    /// add sum_k alpha_k E_k: the anchors prescribed at alpha.
    void
    set_anchor_displacements(const std::array<double, 3> &alpha);

    const std::array<double, 3> &
    anchor_displacements() const
    {
      return anchor_values;
    }

    /**
     * With floating(), on an owner: the reactions at the three anchors,
     * (K w - b) at the anchor dofs, K the unconstrained stiffness, of a
     * solution w of the anchored problem with the load @p b (its load()
     * plus the multiplier terms for a state) and the anchors at
     * @p alpha. Since K w - b vanishes off the anchors and K E_k off them
     * too, E_k^T (K w - b) is the reaction r_k, and it equals
     * sum_j Q_jk alpha_j - E_k^T b, Q_jk = (K E_k)(a_j) (zero where the
     * element space holds the rigid motions exactly): no use of w. With
     * @p sigma_only, @p b is taken to vanish off the Sigma dofs (multiplier
     * terms) and the products run over those alone.
     */
    std::array<double, 3>
    anchor_reactions(const std::array<double, 3>  &alpha,
                     const dealii::Vector<double> &b,
                     const bool                    sigma_only = false) const;

    /// Whether a group of processes shares it (DistributedSystem).
    bool
    distributed() const
    {
      return shared != nullptr;
    }

    /// With distributed(): the matrices of the group.
    const DistributedSystem &
    distributed_system() const
    {
      return *shared;
    }

    /// Whether this process assembles, factorises and solves it.
    bool
    owned() const
    {
      return distribution.owns(index());
    }

    /// Position in every per-subproblem array (Topology::index()).
    unsigned int
    index() const
    {
      return Topology(n_regions).index(layer_,
                                       static_cast<unsigned int>(subdomain_));
    }

    const Distribution &
    processes() const
    {
      return distribution;
    }

    /**
     * Send the values of @p w on the dofs of the Sigma faces from the
     * owner to all processes (collective; nothing to do in a serial run).
     * On the other processes @p w is sized n_dofs() and its other entries
     * stay as they are: the interface reads only these.
     */
    void
    share_trace(dealii::Vector<double> &w) const;

    /// Solve with the extra load vector @p coupling (may be empty = zero).
    /// With condensed(), @p coupling must vanish off the Sigma dofs (the
    /// interface's multiplier terms do): the solution is that without
    /// coupling plus the half-cost solve of solve_from_trailing().
    void
    solve(const dealii::Vector<double> &coupling,
          dealii::Vector<double>       &solution) const;

    /// Solve with the load @p coupling only: no tractions, zero prescribed
    /// displacement (the linear part of the solution map).
    void
    solve_homogeneous(const dealii::Vector<double> &coupling,
                      dealii::Vector<double>       &solution) const;

    /// K^{-1} @p load with the homogeneous constraints, for a load
    /// anywhere (not only on Sigma: the whole factorisation, also where
    /// condensed()); the dual problems of goal-oriented estimates.
    void
    solve_load(const dealii::Vector<double> &load,
               dealii::Vector<double>       &solution) const;

    /// a(w, w) = int sigma(w) : eps(w) dx [energy].
    double
    energy_norm_squared(const dealii::Vector<double> &w) const;

    /**
     * Pi(w) = a(w, w) / 2 - (F, w) + E* [energy], with E* =
     * 1/2 int eps* : C eps* dx the constant of an eigenstrain (0 without
     * one): the potential energy of the eigenstrained body,
     * 1/2 int (eps(w) - eps*) : C (eps(w) - eps*) dx - int f . w dx - the
     * work of the tractions.
     */
    double
    energy(const dealii::Vector<double> &w) const;

    /**
     * Scale the proportional load by @p lambda (any finite number; setup()
     * leaves lambda = 1): the load becomes lambda F_1 + F_pre, with F_1 the
     * tractions, the body force and the prescribed displacement (the
     * inhomogeneities of the constraints, and with them their terms in
     * the right-hand side, scaled by lambda) and F_pre the preload, the
     * terms sigma(eps*) : eps(z) of an eigenstrain (thermal strain
     * included). Both parts come from the one assembly of setup(); the
     * matrix and its factorisation are kept (n_factorisations() does not
     * change), and solve(), solve_on_sigma() (its solution without
     * coupling, one more forward/back substitution) and energy() use the
     * scaled load. lambda = 1 restores the vectors of setup() bit for bit.
     * The body force that the energy release rate and the estimator read
     * is the VolumeLoad's (a ScaledVolumeLoad, which Study scales along).
     * A subproblem shared by a group of processes (distributed(): more
     * than four processes) refuses lambda != 1. Every process calls it
     * (the constraints of every subproblem are kept everywhere).
     * @p preload scales F_pre the same way (Loads/Load factor scales =
     * thermal or all: the load becomes lambda F_1 + preload F_pre; it
     * scales nothing in a subproblem without a preload).
     */
    void
    set_load_factor(const double lambda, const double preload = 1);

    /// The load factor of set_load_factor() (1 after setup()).
    double
    load_factor() const
    {
      return load_factor_;
    }

    /**
     * (F_1, w) [energy]: the work of the unit proportional load (tractions
     * and body force at lambda = 1) on @p w, the displacement conjugate to
     * lambda where the loads are forces (d Pi / d lambda = -(F_1, w) at
     * equilibrium). For a prescribed displacement it is the force part
     * only: the work of the reactions on Gamma_D is not in it. Owners
     * only; refused for a distributed() subproblem with a preload.
     */
    double
    load_work(const dealii::Vector<double> &w) const;

    /// (F_pre, w): the work of the preload on @p w (0 without one); owners
    /// of a subproblem not shared only.
    double
    preload_work(const dealii::Vector<double> &w) const;

    /// Whether the load has a preload part F_pre (an eigenstrain or a
    /// thermal strain), which set_load_factor() leaves unscaled.
    bool
    has_preload() const
    {
      return has_preload_;
    }

    /// The VolumeLoad that setup() was given (null: none).
    const VolumeLoad *
    volume_load() const
    {
      return volume_;
    }

    /// The constraints of solve_homogeneous(): the hanging nodes and zero
    /// displacement on the clamped sides.
    const dealii::AffineConstraints<double> &
    zero_displacement_constraints() const
    {
      return homogeneous_constraints;
    }

    /// The centres and diameters of the active cells (set up once per
    /// mesh).
    const CellExtents &
    cell_extents() const
    {
      return extents;
    }

    /// The dofs on Sigma, in increasing order (set up once per mesh).
    const std::vector<dealii::types::global_dof_index> &
    trace_dofs() const
    {
      return trace_dofs_;
    }

    /// The unconstrained stiffness matrix K (not with distributed(): the
    /// group holds it, see distributed_system()).
    const dealii::SparseMatrix<double> &
    stiffness_matrix() const
    {
      return stiffness;
    }

    /// The load vector F in the unconstrained numbering (tractions, body
    /// forces and preload at the present load factor; owners of a
    /// subproblem not distributed() only).
    const dealii::Vector<double> &
    load() const
    {
      return load_vector;
    }

    /// y = K x, the unconstrained stiffness (collective in the group with
    /// distributed()).
    void
    multiply_stiffness(dealii::Vector<double>       &y,
                       const dealii::Vector<double> &x) const;

    /**
     * With distributed(): the stiffness matrix under other @p constraints
     * (e.g. more dofs held at zero), assembled by the group on the
     * partition of distributed_system() and factorised by its parallel
     * direct solver (collective in the group).
     */
    std::unique_ptr<DistributedSystem>
    factorise_in_group(
      const dealii::AffineConstraints<double> &constraints) const;

    /// "u-", "u+", "v-" or "v+".
    std::string
    name() const;

    Layer
    layer() const
    {
      return layer_;
    }
    Subdomain
    subdomain() const
    {
      return subdomain_;
    }
    /// The region (Topology; Omega-, Omega+: 0, 1) and the scene's number
    /// of regions.
    unsigned int
    region() const
    {
      return static_cast<unsigned int>(subdomain_);
    }
    unsigned int
    regions() const
    {
      return n_regions;
    }
    const dealii::DoFHandler<2> &
    dof_handler() const
    {
      return dofs;
    }
    const dealii::FiniteElement<2> &
    fe() const
    {
      return *fe_system;
    }
    /// The mapping: linear, or MappingQ of the element's degree on
    /// quadrilaterals of degree >= 2 when the mesh has curved (non-flat)
    /// manifolds, so that curved boundaries and a curved Sigma are
    /// approximated to the element's order (isoparametric).
    const dealii::Mapping<2> &
    mapping() const;
    /// The elastic law of @p cell (the one code that knows its material).
    const ElasticLaw &
    law(const dealii::CellAccessor<2, 2> &cell) const
    {
      return laws_.law(cell);
    }

    /// The elastic laws by ply.
    const PlyLaws &
    laws() const
    {
      return laws_;
    }

    /// The law of the cells on interface @p i next to @p point (a crack
    /// tip: the ply of the cell with the face on the interface nearest to
    /// it).
    const ElasticLaw &
    interface_law(const unsigned int i, const dealii::Point<2> &point) const
    {
      return laws_.law(laws_.ply_on_boundary(dof_handler().get_triangulation(),
                                             BoundaryIds::interface(i),
                                             &point));
    }
    unsigned int
    n_dofs() const
    {
      return dofs.n_dofs();
    }
    /// How many times setup() has assembled and factorised the matrix (on
    /// an owner of the subproblem).
    unsigned int
    n_factorisations() const
    {
      return factorisations;
    }
    /// Wall time of assembly and of factorisation in setup() [s].
    double assembly_seconds      = 0;
    double factorisation_seconds = 0;

    /// The orderings the next setup() tries (Solver/Ordering).
    void
    set_ordering(const SparseCholesky::OrderingChoice choice)
    {
      factorisation.set_ordering(choice);
    }
    /// What the last setup()'s analysis found (on an owner that factorises
    /// alone; empty otherwise).
    const SparseCholesky::OrderingReport &
    ordering_report() const
    {
      return factorisation.ordering_report();
    }

  private:
    /// With condensed(): the load @p coupling (zero off the Sigma dofs)
    /// condensed onto the unconstrained Sigma dofs, in the order of the
    /// Schur factor.
    std::vector<double>
    condensed_load(const dealii::Vector<double> &coupling) const;
    /// With condensed(): @p solution = K^{-1} @p coupling with the
    /// homogeneous constraints (the load zero off the Sigma dofs).
    void
    solve_coupling(const dealii::Vector<double> &coupling,
                   dealii::Vector<double>       &solution) const;
    void
    assemble(const std::vector<bool>                        &clamped,
             const std::vector<const dealii::Function<2> *> &traction,
             const VolumeLoad                               *volume);

    const Layer     layer_;
    const Subdomain subdomain_;
    /// The regions of the scene (Topology): the subproblem's index.
    const unsigned int                 n_regions;
    PlyLaws                            laws_;
    std::string                        moduli_entries_; // named on overflow
    unsigned int                       factorisations = 0;
    const Distribution                &distribution;
    std::string                        shared_solver;
    std::unique_ptr<DistributedSystem> shared;
    /// The dofs on the faces on Sigma (glued and crack), constrained ones
    /// included: the support of every trace the interface evaluates.
    std::vector<dealii::types::global_dof_index> trace_dofs_;
    CellExtents                                  extents;
    std::unique_ptr<dealii::FESystem<2>>         fe_system;
    std::unique_ptr<dealii::Mapping<2>>          curved_mapping;
    dealii::DoFHandler<2>                        dofs;
    dealii::AffineConstraints<double>            constraints;
    dealii::AffineConstraints<double>            homogeneous_constraints;
    dealii::SparsityPattern                      sparsity;
    dealii::SparseMatrix<double>                 system_matrix;
    dealii::SparseMatrix<double>                 stiffness;
    dealii::Vector<double>                       system_rhs;
    /// The load F of tractions and volume terms (energy()).
    dealii::Vector<double> load_vector;
    SparseCholesky         factorisation;
    /// With condensed(): the solution without coupling (tractions and
    /// prescribed displacement), and for the Sigma dofs their position in
    /// the Schur complement's order: unconstrained ones directly,
    /// constrained ones (hanging nodes, Gamma_D) through the positions and
    /// weights of their constraint.
    dealii::Vector<double> particular;
    std::vector<std::pair<dealii::types::global_dof_index, unsigned int>>
      sigma_positions;
    struct ConstrainedSigmaDof
    {
      dealii::types::global_dof_index              dof;
      std::vector<std::pair<unsigned int, double>> entries;
    };
    std::vector<ConstrainedSigmaDof> constrained_sigma_dofs;

    /// With floating(): the anchor dofs (hanging-node free, off Sigma
    /// where possible), their modes E_k (owners) and displacements.
    std::vector<dealii::types::global_dof_index> anchors_;
    std::array<dealii::Vector<double>, 3>        anchor_modes;
    std::array<double, 3>                        anchor_values = {{0, 0, 0}};
    /// Q_jk = (K E_k)(a_j) (owners).
    std::array<std::array<double, 3>, 3> anchor_stiffness = {};
    std::array<std::pair<dealii::Point<2>, unsigned int>, 3> anchor_places;
    /// In setup(): the hanging nodes, the anchors of a floating subproblem
    /// and the clamped sides (prescribed and zero), closed.
    void
    make_constraints(const std::vector<bool>   &clamped,
                     const dealii::Function<2> &prescribed);
    /// In setup(), with the hanging-node constraints made: the anchors of a
    /// subproblem none of whose sides in @p clamped is clamped (none
    /// otherwise).
    void
    choose_anchors(const std::vector<bool> &clamped);
    /// In setup(), after the factorisation: the modes E_k (owners).
    void
    make_anchor_modes();
    /// sum_k alpha_k E_k added to @p solution (non-homogeneous solves).
    void
    add_anchor_displacements(dealii::Vector<double> &solution) const;

    /// The load factor, whether there is a preload, and the parts of the
    /// load (owners only): unit_rhs and unit_load the proportional ones at
    /// lambda = 1 (condensed with the prescribed displacement, and
    /// unconstrained), preload_rhs and preload_load the preload's (with a
    /// preload), rhs_at_one and load_at_one those of setup() (with a
    /// preload: restored at lambda = 1).
    double                 load_factor_ = 1, preload_factor_ = 1;
    bool                   has_preload_ = false;
    dealii::Vector<double> unit_rhs, preload_rhs, rhs_at_one;
    dealii::Vector<double> unit_load, preload_load, load_at_one;
    /// The non-zero inhomogeneities of the constraints at lambda = 1 (the
    /// prescribed displacement), on every process.
    std::vector<std::pair<dealii::types::global_dof_index, double>>
      inhomogeneities;

    /// In setup(), after the constraints: load factor 1, whether there is
    /// a preload, the inhomogeneities, and the parts of the load sized
    /// for assemble().
    void
    start_load_parts(const VolumeLoad *volume);
    /// In setup(), after assemble(): the load at lambda = 1 kept (owners).
    void
    keep_load_at_one();

    /// The volume terms of setup(), and E* of energy() (owners only).
    const VolumeLoad *volume_             = nullptr;
    double            eigenstrain_energy_ = 0;

    /// E* = 1/2 int eps* : C eps* dx over all cells (the Gauss rule of the
    /// assembly).
    double
    eigenstrain_energy() const;

    /// The Sigma dofs to eliminate last for the Schur complement, or none
    /// if a constrained Sigma dof depends on dofs off Sigma.
    std::vector<unsigned int>
    schur_dofs() const;
  };
} // namespace bilayer

#endif
