#ifndef bilayer_parameters_h
#define bilayer_parameters_h

#include <deal.II/base/function_parser.h>
#include <deal.II/base/parameter_handler.h>
#include <deal.II/base/point.h>

#include <bilayer/elastic_law.h>
#include <bilayer/layout.h>

#include <array>
#include <map>
#include <memory>
#include <string>
#include <vector>

/**
 * The scene: every entry of a parameter file, typed.
 *
 * One struct per subsection of the .prm file, each with
 * `declare_parameters()` and `parse_parameters()`. Selections are mapped to
 * `enum class` values once, here. Consistency checks that involve several
 * entries (the crack inside Sigma, Sigma inside Omega, ...) are done in
 * Scene::parse_parameters() and end with an ExcMessage that names the entry
 * and the allowed range.
 */
namespace bilayer
{
  /// The four sides of the rectangle Omega.
  enum class Side
  {
    left   = 0,
    right  = 1,
    bottom = 2,
    top    = 3
  };

  constexpr unsigned int n_sides = 4;

  /// One value per side of the rectangle, indexed by Side.
  template <typename T>
  using PerSide = std::array<T, n_sides>;

  /// Name of a side as written in parameter files ("left", ...).
  std::string
  side_name(const Side side);

  enum class ElementShape
  {
    quadrilateral,
    triangle
  };

  /**
   * How the multipliers act on the traces (the matrix C of interface.h).
   * `lumped`: nodal quadrature of the multiplier mesh (node-to-node
   * coupling); `consistent`: Gauss quadrature on the common refinement of
   * the trace meshes (mortar coupling).
   */
  enum class MultiplierCoupling
  {
    lumped,
    consistent
  };

  /**
   * Which trace of layer 1 carries the mesh of mu_1 (the "slave" of the
   * mortar coupling across Sigma, MultiplierSpace): the one with more
   * segments on Sigma (the contact constraint tested at the finer set of
   * points) or the one with fewer (fewer, better conditioned constraints).
   * The two coincide on matching meshes.
   */
  enum class MultiplierMesh
  {
    finer_trace,
    coarser_trace
  };

  /**
   * How the jumps in the Uzawa update are sampled. `weighted`: the weak
   * jump D^{-1} C w (the gradient of the Lagrangian in the metric of the
   * lumped multiplier mass D); `nodal`: the traces evaluated at the
   * multiplier nodes. For lumped coupling and matching meshes both agree.
   */
  enum class JumpSampling
  {
    weighted,
    nodal
  };

  /**
   * Stopping rules of the Uzawa iteration.
   * - `paper`: max over the four subproblems of
   *   ||w^k - w^{k-1}|| / ||w^k||^2 < tol (energy norms), as printed in the
   *   paper (docs/problem.md §5); not scale invariant.
   * - `paper_norm`: the same with ||w^k|| in the denominator.
   * - `relative`: the relative change of the multipliers and the relative
   *   violation of the discrete constraints both below tol.
   * - `kkt`: the relative KKT residual (KKTResidual in interface_diagnostics.h) below
   *   tol; the active-set solver always stops on it.
   */
  enum class StoppingRule
  {
    paper,
    paper_norm,
    relative,
    kkt
  };

  /// Preconditioners of the linear dual solves of the active-set solver.
  enum class DualPreconditioner
  {
    /// None: conjugate gradients on the dual operator itself.
    none,
    /// G^-1 B K_{Sigma Sigma} B^T G^-1 (no solves).
    lumped,
    /// G^-1 B S B^T G^-1, S the Schur complements (one Dirichlet solve per
    /// subproblem).
    dirichlet
  };

  enum class TerminalOutput
  {
    full,
    checks
  };

  /**
   * The named parts of the outer boundary: the rectangle's four sides, or
   * the physical curves of a Gmsh scene other than Sigma and crack. Part i
   * has boundary id i in both subdomain meshes.
   */
  struct BoundaryParts
  {
    std::vector<std::string> names = {"left", "right", "bottom", "top"};
    /// Whether the parts come from a Gmsh file (entries "Traction on NAME")
    /// or are the rectangle's sides ("Traction on NAME side").
    bool gmsh = false;

    unsigned int
    size() const
    {
      return names.size();
    }

    /// The Loads entry of part @p i.
    std::string
    traction_entry(const unsigned int i) const
    {
      return "Traction on " + names[i] + (gmsh ? "" : " side");
    }

    /// The parts of a Gmsh scene (the file's boundary curve names).
    static BoundaryParts
    of_gmsh(const std::vector<std::string> &names)
    {
      return {names, true};
    }
  };

