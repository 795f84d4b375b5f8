#include <bilayer/app/run.h>
#include <bilayer/app/run_environment.h>
#include <bilayer/core/huge_pages.h>

#include <cstdlib>
#include <new>

// Before every shared library's initialisation: invalid thread counts of
// the environment are hidden from the libraries, and refused by the run.
__attribute__((section(".preinit_array"), used)) static void (
    *const hide_invalid_thread_counts_early)(int, char **, char **) =
  &bilayer::hide_invalid_thread_counts;

// The program's large C++ arrays (deal.II's sparse matrices and patterns)
// on transparent huge pages where the kernel grants them
// (include/bilayer/core/huge_pages.h): the replaceable global allocation
// functions, which the shared libraries use as well; every plain and
// nothrow form, so that each new meets its own delete. Not under
// AddressSanitizer, whose own forms check the pairs.
#if !defined(__SANITIZE_ADDRESS__)
void *
operator new(std::size_t size)
{
  void *p = std::malloc(size == 0 ? 1 : size);
  if (p == nullptr)
    throw std::bad_alloc();
  bilayer::huge_pages::advise(p, size);
  return p;
}

void *
operator new[](std::size_t size)
{
  return operator new(size);
}

void *
operator new(std::size_t size, const std::nothrow_t &) noexcept
{
  void *p = std::malloc(size == 0 ? 1 : size);
  bilayer::huge_pages::advise(p, size);
  return p;
}

void *
operator new[](std::size_t size, const std::nothrow_t &tag) noexcept
{
  return operator new(size, tag);
}

void
operator delete(void *p) noexcept
{
  std::free(p);
}

void
operator delete[](void *p) noexcept
{
  std::free(p);
}

void
operator delete(void *p, std::size_t) noexcept
{
  std::free(p);
}

void
operator delete[](void *p, std::size_t) noexcept
{
  std::free(p);
}

void
operator delete(void *p, const std::nothrow_t &) noexcept
{
  std::free(p);
}

void
operator delete[](void *p, const std::nothrow_t &) noexcept
{
  std::free(p);
}
#endif

int
main(int argc, char **argv)
{
  return bilayer::run_program(argc, argv);
}
