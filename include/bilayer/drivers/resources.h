#ifndef bilayer_resources_h
#define bilayer_resources_h

#include <bilayer/parameters/parameters.h>

#include <array>
#include <cstdint>
#include <stdexcept>
#include <string>

namespace bilayer
{
  /**
   * What a cycle of a scene will need, estimated before anything is
   * allocated. The memory model is fitted to the peak resident memory of
   * runs of the 2-core development machine (docs/robustness.md,
   * scripts/memory_model): the four Cholesky factors dominate, and their
   * fill grows like n log n in two dimensions.
   */
  struct ResourceEstimate
  {
    /// Degrees of freedom of the four subproblems.
    double dofs = 0;
    /// Peak memory of one process holding all of them [bytes].
    double memory = 0;
    /// Files of one cycle in the output directory [bytes].
    double output = 0;
  };

  /// Estimate for subdomain meshes of @p cells_minus and @p cells_plus
  /// cells (each layer on both).
  ResourceEstimate
  estimate_resources(const Scene &scene,
                     const double cells_minus,
                     const double cells_plus);

  /**
   * The cells of the two structured meshes of cycle @p cycle (the built-in
   * rectangle, global refinement), computed in floating point so that no
   * size overflows; 0 for scenes whose mesh sizes are only known once
   * built (mesh files, adaptive cycles after the first).
   */
  std::array<double, 2>
  structured_cells(const Scene &scene, const unsigned int cycle);

  /**
   * Memory this process may still allocate [bytes]: the smallest of the
   * machine's available memory (/proc/meminfo), the address-space limit
   * (RLIMIT_AS) and a cgroup's memory.max.
   */
  double
  available_memory();

  /// What limits the memory of this process, for available_memory() and
  /// the refusals.
  struct MemoryAvailability
  {
    enum class Limit
    {
      /// MemAvailable of /proc/meminfo.
      machine,
      /// The address-space limit, RLIMIT_AS (ulimit -v).
      address_space,
      /// The cgroup's memory.max.
      cgroup
    };
    /// What this process may still allocate [bytes] (the smallest limit).
    double bytes = 0;
    Limit  limit = Limit::machine;
    /// MemAvailable [bytes].
    double machine = 0;
    /// With an address-space limit: the limit, the address space mapped
    /// already, and the work buffers the BLAS will map [bytes].
    double address_space = 0, mapped = 0, blas_buffers = 0;
    /// The BLAS is OpenBLAS.
    bool openblas = false;

    /**
     * The end of a refusal of @p needed bytes: what is available, what
     * limits it and what to do: @p entries first; under an address-space
     * limit also the memory each OpenBLAS thread maps, and the variables
     * to set where fewer threads would leave room for @p needed; and the
     * entry that overrides the refusal.
     */
    std::string
    shortage(const std::string &entries, const double needed) const;
  };

  /**
   * The limits of available_memory() (collective: no; the same on every
   * call). Under an address-space limit with OpenBLAS, also makes the
   * process end without OpenBLAS's destructor (whose threads may wait for
   * ever for work buffers the limit does not allow).
   */
  MemoryAvailability
  memory_availability();

  /**
   * Refuse a scene whose largest cycle cannot fit (structured meshes with
   * global refinement, known before anything is built): a one-line message
   * naming the entries, the estimate and what is available.
   */
  void
  check_scene_resources(const Scene &scene, const unsigned int processes);

  /**
   * A run that stopped before its end for a reason that is not a user error
   * (a cycle that would exceed the memory, an allocation that failed): the
   * results of the cycles so far are kept as a failed run.
   */
  class RunFailure : public std::runtime_error
  {
  public:
    RunFailure(const unsigned int cycle, const std::string &why)
      : std::runtime_error(why)
      , cycle(cycle)
    {}

    const unsigned int cycle;
  };

  /// "1.5 GiB", "300 MiB".
  std::string
  format_bytes(const double bytes);
} // namespace bilayer

#endif
