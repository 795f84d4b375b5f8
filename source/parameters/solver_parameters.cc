#include <deal.II/base/exceptions.h>
#include <deal.II/base/utilities.h>

#include <bilayer/parameters/parameter_entries.h>
#include <bilayer/parameters/solver_parameters.h>

namespace bilayer
{
  using namespace dealii;
  using namespace entries;


  void
  SolverParameters::declare_parameters(ParameterHandler &prm)
  {
    prm.enter_subsection("Solver");
    prm.declare_entry("Method",
                      "uzawa",
                      Patterns::Selection("uzawa|accelerated|active set"),
                      "Outer solver on the multipliers: uzawa (the paper's "
                      "projected Uzawa iteration, docs/problem.md section 4), "
                      "accelerated (the same projected step with FISTA "
                      "momentum and adaptive restart; with theta = auto its "
                      "step is Auto theta fraction / lambda_max) or active "
                      "set (primal-dual active set / semismooth Newton on "
                      "the dual problem, preconditioned conjugate gradients "
                      "through the subdomain solves; stops on the KKT "
                      "residual, see the subsection Active set).");
    prm.declare_entry("Uzawa step theta",
                      "65",
                      Patterns::Anything(),
                      "Step theta of the multiplier update [stress/length: "
                      "multiplier units per unit jump], a number > 0 or "
                      "'auto': Auto theta fraction * 2 / lambda_max of the "
                      "dual operator S = D^-1 C A^-1 C^T, estimated by a "
                      "power iteration. The paper uses 65 with moduli in "
                      "GPa.");
    prm.declare_entry("Auto theta fraction",
                      "0.9",
                      Patterns::Double(0, 1),
                      "theta = fraction * 2 / lambda_max for 'auto' [-], in "
                      "(0, 1).");
    prm.declare_entry("Auto theta steps",
                      "adaptive",
                      Patterns::Selection("adaptive|constant"),
                      "Steps of Method = uzawa with theta = auto [-]: "
                      "adaptive (projected gradient ascent on the dual with "
                      "Barzilai-Borwein steps, the first one theta = auto, "
                      "and a non-monotone line search along the projected "
                      "direction, no extra subdomain solves; it needs far "
                      "fewer iterations under material contrast and on "
                      "fine or graded meshes) or constant (the step theta = "
                      "auto in every iteration). A given theta is always "
                      "constant.");
    prm.declare_entry("Spectrum estimate iterations",
                      "30",
                      Patterns::Integer(1, 1000),
                      "Most power iterations for lambda_max of S (each is "
                      "four subdomain solves); it stops earlier when the "
                      "estimate changes by less than 1e-4 [-].");
    prm.declare_entry("Dual spectrum steps",
                      "0",
                      Patterns::Integer(0, 100000),
                      "Most Lanczos steps (each four subdomain solves) for "
                      "the smallest and largest eigenvalues of the dual "
                      "operator S on the free multipliers, printed and "
                      "written to summary.json per cycle with the condition "
                      "number and lambda_min / h (a diagnostic of the "
                      "multiplier spaces; 0: not estimated) [-].");
    prm.declare_entry("Maximum iterations",
                      "100000",
                      Patterns::Integer(1),
                      "Iteration limit of the outer solver [-]; reaching it "
                      "is reported as non-convergence.");
    prm.declare_entry("Stopping rule",
                      "paper",
                      Patterns::Selection("paper|paper with norm|relative|kkt"),
                      "Stopping rule of uzawa and accelerated. paper: max "
                      "||w^k - w^(k-1)|| / ||w^k||^2 < Tolerance over u-, "
                      "u+, v-, v+ in the energy norm, as printed; paper with "
                      "norm: the same with ||w^k||; relative: relative "
                      "change of the multipliers and relative constraint "
                      "violation both < Tolerance; kkt: relative KKT "
                      "residual (constraint violation, negative mu_c, "
                      "complementarity) < Tolerance, the rule of active "
                      "set.");
    prm.declare_entry("Tolerance",
                      "1e-6",
                      Patterns::Double(0),
                      "Tolerance of the stopping rule [-, or 1/energy^(1/2) "
                      "for the paper's rule].");
    prm.declare_entry("Divergence growth factor",
                      "1000",
                      Patterns::Double(1),
                      "The iteration is declared divergent when the norm of "
                      "the multiplier increment exceeds its smallest value so "
                      "far by this factor [-].");
    prm.declare_entry("Acceptance tolerance",
                      "1e-6",
                      Patterns::Double(0),
                      "Bound on the relative constraint violation, relative "
                      "interpenetration and complementarity of the final "
                      "solution; a run beyond it fails [-].");
    prm.declare_entry("Shared subproblem solver",
                      "mumps",
                      Patterns::Selection("mumps|klu"),
                      "Direct solver (Trilinos Amesos) of a subproblem that "
                      "a group of MPI processes shares (more than four "
                      "processes): mumps (MUMPS, the factorisation "
                      "distributed over the group) or klu (KLU on one "
                      "process of the group, the others send their rows).");
    prm.declare_entry("Warm start",
                      "false",
                      Patterns::Bool(),
                      "Start each cycle after the first from the previous "
                      "cycle's multipliers, interpolated onto the new "
                      "multiplier meshes and projected onto the multiplier "
                      "sets (false: from zero, as in the paper).");
    prm.declare_entry(
      "Ordering",
      "minimum degree",
      Patterns::Selection("minimum degree|nested dissection|fewest flops"),
      "Fill-reducing ordering of each subproblem's Cholesky factorisation "
      "with its Sigma dofs last (Solve on Sigma): minimum degree "
      "(constrained approximate minimum degree, CAMD), nested dissection "
      "(CHOLMOD's, with METIS, of the other dofs' vertex graph, Sigma the "
      "last separator), or fewest flops (both analysed, the one with fewer "
      "factorisation flops kept; matrices below 4000 dofs: minimum degree). "
      "Changes round-off only; the terminal and summary.json (factors) "
      "name the ordering, flops and entries of each factor "
      "(docs/performance.md, 'Orderings').");
    prm.declare_entry(
      "Solve on Sigma",
      "true",
      Patterns::Bool(),
      "Iterate on Sigma alone: each subproblem's factorisation eliminates "
      "its Sigma dofs last and keeps the dense Cholesky factor of its Schur "
      "complement S on them, so that a solve for multiplier loads costs two "
      "dense triangular solves on the Sigma dofs instead of a sparse forward "
      "and back substitution, the Dirichlet preconditioner needs no "
      "factorisation of its own (it applies S), and the whole solutions are "
      "computed once, at the end. For the active set method, and for uzawa "
      "and accelerated with the stopping rules kkt and relative (the paper's "
      "energy-norm rules need whole solutions in every iteration). A "
      "subproblem keeps S only where its |Sigma dofs|^2 entries are no more "
      "than those of its sparse factor. false: sparse solves in every "
      "iteration (the same solution, other rounding).");
    prm.enter_subsection("Active set");
    prm.declare_entry("Preconditioner",
                      "dirichlet",
                      Patterns::Selection("dirichlet|lumped|none"),
                      "Preconditioner of the conjugate gradients on the "
                      "dual operator: dirichlet (FETI Dirichlet: Schur "
                      "complements of the subproblems on Sigma; with Solve "
                      "on Sigma the factors already kept, else one extra "
                      "factorisation and one Dirichlet solve per subproblem "
                      "and iteration), lumped (stiffness on Sigma, no "
                      "solves) or none.");
    prm.declare_entry("Inner tolerance",
                      "1e-2",
                      Patterns::Double(0, 1),
                      "Relative residual reduction of the conjugate "
                      "gradients while the active set changes [-], in "
                      "(0, 1); once it stays the same they run to "
                      "Solver/Tolerance.");
    prm.declare_entry("Maximum Newton iterations",
                      "50",
                      Patterns::Integer(1),
                      "Limit of the active-set (Newton) steps [-]; reaching "
                      "it is reported as non-convergence.");
    prm.declare_entry("Maximum inner iterations",
                      "1000",
                      Patterns::Integer(1),
                      "Limit of the conjugate-gradient iterations of one "
                      "Newton step [-].");
    prm.leave_subsection();
    prm.leave_subsection();
  }


