#ifndef bilayer_output_h
#define bilayer_output_h

#include <deal.II/numerics/data_postprocessor.h>

#include <bilayer/interface/interface.h>
#include <bilayer/interface/interface_diagnostics.h>
#include <bilayer/output/output_directory.h>
#include <bilayer/physics/elastic_law.h>
#include <bilayer/physics/plies.h>
#include <bilayer/physics/volume_load.h>
#include <bilayer/solvers/outer_solver.h>
#include <bilayer/subproblem/subproblem.h>

#include <functional>
#include <limits>
#include <ostream>
#include <string>
#include <utility>
#include <vector>

namespace bilayer
{
  /**
   * The stresses of one layer from the displacement gradient, by its
   * ElasticLaw: sigma, sigma_zz, and the von Mises stress
   * sqrt(((s_xx - s_yy)^2 + (s_yy - s_zz)^2 + (s_zz - s_xx)^2) / 2
   *      + 3 s_xy^2).
   * With an eigenstrain eps* (@p volume), of the elastic strain:
   * sigma = C (eps(w) - eps*), sigma_zz = out_of_plane_stress(eps(w) -
   * eps*) + VolumeLoad::eigenstress_zz() (a thermal load in plane strain:
   * -E_3 alpha_3 dT; 0 for an in-plane eigenstrain).
   */
  class StressPostprocessor : public dealii::DataPostprocessor<2>
  {
  public:
    /// The stresses of the plies' @p laws (each cell its own) with the
    /// eigenstrain of @p volume.
    explicit StressPostprocessor(const PlyLaws    &laws,
                                 const VolumeLoad *volume = nullptr);

    void
    evaluate_vector_field(
      const dealii::DataPostprocessorInputs::Vector<2> &inputs,
      std::vector<dealii::Vector<double>> &computed_quantities) const override;

    std::vector<std::string>
    get_names() const override;

    dealii::UpdateFlags
    get_needed_update_flags() const override;

  private:
    const PlyLaws &laws;
    /// The eigenstrain, or null where the layer has none.
    const VolumeLoad *eigenstrain;
  };

  /**
   * Write @p path through a temporary file that is renamed when complete,
   * so that a reader never sees a half-written file.
   */
  void
  write_atomically(const std::string                         &path,
                   const std::function<void(std::ostream &)> &writer);

  /**
   * Append what @p writer writes to the file @p path (created if missing);
   * where that fails, the file is cut back to its length before the call
   * and the failure thrown (one line naming the file).
   */
  void
  append_to(const std::string                         &path,
            const std::function<void(std::ostream &)> &writer);

  /// Further cell data of the solution files, by name: per subproblem one
  /// value per active cell (active_cell_index()); a subproblem whose
  /// vector is empty or of another size gets NaN (all pieces carry the
  /// same fields).
  struct CellFields
  {
    std::vector<std::string>                           names;
    std::vector<PerSubproblem<dealii::Vector<double>>> values;
  };

  /// What write_solution() keeps from cycle to cycle.
  struct SolutionRecords
  {
    /// (cycle, solution-NN.pvtu) for solution.pvd.
    std::vector<std::pair<double, std::string>> pvd;
    /// Per cycle: the XDMF grids of the pieces (solution.xdmf).
    std::vector<std::pair<unsigned int, std::vector<std::string>>> xdmf;
    /// Per interface: (cycle, interface-NN.vtu) for interface.pvd (Sigma;
    /// interface k >= 2: interfacek-NN.vtu, interfacek.pvd).
    std::vector<std::vector<std::pair<double, std::string>>> interface_pvd;
    /// Whether the collections (solution.pvd, solution.xdmf,
    /// interface.pvd) wait for write_collections() instead of being
    /// rewritten whole with every cycle: a growth run of many steps writes
    /// a constant number of bytes per step.
    bool deferred = false;
    /// The time of the records written next in solution.pvd and
    /// interface.pvd (a growth step's load factor, ...); NaN: the cycle's
    /// number.
    double time = std::numeric_limits<double>::quiet_NaN();

    /// The time of cycle @p cycle in the .pvd collections.
    double
    time_of(const unsigned int cycle) const
    {
      return time == time ? time : cycle;
    }
  };

  /**
   * One cycle's solution output, one piece per subproblem written by its
   * owner (fields displacement, von_mises, stress_xx, stress_yy, stress_zz,
   * stress_xy and the cell fields layer = 1, 2 and subdomain = -1, +1):
   *  - with Output/Write VTU, solution-NN-{u,v}-{minus,plus}.vtu, a
   *    solution-NN.pvtu that groups them into one dataset and solution.pvd
   *    over all cycles written so far;
   *  - with Output/Write HDF5, solution-NN-{u,v}-{minus,plus}.h5 (deal.II's
   *    HDF5 writer: nodes, cells and fields of the piece) and
   *    solution.xdmf, a temporal collection over the cycles of spatial
   *    collections of the pieces, which ParaView's XDMF reader opens.
   * The first process writes the .pvtu, .pvd and .xdmf files (collective).
   */
  void
  write_solution(const std::string                              &directory,
                 const unsigned int                              cycle,
                 const PerSubproblem<const ElasticSubproblem *> &subproblems,
                 const Solutions                                &solutions,
                 const OutputParameters                         &parameters,
                 SolutionRecords                                &records,
                 const CellFields                               &extra = {});

  /**
   * The interface dataset of one cycle, interface-NN.vtu, and
   * interface.pvd over the cycles written so far: the polyline along Sigma
   * through the nodes of the multiplier across Sigma (@p nodes, from
   * interface_nodes(); a line cell between neighbours in s), undeformed,
   * with the point data
   *  - contact_pressure, normal_traction, mu_c [stress] (InterfaceNode),
   *  - jump_normal, jump_tangential: [u].nu and [u].tau of layer 1 [length],
   *  - state: 0 open, 1 closed (in contact), 2 glued; crack_tip: 1 at the
   *    glued nodes next to the crack; s: the parameter on Sigma,
   *  - the vectors (x, y components) normal, mu_g, mu_minus, mu_plus
   *    [stress] and the layers' traces u_minus, u_plus, v_minus, v_plus
   *    [length] (named by @p trace_names, one per InterfaceNode::trace).
   */
  void
  write_interface_vtu(const std::string                &directory,
                      const unsigned int                cycle,
                      const std::vector<InterfaceNode> &nodes,
                      const std::vector<std::string>   &trace_names,
                      SolutionRecords                  &records,
                      const unsigned int                i = 0);

  /// The stem of the files of interface @p i: "interface" (Sigma, i = 0),
  /// "interface2", "interface3", ...
  inline std::string
  interface_stem(const unsigned int i)
  {
    return i == 0 ? "interface" : "interface" + std::to_string(i + 1);
  }

  /// solution.pvd, solution.xdmf and interface.pvd of the cycles in
  /// @p records (those with a cycle written; first process).
  void
  write_collections(const std::string     &directory,
                    const SolutionRecords &records);
} // namespace bilayer

#endif
