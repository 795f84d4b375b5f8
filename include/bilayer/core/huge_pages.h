#ifndef bilayer_huge_pages_h
#define bilayer_huge_pages_h

#include <cstddef>

namespace bilayer
{
  /**
   * Transparent huge pages for the large arrays of a run (the sparse
   * factors, the sparse matrices). A fresh allocation of a few hundred
   * MiB is mapped page by page as it is first written; with 4 KiB pages
   * that is one page fault per 4 KiB, and on virtual machines the faults
   * cost more than the factorisation's arithmetic (measured:
   * docs/performance.md, "Memory pages"). Where the kernel grants
   * transparent huge pages on request (/sys/kernel/mm/transparent_hugepage/
   * enabled = madvise or always), asking for them on blocks of at least
   * 4 MiB makes the faults 512 times fewer. Nothing changes in what is
   * computed.
   */
  namespace huge_pages
  {
    /// The smallest block that is advised.
    constexpr std::size_t threshold = std::size_t(4) << 20;

    /// False where the environment says BILAYER_HUGE_PAGES=off (for
    /// benchmarks: scripts/bench_fine_mesh --study pages).
    bool
    enabled() noexcept;

    /// Ask for huge pages on the 2 MiB-aligned part of [p, p + size) if
    /// size >= threshold (a no-op elsewhere, and where the kernel refuses).
    void
    advise(void *p, std::size_t size) noexcept;

    /// CHOLMOD's allocations (SuiteSparse_config's malloc, calloc,
    /// realloc) advised; idempotent and thread-safe.
    void
    use_for_cholmod();
  } // namespace huge_pages
} // namespace bilayer

#endif
