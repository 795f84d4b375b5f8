#ifndef bilayer_build_info_h
#define bilayer_build_info_h

#include <string>

namespace bilayer
{
  /**
   * @name Build information
   *
   * What this program is and what it runs on, for `bilayer --version` and
   * the summary of a run: the version and git commit of bilayer, the
   * deal.II it was compiled with, and the BLAS that this process loaded
   * (which the Cholesky factorisations of CHOLMOD use; on Debian it is
   * chosen at run time by update-alternatives, not at build time).
   */
  /** @{ */

  /**
   * The version of bilayer, e.g. "0.9.0" (set once, by project() in
   * CMakeLists.txt).
   */
  std::string
  version();

  /**
   * The git commit of the source tree when this library was built: the
   * short hash of HEAD, e.g. "75c36da", followed by "-dirty" when tracked
   * files had uncommitted changes, or "unknown" when the sources were not
   * a git checkout or git was missing. It is determined at every build,
   * so it is right after a new commit without re-running cmake.
   */
  std::string
  git_commit();

  /**
   * The version of deal.II that bilayer was compiled with
   * (DEAL_II_PACKAGE_VERSION, e.g. "9.4.1"), followed by " (git
   * SHORTREV)" when that deal.II was built from a git checkout.
   */
  std::string
  deal_ii_version();

  /**
   * The BLAS that this process uses, found at run time: the shared object
   * that provides dgemm_ (as the dynamic loader resolved it, symbolic
   * links resolved), named by the library itself where it can tell:
   * - OpenBLAS: its configuration string and the path, e.g.
   *   "OpenBLAS 0.3.21 DYNAMIC_ARCH NO_AFFINITY Haswell MAX_THREADS=64
   *   (/usr/lib/x86_64-linux-gnu/openblas-pthread/libblas.so.3)";
   * - Intel MKL: its version string and the path;
   * - BLIS: "BLIS" with its version and the path;
   * - Debian's reference BLAS: "reference BLAS
   *   (/usr/lib/x86_64-linux-gnu/blas/libblas.so.3.11.0)";
   * - any other: "BLAS (PATH)";
   * - "unknown" when no BLAS is loaded or it cannot be located.
   */
  std::string
  blas_library();

  /**
   * Set the number of threads of the loaded BLAS to @p n where the BLAS
   * allows it (OpenBLAS: openblas_set_num_threads, Intel MKL:
   * MKL_Set_Num_Threads, BLIS: bli_thread_set_num_threads), looked up at
   * run time; @p n = 0 leaves it unchanged. Returns the number of threads
   * in effect afterwards, as the BLAS reports it (OpenBLAS may cap @p n at
   * the number it was built for), or 1 for a BLAS without threads (the
   * reference BLAS) or an unknown one.
   */
  unsigned int
  set_blas_threads(const unsigned int n);

  /**
   * The number of threads of the loaded BLAS now (set_blas_threads(0)).
   */
  unsigned int
  blas_threads();

  /**
   * "BILAYER_BLAS_THREADS" if that environment variable is set (an
   * override for benchmarks, docs/performance.md), else "". The BLAS's own
   * variables (OPENBLAS_NUM_THREADS, OMP_NUM_THREADS, ...) are overridden:
   * the program sets the count that fits its tasks.
   */
  std::string
  blas_threads_variable();

  /**
   * Give the BLAS the threads that fit the subproblem tasks: the process's
   * @p threads divided among @p tasks that call the BLAS at the same time
   * (at least one each), or BILAYER_BLAS_THREADS where set (a whole number
   * from 1 to 1024, else an exception naming it). Returns the BLAS threads
   * in effect.
   */
  unsigned int
  fit_blas_threads(const unsigned int threads, const unsigned int tasks);

  /**
   * The sparse factorisations' own OpenMP loops (CHOLMOD's supernodal
   * assembly: parallel regions of a team size fixed when CHOLMOD was built,
   * four in Debian's) follow the BLAS: where each task's BLAS call has one
   * thread (@p blas_threads_per_call <= 1), every OpenMP parallel region of
   * the process runs as a team of one (OpenMP's max-active-levels 0),
   * because the tasks already occupy the cores and the extra teams only
   * spin and switch (Example 1 at 1.05 million dofs: the factorisations
   * 8.99 → 7.47 s summed, docs/performance.md "0.31.0: the factorisations'
   * OpenMP loops"); else
   * the OpenMP library's default, also where the environment says
   * BILAYER_OPENMP_LOOPS=library (for benchmarks: scripts/bench_fine_mesh
   * --study setup). Called by fit_blas_threads(); nothing
   * where no OpenMP library is loaded. Changes no result: the loops
   * scatter independent columns.
   */
  void
  fit_factorisation_loops(const unsigned int blas_threads_per_call);

  /// Whether the OpenMP parallel regions run as teams of one
  /// (fit_factorisation_loops()).
  bool
  factorisation_loops_serial();

  /** @} */
} // namespace bilayer

#endif
