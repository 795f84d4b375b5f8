#ifndef bilayer_mesh_parameters_h
#define bilayer_mesh_parameters_h

#include <deal.II/base/parameter_handler.h>

#include <bilayer/core/layout.h>

#include <string>
#include <vector>

/**
 * The subsection Mesh: element shape, cells, polynomial degrees, cycles
 * and their refinement, mesh files and the Gmsh meshing settings.
 */
namespace bilayer
{
  enum class ElementShape
  {
    quadrilateral,
    triangle
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

  /// The quantity whose accuracy Mesh/Target accuracy asks for.
  enum class TargetQuantity
  {
    /// G at every crack tip: its error bar dG relative to |G|.
    G,
    /// The energy: eta^2 / (2 |Pi|), eta the energy-norm estimate.
    energy
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
    /// What adaptive refinement marks for (Mesh/Refinement goal): the
    /// residual estimator of the energy norm (estimator), or the
    /// dual-weighted residual indicators of a goal (docs/fracture.md §11):
    /// the energy, G at every tip, or G at tip goal_tip (0-based).
    enum class Goal
    {
      estimator,
      energy,
      G,
      G_at_tip
    };
    Goal         refinement_goal = Goal::estimator;
    unsigned int goal_tip        = 0;
    /// The relative accuracy wanted of target_quantity: the cycles stop at
    /// the first that meets it; 0: none (n_cycles cycles).
    double         target_accuracy = 0;
    TargetQuantity target_quantity = TargetQuantity::G;
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
} // namespace bilayer

#endif