  struct GeometryParameters
  {
    /**
     * A Gmsh geometry (.geo) or mesh (.msh, format 2) of the specimen, its
     * physical groups naming the subdomains, Sigma, the crack and the
     * boundary parts (docs/geometry.md); empty: the rectangle below.
     * Relative paths are relative to the parameter file.
     */
    std::string   gmsh_file;
    BoundaryParts parts;
    /// The scene file may run programs and write files (the command-line
    /// flag --allow-gmsh-commands; not a parameter entry).
    bool allow_gmsh_commands = false;

    double x_min        = -1.0;
    double x_max        = 1.0;
    double y_min        = -1.0;
    double y_max        = 1.0;
    double sigma_height = 0.0;
    double crack_start  = -0.5;
    double crack_end    = 0.5;

    /// clamped[i] is true if boundary part i belongs to Gamma_D.
    std::vector<bool> clamped = {true, true, false, false};

    static void
    declare_parameters(dealii::ParameterHandler &prm,
                       const BoundaryParts      &parts = BoundaryParts());
    void
    parse_parameters(dealii::ParameterHandler &prm,
                     const BoundaryParts      &parts = BoundaryParts());

    /// The rectangle's crack is not empty (Gmsh scenes: see the file).
    bool
    has_crack() const
    {
      return crack_end > crack_start;
    }

    /// The crack as a set of pieces of Sigma (coordinate x), compared with
    /// a tolerance of 1e-10 times the width of Omega.
    CrackSet
    crack() const
    {
      return has_crack() ?
               CrackSet({{crack_start, crack_end}}, 1e-10 * (x_max - x_min)) :
               CrackSet();
    }
  };

  /// How the mesh of cycle k+1 comes from that of cycle k.
  enum class Refinement
  {
    /// Every cell split (structured meshes are rebuilt with twice the
    /// cells along each side).
    global,
    /// Cells marked from the error indicators (quadrilaterals only).
    adaptive
  };

  /// Marking of cells for adaptive refinement (one threshold over the
  /// cells of both subdomains), named as in deal.II's GridRefinement.
  enum class Marking
  {
    /// deal.II's refine_and_coarsen_fixed_number: the fraction of all cells
    /// with the largest indicators. Parameter files of earlier versions
    /// spell it "fixed fraction"
    /// (MeshParameters::marking_spelled_fixed_fraction).
    fixed_number,
    /// Doerfler marking, deal.II's refine_and_coarsen_fixed_fraction with
    /// the L2 norm: the fewest cells whose squared indicators make up the
    /// fraction of the total.
    bulk
  };

  struct MeshParameters
  {
    Refinement refinement = Refinement::global;
    Marking    marking    = Marking::bulk;
    /// Mesh/Marking was given as "fixed fraction", the spelling of
    /// Marking::fixed_number in earlier versions (not deal.II's fixed
    /// fraction, which is bulk).
    bool   marking_spelled_fixed_fraction = false;
    double refinement_fraction            = 0.5;
    /// Add the interface residuals on Sigma to Kelly's indicators.
    bool interface_terms = true;
    /// Factor on the complementarity term of the estimator.
    double contact_weight = 1;
    /// Refuse scenes and cycles whose estimated memory exceeds what is
    /// available (false: run them anyway).
    bool refuse_above_memory = true;
    /// Cells along Sigma of the Omega+ mesh; 0: as Omega-.
    unsigned int cells_along_sigma_plus = 0;
    ElementShape shape                  = ElementShape::quadrilateral;
    unsigned int cells_along_sigma      = 16;
    /// Cells across each subdomain; 0 chooses square-ish cells.
    unsigned int cells_across = 0;
    /**
     * Structured meshes: move the vertex column nearest to each crack end
     * point onto it (the cells between stretched piecewise linearly), so
     * that any crack interval can be meshed (crack-length sweeps).
     */
    bool         fit_crack_tips = false;
    unsigned int degree_first   = 1;
    unsigned int degree_second  = 1;
    unsigned int n_cycles       = 1;
    /**
     * Gmsh meshes of the two subdomains, one entry per cycle, "{side}"
     * standing for "minus" and "plus". Empty: structured meshes. Relative
     * paths are relative to the parameter file. Cycles beyond the list
     * refine the last meshes uniformly.
     */
    std::vector<std::string> mesh_files;
    /// Mesh size factor of Gmsh scenes (gmsh -clscale).
    double gmsh_size_factor = 1;
    /// Seconds gmsh may run on a .geo scene.
    double gmsh_time_limit = 600;

    static void
    declare_parameters(dealii::ParameterHandler &prm);
    void
    parse_parameters(dealii::ParameterHandler &prm);

    unsigned int
    degree(const Layer layer) const
    {
      return layer == Layer::first ? degree_first : degree_second;
    }
  };

