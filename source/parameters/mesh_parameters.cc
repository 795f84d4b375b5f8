#include <deal.II/base/exceptions.h>
#include <deal.II/base/utilities.h>

#include <bilayer/parameters/mesh_parameters.h>
#include <bilayer/parameters/parameter_entries.h>

namespace bilayer
{
  using namespace dealii;
  using namespace entries;


  void
  MeshParameters::declare_parameters(ParameterHandler &prm)
  {
    prm.enter_subsection("Mesh");
    prm.declare_entry("Element shape",
                      "quadrilaterals",
                      Patterns::Selection("quadrilaterals|triangles"),
                      "Cells of both subdomain meshes: quadrilaterals (Q_k) or "
                      "triangles (P_k, each rectangle cut into two).");
    prm.declare_entry("Cells along Sigma",
                      "16",
                      Patterns::Integer(1, 100000),
                      "Number of cell edges along Sigma on the coarsest mesh "
                      "[-]. The crack end points must be mesh vertices.");
    prm.declare_entry("Cells across each subdomain",
                      "0",
                      Patterns::Integer(0, 100000),
                      "Number of cells between Sigma and the top (bottom) side "
                      "of each subdomain on the coarsest mesh [-]; 0 chooses "
                      "the number that makes the cells closest to squares.");
    prm.declare_entry(
      "Fit crack tips",
      "false",
      Patterns::Bool(),
      "Structured meshes: true moves the column of vertices "
      "nearest to each crack end point onto it (the cells in "
      "between stretched piecewise linearly), so that any crack "
      "interval can be meshed, e.g. for crack-length sweeps "
      "(scripts/crack_growth); false refuses crack end points "
      "that are not vertices.");
    prm.declare_entry("Polynomial degree of layer 1",
                      "1",
                      Patterns::Integer(1, 4),
                      "Degree of the Lagrange elements of layer 1 (u) [-].");
    prm.declare_entry("Polynomial degree of layer 2",
                      "1",
                      Patterns::Integer(1, 4),
                      "Degree of the Lagrange elements of layer 2 (v) and "
                      "of the layers above it (Materials/Number of layers "
                      "> 2) [-].");
    prm.declare_entry(
      "Mesh files",
      "",
      Patterns::List(Patterns::Anything(), 0),
      "Gmsh (.msh, format 2) meshes of Omega- and Omega+, one "
      "entry per cycle, with {side} standing for 'minus' and "
      "'plus', e.g. 'meshes/a_{side}.msh, meshes/b_{side}.msh'. "
      "Empty: structured meshes from Element shape and Cells "
      "along Sigma. Relative paths are relative to the "
      "parameter file; cycles beyond the list refine the last "
      "meshes uniformly. Boundary ids are assigned from the "
      "coordinates.");
    prm.declare_entry("Gmsh mesh size factor",
                      "1",
                      Patterns::Double(0),
                      "Factor on the mesh sizes of a Gmsh geometry "
                      "(Geometry/Gmsh file, .geo), passed to gmsh as "
                      "-clscale [-], > 0: the coarsest mesh, which the cycles "
                      "refine (globally or adaptively) with deal.II, curved "
                      "boundaries and Sigma staying on their circles.");
    prm.declare_entry("Gmsh time limit",
                      "600",
                      Patterns::Double(0),
                      "Seconds gmsh may run on a Gmsh geometry (Geometry/"
                      "Gmsh file, .geo) before bilayer stops it and refuses "
                      "the scene [s], in [1, 1e6]: a scene that loops "
                      "forever or a gmsh that hangs ends with a message.");
    prm.declare_entry("Number of cycles",
                      "1",
                      Patterns::Integer(1, 40),
                      "Number of meshes in the sequence; with global "
                      "refinement cycle k halves the cells of cycle k-1 in "
                      "each direction, with adaptive refinement it refines "
                      "the cells the estimator marks [-].");
    prm.declare_entry("Cells along Sigma on the plus side",
                      "0",
                      Patterns::Integer(0, 100000),
                      "Cells of the structured Omega+ mesh along Sigma (its "
                      "cells across follow from them); 0: as Cells along "
                      "Sigma. Other numbers make the traces on Sigma "
                      "non-matching [-].");
    prm.declare_entry("Refinement",
                      "global",
                      Patterns::Selection("global|adaptive"),
                      "From one cycle to the next: global (every cell "
                      "split) or adaptive (cells marked from the error "
                      "indicators, each subdomain refined on its own with "
                      "hanging nodes; quadrilaterals only).");
    prm.declare_entry("Marking",
                      "bulk",
                      Patterns::Selection("bulk|fixed number|fixed fraction"),
                      "Adaptive marking over the cells of both subdomains, "
                      "named as in deal.II's GridRefinement: bulk (Doerfler "
                      "marking, deal.II's fixed fraction: the fewest cells "
                      "whose squared indicators make up Refinement fraction "
                      "of the total) or fixed number (deal.II's fixed "
                      "number: Refinement fraction of the cells). fixed "
                      "fraction, the spelling of earlier versions, is still "
                      "accepted and means fixed number (not deal.II's "
                      "fixed fraction).");
    prm.declare_entry("Refinement fraction",
                      "0.5",
                      Patterns::Double(0, 1),
                      "The bulk parameter or the fraction of cells refined "
                      "per adaptive cycle [-], in (0, 1].");
    prm.declare_entry(
      "Refinement goal",
      "estimator",
      Patterns::Anything(),
      "What adaptive refinement marks for: estimator (the residual "
      "estimator of the energy norm, docs/numerics.md), or the "
      "dual-weighted residual indicators of a goal (docs/fracture.md §11): "
      "energy, G (G at every tip, each relative to its own G) or G at tip "
      "K (K = 1, 2, ... as numbered in the output). A goal turns on "
      "Fracture/Goal-oriented estimate.");
    prm.declare_entry(
      "Target accuracy",
      "0",
      Patterns::Double(0, 1),
      "The relative accuracy wanted of the Target quantity [-], in [0, 1): "
      "the cycles stop at the first whose estimated relative error is at "
      "most it (or whose estimate is at round-off: a scene without "
      "stresses), and the run fails (exit 2, its results in DIR.failed, "
      "the accuracy reached named) when Number of cycles pass first or "
      "the next mesh does not fit the memory. Number of cycles is then the "
      "most cycles. 0: no target, every one of the Number of cycles. "
      "docs/fracture.md, \"A target accuracy\".");
    prm.declare_entry(
      "Target quantity",
      "G",
      Patterns::Selection("G|energy"),
      "What Target accuracy measures: G (the largest relative error bar "
      "dG / |G| over the crack tips) or energy (eta^2 / (2 |Pi|), eta the "
      "energy-norm estimate of the cycle).");
    prm.declare_entry("Interface terms in the estimator",
                      "true",
                      Patterns::Bool(),
                      "Add to Kelly's indicators the residual of the "
                      "multiplier tractions on the Sigma faces (sigma(w) n - "
                      "multiplier load) and, on the crack, the "
                      "complementarity |int mu_c [u].nu| / (2 mu), which "
                      "mark the crack tips and the end of the contact zone.");
    prm.declare_entry(
      "Refuse above available memory",
      "true",
      Patterns::Bool(),
      "true refuses a scene (before cycle 0) or stops a run (before a "
      "cycle) whose estimated peak memory exceeds the memory available to "
      "the process (MemAvailable, the address-space limit ulimit -v, a "
      "cgroup's memory.max); false runs it anyway. The estimate lies within "
      "25 % of the measured peak resident memory from 1e4 to 6.6e6 dofs "
      "(docs/performance.md); a run beyond the memory is killed by the "
      "system. Nothing runs where no memory at all is left.");
    prm.declare_entry("Weight of the contact term",
                      "1",
                      Patterns::Double(0),
                      "Factor on the complementarity term of the estimator "
                      "(1: the energy-norm indicator; larger values refine "
                      "the end of the contact zone further, for the contact "
                      "pressure and the extent of the contact zone) [-], "
                      ">= 0.");
    prm.leave_subsection();
  }


