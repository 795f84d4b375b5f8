#include <bilayer/core/huge_pages.h>

#include <SuiteSparse_config.h>
#include <cstdint>
#include <cstdlib>
#include <mutex>
#include <string>
#include <sys/mman.h>

namespace bilayer
{
  namespace huge_pages
  {
    bool
    enabled() noexcept
    {
      static const bool on = [] {
        const char *value = std::getenv("BILAYER_HUGE_PAGES");
        return value == nullptr || std::string(value) != "off";
      }();
      return on;
    }


    void
    advise(void *p, const std::size_t size) noexcept
    {
      if (p == nullptr || size < threshold || !enabled())
        return;
      constexpr std::uintptr_t page  = std::uintptr_t(2) << 20;
      const auto               start = reinterpret_cast<std::uintptr_t>(p);
      const std::uintptr_t     begin = (start + page - 1) / page * page,
                           end       = (start + size) / page * page;
      if (end > begin)
        // A refusal (no THP in this kernel) leaves the usual pages.
        (void)madvise(reinterpret_cast<void *>(begin),
                      end - begin,
                      MADV_HUGEPAGE);
    }


    namespace
    {
      void *
      advised_malloc(const std::size_t size)
      {
        void *p = std::malloc(size);
        advise(p, size);
        return p;
      }


      void *
      advised_calloc(const std::size_t n, const std::size_t size)
      {
        void *p = std::calloc(n, size);
        if (size != 0 && n <= SIZE_MAX / size)
          advise(p, n * size);
        return p;
      }


      void *
      advised_realloc(void *old, const std::size_t size)
      {
        void *p = std::realloc(old, size);
        advise(p, size);
        return p;
      }
    } // namespace


    void
    use_for_cholmod()
    {
      static std::once_flag once;
      std::call_once(once, [] {
        SuiteSparse_config.malloc_func  = advised_malloc;
        SuiteSparse_config.calloc_func  = advised_calloc;
        SuiteSparse_config.realloc_func = advised_realloc;
      });
    }
  } // namespace huge_pages
} // namespace bilayer
