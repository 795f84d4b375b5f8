#ifndef bilayer_study_h
#define bilayer_study_h

#include <deal.II/base/conditional_ostream.h>
#include <deal.II/base/convergence_table.h>
#include <deal.II/lac/block_vector.h>

#include <bilayer/distribution.h>
#include <bilayer/geometry.h>
#include <bilayer/interface.h>
#include <bilayer/outer_solver.h>
#include <bilayer/output.h>
#include <bilayer/parameters.h>
#include <bilayer/subproblem.h>

#include <memory>
#include <ostream>
#include <string>
#include <utility>
#include <vector>

namespace bilayer
{
  using namespace dealii;

  /// Everything reported about one cycle (one mesh) of a study.
  struct CycleRecord
  {
    unsigned int   cycle = 0;
    MeshStatistics minus, plus;
    /// Vertices on Sigma and on the outer boundary (P and M of Table 1).
    unsigned int    P = 0, M = 0;
    unsigned int    dofs = 0, multipliers = 0;
    double          theta = 0;
    SolverResult    result;
    double          energy = 0;
    InterfaceReport report;
    /// Acceptance checks: (description, passed).
    std::vector<std::pair<std::string, bool>> checks;
    double setup_seconds = 0, solve_seconds = 0, total_seconds = 0;
    /// MPI processes, values sent from the subproblems' owners to all
    /// processes in the iterations (traces on Sigma), and the peak resident
    /// memory of each process [MiB].
    unsigned int  processes     = 1;
    unsigned long shared_values = 0;
    /// Wall time of that exchange on the first process [s].
    double              shared_seconds = 0;
    std::vector<double> memory_mib;
    /// The memory this cycle was estimated to need before it was built
    /// (bilayer/resources.h) [MiB].
    double memory_estimate_mib = 0;
    /// Parts of setup_seconds: assembly and factorisation of the four
    /// subproblems, summed.
    double assembly_seconds = 0, factorisation_seconds = 0;

    /// What the solver or the checks add to a failure (e.g. the bound p).
    std::string note;

    bool
    accepted() const;

    /// One line for a cycle that is not accepted: the failed checks, the
    /// solver's message and the note.
    std::string
    failure() const;
  };

  /**
   * The outer loop: for each cycle build the two meshes, the four
   * subproblems (assembled and factorised once) and the interface, run the
   * contact solver, check the residuals of the result, and write the
   * outputs (VTU/PVD, interface-NN.csv, summary.json, the mesh-size table).
   */
  class Study
  {
  public:
    /**
     * A study of @p scene that reports to @p out, run by the processes of
     * @p distribution (the MPI job if MPI is initialised; results are
     * reported and written by its first process, the VTU/HDF5 pieces by
     * the owners of the subproblems).
     */
    Study(const Scene        &scene,
          std::ostream       &out,
          const Distribution &distribution = Distribution::world());

    /// All cycles; true if every cycle converged and passed its checks.
    /// Stops at the first cycle that does not.
    bool
    run();

    /// One cycle (mesh cycle @p cycle); appends to records().
    const CycleRecord &
    run_cycle(const unsigned int cycle);

    const std::vector<CycleRecord> &
    records() const
    {
      return cycle_records;
    }
    const Interface &
    interface() const
    {
      return coupling;
    }
    const Solutions &
    solutions() const
    {
      return w;
    }
    const BlockVector<double> &
    multipliers() const
    {
      return mu;
    }
    const ElasticSubproblem &
    subproblem(const Layer layer, const Subdomain subdomain) const
    {
      return *subproblems[Interface::index(layer, subdomain)];
    }

    /**
     * Replace the error indicators by which the next adaptive cycle marks
     * cells (one value per active cell of each subdomain, in the order of
     * active_cell_iterators(); Mesh/Marking applies as usual), so that a
     * driver can refine by a criterion of its own.
     */
    void
    set_indicators(const std::array<Vector<float>, 2> &new_indicators);

  private:
    void
    check(CycleRecord &record) const;
    void
    print_report(const CycleRecord &record) const;
    void
    write_summary() const;
    void
    write_csv_table(std::ostream &out) const;
    void
    add_to_table(const CycleRecord &record);

    const Scene         scene;
    std::ostream       &out;
    const Distribution &distribution;
    /// Progress (Output/Terminal output = full) and the checks, both on the
    /// first process only.
    ConditionalOStream                                pcout, rout;
    Geometry                                          domain;
    std::array<std::unique_ptr<ElasticSubproblem>, 4> subproblems;
    Interface                                         coupling;
    Solutions                                         w;
    BlockVector<double>                               mu;
    std::vector<CycleRecord>                          cycle_records;
    SolutionRecords                                   outputs;
    ConvergenceTable                                  table;
    /// Error indicators of the last cycle, per subdomain (adaptive
    /// refinement).
    std::array<Vector<float>, 2> indicators;
  };
} // namespace bilayer

#endif
