#ifndef bilayer_distribution_h
#define bilayer_distribution_h

#include <deal.II/base/mpi.h>
#include <deal.II/base/types.h>
#include <deal.II/lac/vector.h>

#include <bilayer/core/layout.h>

#include <algorithm>
#include <array>
#include <stdexcept>
#include <string>
#include <vector>

namespace bilayer
{
  /**
   * How the subproblems of the decomposition (u-, u+, v-, v+, ..., in the
   * order of Layout::index()) are distributed over the processes of an
   * MPI job.
   *
   * Subproblem s belongs to process s mod R for R <= 4 processes (R = 4: one
   * each of two layers; R = 2: u- and v- on process 0, u+ and v+ on
   * process 1; more layers go round the processes the same way). For
   * R > 4 (two layers: scene_checks refuses more layers there), subproblem
   * s belongs to the group of processes r with
   * r mod 4 = s, which share its matrix and its factorisation (a METIS
   * partition of the cells, Trilinos distributed matrices and a parallel
   * direct solver: see ElasticSubproblem); the first process of the group
   * is its root.
   *
   * Every process holds the replicated data: both meshes, the dof
   * numbering of all four subproblems, the interface and the multipliers.
   * Only the owners assemble, factorise and solve a subproblem; after each
   * round of solves the root of each subproblem sends the values of its
   * solution on Sigma (the trace dofs) to all processes, which then
   * evaluate the jumps and update the multipliers identically. Those
   * traces are the only data exchanged in an iteration, so the iterates are
   * the same bits as a serial run's when every subproblem is solved by one
   * process.
   *
   * The default-constructed object is the serial layout (one process owns
   * everything, no MPI call is made), so that code without MPI_Init works.
   */
  class Distribution
  {
  public:
    /// The most groups of processes: the four subproblems of two layers. A
    /// job of more processes shares each of them among a group.
    static constexpr unsigned int max_groups = 4;

    /// One process owns everything; no MPI calls.
    Distribution();

    /// The processes of @p communicator (MPI must be initialised).
    explicit Distribution(const MPI_Comm communicator);

    ~Distribution();
    Distribution(const Distribution &) = delete;
    Distribution &
    operator=(const Distribution &) = delete;

    /// MPI_COMM_WORLD if MPI is initialised, the serial layout otherwise.
    static const Distribution &
    world();

    unsigned int
    n_processes() const
    {
      return n_processes_;
    }
    unsigned int
    process() const
    {
      return process_;
    }
    /// Whether this is the process that writes the shared outputs.
    bool
    is_root() const
    {
      return process_ == 0;
    }
    bool
    parallel() const
    {
      return n_processes_ > 1;
    }
    const MPI_Comm &
    communicator() const
    {
      return communicator_;
    }

    /// Whether this process owns (or shares) subproblem @p s.
    bool
    owns(const unsigned int s) const;

    /// The first process of the group of subproblem @p s.
    unsigned int
    root(const unsigned int s) const
    {
      return n_processes_ <= max_groups ? s % n_processes_ : s;
    }

    /// Number of processes that share subproblem @p s.
    unsigned int
    group_size(const unsigned int s) const;

    /// The processes that share this process's subproblem (R > 4; the
    /// process's own communicator otherwise).
    const MPI_Comm &
    group_communicator() const
    {
      return group_communicator_;
    }

    /**
     * Copy the entries @p indices (all entries if null) of @p v from the
     * root of subproblem @p s to every process (collective). @p v must
     * have the same size on every process; it keeps its other entries.
     */
    void
    share(const unsigned int                                  s,
          dealii::Vector<double>                             &v,
          const std::vector<dealii::types::global_dof_index> *indices =
            nullptr) const;

    /**
     * Entry s of @p values from the root of subproblem s, for every s
     * (collective): each owner fills in its own entries.
     */
    void
    share(PerSubproblem<double> &values) const;

    /// Largest of @p value over the processes (collective).
    double
    max(const double value) const;

    /// @p value of every process, at the root (collective).
    std::vector<double>
    gather(const double value) const;

    /// All processes wait here (collective).
    void
    barrier() const;

    /**
     * A flag and a message decided on the root process, the same on every
     * process afterwards (collective): how an error found by one process
     * (an unwritable output directory) stops all of them.
     */
    void
    broadcast(bool &flag, std::string &message) const;

    /**
     * The first non-empty @p message over the processes (in process
     * order), on every process (collective): an error found by some
     * processes (a file that could not be written) becomes known to all,
     * which then stop together.
     */
    std::string
    first_error(const std::string &message) const;

    /// Values sent by share() so far (the root's count: the exchange
    /// volume of the iterations is 8 bytes times this per receiver).
    unsigned long
    shared_values() const
    {
      return shared_values_;
    }

    /// Wall time spent in share() so far [s] (the exchange, with the
    /// waiting for the slowest owner).
    double
    shared_seconds() const
    {
      return shared_seconds_;
    }

  private:
    MPI_Comm              communicator_;
    MPI_Comm              group_communicator_;
    bool                  own_group_communicator = false;
    unsigned int          n_processes_           = 1;
    unsigned int          process_               = 0;
    mutable unsigned long shared_values_         = 0;
    mutable double        shared_seconds_        = 0;
  };

  /**
   * An error that every process throws together (after first_error()), so
   * that they can stop without MPI_Abort and remove what they staged.
   */
  class CollectiveError : public std::runtime_error
  {
  public:
    using std::runtime_error::runtime_error;
  };
} // namespace bilayer

#endif