  void
  SolverParameters::parse_parameters(ParameterHandler &prm)
  {
    prm.enter_subsection("Solver");
    const std::string name = prm.get("Method");
    method                 = name == "accelerated" ? SolverMethod::accelerated :
                             name == "active set"  ? SolverMethod::active_set :
                                                     SolverMethod::uzawa;
    const std::string step = prm.get("Uzawa step theta");
    auto_theta             = step == "auto";
    if (!auto_theta)
      {
        AssertThrow(Patterns::Double(0).match(step),
                    ExcMessage("Solver/Uzawa step theta must be a number > 0 "
                               "or 'auto', got '" +
                               step + "'"));
        theta = to_double(step, "Solver/Uzawa step theta");
        AssertThrow(theta > 0,
                    ExcMessage("Solver/Uzawa step theta must be > 0 or "
                               "'auto', got " +
                               step));
      }
    auto_theta_fraction = get_double(prm, "Solver", "Auto theta fraction");
    AssertThrow(auto_theta_fraction > 0 && auto_theta_fraction < 1,
                ExcMessage("Solver/Auto theta fraction must lie in (0, 1), "
                           "got " +
                           prm.get("Auto theta fraction")));
    adaptive_auto_steps = prm.get("Auto theta steps") == "adaptive";
    spectrum_iterations = prm.get_integer("Spectrum estimate iterations");
    dual_spectrum_steps = prm.get_integer("Dual spectrum steps");
    max_iterations      = prm.get_integer("Maximum iterations");
    const auto rule     = prm.get("Stopping rule");
    stopping_rule       = rule == "paper"           ? StoppingRule::paper :
                          rule == "paper with norm" ? StoppingRule::paper_norm :
                          rule == "relative"        ? StoppingRule::relative :
                                                      StoppingRule::kkt;
    tolerance           = get_double(prm, "Solver", "Tolerance");
    AssertThrow(tolerance > 0,
                ExcMessage("Solver/Tolerance must be > 0, got " +
                           prm.get("Tolerance")));
    divergence_factor = get_double(prm, "Solver", "Divergence growth factor");
    acceptance_tolerance = get_double(prm, "Solver", "Acceptance tolerance");
    AssertThrow(acceptance_tolerance > 0,
                ExcMessage("Solver/Acceptance tolerance must be > 0, got " +
                           prm.get("Acceptance tolerance")));
    warm_start     = prm.get_bool("Warm start");
    solve_on_sigma = prm.get_bool("Solve on Sigma");
    {
      const std::string o = prm.get("Ordering");
      ordering = o == "minimum degree" ? 0 : o == "nested dissection" ? 1 : 2;
    }
    shared_solver = prm.get("Shared subproblem solver") == "klu" ?
                      "Amesos_Klu" :
                      "Amesos_Mumps";
    prm.enter_subsection("Active set");
    const std::string p = prm.get("Preconditioner");
    preconditioner      = p == "dirichlet" ? DualPreconditioner::dirichlet :
                          p == "lumped"    ? DualPreconditioner::lumped :
                                             DualPreconditioner::none;
    inner_tolerance = get_double(prm, "Solver/Active set", "Inner tolerance");
    AssertThrow(inner_tolerance > 0 && inner_tolerance < 1,
                ExcMessage("Solver/Active set/Inner tolerance must lie in "
                           "(0, 1), got " +
                           prm.get("Inner tolerance")));
    max_newton_iterations = prm.get_integer("Maximum Newton iterations");
    max_inner_iterations  = prm.get_integer("Maximum inner iterations");
    prm.leave_subsection();
    prm.leave_subsection();
  }
} // namespace bilayer