  struct MaterialParameters
  {
    std::array<LayerMaterial, 2> layer = {{{200.0, 0.28}, {112.0, 0.32}}};
    /// 2: the two-layer structure; 1: layer 2 absent (a single body).
    unsigned int n_layers = 2;

    bool
    has_layer(const Layer l) const
    {
      return l == Layer::first || n_layers == 2;
    }

    static void
    declare_parameters(dealii::ParameterHandler &prm);
    void
    parse_parameters(dealii::ParameterHandler &prm);
  };

  /**
   * Tractions and prescribed displacements as muparser expressions of x and
   * y. The named constants may use the material constants E1, nu1, mu1,
   * lambda1, E2, nu2, mu2, lambda2 and the constants defined before them.
   */
  struct LoadParameters
  {
    std::string constants = "";
    /// The boundary parts the tractions refer to.
    BoundaryParts parts;
    /// traction[layer][part], "f_x; f_y"
    std::array<std::vector<std::string>, Layout::n_layers> traction;
    /// prescribed[layer], "u_x; u_y", on the clamped sides
    std::array<std::string, 2> prescribed = {{"0; 0", "0; 0"}};

    /// The evaluated constants (material constants included).
    std::map<std::string, double> constant_values;

    LoadParameters();

    static void
    declare_parameters(dealii::ParameterHandler &prm,
                       const BoundaryParts      &parts = BoundaryParts());
    void
    parse_parameters(dealii::ParameterHandler &prm,
                     const MaterialParameters &materials,
                     const BoundaryParts      &parts);

    std::unique_ptr<dealii::FunctionParser<2>>
    traction_function(const Layer layer, const unsigned int part) const;
    std::unique_ptr<dealii::FunctionParser<2>>
    prescribed_function(const Layer layer) const;
    /// Whether the traction expression of a part is identically "0; 0".
    bool
    traction_is_zero(const Layer layer, const unsigned int part) const;
  };

  struct ContactParameters
  {
    bool               non_penetration  = true;
    double             multiplier_bound = 1e7;
    MultiplierCoupling coupling         = MultiplierCoupling::lumped;
    JumpSampling       sampling         = JumpSampling::weighted;
    MultiplierMesh     mesh             = MultiplierMesh::finer_trace;

    static void
    declare_parameters(dealii::ParameterHandler &prm);
    void
    parse_parameters(dealii::ParameterHandler &prm);
  };

  /// Outer solvers on the multipliers.
  enum class SolverMethod
  {
    /// The paper's projected Uzawa iteration.
    uzawa,
    /// The same projected gradient step with Nesterov/FISTA momentum and
    /// adaptive (gradient) restart.
    accelerated,
    /// Primal-dual active set (semismooth Newton) on the dual problem with
    /// preconditioned conjugate gradients through the subdomain solves.
    active_set
  };

  struct SolverParameters
  {
    SolverMethod method = SolverMethod::uzawa;
    /// The Uzawa step; ignored when auto_theta is set.
    double theta = 65.0;
    /// theta = auto_theta_fraction * 2 / lambda_max(S), S estimated.
    bool   auto_theta          = false;
    double auto_theta_fraction = 0.9;
    /// Method = uzawa with theta = auto: Barzilai-Borwein steps with a
    /// non-monotone line search (UzawaSolver) instead of the constant step.
    bool         adaptive_auto_steps = true;
    unsigned int spectrum_iterations = 30;
    /// Lanczos steps for the extreme eigenvalues of the dual operator
    /// reported per cycle (0: none).
    unsigned int dual_spectrum_steps = 0;
    unsigned int max_iterations      = 100000;
    StoppingRule stopping_rule       = StoppingRule::paper;
    /// Amesos solver of subproblems shared by a group of processes.
    std::string shared_solver = "Amesos_Mumps";
    double      tolerance     = 1e-6;
    /// Divergence: the multiplier increment grew by this factor over its
    /// smallest value so far.
    double divergence_factor = 1e3;
    /// Tolerance of the acceptance checks of the final solution.
    double acceptance_tolerance = 1e-6;
    /// Start each cycle from the previous cycle's multipliers.
    bool warm_start = false;
    /// Iterate on Sigma alone (Schur complements, SolveExtent::sigma).
    bool solve_on_sigma = true;

    /// Whether the outer solver's iterations need the solutions on Sigma
    /// only (with solve_on_sigma): the active set method, and the
    /// first-order methods with a stopping rule that reads no energy norm.
    bool
    iterates_on_sigma() const
    {
      return solve_on_sigma && (method == SolverMethod::active_set ||
                                stopping_rule == StoppingRule::kkt ||
                                stopping_rule == StoppingRule::relative);
    }
    /// Solver/Active set: preconditioner, relative tolerance of the linear
    /// solves while the active set changes, limit of their iterations.
    DualPreconditioner preconditioner        = DualPreconditioner::dirichlet;
    double             inner_tolerance       = 1e-2;
    unsigned int       max_newton_iterations = 50;
    unsigned int       max_inner_iterations  = 1000;