  void
  MeshParameters::parse_parameters(ParameterHandler &prm)
  {
    prm.enter_subsection("Mesh");
    shape             = prm.get("Element shape") == "triangles" ?
                          ElementShape::triangle :
                          ElementShape::quadrilateral;
    cells_along_sigma = prm.get_integer("Cells along Sigma");
    cells_across      = prm.get_integer("Cells across each subdomain");
    fit_crack_tips    = prm.get_bool("Fit crack tips");
    degree_first      = prm.get_integer("Polynomial degree of layer 1");
    degree_second     = prm.get_integer("Polynomial degree of layer 2");
    n_cycles          = prm.get_integer("Number of cycles");
    mesh_files        = Utilities::split_string_list(prm.get("Mesh files"));
    gmsh_size_factor  = get_double(prm, "Mesh", "Gmsh mesh size factor");
    AssertThrow(gmsh_size_factor >= 1e-3 && gmsh_size_factor <= 1e3,
                ExcMessage("Mesh/Gmsh mesh size factor must lie in [1e-3, "
                           "1e3], got " +
                           prm.get("Gmsh mesh size factor")));
    gmsh_time_limit = get_double(prm, "Mesh", "Gmsh time limit");
    AssertThrow(gmsh_time_limit >= 1 && gmsh_time_limit <= 1e6,
                ExcMessage("Mesh/Gmsh time limit must lie in [1, 1e6] "
                           "seconds, got " +
                           prm.get("Gmsh time limit")));
    if (!mesh_files.empty())
      shape = ElementShape::triangle;
    cells_along_sigma_plus =
      prm.get_integer("Cells along Sigma on the plus side");
    refinement = prm.get("Refinement") == "adaptive" ? Refinement::adaptive :
                                                       Refinement::global;
    marking =
      prm.get("Marking") == "bulk" ? Marking::bulk : Marking::fixed_number;
    marking_spelled_fixed_fraction = prm.get("Marking") == "fixed fraction";
    refinement_fraction = get_double(prm, "Mesh", "Refinement fraction");
    AssertThrow(refinement_fraction > 0 && refinement_fraction <= 1,
                ExcMessage("Mesh/Refinement fraction must lie in (0, 1], got " +
                           prm.get("Refinement fraction")));
    {
      const std::string goal   = prm.get("Refinement goal");
      const auto        refuse = [&goal]() {
        AssertThrow(false,
                    ExcMessage("Mesh/Refinement goal must be estimator, "
                                      "energy, G or G at tip K (K >= 1), got '" +
                               goal + "'"));
      };
      if (goal == "estimator")
        refinement_goal = Goal::estimator;
      else if (goal == "energy")
        refinement_goal = Goal::energy;
      else if (goal == "G")
        refinement_goal = Goal::G;
      else if (goal.rfind("G at tip ", 0) == 0)
        {
          const std::string number = goal.substr(9);
          if (number.empty() || number.size() > 6 ||
              number.find_first_not_of("0123456789") != std::string::npos ||
              std::stoul(number) == 0)
            refuse();
          refinement_goal = Goal::G_at_tip;
          goal_tip        = std::stoul(number) - 1;
        }
      else
        refuse();
    }
    target_accuracy = get_double(prm, "Mesh", "Target accuracy");
    AssertThrow(target_accuracy >= 0 && target_accuracy < 1,
                ExcMessage("Mesh/Target accuracy must lie in [0, 1), got " +
                           prm.get("Target accuracy")));
    target_quantity     = prm.get("Target quantity") == "energy" ?
                            TargetQuantity::energy :
                            TargetQuantity::G;
    interface_terms     = prm.get_bool("Interface terms in the estimator");
    contact_weight      = get_double(prm, "Mesh", "Weight of the contact term");
    refuse_above_memory = prm.get_bool("Refuse above available memory");
    AssertThrow(refinement == Refinement::global ||
                  shape == ElementShape::quadrilateral,
                ExcMessage("Mesh/Refinement = adaptive needs Mesh/Element "
                           "shape = quadrilaterals and no Mesh files (deal.II "
                           "9.4 refines triangle meshes only globally)"));
    prm.leave_subsection();
  }
} // namespace bilayer