    static void
    declare_parameters(dealii::ParameterHandler &prm);
    void
    parse_parameters(dealii::ParameterHandler &prm);
  };

  /// The cycles whose solution fields (VTU, HDF5) are written.
  enum class WrittenCycles
  {
    every,
    last,
    none
  };

  /// zlib's effort on the VTU data (deal.II's VtkFlags).
  enum class Compression
  {
    none,
    best_speed,
    standard,
    best
  };

  /**
   * The energy release rate at the crack tips (docs/fracture.md): the
   * domain integral of the shape derivative of the energy under a velocity
   * field theta that moves one tip along Sigma.
   */
  struct FractureParameters
  {
    /// Compute G at every crack tip of every cycle.
    bool energy_release_rate = true;
    /**
     * Outer radius R of the support of theta [length]; theta = its
     * direction for r <= R/2 and falls smoothly to 0 at r = R. 0: half the
     * distance from the tip to the nearest other tip, corner of Sigma or
     * point of the outer boundary.
     */
    double support_radius = 0;

    static void
    declare_parameters(dealii::ParameterHandler &prm);
    void
    parse_parameters(dealii::ParameterHandler &prm);
  };

  struct OutputParameters
  {
    std::string    directory         = "results";
    bool           write_vtu         = true;
    bool           write_hdf5        = false;
    bool           write_interface   = true;
    WrittenCycles  written_cycles    = WrittenCycles::every;
    Compression    compression       = Compression::best_speed;
    unsigned int   progress_interval = 100;
    TerminalOutput terminal          = TerminalOutput::full;

    /// Whether the solution fields of @p cycle of @p n_cycles are written
    /// (with the last cycle, also a cycle that fails its checks: the run
    /// ends there).
    bool
    writes_fields(const unsigned int cycle,
                  const unsigned int n_cycles,
                  const bool         accepted) const
    {
      if (!write_vtu && !write_hdf5)
        return false;
      switch (written_cycles)
        {
          case WrittenCycles::every:
            return true;
          case WrittenCycles::last:
            return cycle + 1 >= n_cycles || !accepted;
          default:
            return false;
        }
    }

    static void
    declare_parameters(dealii::ParameterHandler &prm);
    void
    parse_parameters(dealii::ParameterHandler &prm);
  };

  /**
   * All subsections together. parse_parameters() also checks the
   * relations between entries.
   */
  struct Scene
  {
    std::string        name = "scene";
    GeometryParameters geometry;
    MeshParameters     mesh;
    MaterialParameters materials;
    LoadParameters     loads;
    ContactParameters  contact;
    SolverParameters   solver;
    FractureParameters fracture;
    OutputParameters   output;
    /// The parameter file and the files it includes (not the mesh files).
    std::vector<std::string> input_files;

    /// Declare every entry; a Gmsh scene's boundary @p parts give the
    /// entries of the Loads section.
    static void
    declare_parameters(dealii::ParameterHandler &prm,
                       const BoundaryParts      &parts = BoundaryParts());
    void
    parse_parameters(dealii::ParameterHandler &prm,
                     const BoundaryParts      &parts = BoundaryParts());
  };

  /**
   * Declare, read a parameter file and parse it into a Scene. The Scene's
   * name is the file name without directory and extension. With
   * @p allow_gmsh_commands a .geo scene may run programs and write files
   * (--allow-gmsh-commands; docs/geometry.md).
   */
  Scene
  read_scene(dealii::ParameterHandler       &prm,
             const std::string              &filename,
             const std::vector<std::string> &overrides           = {},
             const bool                      allow_gmsh_commands = false);

  /// Parse a Scene from parameter-file text (entries not given keep their
  /// defaults).
  Scene
  scene_from_string(const std::string &text, const std::string &name);

  /**
   * The entries @p short_prm (ParameterHandler::ShortPRM) without those that
   * the scene does not use, each replaced by a comment line that names it:
   * for a Gmsh scene (Geometry/Gmsh file) the rectangle's corners, Height
   * of Sigma and Crack interval, and the structured mesh's cell counts,
   * Fit crack tips and Mesh files.
   */
  std::string
  applicable_entries(const std::string &short_prm, const Scene &scene);

  /// The message of a deal.II exception (a user error) on one line.
  std::string
  one_line_message(const dealii::ExceptionBase &exception);
} // namespace bilayer

#endif
